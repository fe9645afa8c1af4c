//! The checkable claims a figure makes, located live at the current
//! parameters: where the plastic share passes ½ and where the index in use
//! (Ψ* with the size effect, Ψ_P without) crosses 1 along the sweep.

use rough_model::{psi_in_use, slopes, Axis, Sweep};

use super::number::short_number;
use super::series::at;
use crate::snapshot::State;

/// Which quantity crosses which level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimKind {
    /// S_pl/S_tot crosses ½.
    ShareHalf,
    /// The index in use crosses 1.
    IndexOne,
}

/// One crossing along the sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    pub kind: ClaimKind,
    /// The swept parameter.
    pub axis: Axis,
    /// The swept value where the crossing lies (to ~1e-13 relative).
    pub at: f64,
    /// Whether the quantity rises through the level there.
    pub rising: bool,
    /// With the size effect (the index in use is Ψ*), or without (Ψ_P).
    pub size_effect: bool,
}

impl Claim {
    /// The claim in words: "plastic share passes ½ at ζ = 322.3",
    /// "Ψ* falls below 1 at ζ = 5324".
    pub fn text(&self) -> String {
        let what = match (self.kind, self.rising) {
            (ClaimKind::ShareHalf, true) => "plastic share passes ½".to_string(),
            (ClaimKind::ShareHalf, false) => "plastic share falls below ½".to_string(),
            (ClaimKind::IndexOne, rising) => {
                let psi = if self.size_effect { "Ψ*" } else { "Ψ_P" };
                let verb = if rising { "reaches" } else { "falls below" };
                format!("{psi} {verb} 1")
            }
        };
        let unit = super::axis_unit(self.axis);
        let sep = if unit.is_empty() { "" } else { " " };
        format!(
            "{what} at {} = {}{sep}{unit}",
            self.axis.symbol(),
            short_number(self.at)
        )
    }
}

/// Samples per sweep before bisecting each bracketed crossing.
const SAMPLES: usize = 256;

/// Most crossings reported per kind.
const MAX_PER_KIND: usize = 4;

/// Every crossing of the share ½ and of the index in use 1 along the
/// state's sweep, in sweep order within each kind (share first). Crossings
/// closer together than the sampling step (1/256 of the sweep) may be missed.
pub fn claims(state: &State) -> Vec<Claim> {
    let index = |x: f64| {
        let p = at(&state.params, state.sweep.axis(), x);
        psi_in_use(&p, state.size_effect, state.moments).0
    };
    let share = |x: f64| slopes(state.model, index(x)).plastic_share() - 0.5;
    let psi = |x: f64| index(x).to_f64() - 1.0;
    let mut out = Vec::new();
    for (kind, f) in [
        (ClaimKind::ShareHalf, &share as &dyn Fn(f64) -> f64),
        (ClaimKind::IndexOne, &psi),
    ] {
        for (at, rising) in crossings(&state.sweep, f) {
            out.push(Claim {
                kind,
                axis: state.sweep.axis(),
                at,
                rising,
                size_effect: state.size_effect,
            });
        }
    }
    out
}

/// Zeros of `f` along `s` where it changes sign: (where, rising).
fn crossings(s: &Sweep, f: &dyn Fn(f64) -> f64) -> Vec<(f64, bool)> {
    let xs: Vec<f64> = s.points(SAMPLES).collect();
    let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
    let mut out = Vec::new();
    for i in 0..xs.len() - 1 {
        let (a, b) = (vs[i], vs[i + 1]);
        if a.is_nan() || b.is_nan() || (a < 0.0) == (b < 0.0) {
            continue;
        }
        out.push((bisect(s.axis().is_log(), xs[i], xs[i + 1], f), a < 0.0));
        if out.len() == MAX_PER_KIND {
            break;
        }
    }
    out
}

/// The sign change of `f` in [lo, hi], halving in log space on log axes,
/// until the bracket is 1e-14 relative or cannot shrink.
fn bisect(log: bool, mut lo: f64, mut hi: f64, f: &dyn Fn(f64) -> f64) -> f64 {
    let neg_lo = f(lo) < 0.0;
    for _ in 0..200 {
        let mid = if log {
            (0.5 * (lo.ln() + hi.ln())).exp()
        } else {
            0.5 * (lo + hi)
        };
        if !(mid > lo && mid < hi) || hi - lo <= 1e-14 * hi.abs().max(lo.abs()) {
            break;
        }
        if (f(mid) < 0.0) == neg_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bisection_finds_a_known_root_to_1e_14() {
        let s = Sweep::new(Axis::Zeta, 1.0, 1e4).unwrap();
        let root = 322.27f64;
        let c = crossings(&s, &|x: f64| x.ln() - root.ln());
        assert_eq!(c.len(), 1);
        assert!((c[0].0 / root - 1.0).abs() < 1e-13, "{}", c[0].0);
        assert!(c[0].1);
    }

    #[test]
    fn claims_read_as_sentences() {
        let c = Claim {
            kind: ClaimKind::IndexOne,
            axis: Axis::Zeta,
            at: 5324.4,
            rising: false,
            size_effect: true,
        };
        assert_eq!(c.text(), "Ψ* falls below 1 at ζ = 5324");
        let c = Claim {
            kind: ClaimKind::ShareHalf,
            axis: Axis::HRms,
            at: 2.5e-8,
            rising: true,
            size_effect: false,
        };
        assert_eq!(c.text(), "plastic share passes ½ at h_rms = 2.5e-8 m");
    }
}

#[cfg(test)]
mod preset_tests {
    use super::*;

    fn texts(name: &str) -> Vec<String> {
        claims(&crate::presets::load(name).unwrap())
            .iter()
            .map(Claim::text)
            .collect()
    }

    #[test]
    fn the_presets_claims() {
        assert_eq!(
            texts("fig2"),
            [
                "plastic share passes ½ at ζ = 321.5",
                "Ψ_P reaches 1 at ζ = 3272"
            ]
        );
        assert_eq!(
            texts("fig4"),
            [
                "plastic share falls below ½ at ζ = 1.698e4",
                "Ψ* falls below 1 at ζ = 5324"
            ]
        );
        assert_eq!(
            texts("fig1"),
            [
                "plastic share falls below ½ at H0/E = 0.008318",
                "Ψ_P falls below 1 at H0/E = 0.00523"
            ]
        );
        assert!(texts("fig3").is_empty());
    }
}
