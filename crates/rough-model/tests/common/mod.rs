//! Shared by the reference tests: the CSV reader, the named tolerances and a
//! comparison that reports input, got, want and relative error.
#![allow(dead_code)]

use std::collections::HashMap;

/// Named tolerances, relative. One place, so that a change is visible.
pub mod tol {
    /// The contract: every output within 1e-12 of the 50-digit reference.
    pub const CONTRACT: f64 = 1e-12;
    /// Below this the contract allows 0 (or any value below it).
    pub const TINY: f64 = 1e-300;
}

/// One reference table: column names and rows of text fields.
pub struct Table {
    pub columns: Vec<String>,
    pub rows: Vec<Vec<String>>,
    index: HashMap<String, usize>,
}

impl Table {
    /// Reads `tests/data/{name}`: `#` comment lines, a header, then rows.
    pub fn load(name: &str) -> Table {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let mut lines = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty());
        let columns: Vec<String> = lines
            .next()
            .expect("header")
            .split(',')
            .map(str::to_owned)
            .collect();
        let index = columns
            .iter()
            .enumerate()
            .map(|(i, c)| (c.clone(), i))
            .collect();
        let rows: Vec<Vec<String>> = lines
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect();
        assert!(!rows.is_empty(), "{path} has no rows");
        Table {
            columns,
            rows,
            index,
        }
    }

    pub fn col(&self, name: &str) -> usize {
        *self
            .index
            .get(name)
            .unwrap_or_else(|| panic!("no column {name}"))
    }

    /// The value in `row` of column `name`; `None` for an empty field.
    pub fn get(&self, row: &[String], name: &str) -> Option<f64> {
        let s = row[self.col(name)].trim();
        if s.is_empty() {
            None
        } else {
            Some(parse(s))
        }
    }
}

pub fn parse(s: &str) -> f64 {
    match s {
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        _ => s.parse().unwrap_or_else(|e| panic!("bad number {s}: {e}")),
    }
}

/// Relative error of `got` against `want` under the contract's rules:
/// infinities must match exactly; below `TINY` any value below `TINY` is exact.
pub fn rel_err(got: f64, want: f64) -> f64 {
    if got.is_nan() {
        return f64::INFINITY;
    }
    if want.is_infinite() || got.is_infinite() {
        return if got == want { 0.0 } else { f64::INFINITY };
    }
    if want.abs() < tol::TINY && got.abs() < tol::TINY {
        return 0.0;
    }
    if want == 0.0 {
        return f64::INFINITY;
    }
    ((got - want) / want).abs()
}

/// Collects failures so one run shows all of them, and the worst case.
#[derive(Default)]
pub struct Report {
    failures: Vec<String>,
    pub worst: f64,
    worst_at: String,
    pub checked: usize,
}

impl Report {
    pub fn check(&mut self, what: &str, input: &str, got: f64, want: f64, tol: f64) {
        let e = rel_err(got, want);
        self.checked += 1;
        if e > self.worst || (self.worst_at.is_empty() && e == 0.0) {
            if e > self.worst {
                self.worst = e;
            }
            self.worst_at = format!("{what} at {input}");
        }
        if e > tol {
            self.failures.push(format!(
                "{what} at {input}: got {got:e}, want {want:e}, rel err {e:.2e} > {tol:.0e}"
            ));
        }
    }

    pub fn finish(self, title: &str) {
        eprintln!(
            "{title}: {} values, worst rel err {:.2e} ({})",
            self.checked, self.worst, self.worst_at
        );
        if !self.failures.is_empty() {
            let n = self.failures.len();
            let shown: Vec<_> = self.failures.into_iter().take(40).collect();
            panic!("{title}: {n} values off\n{}", shown.join("\n"));
        }
    }
}
