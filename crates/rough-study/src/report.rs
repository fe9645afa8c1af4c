//! Collects a reference test's failures so one run shows all of them, and
//! the worst case.

use crate::rel_err;

/// Failures and the worst [`rel_err`] over the values checked.
#[derive(Default)]
pub struct Report {
    failures: Vec<String>,
    pub worst: f64,
    worst_at: String,
    pub checked: usize,
}

impl Report {
    /// Compares `got` with `want` ([`rel_err`]); over `tol` is a failure.
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

    /// Prints the worst case; panics with the first 40 failures if any.
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
