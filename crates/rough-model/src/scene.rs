//! A sweep of one parameter, computing only the curves a view asks for.

use std::ops::{Add, Div, Mul};

use crate::dd::{Dd, PI, PI2_HALF};
use crate::indices::psi_from_core;
use crate::params::{Axis, Params};
use crate::roughness::{self, Roughness};
use crate::slopes::{slopes_sq, Model, SQRT_2_OVER_PI};
use crate::spectrum::{Core, Moments};
use crate::sweep::{Sweep, SweepError};

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

    fn needs_slopes(self) -> bool {
        self.elastic || self.plastic || self.total
    }
}

/// What a view asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneSpec {
    /// Parameters; the swept one is overridden at each point.
    pub base: Params,
    pub sweep: Sweep,
    /// Index in use Ψ* and normalization by H_y when true; Ψ_P and H0 otherwise.
    pub size_effect: bool,
    pub model: Model,
    /// Truncated or asymptotic (eq. 10) spectrum moments (the power law's;
    /// a measured surface has its own).
    pub moments: Moments,
    /// The power law, or a measured surface's moment table.
    pub roughness: Roughness,
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
    /// asked for, with what is constant along the sweep computed once. Every
    /// value is finite or a documented infinity; the values are those of
    /// [`crate::psi_in_use`] and [`crate::slopes()`] at each point.
    pub fn compute(spec: &SceneSpec) -> Result<Scene, SweepError> {
        Scene::compute_range(spec, 0..spec.points)
    }

    /// Points `range` of the `spec.points`-point sweep (the same values as
    /// [`Scene::compute`] gives there): for long sweeps computed and written
    /// in blocks, or on several threads. `range` is cut to the sweep.
    pub fn compute_range(
        spec: &SceneSpec,
        range: std::ops::Range<usize>,
    ) -> Result<Scene, SweepError> {
        if spec.points < 2 {
            return Err(SweepError::TooFewPoints(spec.points));
        }
        let range = range.start.min(spec.points)..range.end.min(spec.points);
        let n = range.len();
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
        let kernel = Kernel::new(spec);
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("fma") {
                // SAFETY: the CPU has just been checked to support FMA.
                unsafe { fill_fma(spec, &kernel, range, &mut s) };
                return Ok(s);
            }
        }
        fill(spec, &kernel, range, &mut s);
        Ok(s)
    }
}

/// The per-point loop compiled with hardware FMA, which the double-double
/// products inlined into it use (a library call otherwise).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn fill_fma(spec: &SceneSpec, k: &Kernel, range: std::ops::Range<usize>, s: &mut Scene) {
    fill(spec, k, range, s)
}

#[inline(always)]
fn fill(spec: &SceneSpec, k: &Kernel, range: std::ops::Range<usize>, s: &mut Scene) {
    let c = spec.curves;
    for i in range {
        let t = i as f64 / (spec.points - 1) as f64;
        let x = spec.sweep.at(t);
        let (sq, hr) = k.psi_sq(spec, x, t);
        // ψ = √(ψ²) to ~1 ulp; 1/ψ only scales (no exponent).
        let psi = if sq.hi > 0.0 {
            sq.hi.sqrt() * (1.0 + 0.5 * sq.lo / sq.hi)
        } else {
            0.0
        };
        let inv = 1.0 / psi;
        s.x.push(x);
        s.psi.push(psi);
        s.hardness_ratio.push(hr);
        if c.needs_slopes() {
            let sl = slopes_sq(spec.model, psi, inv, sq);
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
            s.persson_elastic.push(SQRT_2_OVER_PI * inv);
        }
    }
}

/// What is constant along a sweep.
enum Kernel {
    /// ζ sweep: Ψ_P² = A·g2 and, with size effect, (H_y/H0)² = 1 + B·√(g4 e4)
    /// with B = R* h q0² √(¾H/(π e4))/0.45; g·e = ζ^e − 1 for truncated
    /// moments, ζ^e for asymptotic ones.
    Zeta {
        a: Dd,
        a_e2: Dd,
        e2: f64,
        e4: f64,
        b: Option<Dd>,
        asymptotic: bool,
    },
    /// Axes that leave the moments' g(ζ, e) unchanged: computed once.
    Fixed(Core),
    /// The Hurst exponent changes everything.
    General,
    /// A measured surface: the moments at each point's ζ from its table
    /// (a binary search), then ψ² from them.
    Measured,
}

impl Kernel {
    fn new(spec: &SceneSpec) -> Kernel {
        let p = &spec.base;
        if spec.roughness.is_measured() {
            return Kernel::Measured;
        }
        match spec.sweep.axis() {
            Axis::Zeta => {
                let hu = p.hurst();
                let t = Dd::prod(p.h_rms(), p.q0()).div(Dd::from_f64(p.h0_over_e()));
                let a = t.mul(t).mul_f64(hu).mul_f64(0.5);
                let e2 = Dd::sum(2.0, -2.0 * hu);
                let e4 = Dd::sum(4.0, -2.0 * hu);
                let a_e2 = if e2.hi == 0.0 { a } else { a.div(e2) };
                let b = (spec.size_effect && p.r_star() > 0.0).then(|| {
                    let root = Dd::from_f64(0.75 * hu).div(PI.mul(e4)).sqrt();
                    Dd::prod(p.h_rms(), p.q0())
                        .mul_f64(p.q0())
                        .mul_f64(p.r_star())
                        .mul(root)
                        .div(Dd::from_f64(0.45))
                });
                let finite = |d: Dd| d.hi.is_normal();
                let asymptotic = spec.moments == Moments::Asymptotic;
                // The asymptotic m2 is infinite at H = 1 (e2 = 0): the general path.
                if finite(a)
                    && finite(a_e2)
                    && b.is_none_or(finite)
                    && !(asymptotic && e2.hi == 0.0)
                {
                    Kernel::Zeta {
                        a,
                        a_e2,
                        e2: e2.hi,
                        e4: e4.hi,
                        b,
                        asymptotic,
                    }
                } else {
                    Kernel::General
                }
            }
            Axis::Hurst => Kernel::General,
            _ => Kernel::Fixed(Core::new(p, spec.moments, spec.size_effect)),
        }
    }

    /// ψ² in use and the hardness ratio in use at sweep value `x`.
    #[inline(always)]
    fn psi_sq(&self, spec: &SceneSpec, x: f64, t: f64) -> (Dd, f64) {
        // Sweep values lie in the validated range, so in the domain.
        let at = || spec.base.with_unchecked(spec.sweep.axis(), x);
        let from_psi = |(psi, hr): (Dd, f64)| (psi.mul(psi), hr);
        match self {
            Kernel::Zeta {
                a,
                a_e2,
                e2,
                e4,
                b,
                asymptotic,
            } => {
                // Inside a ζ sweep x = fl(e^y), y = ln from + t·(ln to − ln
                // from), so |ln x − y| ≤ 2.2e-16, below ln's own rounding
                // once y > 1; the ends are exact values and take the log.
                let (la, lb) = spec.sweep.ends;
                let y = la + (lb - la) * t;
                let l = if y > 1.0 && t > 0.0 && t < 1.0 {
                    y
                } else {
                    ln_apart(x)
                };
                let (e2l, e4l) = (e2 * l, e4 * l);
                let pointwise = || {
                    let p = at();
                    from_psi(psi_from_core(
                        &p,
                        &Core::new(&p, spec.moments, b.is_some()),
                        b.is_some(),
                    ))
                };
                let eval = |ze2: Dd, ze4: Dd| {
                    zeta_point(*a, *a_e2, *e2, l, e4l, *b, *asymptotic, ze2, ze4)
                };
                // Truncated moments below e·ln ζ = ½ take expm1 and need no ζ^e.
                let mut out = if e4l <= 0.5 && !asymptotic {
                    eval(Dd::from_f64(0.0), Dd::from_f64(0.0))
                } else {
                    // exp(e·ln ζ) carries the rounding of ln ζ times e·ln ζ
                    // into ψ² ...
                    let ze4 = if b.is_some() { e4l.exp() } else { 0.0 };
                    let fast = eval(Dd::from_f64(e2l.exp()), Dd::from_f64(ze4));
                    // ... which the slopes amplify by about max(π²ψ²/2,
                    // 1/(2ψ²)) for the exact model; the closed form's
                    // exponents are −1/(2ψ²) and its polynomials in 1/ψ² have
                    // degree ≤ 3 where ψ is large, so 4 + 1/(2ψ²) bounds it.
                    // Where that could cost 1e-13, form ζ^e as the pointwise
                    // path does (`spectrum::g`): ζ^n·ζ^(−2H) with an exact
                    // product; for asymptotic moments ψ² is proportional to
                    // ζ^e, so e^(e·ln ζ) itself is as good where e·ln ζ ≤ ½.
                    let sq = fast.0.hi;
                    let amp = match spec.model {
                        Model::Exact => 1.0 + (PI2_HALF.hi * sq).max(0.5 / sq),
                        Model::ClosedForm => 4.0 + 0.5 / sq,
                    };
                    if amp * (e4l + 1.0) * 4.4e-16 <= 1e-13 {
                        fast
                    } else {
                        let pw = x.powf(-2.0 * spec.base.hurst());
                        let z2 = Dd::prod(x, x);
                        let near_one = |el: f64, ze: Dd| {
                            if *asymptotic && el <= 0.5 {
                                Dd::from_f64(el.exp())
                            } else {
                                ze
                            }
                        };
                        eval(
                            near_one(e2l, z2.mul_f64(pw)),
                            near_one(e4l, z2.mul(z2).mul_f64(pw)),
                        )
                    }
                };
                if !(out.0.hi.is_finite() && out.1.is_finite()) {
                    out = pointwise();
                }
                out
            }
            Kernel::Fixed(core) => from_psi(psi_from_core(&at(), core, spec.size_effect)),
            Kernel::General => from_psi(psi_from_core(
                &at(),
                &Core::new(&at(), spec.moments, spec.size_effect),
                spec.size_effect,
            )),
            Kernel::Measured => {
                let p = at();
                match spec.roughness.table() {
                    Some(t) => roughness::psi_sq(&p, &t.at_zeta(p.zeta()), spec.size_effect),
                    None => from_psi(psi_from_core(
                        &p,
                        &Core::new(&p, spec.moments, spec.size_effect),
                        spec.size_effect,
                    )),
                }
            }
        }
    }
}

/// (ψ², H_y/H0) at one ζ of a ζ sweep, from ζ^e2 and ζ^e4 (for truncated
/// moments read only where e·ln ζ > ½; below, expm1 is used).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn zeta_point(
    a: Dd,
    a_e2: Dd,
    e2: f64,
    l: f64,
    e4l: f64,
    b: Option<Dd>,
    asymptotic: bool,
    ze2: Dd,
    ze4: Dd,
) -> (Dd, f64) {
    let minus1 = Dd::from_f64(-1.0);
    let e2l = e2 * l;
    let sp = if asymptotic {
        ze2.mul(a_e2)
    } else if e2 == 0.0 {
        a.mul_f64(l)
    } else if e2l <= 0.5 {
        a_e2.mul_f64(e2l.exp_m1())
    } else {
        ze2.add(minus1).mul(a_e2)
    };
    let Some(b) = b else {
        return (sp, 1.0);
    };
    let gm4 = if asymptotic {
        ze4
    } else if e4l <= 0.5 {
        Dd::from_f64(e4l.exp_m1())
    } else {
        ze4.add(minus1)
    };
    let hy2 = b.mul(gm4.sqrt()).add(Dd::from_f64(1.0));
    (sp.div(hy2), hy2.hi.sqrt())
}

/// ln x out of line: inlined, the optimizer computes it ahead of the branch
/// that usually makes it unnecessary.
#[cold]
#[inline(never)]
fn ln_apart(x: f64) -> f64 {
    x.ln()
}
