//! The sliders' steps: each parameter's default range and the grid its
//! coarse and fine steps move on.

use rough_model::Axis;

/// The default range of each parameter, for its slider and when `x` makes it
/// the swept one.
pub fn default_range(axis: Axis) -> (f64, f64) {
    match axis {
        Axis::H0OverE => (1e-4, 1e-1),
        Axis::HRms => (1e-9, 1e-5),
        Axis::Zeta => (1.0, 1e6),
        Axis::Hurst => (0.05, 1.0),
        Axis::RStar => (1e-6, 1e-2),
    }
}

/// Log steps per decade (coarse, fine); Hurst steps (coarse, fine).
pub const LOG_STEPS: (f64, f64) = (4.0, 40.0);
pub const HURST_STEPS: (f64, f64) = (0.05, 0.01);

/// One step from `v` on the grid of the given step, clamped to `[lo, hi]`.
/// Values snap to the grid (10^(k/4), 10^(k/40); multiples of 0.05, 0.01),
/// so repeated steps do not drift and a coarse step from a fine value lands
/// on the next coarse one.
pub fn step_value(axis: Axis, v: f64, (lo, hi): (f64, f64), up: bool, fine: bool) -> f64 {
    const EPS: f64 = 1e-6;
    let next = |t: f64| {
        if up {
            (t + EPS).floor() + 1.0
        } else {
            (t - EPS).ceil() - 1.0
        }
    };
    let out = if axis.is_log() {
        let n = if fine { LOG_STEPS.1 } else { LOG_STEPS.0 };
        if !(v > 0.0 && v.is_finite()) {
            return lo;
        }
        10f64.powf(next(v.log10() * n) / n)
    } else {
        let s = if fine { HURST_STEPS.1 } else { HURST_STEPS.0 };
        if !v.is_finite() {
            return lo;
        }
        // Round to kill 0.15000000000000002.
        (next(v / s) * s * 1e9).round() / 1e9
    };
    out.clamp(lo, hi)
}
