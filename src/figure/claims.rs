//! The checkable claims a figure makes, located live at the current
//! parameters: where the plastic share passes ½ and where the index in use
//! (Ψ* with the size effect, Ψ_P without) crosses 1 along the sweep.
//!
//! On a measured surface whose moments are sums over the data's
//! wavevectors, the moments are a step function of ζ: a crossing may be a
//! jump at one of the data's wavevectors. Bisection then closes on the jump,
//! and the claim says it is one.

use rough_model::{slopes, Axis, Sweep};

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
    /// The quantity jumps across the level there (a step of a measured
    /// spectrum's sums, at one of its wavevectors) rather than passing it.
    pub step: bool,
}

impl Claim {
    /// The claim in words: "plastic share passes ½ at ζ = 322.3",
    /// "Ψ* falls below 1 at ζ = 5324".
    pub fn text(&self) -> String {
        let what = match (self.kind, self.rising, self.step) {
            (ClaimKind::ShareHalf, true, false) => "plastic share passes ½".to_string(),
            (ClaimKind::ShareHalf, false, false) => "plastic share falls below ½".to_string(),
            (ClaimKind::ShareHalf, true, true) => "plastic share jumps past ½".to_string(),
            (ClaimKind::ShareHalf, false, true) => "plastic share drops below ½".to_string(),
            (ClaimKind::IndexOne, rising, step) => {
                let psi = if self.size_effect { "Ψ*" } else { "Ψ_P" };
                let verb = match (rising, step) {
                    (true, false) => "reaches",
                    (false, false) => "falls below",
                    (true, true) => "jumps past",
                    (false, true) => "drops below",
                };
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
    let roughness = state.roughness();
    let index = |x: f64| {
        let p = at(&state.params, state.sweep.axis(), x);
        roughness.psi_in_use(&p, state.size_effect, state.moments).0
    };
    let share = |x: f64| slopes(state.model, index(x)).plastic_share() - 0.5;
    let psi = |x: f64| index(x).to_f64() - 1.0;
    let mut out = Vec::new();
    for (kind, f) in [
        (ClaimKind::ShareHalf, &share as &dyn Fn(f64) -> f64),
        (ClaimKind::IndexOne, &psi),
    ] {
        for Crossing { at, rising, step } in crossings(&state.sweep, f) {
            out.push(Claim {
                kind,
                axis: state.sweep.axis(),
                at,
                rising,
                size_effect: state.size_effect,
                step,
            });
        }
    }
    out
}

/// A sign change of a function along a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Crossing {
    at: f64,
    rising: bool,
    /// The function jumps there (its values either side of the closed
    /// bracket differ by more than a continuous function's could).
    step: bool,
}

/// A jump larger than this across a bracket of 1e-14 relative is a step:
/// a continuous share or index moves by ~1e-13 at most there.
const STEP: f64 = 1e-9;

/// Zeros of `f` along `s` where it changes sign.
fn crossings(s: &Sweep, f: &dyn Fn(f64) -> f64) -> Vec<Crossing> {
    let xs: Vec<f64> = s.points(SAMPLES).collect();
    let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
    let mut out = Vec::new();
    for i in 0..xs.len() - 1 {
        let (a, b) = (vs[i], vs[i + 1]);
        if a.is_nan() || b.is_nan() || (a < 0.0) == (b < 0.0) {
            continue;
        }
        let (lo, hi) = bisect(s.axis().is_log(), xs[i], xs[i + 1], f);
        let jump = (f(hi) - f(lo)).abs();
        out.push(Crossing {
            // A step lies at the bracket's upper end: sums over |q| ≤ q1
            // take a wavevector in once q1 reaches it.
            at: if jump > STEP { hi } else { 0.5 * (lo + hi) },
            rising: a < 0.0,
            step: jump > STEP,
        });
        if out.len() == MAX_PER_KIND {
            break;
        }
    }
    out
}

/// The sign change of `f` in [lo, hi], halving in log space on log axes,
/// until the bracket is 1e-14 relative or cannot shrink: the bracket.
fn bisect(log: bool, mut lo: f64, mut hi: f64, f: &dyn Fn(f64) -> f64) -> (f64, f64) {
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
    (lo, hi)
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
        assert!((c[0].at / root - 1.0).abs() < 1e-13, "{}", c[0].at);
        assert!(c[0].rising && !c[0].step);
    }

    #[test]
    fn bisection_finds_a_step_where_it_is() {
        // A step function like a discrete spectrum's sums: 0.4 below the
        // node, 1.3 from it on.
        let s = Sweep::new(Axis::Zeta, 1.0, 1e4).unwrap();
        let node = 45.254833995939045f64;
        let c = crossings(&s, &|x: f64| if x >= node { 0.3 } else { -0.6 });
        assert_eq!(c.len(), 1);
        assert!(c[0].step && c[0].rising);
        assert!((c[0].at / node - 1.0).abs() < 1e-13, "{}", c[0].at);
        let claim = Claim {
            kind: ClaimKind::IndexOne,
            axis: Axis::Zeta,
            at: c[0].at,
            rising: true,
            size_effect: false,
            step: true,
        };
        assert_eq!(claim.text(), "Ψ_P jumps past 1 at ζ = 45.25");
    }

    #[test]
    fn claims_read_as_sentences() {
        let c = Claim {
            kind: ClaimKind::IndexOne,
            axis: Axis::Zeta,
            at: 5324.4,
            rising: false,
            size_effect: true,
            step: false,
        };
        assert_eq!(c.text(), "Ψ* falls below 1 at ζ = 5324");
        let c = Claim {
            kind: ClaimKind::ShareHalf,
            axis: Axis::HRms,
            at: 2.5e-8,
            rising: true,
            size_effect: false,
            step: false,
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
