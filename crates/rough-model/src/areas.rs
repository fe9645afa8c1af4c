//! Contact areas at finite load: A_el/A0, A_pl/A0 and A_tot/A0 at mean pressure
//! p̄ = ρ·H for both models, as functions of ψ = √V/H and ρ = p̄/H ∈ (0, 1].
//!
//! Normalized units throughout: H = 1, the diffusion "time" is V = ψ², the start
//! is ρ, and x = 1/ψ. The interval mass that recurs below is
//! E_k(ρ) = erfc((k−ρ)/r) − erfc((k+ρ)/r), r = √2 ψ, k ≥ 1: twice the mass of
//! N(0, ψ²) on [k−ρ, k+ρ]. It is summed from two erfc values only where
//! they differ by a factor e (b² − a² ≥ 1); narrower intervals use the Hermite
//! series of ∫ e^(−t²) about the midpoint, so a width of 1e-12 keeps every digit.
//!
//! # Exact two-barrier solution ([`exact_areas`])
//!
//! With absorption at 0 and 1, by images A_tot = erf(ρ/r) + E_2 + E_4 + …,
//! A_pl = E_1 + E_3 + … (the probability of absorption at p = H, all terms
//! positive) and A_el = erf(ρ'/r) − E_1(ρ') + E_2(ρ') − … with ρ' = min(ρ, 1−ρ)
//! (A_el is symmetric under ρ → 1−ρ; with ρ' ≤ 1/2 the alternating sum keeps
//! more than a third of its first term). Persson's sine series, in
//! q = e^(−π²ψ²/2), gives A_el = (4/π) Σ_{k odd} sin(kπρ') q^(k²)/k (dominated by
//! its first term, never a difference) and A_pl = ρ − (2/π) Σ_k ±sin(kπρ') q^(k²)/k.
//! Each quantity takes the cheaper form where that form is accurate:
//!
//! - A_el: images for ψ ≤ 0.3 (at most three intervals), sine series above
//!   (q ≤ e^(−0.44): at most ten terms, sines by the Chebyshev recurrence);
//! - A_pl: the positive image sum for ψ ≤ 0.4 (at most two intervals), the sine
//!   series above, where ρ − (2/π)Σ keeps at least S_pl(0.4)·ρ ≈ 0.175 ρ;
//! - A_tot = A_el + A_pl (both ≥ 0).
//!
//! Image terms are dropped once their bound min(1, 4h/√π) e^(−(k−ρ)²/r²) falls
//! below 1e-18 of the sum.
//!
//! # The paper's closed form ([`closed_form_areas`])
//!
//! With y = 2x², D' = 1 − e^(−y), a = (1 − e^(−(1−ρ)y))/D', b = (1 − e^(−ρy))/D'
//! (MODEL.md's a, b after dividing the Gaussians through) and 1 − a = b e^(−2(1−ρ)x²):
//!
//! - A_tot = ((1+a)/2) erf(ρx/√2) + (b/2)[erfc((2−ρ)x/√2) + e^(−2(1−ρ)x²)]
//! - A_pl = A_tot − A_el = ((1+b) erfc((1−ρ)x/√2) − a erfc((1+ρ)x/√2))/2
//!   = (E_1 + b erfc((1−ρ)x/√2) + b e^(−2(1−ρ)x²) erfc((1+ρ)x/√2))/2,
//!   three positive terms (E_1 at ψ = 1/x).
//! - A_el is symmetric under ρ → 1−ρ (P_{1−ρ}(1−p) = P_ρ(p)). For x ≥ 0.8 it is
//!   A_tot − A_pl, at ρ' = 1 − ρ instead of ρ > 1/2 when the difference at ρ
//!   would keep less than a quarter of A_tot; at ρ' ≤ 1/2 it keeps at least
//!   ~1/50 of A_tot at x = 0.8 and more above. For
//!   x < 0.8 it falls like x⁵ below A_tot and is summed from its exact Taylor
//!   series A_el = x⁵/√(2π) · τ · Σ_{j≥2} x^(2(j−2)) R_j(τ), τ = ρ(1−ρ), R_j of
//!   degree j−2 (`scripts/closed_areas_series.py`, 25 polynomials; radius x² < π).
//!
//! # Domain, limits, accuracy
//!
//! ρ must be finite and in (0, 1], ψ ≥ 0 (f64 or [`Dd`]; the squares and
//! exponent arguments are carried in double-double, as in the slopes). ψ = ∞:
//! elastic 0, plastic = total = ρ. ψ = 0 (no roughness): the pressure stays a
//! delta at p̄, so for ρ < 1 the contact is full and elastic (1, 0, 1) — the limit
//! ψ → 0 at fixed ρ, where A_el → 1 for any p̄ > 0 (the initial elastic slope is
//! infinite). ρ = 1 (p̄ = H), any ψ: the pressure starts on the plastic barrier,
//! (0, 1, 1) in both models. Against the mpmath references
//! (`areas.csv`, `areas_extra.csv` in `crates/rough-study/data/`) every output is within
//! 1e-12 relative (values below 1e-300 may be 0; measured at most 5e-15, the
//! worst being the closed-form elastic area next to x = 0.8); never NaN;
//! A(ρ)/ρ → the initial slopes of [`mod@crate::slopes`] as ρ → 0. The closed-form
//! elastic area is never negative: P = P0(p−p̄)·N(p)/D' with N concave in p and
//! zero at p = 0 and p = H.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_2_SQRT_PI, PI};
use std::fmt;

use libm::erf;

use crate::dd::{Dd, PI2_HALF};
use crate::params::Shown;
use crate::slopes::Model;

/// 1/√(2π).
const INV_SQRT_2PI: f64 = 0.3989422804014327;

/// Contact areas over nominal area, A/A0 (dimensionless, in [0, 1]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Areas {
    pub elastic: f64,
    pub plastic: f64,
    pub total: f64,
}

impl Areas {
    /// Each fraction kept in [0, 1], where it lies exactly: rounding can
    /// put a total of 1 − 1e-17 at 1 + 2e-16.
    fn clamped(self) -> Areas {
        let c = |v: f64| v.clamp(0.0, 1.0);
        Areas {
            elastic: c(self.elastic),
            plastic: c(self.plastic),
            total: c(self.total),
        }
    }
}

/// Invalid input to the area functions.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum AreaError {
    /// ρ = p̄/H outside (0, 1] or not finite.
    Rho(f64),
    /// ψ = √V/H negative or NaN.
    Psi(f64),
}

impl fmt::Display for AreaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AreaError::Rho(v) => write!(
                f,
                "rho = p̄/H must be finite and in (0, 1] (0 < rho ≤ 1), got {}",
                Shown(*v)
            ),
            AreaError::Psi(v) => write!(f, "psi = √V/H must be ≥ 0 (0 to +inf), got {}", Shown(*v)),
        }
    }
}

impl std::error::Error for AreaError {}

/// Validates, then settles ψ = ∞, ρ = 1 and ψ = 0 (see the module doc).
fn check(psi: Dd, rho: f64) -> Result<Option<Areas>, AreaError> {
    if !(rho > 0.0 && rho <= 1.0) {
        return Err(AreaError::Rho(rho));
    }
    if psi.hi.is_nan() || psi.hi < 0.0 {
        return Err(AreaError::Psi(psi.hi));
    }
    Ok(if psi.hi == f64::INFINITY {
        Some(Areas {
            elastic: 0.0,
            plastic: rho,
            total: rho,
        })
    } else if rho == 1.0 {
        Some(Areas {
            elastic: 0.0,
            plastic: 1.0,
            total: 1.0,
        })
    } else if psi.hi == 0.0 {
        Some(Areas {
            elastic: 1.0,
            plastic: 0.0,
            total: 1.0,
        })
    } else {
        None
    })
}

/// Contact areas A/A0 (dimensionless) of `model` at mean pressure p̄ = `rho`·H,
/// index `psi` = √V/H.
///
/// Domain: ρ finite in (0, 1], ψ ≥ 0 including +∞ (f64 or [`Dd`]); anything
/// else is an [`AreaError`] naming the field. Accuracy: within 1e-12 relative
/// of the mpmath reference for every output (below 1e-300 may be 0), never NaN;
/// a few hundred ns at most. See [`exact_areas`] and [`closed_form_areas`].
pub fn areas(model: Model, psi: impl Into<Dd>, rho: f64) -> Result<Areas, AreaError> {
    match model {
        Model::Exact => exact_areas(psi, rho),
        Model::ClosedForm => closed_form_areas(psi, rho),
    }
}

/// 1/n for n < 64 (the Hermite recurrence divides by n every step).
const INV_N: [f64; 64] = {
    let mut t = [0.0; 64];
    let mut n = 1;
    while n < 64 {
        t[n] = 1.0 / n as f64;
        n += 1;
    }
    t
};

/// E_k = erfc((k−ρ)/r) − erfc((k+ρ)/r) for integer k ≥ 1, 0 < ρ ≤ 1 ≤ k, where
/// `w` = 1/r² (double-double). Never negative.
#[inline]
fn interval(k: f64, rho: f64, w: Dd) -> f64 {
    // b² − a² = 4kρ/r²: the ratio erfc(b)/erfc(a) is below e^(−δ).
    let delta = 4.0 * k * rho * w.hi;
    if delta >= 1.0 {
        let a = Dd::sum(k, -rho);
        let ea = (a * a * w).erfc_of_sqrt();
        if delta > 45.0 {
            return ea; // erfc(b) < e^(−45) erfc(a)
        }
        let b = Dd::sum(k, rho);
        return (ea - (b * b * w).erfc_of_sqrt()).max(0.0);
    }
    // Midpoint m = k/r, half-width h = ρ/r, 2mh = δ/2 < 1/2, h² ≤ mh < 1/4:
    // E = (2/√π) e^(−m²) ∫_{−h}^{h} e^(−2mu − u²) du
    //   = (4h/√π) e^(−m²) Σ_{n even} t_n/(n+1),  t_n = H_n(m) hⁿ/n!,
    // t_{n+1} = (2mh t_n − 2h² t_{n−1})/(n+1).
    let sw = w.hi.sqrt();
    let (m, h) = (k * sw, rho * sw);
    let (u, h2) = (2.0 * m * h, 2.0 * h * h);
    let (mut prev, mut cur) = (1.0, u); // t_{n−1}, t_n with n = 1
    let mut s = 1.0;
    let mut n = 1;
    while n + 2 < INV_N.len() {
        let next = (u * cur - h2 * prev) * INV_N[n + 1]; // t_{n+1}, n+1 even
        s += next * INV_N[n + 2];
        let after = (u * next - h2 * cur) * INV_N[n + 2]; // t_{n+2}, odd
        if next.abs() < 1e-18 && after.abs() < 1e-18 {
            break;
        }
        prev = next;
        cur = after;
        n += 2;
    }
    FRAC_2_SQRT_PI * 2.0 * h * w.mul_f64(k * k).exp_neg() * s
}

/// ρ/r = ρ/(√2 ψ), finite whenever it is representable (also where 1/(2ψ²)
/// overflows, ψ < 1e-154).
#[inline]
fn over_r(rho: f64, psi: f64) -> f64 {
    rho / psi * FRAC_1_SQRT_2
}

/// 1/(2ψ²) as a double-double (∞ when it overflows).
#[inline]
fn half_inv_sq(psi: Dd) -> Dd {
    let x = psi.recip();
    (x * x).mul_f64(0.5)
}

/// Exact two-barrier areas (Persson's diffusion in p with variance V = ψ²H²,
/// absorbing at 0 and H) at load `rho` = p̄/H and index `psi` = √V/H.
///
/// Domain: ρ finite in (0, 1], ψ ≥ 0 (f64 or [`Dd`]); otherwise [`AreaError`].
/// Returns A/A0 (dimensionless): elastic = ∫₀ᴴ P dp, plastic = (p̄ − ∫₀ᴴ p P dp)/H
/// (the probability of absorption at H), total = their sum. Images for
/// ψ² ≤ 1/π, Persson's sine series above (module doc). Accuracy: within 1e-12
/// relative of the 50-digit mpmath reference for every output and every input in
/// the domain (results below 1e-300 may be 0); never NaN. ψ = 0 gives (1, 0, 1)
/// for ρ < 1, ψ = ∞ gives (0, ρ, ρ), ρ = 1 gives (0, 1, 1).
pub fn exact_areas(psi: impl Into<Dd>, rho: f64) -> Result<Areas, AreaError> {
    exact_areas_unclamped(psi.into(), rho).map(Areas::clamped)
}

fn exact_areas_unclamped(psi: Dd, rho: f64) -> Result<Areas, AreaError> {
    if let Some(a) = check(psi, rho)? {
        return Ok(a);
    }
    let s2 = psi * psi;
    let (elastic, plastic) = if s2.hi > PL_FOURIER_PSI2 {
        exact_fourier(s2, rho)
    } else if s2.hi > EL_FOURIER_PSI2 {
        let pl = images_plastic(half_inv_sq(psi), rho);
        (exact_fourier(s2, rho).0, pl)
    } else {
        exact_images(psi, rho)
    };
    Ok(Areas {
        elastic,
        plastic,
        total: elastic + plastic,
    })
}

/// ρ' = min(ρ, 1 − ρ) (exact: 1 − ρ is exact for ρ ≥ 1/2).
#[inline]
fn reflect(rho: f64) -> f64 {
    if rho > 0.5 {
        1.0 - rho
    } else {
        rho
    }
}

/// Above this ψ² the elastic area is taken from the sine series (q ≤ e^(−0.44),
/// at most ten terms), below it from images (at most three intervals).
const EL_FOURIER_PSI2: f64 = 0.09;

/// Above this ψ² the plastic area is taken from the sine series as
/// ρ − (2/π)Σ…, which there cancels by at most 1/S_pl(0.4) ≈ 6; below it from
/// the positive image sum (at most two intervals).
const PL_FOURIER_PSI2: f64 = 0.16;

/// Image sums (elastic, plastic) for 0 < ρ < 1, 0 < ψ < ∞.
fn exact_images(psi: Dd, rho: f64) -> (f64, f64) {
    let w = half_inv_sq(psi);
    let pl = images_plastic(w, rho);
    let el = if reflect(rho) == rho {
        images_elastic(w, psi.hi, rho, Some(pl))
    } else {
        images_elastic(w, psi.hi, 1.0 - rho, None)
    };
    (el, pl)
}

/// A_pl = E_1 + E_3 + … (positive terms), `w` = 1/(2ψ²).
fn images_plastic(w: Dd, rho: f64) -> f64 {
    let mut pl = interval(1.0, rho, w);
    let floor = Floor::new(rho, w, pl);
    for k in (3..2 * IMAGE_KMAX).step_by(2) {
        if floor.negligible(k as f64) {
            break;
        }
        pl += interval(k as f64, rho, w);
    }
    pl
}

/// A_el = erf(ρ'/r) − E_1 + E_2 − … at ρ' = `rp` ≤ 1/2; `e1_plus` is the
/// plastic image sum at the same ρ' when known (it starts with E_1).
fn images_elastic(w: Dd, psi: f64, rp: f64, e1_plus: Option<f64>) -> f64 {
    let mut el = erf(over_r(rp, psi));
    // The alternating sum stays above a third of its first term.
    let floor = Floor::new(rp, w, el / 3.0);
    for k in 1..IMAGE_KMAX {
        if floor.negligible(k as f64) {
            break;
        }
        let e = match (k, e1_plus) {
            // E_1 is the plastic sum less its odd terms from E_3 on, which are
            // below 1e-18 of it whenever E_2 is negligible here; recompute
            // otherwise.
            (1, Some(pl)) if floor.negligible(2.0) => pl,
            _ => interval(k as f64, rp, w),
        };
        el += if k % 2 == 1 { -e } else { e };
    }
    el.max(0.0)
}

/// Highest image index tried (reached only for ψ² near 1/π by the images,
/// or by the tests through [`forms`]).
const IMAGE_KMAX: u32 = 40;

/// Most terms of the sine series (reached only for q near 1, tiny ψ², by
/// the tests through [`forms`]).
const SINE_KMAX: u32 = 400;

/// Decides when image terms E_k (k ≥ 1, decreasing in k) fall below 1e-18 of a
/// sum of at least `acc`: E_k ≤ min(1, 4h/√π) e^(−(k−ρ)²/r²), h = ρ/r.
struct Floor {
    rho: f64,
    w: f64,
    /// ln(1e-18 · acc / min(1, 4h/√π)).
    log_floor: f64,
}

impl Floor {
    #[inline]
    fn new(rho: f64, w: Dd, acc: f64) -> Floor {
        let width = (2.0 * FRAC_2_SQRT_PI * rho * w.hi.sqrt()).min(1.0);
        Floor {
            rho,
            w: w.hi,
            // A zero sum (underflow) makes every term negligible.
            log_floor: if acc > 0.0 {
                (acc / width).ln() - 41.45
            } else {
                f64::INFINITY
            },
        }
    }

    /// True when E_k and every later term are negligible (also for acc = 0).
    #[inline]
    fn negligible(&self, k: f64) -> bool {
        let a = k - self.rho;
        // Margin 1 for the f64 rounding of the exponent.
        -(a * a * self.w) < self.log_floor - 1.0
    }
}

/// Sine series (elastic, plastic) for 0 < ρ < 1 from ψ² = `s2` > 0.
fn exact_fourier(s2: Dd, rho: f64) -> (f64, f64) {
    let q = (PI2_HALF * s2).exp_neg();
    let rp = reflect(rho);
    let upper = rho > 0.5;
    let (sin1, cos1) = (PI * rp).sin_cos();
    let q2 = q * q;
    let (mut qk, mut step) = (q, q * q2); // q^(k²), q^(2k+1)
    let (mut s_prev, mut s_k) = (0.0, sin1); // sin((k−1)πρ'), sin(kπρ')
    let (mut el, mut mom) = (0.0, 0.0);
    for k in 1..=SINE_KMAX {
        let t = s_k * qk / k as f64;
        let odd = k % 2 == 1;
        if odd {
            el += t;
        }
        // sin(kπρ) = (−1)^(k+1) sin(kπρ') for ρ > 1/2.
        mom += if upper || odd { t } else { -t };
        if qk <= 1e-18 * q {
            break;
        }
        let s_next = 2.0 * cos1 * s_k - s_prev;
        s_prev = s_k;
        s_k = s_next;
        qk *= step;
        step *= q2;
    }
    let el = (4.0 / PI * el).max(0.0);
    (el, (rho - 2.0 / PI * mom).max(0.0))
}

/// Below this x = 1/ψ the closed-form elastic area comes from its series.
const CLOSED_AREA_SERIES_X: f64 = 0.8;

/// The paper's three-Gaussian closed form (Xu, Li and Mulvihill; MODEL.md) at
/// load `rho` = p̄/H and index `psi` = √V/H.
///
/// Domain: ρ finite in (0, 1], ψ ≥ 0 (f64 or [`Dd`]); otherwise [`AreaError`].
/// Returns A/A0 (dimensionless): elastic = M(p̄) − a M(−p̄) − b M(2H − p̄),
/// total as in MODEL.md, plastic = total − elastic, each from a
/// cancellation-free form (module doc): a positive three-term sum for the
/// plastic area, and for the elastic area a 25-polynomial Taylor series in
/// x = 1/ψ < 0.8 where it falls like x⁵. Accuracy: within 1e-12 relative of
/// the 50-digit mpmath reference for every output (results below 1e-300 may
/// be 0); never NaN. Limits as for [`exact_areas`]: ψ = 0 gives (1, 0, 1) for
/// ρ < 1, ψ = ∞ gives (0, ρ, ρ), ρ = 1 gives (0, 1, 1).
pub fn closed_form_areas(psi: impl Into<Dd>, rho: f64) -> Result<Areas, AreaError> {
    closed_form_areas_unclamped(psi.into(), rho).map(Areas::clamped)
}

fn closed_form_areas_unclamped(psi: Dd, rho: f64) -> Result<Areas, AreaError> {
    if let Some(a) = check(psi, rho)? {
        return Ok(a);
    }
    let c = Closed::new(psi);
    let rp = reflect(rho);
    if c.x < CLOSED_AREA_SERIES_X {
        let (pl, _) = c.plastic_total(rho, false);
        let elastic = c.elastic_series(rho);
        return Ok(Areas {
            elastic,
            plastic: pl,
            total: elastic + pl,
        });
    }
    let (pl, tot_direct) = c.plastic_total(rho, true);
    let elastic = if rp == rho || tot_direct - pl >= 0.25 * tot_direct {
        // No reflection needed, or the difference keeps a quarter of A_tot.
        return Ok(Areas {
            elastic: (tot_direct - pl).max(0.0),
            plastic: pl,
            total: tot_direct,
        });
    } else {
        let (pl_r, tot_r) = c.plastic_total(rp, true);
        (tot_r - pl_r).max(0.0)
    };
    Ok(Areas {
        elastic,
        plastic: pl,
        total: elastic + pl,
    })
}

/// The closed form at one ψ (0 < ψ < ∞).
struct Closed {
    /// ψ (leading part).
    psi: f64,
    /// x = 1/ψ.
    x: f64,
    /// x² (double-double).
    t: Dd,
    /// x²/2 = 1/(2ψ²) (double-double).
    w: Dd,
}

impl Closed {
    fn new(psi: Dd) -> Closed {
        let xd = psi.recip();
        let t = xd * xd;
        Closed {
            psi: psi.hi,
            x: xd.hi,
            t,
            w: t.mul_f64(0.5),
        }
    }

    /// a = (1 − e^(−(1−ρ)y))/(1 − e^(−y)), b = (1 − e^(−ρy))/(1 − e^(−y)), y = 2x².
    fn ab(&self, rho: f64) -> (f64, f64) {
        let y = 2.0 * self.t.hi;
        let c = 1.0 - rho;
        if y < 1e-8 {
            // (1 − e^(−cy))/(1 − e^(−y)) = c + c(1−c) y/2 + O(c y²/20)
            (c * (1.0 + rho * y / 2.0), rho * (1.0 + c * y / 2.0))
        } else {
            let d = -(-y).exp_m1();
            (-(-c * y).exp_m1() / d, -(-rho * y).exp_m1() / d)
        }
    }

    /// (A_pl, A_tot) from their positive forms, 0 < ρ < 1; A_tot only when
    /// `with_total` (else 0).
    fn plastic_total(&self, rho: f64, with_total: bool) -> (f64, f64) {
        let (a, b) = self.ab(rho);
        let w = self.w;
        let c = Dd::sum(1.0, -rho);
        let e2c = (c * self.t).mul_f64(2.0).exp_neg(); // e^(−2(1−ρ)x²)

        // erfc(α), erfc(β) at α = (1−ρ)x/√2, β = (1+ρ)x/√2; β² − α² = 2ρx² = δ
        // and erfc(β) < e^(−δ) erfc(α).
        let delta = 4.0 * rho * w.hi;
        let ea = (c * c * w).erfc_of_sqrt();
        let eb = if delta > 45.0 {
            0.0
        } else {
            let cp = Dd::sum(1.0, rho);
            (cp * cp * w).erfc_of_sqrt()
        };
        let e1 = if delta >= 1.0 {
            (ea - eb).max(0.0)
        } else {
            interval(1.0, rho, w)
        };
        let pl = 0.5 * (e1 + b * ea + b * e2c * eb);
        if !with_total {
            return (pl, 0.0);
        }
        let first = 0.5 * (1.0 + a) * erf(over_r(rho, self.psi));
        // erfc((2−ρ)x/√2) = erfc(z) < e^(−z²) is below 1e-19 of e^(−2(1−ρ)x²)
        // when ρ²x²/2 > 45, and of the first term when z² > 44 − ln(first).
        let c2 = Dd::sum(2.0, -rho);
        let z2 = c2 * c2 * w;
        let tail = if rho * rho * w.hi > 45.0 || (z2.hi > 45.0 && z2.hi > 44.0 - first.ln()) {
            0.0
        } else {
            z2.erfc_of_sqrt()
        };
        (pl, first + 0.5 * b * (tail + e2c))
    }

    /// x⁵/√(2π) · τ · Σ_{j≥2} x^(2(j−2)) R_j(τ), τ = ρ(1−ρ); x < 0.8 (x² < π).
    fn elastic_series(&self, rho: f64) -> f64 {
        let tau = rho * (1.0 - rho);
        let t = self.t.hi;
        // Terms fall like (x²/π)^(j−2); keep those above 1e-18.
        let n = if t < 1e-300 {
            1
        } else {
            let r = (t / PI).ln();
            ((-41.5 / r).ceil() as usize + 1).min(CLOSED_EL_AREA.len())
        };
        let mut acc = 0.0;
        for poly in CLOSED_EL_AREA[..n].iter().rev() {
            let mut p = 0.0;
            for c in poly.iter().rev() {
                p = p * tau + c;
            }
            acc = acc * t + p;
        }
        let x = self.x;
        let x2 = x * x;
        INV_SQRT_2PI * x * x2 * x2 * tau * acc
    }
}

/// Forms exposed for the tests: each evaluates one representation regardless
/// of where the public functions would use it (0 < ρ < 1, 0 < ψ < ∞).
#[doc(hidden)]
pub mod forms {
    use super::*;

    /// Exact (elastic, plastic) by images.
    pub fn exact_images(psi: f64, rho: f64) -> (f64, f64) {
        super::exact_images(Dd::from_f64(psi), rho)
    }

    /// Exact (elastic, plastic) by the sine series.
    pub fn exact_fourier(psi: f64, rho: f64) -> (f64, f64) {
        super::exact_fourier(Dd::prod(psi, psi), rho)
    }

    /// Closed-form elastic area from its Taylor series in x = 1/ψ.
    pub fn closed_elastic_series(psi: f64, rho: f64) -> f64 {
        Closed::new(Dd::from_f64(psi)).elastic_series(rho)
    }

    /// Closed-form elastic area as A_tot(ρ') − A_pl(ρ').
    pub fn closed_elastic_direct(psi: f64, rho: f64) -> f64 {
        let (pl, tot) = Closed::new(Dd::from_f64(psi)).plastic_total(reflect(rho), true);
        tot - pl
    }
}

#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::approx_constant)]
// generated by scripts/closed_areas_series.py 26 (sympy 1.14.0, exact rationals)
const CLOSED_EL_AREA: [&[f64]; 25] = [
    &[0.3333333333333333], // R_2: tau^0..tau^0
    &[-0.05, 0.16666666666666666], // R_3: tau^0..tau^1
    &[-0.021825396825396824, -0.05555555555555555, 0.041666666666666664], // R_4: tau^0..tau^2
    &[0.003587962962962963, -0.00625, -0.021527777777777778, 0.006944444444444444], // R_5: tau^0..tau^3
    &[0.002246422558922559, 0.004497354497354497, 0.0008680555555555555, -0.004861111111111111, 0.0008680555555555555], // R_6: tau^0..tau^4
    &[-0.00035717465404965404, 0.0006748787477954144, 0.0016005291005291005, 0.0007605820105820106, -0.0007667824074074074, 8.680555555555556e-05], // R_7: tau^0..tau^5
    &[-0.0002261766975308642, -0.0004553220699054032, -7.543816137566137e-05, 0.0002810846560846561, 0.0001984126984126984, -9.259259259259259e-05, 7.2337962962962966e-06], // R_8: tau^0..tau^6
    &[3.5864787176444654e-05, -6.733547043876905e-05, -0.0001602946107069371, -7.004726080246914e-05, 2.482742228835979e-05, 3.28104332010582e-05, -9.04224537037037e-06, 5.166997354497355e-07], // R_9: tau^0..tau^7
    &[2.2892620272503902e-05, 4.5969798728975314e-05, 8.243569615872444e-06, -2.704184972600151e-05, -1.6842258460097002e-05, -1.5500992063492063e-07, 4.034563767636684e-06, -7.406029541446208e-07, 3.229373346560847e-08], // R_10: tau^0..tau^8
    &[-3.6264898063865697e-06, 6.808369602668094e-06, 1.612805189013233e-05, 7.17390609968735e-06, -2.1328379957394716e-06, -2.4093408560639463e-06, -3.99724656452087e-07, 3.9675158257747543e-07, -5.220820243606702e-08, 1.7940963036449148e-09], // R_11: tau^0..tau^9
    &[-2.3188712047618313e-06, -4.65433344869756e-06, -8.448895782841405e-07, 2.686214185625148e-06, 1.6774096780529692e-06, 6.036427296554611e-08, -2.3525332431039896e-07, -7.047210280717225e-08, 3.25628479111552e-08, -3.2293733465608467e-09, 8.970481518224574e-11], // R_12: tau^0..tau^10
    &[3.6725335549612213e-07, -6.894507137623545e-07, -1.631628686750436e-06, -7.27152954295665e-07, 2.0365088946752478e-07, 2.3135315132023755e-07, 4.002662907207798e-08, -1.5733680917419345e-08, -8.065424007903702e-09, 2.2949481884124533e-09, -1.7791455011145404e-10, 4.077491599192988e-12], // R_13: tau^0..tau^11
    &[2.3493478778736684e-07, 4.714964187559102e-07, 8.586004335029353e-08, -2.709354398526568e-07, -1.688771876492927e-07, -7.489646099086547e-09, 2.1424970505826264e-08, 6.039216121578059e-09, -5.705964077404016e-10, -7.174961328624385e-10, 1.4176564542194191e-10, -8.834565131584808e-12, 1.6989548329970785e-13], // R_14: tau^0..tau^12
    &[-3.720583209861173e-08, 6.984650177112931e-08, 1.6525571468472158e-07, 7.368594599576824e-08, -2.0353551722027114e-08, -2.3077313589860532e-08, -4.057079497017028e-09, 1.3147689941886714e-09, 5.934105084397752e-10, 1.851537157522435e-11, -5.305755040838781e-11, 7.795775605123737e-12, -3.992543857543134e-13, 6.534441665373378e-15], // R_15: tau^0..tau^13
    &[-2.380346618478689e-08, -4.777040859899425e-08, -8.705805741957537e-09, 2.742037575642974e-08, 1.7084164826403988e-08, 7.859713168744887e-10, -2.109571284137671e-09, -5.874192220121832e-10, 3.7709547173925466e-11, 4.3629035645809444e-11, 5.260152935718177e-12, -3.380111091553235e-12, 3.863099679790976e-13, -1.655391888561256e-14, 2.333729166204778e-16], // R_16: tau^0..tau^14
    &[3.7696197722240025e-09, -7.076691820894372e-09, -1.6742323959621972e-08, -7.46616877583696e-09, 2.0552546054165426e-09, 2.3293088972410203e-09, 4.0996692606907126e-10, -1.2697010193371801e-10, -5.563288262081745e-11, -2.3937089136768685e-12, 2.482033561430221e-12, 5.424345397834248e-13, -1.8977224356313497e-13, 1.742128822571867e-14, -6.339964234856313e-16, 7.779097220682594e-18], // R_17: tau^0..tau^15
    &[2.4117851255494296e-09, 4.840099595239849e-09, 8.822432135730611e-10, -2.777481162353463e-09, -1.7303066670464514e-09, -8.028425442663044e-11, 2.122903311488255e-10, 5.880615663374276e-11, -3.4706179187573257e-12, -3.928228447667247e-12, -4.4755673436753513e-13, 1.0574278112297584e-13, 4.0752583500325505e-14, -9.541062741167201e-15, 7.208167049664639e-16, -2.255938193997952e-17, 2.4309678814633105e-19], // R_18: tau^0..tau^16
    &[-3.819393207305283e-10, 7.170127674871007e-10, 1.6963121454462857e-09, 7.564864711384815e-10, -2.0806561868596416e-10, -2.357837107135196e-10, -4.150483349513762e-11, 1.2725757273028115e-11, 5.524292485357853e-12, 2.3946660723334634e-13, -2.133645305456466e-13, -3.9233784224212414e-14, 2.7000561362040868e-15, 2.5232312157911146e-15, -4.3475429592089845e-16, 2.755096932325085e-17, -7.495484301178541e-19, 7.14990553371562e-21], // R_19: tau^0..tau^17
    &[-2.443646642081052e-10, -4.904032347163836e-10, -8.939398987297873e-11, 2.8139787110081936e-10, 1.7529943575939662e-10, 8.15041418403165e-12, -2.1473435920331124e-11, -5.940164129823965e-12, 3.451908177817403e-13, 3.8702418573221173e-13, 4.235632516469872e-14, -8.621095941917393e-15, -2.5109953441210828e-15, -4.230370900965403e-17, 1.3523339270809203e-16, -1.8124987829856287e-17, 9.784645722889824e-19, -2.3356358076804354e-20, 1.9860848704765608e-22], // R_20: tau^0..tau^18
    &[3.869846767301401e-11, -7.264842986175707e-11, -1.7187134401148933e-10, -7.664823943350651e-11, 2.1077036104856127e-11, 2.3884212668813066e-11, 4.204398327047621e-12, -1.2860347009793225e-12, -5.569856325273426e-13, -2.3995531535998584e-14, 2.0884272691975406e-14, 3.605258156958507e-15, -2.0817505286218795e-16, -1.2838905174829434e-16, -1.0750312342575337e-17, 6.4418719519189265e-18, -6.966724670215415e-19, 3.245120815153666e-20, -6.851992803144135e-22, 5.2265391328330545e-24], // R_21: tau^0..tau^19
    &[2.475931044778807e-11, 4.9688201132604303e-11, 9.057607713870644e-12, -2.8511064145111093e-11, -1.7761108144789858e-11, -8.262074136517832e-13, 2.1748093411202106e-12, 6.014028938398619e-13, -3.483194098910809e-14, -3.895840774663867e-14, -4.209749506367248e-15, 8.428748399411801e-16, 2.246787323087421e-16, 2.7977438776816515e-18, -5.358347744555151e-18, -8.458628163190047e-19, 2.7734654875850174e-19, -2.484648918248191e-20, 1.0094749231547234e-21, -1.8989758849293433e-23, 1.3066347832082636e-25], // R_22: tau^0..tau^20
    &[-3.920972615254859e-12, 7.36082104418432e-12, 1.7414182429041822e-11, 7.766093731350783e-12, -2.1354385378215685e-12, -2.4198332185733386e-12, -4.259705557528342e-13, 1.3021948982222413e-13, 5.636610590883243e-14, 2.4231674339076867e-15, -2.100136090488344e-15, -3.5658204696422154e-16, 2.094688108691727e-17, 1.1213557016860897e-17, 6.807246038749581e-19, -1.7811560767226882e-19, -4.8953109626730664e-20, 1.0920269491901567e-20, -8.266684208900256e-22, 2.956727852288414e-23, -4.986989422578206e-25, 3.1110351981149134e-27], // R_23: tau^0..tau^21
    &[-2.508642474321416e-12, -5.0344664636501555e-12, -9.17730138927652e-13, 2.888762075471737e-12, 1.7995653967724864e-12, 8.372232915173189e-14, -2.2033144338045618e-13, -6.092314952734623e-14, 3.525805600997059e-15, 3.941081756484219e-15, 4.2447179990992963e-16, -8.483821523980797e-17, -2.2142849641388965e-17, -1.8001349154164488e-19, 4.601300583448632e-19, 4.820173866660144e-20, -4.126337416787063e-21, -2.373593989872698e-21, 3.9672788636634063e-22, -2.5777622846887093e-23, 8.182022571042223e-25, -1.2444140792459653e-26, 7.070534541170258e-29], // R_24: tau^0..tau^22
    &[3.9727753740804375e-13, -7.458070030430843e-13, -1.764424928062289e-12, -7.868698946640569e-13, 2.163623330831985e-13, 2.4517673374279405e-13, 4.315922331546426e-14, -1.3191909429902835e-14, -5.709363042714061e-15, -2.4530048450378526e-16, 2.1241239018925771e-16, 3.592103932448974e-17, -2.129406711264855e-18, -1.103568564667681e-18, -5.811742687461844e-20, 1.538838624765005e-20, 2.442954712160477e-21, -1.379452863261989e-23, -1.0123640201657031e-22, 1.3391687087577824e-23, -7.564028391583354e-25, 2.145688383366518e-26, -2.9578402830562246e-28, 1.5370727263413605e-30], // R_25: tau^0..tau^23
    &[2.541786206183863e-13, 5.100980786093929e-13, 9.298556990122321e-14, -2.9269247135447373e-13, -1.8233381474859525e-13, -8.483098523311175e-15, 2.2323665899532265e-14, 6.1725090668447425e-15, -3.571548229484372e-16, -3.9915991483310837e-16, -4.2955952923819e-17, 8.583515821935206e-18, 2.2293706873928777e-18, 1.544596314211191e-20, -4.5418124710070014e-20, -4.15894021843888e-21, 3.928900022405677e-22, 1.0022568866793132e-22, 5.2447961341373204e-24, -3.894196173084712e-24, 4.22411851734273e-25, -2.096059964729923e-26, 5.3470917467600075e-28, -6.711884238357274e-30, 3.202234846544501e-32], // R_26: tau^0..tau^24
];
