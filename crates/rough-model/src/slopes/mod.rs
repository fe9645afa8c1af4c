//! Initial slopes of the area–load curves, H·(1/A0)·dA/dp̄ at p̄ → 0.
//!
//! All are functions of the index in use ψ alone (x = 1/ψ). Two models:
//!
//! - [`Model::Exact`]: Persson's two-barrier diffusion solved exactly, theta
//!   functions of x. Each quantity is summed in whichever of its two forms
//!   (image sum in x, Fourier sum in ψ) converges fast *and* has positive or
//!   mildly alternating terms on that side of x² = π; at x² = π both forms
//!   decay like e^(−π k²/2), so five terms reach 1e-24. The elastic slope in
//!   the plastic regime is the positive Fourier sum 4Σ_{k odd} e^(−π²k²ψ²/2),
//!   never a difference.
//! - [`Model::ClosedForm`]: the three-Gaussian form of Xu, Li and Mulvihill
//!   that the paper uses, from one exponential, one erfcx table and
//!   polynomial fits where its elastic slope cancels (it falls like x⁵); the
//!   choices and their error budget are argued in `closed.rs`.
//!
//! ψ enters as a double-double ([`Dd`]): exponents reach ~1400 where slopes
//! approach 1e-300, and each ulp of ψ there costs ~1400 ulp of the slope.
//! Both models carry it only into their exponentials.
//!
//! Accuracy (against the mpmath reference `crates/rough-study/data/slopes.csv`):
//! within 1e-12 relative for every ψ ≥ 0 (the contract; measured: the exact
//! model ~4e-16, the closed form ~1e-15); results below 1e-300 may be 0.
//! ψ = 0 gives elastic = total = +∞, plastic = 0; ψ = ∞ gives elastic = 0,
//! plastic = total = 1. Never NaN. The series forms on their own, for
//! comparison, are in `rough_study::forms`.

use std::ops::Mul;

use crate::dd::{Dd, PI2_HALF};

mod closed;
mod closed_fits;

/// √(2/π), the prefactor of the elastic slope √(2/π)/ψ.
pub const SQRT_2_OVER_PI: f64 = 0.7978845608028654;

/// Which solution of the elasto-plastic problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Model {
    /// Exact two-barrier diffusion (theta series).
    Exact,
    /// The paper's three-Gaussian closed form (Appendix A).
    ClosedForm,
}

impl Model {
    /// The other model.
    pub fn other(self) -> Model {
        match self {
            Model::Exact => Model::ClosedForm,
            Model::ClosedForm => Model::Exact,
        }
    }

    /// A short human name.
    pub fn label(self) -> &'static str {
        match self {
            Model::Exact => "exact",
            Model::ClosedForm => "closed form",
        }
    }
}

/// Normalized initial slopes H·(1/A0)·dA/dp̄ (dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slopes {
    pub elastic: f64,
    pub plastic: f64,
    pub total: f64,
}

/// Below this plastic share S_pl/S_tot the contact is called elastic: this
/// program's threshold, not the paper's (the paper sets none).
pub const ELASTIC_BELOW: f64 = 0.1;
/// Above this plastic share the contact is called plastic (this program's
/// threshold, like [`ELASTIC_BELOW`]).
pub const PLASTIC_ABOVE: f64 = 0.9;

/// Contact regime from the plastic share of the initial slope
/// ([`ELASTIC_BELOW`], [`PLASTIC_ABOVE`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Regime {
    /// Plastic share below 10 %.
    Elastic,
    /// Plastic share from 10 % to 90 %.
    ElastoPlastic,
    /// Plastic share above 90 %.
    Plastic,
}

impl Regime {
    /// The regime of a plastic share ([`ELASTIC_BELOW`], [`PLASTIC_ABOVE`]).
    pub fn of_share(share: f64) -> Regime {
        if share < ELASTIC_BELOW {
            Regime::Elastic
        } else if share > PLASTIC_ABOVE {
            Regime::Plastic
        } else {
            Regime::ElastoPlastic
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Regime::Elastic => "elastic",
            Regime::ElastoPlastic => "elasto-plastic",
            Regime::Plastic => "plastic",
        }
    }
}

impl Slopes {
    const ZERO_PSI: Slopes = Slopes {
        elastic: f64::INFINITY,
        plastic: 0.0,
        total: f64::INFINITY,
    };
    const INFINITE_PSI: Slopes = Slopes {
        elastic: 0.0,
        plastic: 1.0,
        total: 1.0,
    };

    /// S_pl/S_tot in [0, 1] (0 at ψ = 0).
    pub fn plastic_share(&self) -> f64 {
        if self.total.is_infinite() {
            0.0
        } else {
            self.plastic / self.total
        }
    }

    /// Below 10 % plastic share elastic, above 90 % plastic.
    pub fn regime(&self) -> Regime {
        Regime::of_share(self.plastic_share())
    }
}

/// The slopes of `model` at index `psi` (≥ 0; f64 or [`Dd`]).
pub fn slopes(model: Model, psi: impl Into<Dd>) -> Slopes {
    match model {
        Model::Exact => exact(psi),
        Model::ClosedForm => closed_form(psi),
    }
}

/// [`slopes`] from ψ (f64), x = 1/ψ and ψ² as for [`exact_sq`].
#[inline(always)]
pub(crate) fn slopes_sq(model: Model, psi: f64, x: f64, s: Dd) -> Slopes {
    if s.hi == 0.0 && x == f64::INFINITY {
        return Slopes::ZERO_PSI;
    }
    if x == 0.0 {
        return Slopes::INFINITE_PSI;
    }
    match model {
        Model::Exact => exact_sq(x, s),
        Model::ClosedForm => closed::closed_parts(psi, x, s.recip()),
    }
}

/// Persson's elastic solution √(2/π)/ψ (∞ at ψ = 0).
pub fn persson_elastic(psi: impl Into<Dd>) -> f64 {
    let psi = psi.into();
    if psi.hi == 0.0 {
        return f64::INFINITY;
    }
    SQRT_2_OVER_PI / psi.hi * (1.0 - psi.lo / psi.hi)
}

/// e^(−a), e^(−4a), e^(−9a), e^(−16a), e^(−25a) from q = e^(−a). Only q
/// itself needs full accuracy: the others enter the sums at ≤ q⁴ relative.
#[inline(always)]
fn powers(q: f64) -> [f64; 5] {
    let q2 = q * q;
    let q4 = q2 * q2;
    let q8 = q4 * q4;
    let q9 = q8 * q;
    let q16 = q8 * q8;
    [q, q4, q9, q16, q16 * q9]
}

/// Exact two-barrier slopes; see the module doc for forms, accuracy and limits.
pub fn exact(psi: impl Into<Dd>) -> Slopes {
    let psi = psi.into();
    if psi.hi == 0.0 {
        return Slopes::ZERO_PSI;
    }
    if psi.hi == f64::INFINITY {
        return Slopes::INFINITE_PSI;
    }
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU has just been checked to support FMA.
        return unsafe { exact_fma(psi) };
    }
    exact_finite(psi)
}

#[inline(always)]
fn exact_finite(psi: Dd) -> Slopes {
    exact_sq(psi.recip().hi, psi.mul(psi))
}

/// [`exact_finite`] compiled with hardware FMA, which its double-double
/// products use (a library call otherwise; the same bits either way).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn exact_fma(psi: Dd) -> Slopes {
    exact_finite(psi)
}

/// [`exact`] from x = 1/ψ (f64: only a prefactor) and ψ² (double-double:
/// the exponents). Either may overflow or underflow; ψ ∈ (0, ∞) assumed.
#[inline(always)]
pub(crate) fn exact_sq(x: f64, s: Dd) -> Slopes {
    if s.hi * std::f64::consts::PI > 1.0 {
        // x² < π: Fourier forms in q = e^(−π²ψ²/2) ≤ e^(−π/2).
        let [q, q4, q9, q16, q25] = powers(PI2_HALF.mul(s).exp_neg());
        Slopes {
            elastic: 4.0 * (q + q9 + q25),
            plastic: 1.0 + 2.0 * ((q4 - q) + (q16 - q9) - q25),
            total: 1.0 + 2.0 * (q + q4 + q9 + q16 + q25),
        }
    } else {
        // x² ≥ π: image forms in r = e^(−x²/2) ≤ e^(−π/2).
        let [r, r4, r9, r16, r25] = powers(s.recip().mul_f64(0.5).exp_neg());
        let pref = SQRT_2_OVER_PI * x;
        let plastic = if r == 0.0 {
            0.0
        } else {
            2.0 * pref * (r + r9 + r25)
        };
        Slopes {
            elastic: pref * (1.0 + 2.0 * ((r4 - r) + (r16 - r9) - r25)),
            plastic,
            total: pref * (1.0 + 2.0 * (r4 + r16)),
        }
    }
}

/// The paper's closed-form slopes; see the module doc and [`closed`] for how.
pub fn closed_form(psi: impl Into<Dd>) -> Slopes {
    let psi = psi.into();
    if psi.hi == 0.0 {
        return Slopes::ZERO_PSI;
    }
    if psi.hi == f64::INFINITY {
        return Slopes::INFINITE_PSI;
    }
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU has just been checked to support FMA.
        return unsafe { closed_form_fma(psi) };
    }
    closed_form_finite(psi)
}

/// [`closed_form_finite`] compiled with hardware FMA, which its `mul_add`s
/// use (a library call otherwise; the same bits either way).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn closed_form_fma(psi: Dd) -> Slopes {
    closed_form_finite(psi)
}

#[inline(always)]
fn closed_form_finite(psi: Dd) -> Slopes {
    let (x, u) = closed::x_and_u(psi);
    if x == f64::INFINITY {
        // Subnormal ψ: √(2/π)/ψ itself overflows.
        return Slopes::ZERO_PSI;
    }
    closed::closed_parts(psi.hi, x, u)
}

#[cfg(test)]
mod tests {
    #[test]
    fn sqrt_2_over_pi_is_the_nearest_double() {
        // √(2/π) = 0.79788456080286535587989211986876…
        assert_eq!(super::SQRT_2_OVER_PI, 0.797_884_560_802_865_4);
        assert!((super::SQRT_2_OVER_PI - (2.0 / std::f64::consts::PI).sqrt()).abs() <= 1.2e-16);
    }
}
