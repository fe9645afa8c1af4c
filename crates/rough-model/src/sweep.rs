//! A validated range of one parameter, and its grid of points.

use std::fmt;

use crate::params::{Axis, Shown};

/// A validated range of one parameter: log-spaced for all axes but the
/// Hurst exponent, which is linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sweep {
    axis: Axis,
    from: f64,
    to: f64,
    /// ln from, ln to for log axes (from, to for linear ones).
    pub(crate) ends: (f64, f64),
    /// log10 from, log10 to when both ends are exact powers of ten: the
    /// grid's whole decades are then returned exactly (10, not
    /// 10.000000000000002).
    decades: Option<(f64, f64)>,
}

/// Why a sweep or scene request was rejected.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SweepError {
    /// An end of the range lies outside the swept parameter's domain.
    OutOfDomain {
        end: &'static str,
        field: &'static str,
        value: f64,
        valid: &'static str,
    },
    /// `from` is not below `to`.
    Empty { from: f64, to: f64 },
    /// Fewer than two points requested.
    TooFewPoints(usize),
}

impl fmt::Display for SweepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SweepError::OutOfDomain {
                end,
                field,
                value,
                valid,
            } => write!(
                f,
                "sweep {end} = {} is outside the domain of {field}: it must be {valid}",
                Shown(*value)
            ),
            SweepError::Empty { from, to } => write!(
                f,
                "sweep range is empty: from = {} must be below to = {}",
                Shown(*from),
                Shown(*to)
            ),
            SweepError::TooFewPoints(n) => {
                write!(f, "a sweep needs at least 2 points, got {n}")
            }
        }
    }
}

impl std::error::Error for SweepError {}

impl Sweep {
    /// A range `from < to` inside the domain of `axis`; log axes need `from > 0`.
    pub fn new(axis: Axis, from: f64, to: f64) -> Result<Sweep, SweepError> {
        for (end, v) in [("from", from), ("to", to)] {
            let log_zero = axis.is_log() && v == 0.0;
            if !axis.accepts(v) || log_zero {
                return Err(SweepError::OutOfDomain {
                    end,
                    field: axis.field(),
                    value: v,
                    // The axis's own domain when the value is outside it
                    // (ζ = 0 must read "≥ 1"); the log-spacing rule only
                    // for a zero the axis itself accepts (R* = 0).
                    valid: if axis.accepts(v) {
                        "finite and > 0 (the sweep is log-spaced)"
                    } else {
                        axis.domain()
                    },
                });
            }
        }
        if from >= to {
            return Err(SweepError::Empty { from, to });
        }
        let ends = if axis.is_log() {
            (from.ln(), to.ln())
        } else {
            (from, to)
        };
        let decades = match (decade_of(from), decade_of(to)) {
            (Some(a), Some(b)) if axis.is_log() => Some((f64::from(a), f64::from(b))),
            _ => None,
        };
        Ok(Sweep {
            axis,
            from,
            to,
            ends,
            decades,
        })
    }

    pub fn axis(&self) -> Axis {
        self.axis
    }
    pub fn from(&self) -> f64 {
        self.from
    }
    pub fn to(&self) -> f64 {
        self.to
    }

    /// The value at fraction `t` in [0, 1] of the range (log or linear); the
    /// ends are returned exactly, and so are whole decades inside a sweep
    /// between powers of ten.
    pub fn at(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return self.from;
        }
        if t >= 1.0 {
            return self.to;
        }
        let (a, b) = self.ends;
        let v = if self.axis.is_log() {
            if let Some((da, db)) = self.decades {
                let d = da + (db - da) * t;
                // Grid points lie far more than 1e-9 decades apart.
                if (d - d.round()).abs() < 1e-9 {
                    return power_of_ten(d.round() as i32);
                }
            }
            (a + (b - a) * t).exp()
        } else {
            decimal_grid(a + (b - a) * t)
        };
        v.clamp(self.from, self.to)
    }

    /// `n` points including both ends.
    pub fn points(&self, n: usize) -> impl Iterator<Item = f64> + '_ {
        let last = n.saturating_sub(1).max(1) as f64;
        (0..n).map(move |i| self.at(i as f64 / last))
    }
}

/// `v`, or the 12-digit decimal within 2 ulp of it: the points of a
/// linear grid between short decimals (0.1 to 0.9) are then those decimals
/// (0.3, not 0.30000000000000004), and other points move by at most 2 ulp.
#[cold]
fn decimal_grid(v: f64) -> f64 {
    let short: f64 = format!("{v:.11e}").parse().unwrap_or(v);
    let ulp = f64::EPSILON * v.abs().max(f64::MIN_POSITIVE);
    if (short - v).abs() <= 2.0 * ulp {
        short
    } else {
        v
    }
}

/// 10^k correctly rounded (k within the f64 range); cold: only whole
/// decades of a sweep come here.
#[cold]
fn power_of_ten(k: i32) -> f64 {
    format!("1e{k}").parse().unwrap_or(f64::NAN)
}

/// k when `v` is exactly the double nearest 10^k.
fn decade_of(v: f64) -> Option<i32> {
    if !(v > 0.0 && v.is_finite()) {
        return None;
    }
    let k = v.log10().round() as i32;
    (power_of_ten(k) == v).then_some(k)
}
