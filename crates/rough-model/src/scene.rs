//! A sweep of one parameter, computing only the curves a view asks for.

use std::fmt;

use crate::indices::psi_in_use;
use crate::params::{Axis, Params};
use crate::slopes::{persson_elastic, slopes, Model};

/// A validated range of one parameter: log-spaced for all axes but the
/// Hurst exponent, which is linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sweep {
    axis: Axis,
    from: f64,
    to: f64,
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
                "sweep {end} = {value} is outside the domain of {field}: it must be {valid}"
            ),
            SweepError::Empty { from, to } => write!(
                f,
                "sweep range is empty: from = {from} must be below to = {to}"
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
                    valid: if log_zero {
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
        Ok(Sweep { axis, from, to })
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
    /// ends are returned exactly.
    pub fn at(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return self.from;
        }
        if t >= 1.0 {
            return self.to;
        }
        let v = if self.axis.is_log() {
            let (a, b) = (self.from.ln(), self.to.ln());
            (a + (b - a) * t).exp()
        } else {
            self.from + (self.to - self.from) * t
        };
        v.clamp(self.from, self.to)
    }

    /// Where `value` lies in the range as a fraction (log or linear); may be
    /// outside [0, 1] for values outside the range.
    pub fn fraction(&self, value: f64) -> f64 {
        if self.axis.is_log() {
            (value.ln() - self.from.ln()) / (self.to.ln() - self.from.ln())
        } else {
            (value - self.from) / (self.to - self.from)
        }
    }

    /// `n` points including both ends.
    pub fn points(&self, n: usize) -> impl Iterator<Item = f64> + '_ {
        let last = n.saturating_sub(1).max(1) as f64;
        (0..n).map(move |i| self.at(i as f64 / last))
    }
}

/// Which curves to compute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Curves {
    pub elastic: bool,
    pub plastic: bool,
    pub total: bool,
    pub persson_elastic: bool,
}

impl Curves {
    pub const ALL: Curves = Curves {
        elastic: true,
        plastic: true,
        total: true,
        persson_elastic: true,
    };
    pub const NONE: Curves = Curves {
        elastic: false,
        plastic: false,
        total: false,
        persson_elastic: false,
    };

    fn needs_slopes(self) -> bool {
        self.elastic || self.plastic || self.total
    }
}

/// What a view asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneSpec {
    /// Parameters; the swept one is overridden at each point.
    pub base: Params,
    pub sweep: Sweep,
    /// Index in use Ψ* and normalization by H_y when true; Ψ_P and H0 otherwise.
    pub size_effect: bool,
    pub model: Model,
    pub curves: Curves,
    /// Number of points, both ends included (≥ 2).
    pub points: usize,
}

/// The computed curves; a curve not asked for is empty.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    /// The swept values.
    pub x: Vec<f64>,
    /// The index in use at each point.
    pub psi: Vec<f64>,
    /// The hardness in use over H0 (1 without size effect).
    pub hardness_ratio: Vec<f64>,
    pub elastic: Vec<f64>,
    pub plastic: Vec<f64>,
    pub total: Vec<f64>,
    pub persson_elastic: Vec<f64>,
}

impl Scene {
    /// Computes `spec`: per point only ψ, the hardness in use and the curves
    /// asked for. Every value is finite or a documented infinity.
    pub fn compute(spec: &SceneSpec) -> Result<Scene, SweepError> {
        if spec.points < 2 {
            return Err(SweepError::TooFewPoints(spec.points));
        }
        let n = spec.points;
        let c = spec.curves;
        let with = |want: bool| {
            if want {
                Vec::with_capacity(n)
            } else {
                Vec::new()
            }
        };
        let mut s = Scene {
            x: Vec::with_capacity(n),
            psi: Vec::with_capacity(n),
            hardness_ratio: Vec::with_capacity(n),
            elastic: with(c.elastic),
            plastic: with(c.plastic),
            total: with(c.total),
            persson_elastic: with(c.persson_elastic),
        };
        let axis = spec.sweep.axis();
        for x in spec.sweep.points(n) {
            // Sweep ends are validated and the domains are intervals, so this
            // cannot fail; the base point stands in should it ever.
            let p = spec.base.with(axis, x).unwrap_or(spec.base);
            let (psi, hr) = psi_in_use(&p, spec.size_effect);
            s.x.push(x);
            s.psi.push(psi.to_f64());
            s.hardness_ratio.push(hr);
            if c.needs_slopes() {
                let sl = slopes(spec.model, psi);
                if c.elastic {
                    s.elastic.push(sl.elastic);
                }
                if c.plastic {
                    s.plastic.push(sl.plastic);
                }
                if c.total {
                    s.total.push(sl.total);
                }
            }
            if c.persson_elastic {
                s.persson_elastic.push(persson_elastic(psi));
            }
        }
        Ok(s)
    }
}
