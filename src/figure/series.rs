//! The index view's series along the sweep and the load view's curve.

use std::ops::Range;

use rough_model::{areas, slopes, Params, Slopes, SweepError};

use crate::scene::State;

/// The plasticity indices along the state's sweep (all dimensionless).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IndexSeries {
    /// The swept values, both ends included (log-spaced on log axes).
    pub x: Vec<f64>,
    /// Greenwood–Williamson index (E/H0)√(h_rms/R_s).
    pub psi_gw: Vec<f64>,
    /// Persson's index Ψ_P = √V/H0.
    pub psi_p: Vec<f64>,
    /// Ψ* = √V/H_y.
    pub psi_star: Vec<f64>,
    /// Eq. 13's asymptotic Ψ*; `None` where undefined (R* = 0, H = 1, a
    /// measured surface).
    pub psi_star_asymptotic: Vec<Option<f64>>,
    /// H_y/H0 (whatever the size-effect switch says: Ψ* always uses it).
    pub hardness_ratio: Vec<f64>,
}

impl IndexSeries {
    /// The indices of `state` at `points` points of its sweep, under its
    /// moments convention.
    pub fn compute(state: &State, points: usize) -> Result<IndexSeries, SweepError> {
        IndexSeries::compute_range(state, points, 0..points)
    }

    /// Points `range` of [`IndexSeries::compute`]'s series (cut to the
    /// sweep), so that long series can be computed and written in blocks.
    pub fn compute_range(
        state: &State,
        points: usize,
        range: Range<usize>,
    ) -> Result<IndexSeries, SweepError> {
        if points < 2 {
            return Err(SweepError::TooFewPoints(points));
        }
        let mut s = IndexSeries::default();
        let axis = state.sweep.axis();
        let roughness = state.roughness();
        let last = (points - 1) as f64;
        for i in range.start.min(points)..range.end.min(points) {
            let x = state.sweep.at(i as f64 / last);
            let ix = roughness.indices(&at(&state.params, axis, x), state.moments);
            s.x.push(x);
            s.psi_gw.push(ix.psi_gw);
            s.psi_p.push(ix.psi_p);
            s.psi_star.push(ix.psi_star);
            s.psi_star_asymptotic.push(ix.psi_star_asymptotic);
            s.hardness_ratio.push(ix.hardness_ratio);
        }
        Ok(s)
    }

    pub fn len(&self) -> usize {
        self.x.len()
    }

    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }
}

/// `p` with `axis` set to `x`, a value of a validated sweep of that axis
/// (so inside the parameter's domain).
pub(crate) fn at(p: &Params, axis: rough_model::Axis, x: f64) -> Params {
    p.with(axis, x).unwrap_or(*p)
}

/// Contact areas A/A0 against the load p̄/H (H the hardness in use) from 0
/// to 1, at the state's parameters, for its model.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadCurve {
    /// p̄/H, evenly spaced from 0 to 1, both ends included.
    pub load: Vec<f64>,
    pub elastic: Vec<f64>,
    pub plastic: Vec<f64>,
    pub total: Vec<f64>,
    /// The index in use (Ψ* with the size effect, Ψ_P without).
    pub psi: f64,
    /// The initial slopes at that index: the tangents at the origin.
    pub slopes: Slopes,
}

impl LoadCurve {
    /// The areas of `state` at `points` loads (≥ 2). At p̄ = 0 every area is
    /// 0; at p̄ = H the contact is fully plastic (0, 1, 1).
    pub fn compute(state: &State, points: usize) -> Result<LoadCurve, SweepError> {
        LoadCurve::compute_range(state, points, 0..points)
    }

    /// Points `range` of [`LoadCurve::compute`]'s curve (cut to the grid).
    pub fn compute_range(
        state: &State,
        points: usize,
        range: Range<usize>,
    ) -> Result<LoadCurve, SweepError> {
        if points < 2 {
            return Err(SweepError::TooFewPoints(points));
        }
        let ix = state.roughness().indices(&state.params, state.moments);
        let psi = ix.psi_in_use(state.size_effect);
        let range = range.start.min(points)..range.end.min(points);
        let n = range.len();
        let mut c = LoadCurve {
            load: Vec::with_capacity(n),
            elastic: Vec::with_capacity(n),
            plastic: Vec::with_capacity(n),
            total: Vec::with_capacity(n),
            psi: psi.to_f64(),
            slopes: slopes(state.model, psi),
        };
        let last = (points - 1) as f64;
        for i in range {
            let rho = if i == points - 1 {
                1.0
            } else {
                i as f64 / last
            };
            let a = if rho == 0.0 {
                rough_model::Areas {
                    elastic: 0.0,
                    plastic: 0.0,
                    total: 0.0,
                }
            } else {
                // ρ in (0, 1] and ψ ≥ 0 by construction.
                areas(state.model, psi, rho).unwrap_or(rough_model::Areas {
                    elastic: f64::NAN,
                    plastic: f64::NAN,
                    total: f64::NAN,
                })
            };
            c.load.push(rho);
            c.elastic.push(a.elastic);
            c.plastic.push(a.plastic);
            c.total.push(a.total);
        }
        Ok(c)
    }

    /// The initial-slope line of the total area, S_tot·p̄/H, capped at 1
    /// (an area fraction): where it meets the cap, and the cap.
    pub fn tangent_end(&self) -> (f64, f64) {
        let s = self.slopes.total;
        if s > 1.0 {
            (1.0 / s, 1.0)
        } else {
            (1.0, s)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fig(name: &str) -> State {
        crate::presets::load(name).unwrap()
    }

    #[test]
    fn index_series_follow_their_definitions() {
        let s = fig("fig4");
        let ix = IndexSeries::compute(&s, 9).unwrap();
        assert_eq!(ix.len(), 9);
        assert_eq!((ix.x[0], ix.x[8]), (1.0, 1e6));
        for i in 0..9 {
            // Ψ* = Ψ_P/(H_y/H0), the hardness growing with ζ.
            let r = ix.psi_p[i] / ix.hardness_ratio[i] / ix.psi_star[i] - 1.0;
            assert!(r.abs() < 1e-15, "{i}: {r}");
            assert!(i == 0 || ix.hardness_ratio[i] > ix.hardness_ratio[i - 1]);
            assert!(ix.psi_star_asymptotic[i].is_some());
        }
        // Eq. 13 approaches Ψ* at large ζ.
        let dev = ix.psi_star_asymptotic[8].unwrap() / ix.psi_star[8] - 1.0;
        assert!(dev.abs() < 1e-3, "{dev}");
        assert!(IndexSeries::compute(&s, 1).is_err());
    }

    #[test]
    fn load_curve_starts_on_its_initial_slope_and_ends_plastic() {
        let s = fig("fig2");
        let c = LoadCurve::compute(&s, 1001).unwrap();
        assert_eq!((c.load[0], c.total[0]), (0.0, 0.0));
        assert_eq!(
            (c.elastic[1000], c.plastic[1000], c.total[1000]),
            (0.0, 1.0, 1.0)
        );
        // A/A0 ≈ S·p̄/H near the origin: the tangent the view draws.
        let slope = c.total[1] / c.load[1];
        assert!((slope / c.slopes.total - 1.0).abs() < 1e-2, "{slope}");
        for i in 1..=1000 {
            assert!(c.total[i] >= c.total[i - 1] && c.total[i] <= 1.0);
            let sum = c.elastic[i] + c.plastic[i];
            assert!((sum - c.total[i]).abs() <= 1e-15, "{i}");
        }
        let (x, y) = c.tangent_end();
        assert!((x - 1.0 / c.slopes.total).abs() < 1e-15 && y == 1.0);
        // Blocks give the same rows as the whole curve.
        let part = LoadCurve::compute_range(&s, 1001, 500..503).unwrap();
        assert_eq!(part.total[..], c.total[500..503]);
    }
}
