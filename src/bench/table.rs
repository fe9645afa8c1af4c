//! The table of `roughtui bench` and how its numbers are printed.

use std::fmt::Write as _;

use rough_study::compare::ErrorStat;

use crate::physical::short_number;

/// The table's header, fixed by the command's contract.
pub const HEADER: &str = "| method | terms | ns/point | max rel error | worst psi |";

/// One measured row of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub name: String,
    pub terms: String,
    pub ns_per_point: f64,
    pub err: ErrorStat,
}

/// Errors print like `3.2e-15`; ∞ as `inf`, exact as `0`.
pub fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e.is_infinite() {
        "inf".into()
    } else {
        format!("{e:.1e}")
    }
}

/// A range of ψ from [`rough_study::compare::accurate_range`] as text.
pub fn fmt_range(range: Option<(f64, f64, bool)>) -> String {
    match range {
        None => "nowhere".into(),
        Some((a, b, all)) => format!(
            "ψ from {} to {}{}",
            short_number(a),
            short_number(b),
            if all { " (all ψ > 0)" } else { "" }
        ),
    }
}

/// The markdown table of `rows`.
pub fn render_table(rows: &[Row]) -> String {
    let mut s = String::new();
    s.push_str(HEADER);
    s.push('\n');
    s.push_str("|---|---|---:|---:|---:|\n");
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.1} | {} | {} |",
            r.name,
            r.terms,
            r.ns_per_point,
            fmt_err(r.err.max),
            short_number(r.err.worst_psi)
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use rough_study::compare::methods;

    #[test]
    fn psi_format() {
        assert_eq!(fmt_err(3.2e-15), "3.2e-15");
        assert_eq!(fmt_range(None), "nowhere");
        assert_eq!(
            fmt_range(Some((1e-308, 0.2576, false))),
            "ψ from 1e-308 to 0.2576"
        );
    }

    #[test]
    fn table_has_exact_header_and_every_row() {
        let rows: Vec<Row> = methods()
            .iter()
            .map(|m| Row {
                name: m.name.into(),
                terms: m.terms.clone(),
                ns_per_point: 12.3,
                err: ErrorStat {
                    max: 3.2e-15,
                    worst_psi: 1.0,
                },
            })
            .collect();
        let t = render_table(&rows);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines[0], HEADER);
        assert_eq!(lines.len(), 2 + rows.len());
        for need in ["shipped", "image 1 ", "image 2 ", "image 4 ", "image 8 "] {
            assert!(t.contains(need), "{need}");
        }
        assert!(t.contains("image 64"));
        assert!(t.contains("fourier 8") && t.contains("fourier 64"));
        assert!(t.contains("naive") && t.contains("model error"));
        assert!(t.contains("finite"));
        assert!(lines[2].contains("| 3.2e-15 |"), "{}", lines[2]);
        for l in &lines[2..] {
            assert_eq!(l.matches('|').count(), 6, "{l}");
        }
    }
}
