//! The research side of roughtui, kept out of the model and the product.
//!
//! - `data/`: the 50-digit mpmath reference tables, written by the committed
//!   scripts (`scripts/gen_reference.py`, `gen_asymptotic.py`,
//!   `gen_areas_extra.py`). The model's tests read them from disk
//!   ([`Table::read`]); `roughtui bench` embeds the slopes table
//!   ([`SLOPES_CSV`]) so that it runs anywhere.
//! - [`Table`]: the one reader of those tables.
//! - [`rel_err`]: the one rule by which anything is compared with them.
//! - [`forms`]: the exact slopes' two series on their own and the paper's
//!   closed form taken literally: alternatives to compare, not to use.
//! - [`closed_previous`]: the closed form as the model computed it before its
//!   fast path (double-double exponents, libm erfc, a 39-term series).
//! - [`compare`]: every way of computing the initial slopes, with its error
//!   over the reference grid (the rows of `roughtui bench`).
//! - [`Report`]: collects a test's failures so one run shows all of them.

pub mod closed_previous;
pub mod compare;
pub mod forms;
mod report;
mod table;

pub use report::Report;
pub use table::{slopes_reference, SlopeRow, Table, TableError, MODEL_COLUMNS};

/// The folder of the reference tables.
pub const DATA_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data");

/// The slopes reference (`data/slopes.csv`), embedded.
pub const SLOPES_CSV: &str = include_str!("../data/slopes.csv");

/// Named tolerances, relative. One place, so that a change is visible.
pub mod tol {
    /// The contract: every output within 1e-12 of the 50-digit reference.
    pub const CONTRACT: f64 = 1e-12;
    /// Below this the contract allows 0 (or any value up to it).
    pub const TINY: f64 = 1e-300;
    /// Where a smooth curve has its minimum, relative. Values alone place a
    /// minimum only to ~√ε; the explorer takes the root of a five-point
    /// derivative (step h = 1e-3 in ln x), which rounding ε_f in f moves by
    /// ≈ 1.5 ε_f/(h f″/f), the stencil's own error by h⁴|f⁽⁵⁾/f″|/30.
    /// The flattest minimum checked (fig4's, f″/f = 0.035 in ln ζ) gives
    /// 4.7e-12 for ε_f = 1 ulp; the steepest stencil error (fig1's,
    /// f⁽⁵⁾/f″ = 77) 2.6e-12.
    pub const MINIMUM_PLACE: f64 = 1e-11;
    /// What both models' slopes achieve at an exact double ψ, tighter than
    /// the contract: the bound `roughtui bench` is measured against (the
    /// closed form's fast path must not trade accuracy for its speed).
    pub const SLOPES: f64 = 2e-15;
}

/// Relative error |got − want|/|want| of `got` against the reference value
/// `want`, under the model's contract:
///
/// - NaN (in `got`) is an infinite error;
/// - infinities must match exactly (∞ = ∞ is 0, anything else ∞);
/// - a `want` below [`tol::TINY`] in magnitude (0 included) accepts any
///   |`got`| ≤ `TINY` as exact, since results below 1e-300 may be 0 and
///   their digits are not asked for;
/// - a `want` of 0 with |`got`| > `TINY` is an infinite error.
pub fn rel_err(got: f64, want: f64) -> f64 {
    if got.is_nan() {
        return f64::INFINITY;
    }
    if want.is_infinite() || got.is_infinite() {
        return if got == want { 0.0 } else { f64::INFINITY };
    }
    if want.abs() < tol::TINY && got.abs() <= tol::TINY {
        return 0.0;
    }
    if want == 0.0 {
        return f64::INFINITY;
    }
    ((got - want) / want).abs()
}

#[cfg(test)]
mod tests {
    use super::rel_err;

    #[test]
    fn rel_err_conventions() {
        assert_eq!(rel_err(f64::INFINITY, f64::INFINITY), 0.0);
        assert_eq!(rel_err(1.0, f64::INFINITY), f64::INFINITY);
        assert_eq!(rel_err(f64::INFINITY, 1.0), f64::INFINITY);
        assert_eq!(rel_err(1e-301, 0.0), 0.0);
        assert_eq!(rel_err(1e-200, 0.0), f64::INFINITY);
        assert_eq!(rel_err(0.0, 1e-305), 0.0);
        assert_eq!(rel_err(2e-305, 1e-305), 0.0);
        assert_eq!(rel_err(2e-300, 1e-301), 19.0);
        assert_eq!(rel_err(0.0, 1e-200), 1.0);
        assert_eq!(rel_err(f64::NAN, 1.0), f64::INFINITY);
        assert_eq!(rel_err(3.0, 3.0), 0.0);
        assert!((rel_err(1.5, 1.0) - 0.5).abs() < 1e-15);
    }
}
