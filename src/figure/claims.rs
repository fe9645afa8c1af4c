//! The checkable claims a figure makes, located live at the current
//! parameters: where the plastic share passes ½, where the index in use
//! (Ψ* with the size effect, Ψ_P without) crosses 1, and where the total
//! slope has a minimum inside the sweep.
//!
//! On a measured surface whose moments are sums over the data's
//! wavevectors, the moments are a step function of ζ: a crossing may be a
//! jump at one of the data's wavevectors. Bisection then closes on the jump,
//! and the claim says it is one.

use rough_model::{slopes, Axis};

use super::minimum::{bracketed, refine};
use super::series::at;
use crate::physical::short_number;
use crate::scene::State;

/// Which quantity does what.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimKind {
    /// S_pl/S_tot crosses ½.
    ShareHalf,
    /// The index in use crosses 1.
    IndexOne,
    /// The total slope S_tot (normalized by the hardness in use) has a
    /// local minimum inside the sweep.
    TotalMinimum,
}

/// One crossing, or one minimum, along the sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    pub kind: ClaimKind,
    /// The swept parameter.
    pub axis: Axis,
    /// The swept value where the crossing or the minimum lies (a crossing
    /// to ~1e-14 relative, a minimum to ~1e-12).
    pub at: f64,
    /// Whether the quantity rises through the level there (false for a
    /// minimum).
    pub rising: bool,
    /// With the size effect (the index in use is Ψ*), or without (Ψ_P).
    pub size_effect: bool,
    /// The quantity at `at`: the level crossed (½ or 1), or the total
    /// slope at its minimum.
    pub value: f64,
    /// The quantity jumps across the level there (a step of a measured
    /// spectrum's sums, at one of its wavevectors) rather than passing it.
    pub step: bool,
}

impl Claim {
    /// The claim in words, the place in the slider's unit: "plastic share
    /// passes ½ at ζ = 322.3", "… at h_rms = 23.82 nm",
    /// "Ψ* falls below 1 at ζ = 5324", "total slope's minimum 3.91 at
    /// ζ = 3.19"; on an H0/E sweep the place also as E/H0, the paper's
    /// way of naming hardness ("… at H0/E = 0.00523 (E/H0 = 191.2)").
    pub fn text(&self) -> String {
        let psi = if self.size_effect { "Ψ*" } else { "Ψ_P" };
        let what = match (self.kind, self.rising, self.step) {
            (ClaimKind::ShareHalf, true, false) => "plastic share passes ½".to_string(),
            (ClaimKind::ShareHalf, false, false) => "plastic share falls below ½".to_string(),
            (ClaimKind::ShareHalf, true, true) => "plastic share jumps past ½".to_string(),
            (ClaimKind::ShareHalf, false, true) => "plastic share drops below ½".to_string(),
            (ClaimKind::IndexOne, rising, step) => {
                let verb = match (rising, step) {
                    (true, false) => "reaches",
                    (false, false) => "falls below",
                    (true, true) => "jumps past",
                    (false, true) => "drops below",
                };
                format!("{psi} {verb} 1")
            }
            (ClaimKind::TotalMinimum, _, false) => {
                format!("total slope's minimum {}", short_number(self.value))
            }
            (ClaimKind::TotalMinimum, _, true) => {
                format!(
                    "total slope drops to its minimum {}",
                    short_number(self.value)
                )
            }
        };
        let place = format!("{} = {}", self.axis.symbol(), self.number());
        match self.inverse() {
            Some(inv) => format!("{what} at {place} (E/H0 = {inv})"),
            None => format!("{what} at {place}"),
        }
    }

    /// The claim in fewer words, for a narrow screen: "plastic share ½ at
    /// ζ = 321.5", "Ψ_P = 1 at E/H0 = 191.2", "total slope min 3.91 at
    /// ζ = 3.19" (an H0/E sweep names the place by E/H0 alone).
    pub fn short_text(&self) -> String {
        let what = match self.kind {
            ClaimKind::ShareHalf => "plastic share ½".to_string(),
            ClaimKind::IndexOne if self.size_effect => "Ψ* = 1".to_string(),
            ClaimKind::IndexOne => "Ψ_P = 1".to_string(),
            ClaimKind::TotalMinimum => format!("total slope min {}", short_number(self.value)),
        };
        match self.inverse() {
            Some(inv) => format!("{what} at E/H0 = {inv}"),
            None => format!("{what} at {} = {}", self.axis.symbol(), self.number()),
        }
    }

    /// The place in the slider's unit: "321.5", "23.82 nm", "1.5 mm".
    fn number(&self) -> String {
        match super::axis_unit(self.axis) {
            "m" => crate::physical::short_length(self.at),
            _ => short_number(self.at),
        }
    }

    /// E/H0 at the place, on an H0/E sweep.
    fn inverse(&self) -> Option<String> {
        (self.axis == Axis::H0OverE).then(|| short_number(1.0 / self.at))
    }
}

/// Samples per sweep before bisecting each bracketed crossing.
const SAMPLES: usize = 256;

/// Most crossings reported per kind.
const MAX_PER_KIND: usize = 4;

/// Every crossing of the share ½ and of the index in use 1 along the
/// state's sweep, in sweep order within each kind (share first), then
/// every local minimum of the total slope inside the sweep. Crossings or
/// minima closer together than the sampling step (1/256 of the sweep) may
/// be missed; a minimum on a plateau that rounding cannot resolve (the
/// exact total slope at 1 + 1e-20) is left out.
/// Below this magnification the truncated moments are an artefact of the
/// cut at q0 (at ζ = 1 they vanish: no roughness, Ψ = 0), not a property
/// of the model: a claim there is not shown.
pub const TRUNCATION_ZETA: f64 = 10.0;

/// The claims worth showing: [`claims`] without those that the truncation
/// of the moments makes (with truncated moments on the paper's power law,
/// a crossing or minimum at ζ below [`TRUNCATION_ZETA`]).
pub fn shown_claims(state: &State) -> Vec<Claim> {
    let artefact = |c: &Claim| {
        !state.is_measured()
            && state.moments == rough_model::Moments::Truncated
            && c.axis == Axis::Zeta
            && c.at < TRUNCATION_ZETA
    };
    claims(state).into_iter().filter(|c| !artefact(c)).collect()
}

pub fn claims(state: &State) -> Vec<Claim> {
    let roughness = state.roughness();
    let index = |x: f64| {
        let p = at(&state.params, state.sweep.axis(), x);
        roughness.psi_in_use(&p, state.size_effect, state.moments).0
    };
    let share = |x: f64| slopes(state.model, index(x)).plastic_share() - 0.5;
    let psi = |x: f64| index(x).to_f64() - 1.0;
    let total = |x: f64| slopes(state.model, index(x)).total;
    // One pass over the samples gives all three curves.
    let xs: Vec<f64> = state.sweep.points(SAMPLES).collect();
    let (mut share_v, mut psi_v, mut total_v) = (vec![], vec![], vec![]);
    for &x in &xs {
        let i = index(x);
        let s = slopes(state.model, i);
        share_v.push(s.plastic_share() - 0.5);
        psi_v.push(i.to_f64() - 1.0);
        total_v.push(s.total);
    }
    let log = state.sweep.axis().is_log();
    let claim = |kind, at, rising, value, step| Claim {
        kind,
        axis: state.sweep.axis(),
        at,
        rising,
        size_effect: state.size_effect,
        value,
        step,
    };
    let mut out = Vec::new();
    for (kind, level, vs, f) in [
        (
            ClaimKind::ShareHalf,
            0.5,
            &share_v,
            &share as &dyn Fn(f64) -> f64,
        ),
        (ClaimKind::IndexOne, 1.0, &psi_v, &psi),
    ] {
        for Crossing { at, rising, step } in crossings(log, &xs, vs, f) {
            out.push(claim(kind, at, rising, level, step));
        }
    }
    let minima = bracketed(&total_v).filter_map(|i| refine(&xs, &total_v, i, log, &total));
    // Along ζ, a discrete spectrum's moments are constant between its
    // wavevectors: the lowest step begins at one, where the slope drops.
    let table = roughness
        .table()
        .filter(|t| t.is_discrete() && state.sweep.axis() == Axis::Zeta);
    for (at, value) in minima.take(MAX_PER_KIND) {
        let step = table.and_then(|t| step_start(t, at));
        out.push(claim(
            ClaimKind::TotalMinimum,
            step.unwrap_or(at),
            false,
            value,
            step.is_some(),
        ));
    }
    out
}

/// The ζ of the table's last wavevector at or below ζ = `at` (within the
/// table's own 1e-12), where the sums take their value at `at`.
fn step_start(t: &rough_model::MomentTable, at: f64) -> Option<f64> {
    let q = at * t.q0() * (1.0 + 1e-12);
    let k = t.nodes().partition_point(|&n| n <= q);
    k.checked_sub(1).map(|k| t.nodes()[k] / t.q0())
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

/// Zeros of `f` where its samples `vs` at `xs` change sign.
fn crossings(log: bool, xs: &[f64], vs: &[f64], f: &dyn Fn(f64) -> f64) -> Vec<Crossing> {
    let mut out = Vec::new();
    for i in 0..xs.len().saturating_sub(1) {
        let (a, b) = (vs[i], vs[i + 1]);
        if a.is_nan() || b.is_nan() || (a < 0.0) == (b < 0.0) {
            continue;
        }
        let (lo, hi) = bisect(log, xs[i], xs[i + 1], f);
        let step = (f(hi) - f(lo)).abs() > STEP;
        out.push(Crossing {
            // A step lies at the bracket's upper end: sums over |q| ≤ q1
            // take a wavevector in once q1 reaches it.
            at: if step { hi } else { 0.5 * (lo + hi) },
            rising: a < 0.0,
            step,
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
    use rough_model::Sweep;

    #[test]
    fn bisection_finds_a_known_root_to_1e_14() {
        let s = Sweep::new(Axis::Zeta, 1.0, 1e4).unwrap();
        let root = 322.27f64;
        let f = |x: f64| x.ln() - root.ln();
        let xs: Vec<f64> = s.points(SAMPLES).collect();
        let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let c = crossings(true, &xs, &vs, &f);
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
        let f = |x: f64| if x >= node { 0.3 } else { -0.6 };
        let xs: Vec<f64> = s.points(SAMPLES).collect();
        let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let c = crossings(true, &xs, &vs, &f);
        assert_eq!(c.len(), 1);
        assert!(c[0].step && c[0].rising);
        assert!((c[0].at / node - 1.0).abs() < 1e-13, "{}", c[0].at);
        let claim = Claim {
            kind: ClaimKind::IndexOne,
            axis: Axis::Zeta,
            at: c[0].at,
            rising: true,
            size_effect: false,
            value: 1.0,
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
            value: 1.0,
            step: false,
        };
        assert_eq!(c.text(), "Ψ* falls below 1 at ζ = 5324");
        assert_eq!(c.short_text(), "Ψ* = 1 at ζ = 5324");
        let c = Claim {
            kind: ClaimKind::ShareHalf,
            axis: Axis::HRms,
            at: 2.5e-8,
            rising: true,
            size_effect: false,
            value: 0.5,
            step: false,
        };
        assert_eq!(c.text(), "plastic share passes ½ at h_rms = 25 nm");
        assert_eq!(c.short_text(), "plastic share ½ at h_rms = 25 nm");
        let c = Claim { at: 2.382e-8, ..c };
        assert_eq!(c.text(), "plastic share passes ½ at h_rms = 23.82 nm");
        let c = Claim {
            axis: Axis::RStar,
            at: 1.5e-3,
            ..c
        };
        assert_eq!(c.short_text(), "plastic share ½ at R* = 1.5 mm");
        let c = Claim {
            kind: ClaimKind::IndexOne,
            axis: Axis::H0OverE,
            at: 0.005229641722173285,
            rising: false,
            size_effect: false,
            value: 1.0,
            step: false,
        };
        assert_eq!(
            c.text(),
            "Ψ_P falls below 1 at H0/E = 0.00523 (E/H0 = 191.2)"
        );
        assert_eq!(c.short_text(), "Ψ_P = 1 at E/H0 = 191.2");
        let c = Claim {
            kind: ClaimKind::TotalMinimum,
            axis: Axis::Zeta,
            at: 3.1902,
            rising: false,
            size_effect: true,
            value: 3.90981,
            step: false,
        };
        assert_eq!(c.text(), "total slope's minimum 3.91 at ζ = 3.19");
        assert_eq!(c.short_text(), "total slope min 3.91 at ζ = 3.19");
    }
}

#[cfg(test)]
mod preset_tests {
    use super::*;
    use rough_model::Sweep;

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
                "Ψ* falls below 1 at ζ = 5324",
                "total slope's minimum 0.9796 at ζ = 2209"
            ]
        );
        // The paper calls E/H0 = 25…1000 practically elastic; its own
        // equations put Ψ_P = 1 at E/H0 = 191.
        assert_eq!(
            texts("fig1"),
            [
                "plastic share falls below ½ at H0/E = 0.008318 (E/H0 = 120.2)",
                "Ψ_P falls below 1 at H0/E = 0.00523 (E/H0 = 191.2)",
                "total slope's minimum 0.9796 at H0/E = 0.003678 (E/H0 = 271.9)"
            ]
        );
        // "First decreases and then increases": where it turns.
        assert_eq!(texts("fig3"), ["total slope's minimum 3.91 at ζ = 3.191"]);
    }

    #[test]
    fn fig3s_minimum_moves_with_the_moments_and_the_sliders() {
        let mut s = crate::presets::load("fig3").unwrap();
        s.moments = rough_model::Moments::Truncated;
        let c = claims(&s);
        assert_eq!(c.len(), 1);
        assert_eq!(c[0].text(), "total slope's minimum 5.59 at ζ = 7.763");
        // The exact model has the same minimum: ψ is small there, and
        // the two models' total slopes agree far below rounding.
        s.model = rough_model::Model::Exact;
        let e = claims(&s);
        assert_eq!(e.len(), 1);
        assert_eq!(e[0].value, c[0].value);
        assert!((e[0].at / c[0].at - 1.0).abs() < 1e-11, "{e:?} {c:?}");
        // A sweep that starts past the minimum has none inside.
        s.sweep = Sweep::new(Axis::Zeta, 10.0, 1e4).unwrap();
        assert!(claims(&s).is_empty());
        // Without the size effect the total slope only falls (exact model).
        s.size_effect = false;
        s.sweep = Sweep::new(Axis::Zeta, 1.0, 1e4).unwrap();
        assert!(claims(&s).iter().all(|c| c.kind != ClaimKind::TotalMinimum));
        // A smaller R* lets the hardness catch up later: the minimum moves
        // to finer scales.
        let mut s = crate::presets::load("fig3").unwrap();
        let at = |s: &State| claims(s)[0].at;
        let base = at(&s);
        s.params = s.params.with(Axis::RStar, 1e-4).unwrap();
        assert!(at(&s) > base, "{} {base}", at(&s));
    }
}
