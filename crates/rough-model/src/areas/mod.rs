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
//! (docs/model.md's a, b after dividing the Gaussians through) and 1 − a = b e^(−2(1−ρ)x²):
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

mod closed;

pub use closed::closed_form_areas;
use closed::Closed;

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
