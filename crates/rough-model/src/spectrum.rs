//! The power-law spectrum and its moments.
//!
//! C(q) = Z q^(−2(1+H)) for q0 < q < q1 = ζ q0, with Z fixed by `h_rms` under
//! the paper's convention (spectrum extended to q → ∞): Z = h_rms² H q0^(2H)/π.
//! The moments are written so that π and the large powers cancel analytically:
//!
//! - m0 = h_rms² f0
//! - m2 = (h_rms q0)² H g(ζ, 2 − 2H)
//! - m4 = ¾ (h_rms q0²)² H g(ζ, 4 − 2H)
//!
//! With [`Moments::Truncated`] (the band q0 … ζ q0 integrated exactly)
//! f0 = 1 − ζ^(−2H) and g(ζ, e) = (ζ^e − 1)/e (→ ln ζ as e → 0); with
//! [`Moments::Asymptotic`] (the paper's eq. 10) f0 = 1 and g(ζ, e) = ζ^e/e
//! (∞ at e = 0, i.e. m2 at H = 1). `g` is evaluated to ~1 ulp in
//! double-double for every ζ ≥ 1 (see `g`), which is what keeps the
//! plasticity indices, and through them the slopes, within 1e-12.

use std::ops::{Add, Div, Mul};

use crate::dd::Dd;
use crate::params::Params;

/// Which profile moments a computation uses (`docs/model.md`, "Spectrum").
///
/// - `Truncated`: the band-limited spectrum q0 < q < ζ q0 integrated exactly,
///   m_n ∝ (ζ^e − 1)/e; at ζ = 1 there is no roughness (ψ = 0).
/// - `Asymptotic`: the paper's eq. 10 (written with ≃, i.e. ζ ≫ 1),
///   m_n ∝ ζ^e/e and m0 without its (1 − ζ^(−2H)) factor; what the paper's
///   figures use. Finite at ζ = 1; m2 is infinite at H = 1.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Moments {
    #[default]
    Truncated,
    Asymptotic,
}

impl Moments {
    /// The other convention.
    pub fn other(self) -> Moments {
        match self {
            Moments::Truncated => Moments::Asymptotic,
            Moments::Asymptotic => Moments::Truncated,
        }
    }

    /// A short lower-case name for headers and status lines.
    pub fn label(self) -> &'static str {
        match self {
            Moments::Truncated => "truncated",
            Moments::Asymptotic => "asymptotic",
        }
    }

    /// Whether `p` can be computed with these moments: the asymptotic m2 is
    /// infinite at H = 1, so that pair is refused with an error naming both.
    pub fn check(self, p: &Params) -> Result<(), crate::ParamError> {
        if self == Moments::Asymptotic && p.hurst() == 1.0 {
            return Err(crate::ParamError::HurstOneAsymptotic);
        }
        Ok(())
    }
}

/// Spectrum moments and derived geometry of one parameter set, SI units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spectrum {
    /// Spectrum amplitude Z, m^(2−2H).
    pub z: f64,
    /// Zeroth moment m0 = h_rms² at this ζ, m².
    pub m0: f64,
    /// Second moment m2 (half the mean square slope), dimensionless.
    pub m2: f64,
    /// Fourth moment m4, 1/m².
    pub m4: f64,
    /// Mean summit radius R_s = (3/8)√(π/m4), m (∞ at ζ = 1).
    pub r_s: f64,
    /// Shortest wavelength λ1 = 2π/q1, m.
    pub lambda1: f64,
    /// Actual rms height √m0 at this ζ, m.
    pub h_rms_actual: f64,
    /// rms slope √(2 m2).
    pub rms_slope: f64,
    /// rms curvature √(8 m4/3), 1/m.
    pub rms_curvature: f64,
}

/// g(ζ, e) for e = n − 2H (n = 2 or 4), in double-double: (ζ^e − 1)/e for
/// truncated moments, ζ^e/e for asymptotic ones.
///
/// `zeta_pow_m2h` is ζ^(−2H), shared by both moments (only read where
/// e·ln ζ > ½).
///
/// Accuracy ~1–2 ulp for every ζ ≥ 1, 0 < H ≤ 1: below e·ln ζ = ½ through
/// `expm1` or `exp` (well conditioned there); above through ζ^n·ζ^(−2H),
/// where ζ^n is an exact double-double product and `powf` is within an ulp,
/// so the error of ln ζ is never multiplied by a large exponent.
#[inline(always)]
pub(crate) fn g(
    moments: Moments,
    zeta: f64,
    ln_zeta: f64,
    n: u32,
    hurst: f64,
    zeta_pow_m2h: f64,
) -> Dd {
    let e = Dd::sum(n as f64, -2.0 * hurst);
    let truncated = moments == Moments::Truncated;
    if e.hi == 0.0 {
        return Dd::from_f64(if truncated { ln_zeta } else { f64::INFINITY });
    }
    let big_e = e.hi * ln_zeta;
    if big_e <= 0.5 {
        let v = if truncated {
            big_e.exp_m1()
        } else {
            big_e.exp()
        };
        return Dd::from_f64(v).div(e);
    }
    let z2 = Dd::prod(zeta, zeta);
    let zn = if n == 2 { z2 } else { z2.mul(z2) };
    let mut ze = zn.mul_f64(zeta_pow_m2h);
    if !ze.hi.is_finite() || ze.hi == 0.0 {
        // ζ^n overflowed on its own; ζ^e itself may still be finite.
        ze = Dd::from_f64(zeta.powf(e.hi));
    }
    if truncated {
        ze = ze.add(Dd::from_f64(-1.0));
    }
    ze.div(e)
}

/// ln g(ζ, e), finite for every ζ > 1 even where g overflows (+∞ for the
/// asymptotic g at e = 0).
pub(crate) fn ln_g(moments: Moments, ln_zeta: f64, n: u32, hurst: f64) -> f64 {
    let e = n as f64 - 2.0 * hurst;
    if moments == Moments::Asymptotic {
        return if e == 0.0 {
            f64::INFINITY
        } else {
            e * ln_zeta - e.ln()
        };
    }
    if e == 0.0 {
        return ln_zeta.ln();
    }
    let big_e = e * ln_zeta;
    if big_e <= 0.5 {
        (big_e.exp_m1() / e).ln()
    } else {
        big_e + (-(-big_e).exp_m1()).ln() - e.ln()
    }
}

/// The pieces shared by the spectrum and the indices.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Core {
    pub moments: Moments,
    pub ln_zeta: f64,
    /// m0/h_rms²: 1 − ζ^(−2H) (truncated) or 1 (asymptotic).
    pub f0: f64,
    pub g2: Dd,
    pub g4: Dd,
}

impl Core {
    pub fn of(p: &Params, moments: Moments) -> Core {
        Core::new(p, moments, true)
    }

    /// Without `with_g4`, g4 is left 0: for callers that need only m2.
    #[inline(always)]
    pub fn new(p: &Params, moments: Moments, with_g4: bool) -> Core {
        let (zeta, hu) = (p.zeta(), p.hurst());
        let ln_zeta = zeta.ln();
        // e·ln ζ > ½ for either moment iff it is for m4 (the larger exponent).
        let pw = if (4.0 - 2.0 * hu) * ln_zeta > 0.5 {
            zeta.powf(-2.0 * hu)
        } else {
            f64::NAN
        };
        Core {
            moments,
            ln_zeta,
            f0: match moments {
                Moments::Truncated => -(-2.0 * hu * ln_zeta).exp_m1(),
                Moments::Asymptotic => 1.0,
            },
            g2: g(moments, zeta, ln_zeta, 2, hu, pw),
            g4: if with_g4 {
                g(moments, zeta, ln_zeta, 4, hu, pw)
            } else {
                Dd::from_f64(0.0)
            },
        }
    }

    /// ln g for moment n, beyond the f64 range too.
    pub fn ln_g(&self, n: u32, hurst: f64) -> f64 {
        ln_g(self.moments, self.ln_zeta, n, hurst)
    }
}

impl Spectrum {
    /// All moments of `p` under the `moments` convention. Values beyond the
    /// f64 range come out as 0 or ∞, never NaN; with truncated moments ζ = 1
    /// gives m2 = m4 = 0 and R_s = ∞, with asymptotic ones H = 1 gives m2 = ∞.
    pub fn of(p: &Params, moments: Moments) -> Spectrum {
        Spectrum::from_core(p, &Core::of(p, moments))
    }

    pub(crate) fn from_core(p: &Params, c: &Core) -> Spectrum {
        if !in_range(p, c, true, true) {
            return Spectrum::from_logs(p, &Logs::of(p, c));
        }
        let (h, hu, q0) = (p.h_rms(), p.hurst(), p.q0());
        let g2 = c.g2.to_f64();
        let g4 = c.g4.to_f64();
        let hq = h * q0;
        let hq2 = hq * q0;
        let m4_unit = 0.75 * hu * g4; // m4 / (h q0²)²
        Spectrum {
            z: (h * q0.powf(hu)).powi(2) * hu / std::f64::consts::PI,
            m0: h * h * c.f0,
            m2: hq * hq * hu * g2,
            m4: hq2 * hq2 * m4_unit,
            r_s: 0.375 * (std::f64::consts::PI / m4_unit).sqrt() / hq2,
            lambda1: std::f64::consts::TAU / (p.zeta() * q0),
            h_rms_actual: h * c.f0.sqrt(),
            rms_slope: hq * (2.0 * hu * g2).sqrt(),
            rms_curvature: std::f64::consts::SQRT_2 * hq2 * (hu * g4).sqrt(),
        }
    }
}

impl Spectrum {
    fn from_logs(p: &Params, l: &Logs) -> Spectrum {
        let e = f64::exp;
        Spectrum {
            z: e(l.z),
            m0: e(l.m0),
            m2: e(l.m2),
            m4: e(l.m4),
            r_s: e(l.r_s()),
            lambda1: std::f64::consts::TAU / (p.zeta() * p.q0()),
            h_rms_actual: e(0.5 * l.m0),
            rms_slope: e(0.5 * (2f64.ln() + l.m2)),
            rms_curvature: e(0.5 * ((8.0f64 / 3.0).ln() + l.m4)),
        }
    }
}

/// Natural logarithms of the spectrum's quantities, from the inputs directly:
/// the path for parameter sets whose intermediate factors (h q0, g(ζ, e), …)
/// leave the f64 range although the results may not. Relative accuracy
/// ~|ln value|·1e-16, i.e. ~1e-13 at the ends of the range.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Logs {
    pub z: f64,
    pub m0: f64,
    pub m2: f64,
    pub m4: f64,
}

impl Logs {
    pub fn of(p: &Params, c: &Core) -> Logs {
        let (lh, lq, hu) = (p.h_rms().ln(), p.q0().ln(), p.hurst());
        Logs {
            z: 2.0 * lh + hu.ln() + 2.0 * hu * lq - std::f64::consts::PI.ln(),
            m0: 2.0 * lh + c.f0.ln(),
            m2: 2.0 * lh + 2.0 * lq + hu.ln() + c.ln_g(2, hu),
            m4: 0.75f64.ln() + 2.0 * lh + 4.0 * lq + hu.ln() + c.ln_g(4, hu),
        }
    }

    /// ln R_s = ln(3/8) + ½(ln π − ln m4).
    pub fn r_s(&self) -> f64 {
        0.375f64.ln() + 0.5 * (std::f64::consts::PI.ln() - self.m4)
    }
}

/// Whether every intermediate factor of the direct path is a normal double:
/// those of Ψ_P, with `with_g4` also those of m4 and H_y, with `full` also
/// those of Z and m0.
#[inline(always)]
pub(crate) fn in_range(p: &Params, c: &Core, with_g4: bool, full: bool) -> bool {
    let hq = p.h_rms() * p.q0();
    let ok = |v: f64| v.is_normal();
    let g_ok = |g: Dd| ok(g.hi) || (g.hi == 0.0 && c.ln_zeta == 0.0);
    if !(ok(hq) && ok(hq / p.h0_over_e()) && g_ok(c.g2)) {
        return false;
    }
    let hq2 = hq * p.q0();
    if with_g4 && !(ok(hq2) && ok(hq2 * hq2) && g_ok(c.g4)) {
        return false;
    }
    !full || (ok(p.h_rms() * p.h_rms()) && ok(p.h_rms() * p.q0().powf(p.hurst())))
}
