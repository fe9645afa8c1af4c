//! Plasticity indices Ψ_GW, Ψ_P, Ψ* and the paper's asymptotic Ψ* (eq. 13).
//!
//! Ψ_P = √V/H0 with V = E² m2/2, i.e. Ψ_P = (E/H0)√(m2/2) (eq. 11);
//! Ψ* = √V/H_y = Ψ_P/(H_y/H0) (eq. 12); Ψ_GW = (E/H0)√(h_rms/R_s) with
//! h_rms = √m0 (eq. 2). The index *in use* is Ψ_P without size effect and Ψ*
//! with it; the slopes are functions of it alone.

use std::ops::{Add, Div, Mul};

use crate::dd::Dd;
use crate::params::Params;
use crate::spectrum::{in_range, ln_g, Core, Logs, Moments, Spectrum};

/// R_p/R_s of the hardness law times (3/8): R*/(1.2 R_s) = R*·√(m4/π)/0.45.
const RP_COEF: f64 = 0.45;

/// Indices of one parameter set (dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Indices {
    /// Greenwood–Williamson index (E/H0)√(h_rms/R_s).
    pub psi_gw: f64,
    /// Persson's index without size effect, √V/H0.
    pub psi_p: f64,
    /// Ciavarella's index with size-dependent hardness, √V/H_y.
    pub psi_star: f64,
    /// Eq. 13: Ψ* for R*/R_p ≫ 1 and ζ ≫ 1. `None` where it is undefined:
    /// R* = 0 (no size effect) or H = 1 (m2 then grows like ln ζ, not a power).
    pub psi_star_asymptotic: Option<f64>,
    /// H_y/H0 = √(1 + R*/(1.2 R_s)).
    pub hardness_ratio: f64,
    psi_p_dd: Dd,
    psi_star_dd: Dd,
}

impl Indices {
    /// All indices of `p` under the `moments` convention; see [`Surface`]
    /// for everything at once.
    pub fn of(p: &Params, moments: Moments) -> Indices {
        Indices::from_core(p, &Core::of(p, moments))
    }

    pub(crate) fn from_core(p: &Params, c: &Core) -> Indices {
        if !in_range(p, c, true, false) {
            return Indices::from_logs(p, c);
        }
        let (psi_p, hy) = psi_p_and_hardness(p, c);
        let psi_star = psi_star(p, c, psi_p, hy);
        let hu = p.hurst();
        let frac0 = c.f0;
        let g4 = c.g4.to_f64();
        let hq = p.h_rms() * p.q0() / p.h0_over_e();
        // √(√m0/R_s)/(H0/E) with √m0 = h√frac0 and 1/R_s = h q0² √(¾ H g4/π)/0.375.
        let psi_gw =
            hq * (frac0.sqrt() * (0.75 * hu * g4 / std::f64::consts::PI).sqrt() / 0.375).sqrt();
        Indices {
            psi_gw,
            psi_p: psi_p.to_f64(),
            psi_star: psi_star.to_f64(),
            psi_star_asymptotic: asymptotic(p, c.ln_zeta),
            hardness_ratio: hy.to_f64(),
            psi_p_dd: psi_p,
            psi_star_dd: psi_star,
        }
    }

    /// The index in use as a double-double: Ψ* with size effect, Ψ_P without.
    /// Feed it to [`crate::slopes::slopes`]; its extra bits matter where the
    /// slopes are exponentially small.
    pub fn psi_in_use(&self, size_effect: bool) -> Dd {
        if size_effect {
            self.psi_star_dd
        } else {
            self.psi_p_dd
        }
    }

    /// The hardness in use over H0: H_y/H0 with size effect, 1 without.
    pub fn hardness_in_use(&self, size_effect: bool) -> f64 {
        if size_effect {
            self.hardness_ratio
        } else {
            1.0
        }
    }

    /// Relative deviation of the asymptotic Ψ* from the exact one.
    pub fn asymptotic_deviation(&self) -> Option<f64> {
        let a = self.psi_star_asymptotic?;
        if self.psi_star == 0.0 || !self.psi_star.is_finite() || !a.is_finite() {
            return None;
        }
        Some(a / self.psi_star - 1.0)
    }
}

impl Indices {
    /// Indices from values computed elsewhere (a measured surface's moments).
    pub(crate) fn from_parts(
        psi_gw: f64,
        psi_p: Dd,
        psi_star: Dd,
        psi_star_asymptotic: Option<f64>,
        hardness_ratio: f64,
    ) -> Indices {
        Indices {
            psi_gw,
            psi_p: psi_p.to_f64(),
            psi_star: psi_star.to_f64(),
            psi_star_asymptotic,
            hardness_ratio,
            psi_p_dd: psi_p,
            psi_star_dd: psi_star,
        }
    }

    /// The log-domain path for inputs whose intermediate factors leave the
    /// f64 range (see [`Logs`]).
    fn from_logs(p: &Params, c: &Core) -> Indices {
        let l = Logs::of(p, c);
        let lh0 = p.h0_over_e().ln();
        let ln_psi_p = 0.5 * (l.m2 - 2f64.ln()) - lh0;
        let ln_hy = if p.r_star() == 0.0 {
            0.0
        } else {
            // c = R*/(1.2 R_s); H_y/H0 = √(1 + c).
            let lc = p.r_star().ln() - 1.2f64.ln() - l.r_s();
            if lc > 0.0 {
                0.5 * (lc + (-lc).exp().ln_1p())
            } else {
                0.5 * lc.exp().ln_1p()
            }
        };
        let psi_p = Dd::from_f64(ln_psi_p.exp());
        let psi_star = Dd::from_f64((ln_psi_p - ln_hy).exp());
        Indices {
            psi_gw: (0.5 * (0.5 * l.m0 - l.r_s()) - lh0).exp(),
            psi_p: psi_p.hi,
            psi_star: psi_star.hi,
            psi_star_asymptotic: asymptotic(p, c.ln_zeta),
            hardness_ratio: ln_hy.exp(),
            psi_p_dd: psi_p,
            psi_star_dd: psi_star,
        }
    }
}

/// Ψ_P and H_y/H0, both in double-double.
#[inline(always)]
fn psi_p_and_hardness(p: &Params, c: &Core) -> (Dd, Dd) {
    let hu = Dd::from_f64(p.hurst());
    let hq = Dd::prod(p.h_rms(), p.q0());
    // Ψ_P = (h q0/(H0/E))·√(H g2/2)
    let psi_p = hq
        .div(Dd::from_f64(p.h0_over_e()))
        .mul(hu.mul(c.g2).mul_f64(0.5).sqrt());
    let hy = if p.r_star() == 0.0 || c.g4.hi == 0.0 {
        Dd::from_f64(1.0)
    } else {
        // R*/(1.2 R_s) = R* h q0² √(¾ H g4/π)/0.45
        let root = hu.mul(c.g4).mul_f64(0.75).div(crate::dd::PI).sqrt();
        let ratio = hq
            .mul_f64(p.q0())
            .mul_f64(p.r_star())
            .mul(root)
            .div(Dd::from_f64(RP_COEF));
        ratio.add(Dd::from_f64(1.0)).sqrt()
    };
    (psi_p, hy)
}

/// Ψ* = Ψ_P/(H_y/H0); in logarithms where either overflows (ζ ≳ 1e77).
#[inline(always)]
fn psi_star(p: &Params, c: &Core, psi_p: Dd, hy: Dd) -> Dd {
    if hy.hi.is_finite() {
        return psi_p.div(hy);
    }
    let (h, hu, q0) = (p.h_rms(), p.hurst(), p.q0());
    let ln_psi_p =
        h.ln() + q0.ln() - p.h0_over_e().ln() + 0.5 * (hu.ln() + c.ln_g(2, hu) - 2f64.ln());
    // ln(H_y/H0) = ½ ln(1 + r), r huge here, so ½ ln r.
    let ln_r = p.r_star().ln() - RP_COEF.ln()
        + h.ln()
        + 2.0 * q0.ln()
        + 0.5 * (0.75f64.ln() + hu.ln() + c.ln_g(4, hu) - std::f64::consts::PI.ln());
    let ln_hy = 0.5 * (ln_r + (-ln_r).exp().ln_1p());
    Dd::from_f64((ln_psi_p - ln_hy).exp())
}

/// Eq. 13: Ψ_P∞ √(1.2 R_s∞/R*), where ∞ marks the moments with ζ^e/e in
/// place of (ζ^e − 1)/e. Evaluated in logarithms so no factor overflows.
fn asymptotic(p: &Params, ln_zeta: f64) -> Option<f64> {
    let (h, hu, q0, rs) = (p.h_rms(), p.hurst(), p.q0(), p.r_star());
    if rs == 0.0 || hu == 1.0 {
        return None;
    }
    let ln_g2 = ln_g(Moments::Asymptotic, ln_zeta, 2, hu);
    let ln_g4 = ln_g(Moments::Asymptotic, ln_zeta, 4, hu);
    let ln_psi_p = h.ln() + q0.ln() - p.h0_over_e().ln() + 0.5 * (hu.ln() + ln_g2 - 2f64.ln());
    let ln_rs = 0.375f64.ln() + 0.5 * (std::f64::consts::PI.ln() - 0.75f64.ln() - hu.ln() - ln_g4)
        - h.ln()
        - 2.0 * q0.ln();
    Some((ln_psi_p + 0.5 * (1.2f64.ln() + ln_rs - rs.ln())).exp())
}

/// Spectrum and indices of one parameter set, computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    pub params: Params,
    pub moments: Moments,
    pub spectrum: Spectrum,
    pub indices: Indices,
}

impl Surface {
    /// Spectrum and indices of `p` under the `moments` convention.
    pub fn of(p: &Params, moments: Moments) -> Surface {
        let c = Core::of(p, moments);
        Surface {
            params: *p,
            moments,
            spectrum: Spectrum::from_core(p, &c),
            indices: Indices::from_core(p, &c),
        }
    }
}

/// The index in use and the hardness ratio in use, without the rest of the
/// indices: the per-point work of a sweep.
pub fn psi_in_use(p: &Params, size_effect: bool, moments: Moments) -> (Dd, f64) {
    psi_from_core(p, &Core::new(p, moments, size_effect), size_effect)
}

/// [`psi_in_use`] from a `Core` computed with `with_g4 = size_effect`.
#[inline(always)]
pub(crate) fn psi_from_core(p: &Params, c: &Core, size_effect: bool) -> (Dd, f64) {
    let c = *c;
    if !in_range(p, &c, size_effect, false) {
        let ix = Indices::from_logs(p, &Core::of(p, c.moments));
        return (ix.psi_in_use(size_effect), ix.hardness_in_use(size_effect));
    }
    let (psi_p, hy) = if size_effect {
        psi_p_and_hardness(p, &c)
    } else {
        let hu = Dd::from_f64(p.hurst());
        let psi_p = Dd::prod(p.h_rms(), p.q0())
            .div(Dd::from_f64(p.h0_over_e()))
            .mul(hu.mul(c.g2).mul_f64(0.5).sqrt());
        return (psi_p, 1.0);
    };
    (psi_star(p, &c, psi_p, hy), hy.to_f64())
}
