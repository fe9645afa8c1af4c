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
//!   that the paper uses. Its elastic slope cancels like x⁵ for small x; there
//!   it is a Taylor series (39 exact coefficients) up to x = 1, beyond which
//!   the difference loses at most a factor 10.
//!
//! ψ enters as a double-double ([`Dd`]): exponents reach ~1400 where slopes
//! approach 1e-300, and each ulp of ψ there costs ~1400 ulp of the slope.
//!
//! Accuracy (against the mpmath reference `crates/rough-study/data/slopes.csv`):
//! within 1e-12 relative for every ψ ≥ 0; results below 1e-300 may be 0.
//! ψ = 0 gives elastic = total = +∞, plastic = 0; ψ = ∞ gives elastic = 0,
//! plastic = total = 1. Never NaN. The series forms on their own, for
//! comparison, are in `rough_study::forms`.

use std::ops::Mul;

use crate::dd::{Dd, PI2_HALF};

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
        let s = self.plastic_share();
        if s < ELASTIC_BELOW {
            Regime::Elastic
        } else if s > PLASTIC_ABOVE {
            Regime::Plastic
        } else {
            Regime::ElastoPlastic
        }
    }
}

/// The slopes of `model` at index `psi` (≥ 0; f64 or [`Dd`]).
pub fn slopes(model: Model, psi: impl Into<Dd>) -> Slopes {
    match model {
        Model::Exact => exact(psi),
        Model::ClosedForm => closed_form(psi),
    }
}

/// [`slopes`] from x = 1/ψ and ψ² as for [`exact_sq`].
#[inline(always)]
pub(crate) fn slopes_sq(model: Model, x: f64, s: Dd) -> Slopes {
    if s.hi == 0.0 && x == f64::INFINITY {
        return Slopes::ZERO_PSI;
    }
    if x == 0.0 {
        return Slopes::INFINITE_PSI;
    }
    match model {
        Model::Exact => exact_sq(x, s),
        Model::ClosedForm => closed_form_sq(x, s),
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
    exact_sq(psi.recip().hi, psi.mul(psi))
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

/// Below this x the closed form's elastic slope is taken from its series.
const CLOSED_SLOPE_SERIES_X: f64 = 1.0;

/// Taylor coefficients of the closed-form S_el in x: x⁵, x⁷, …, x⁸¹, exact
/// rationals times √(2/π) (`scripts/gen_reference.py`, `closed_series.txt`).
/// Radius of convergence √π; at x = 1 the terms fall ~3× per power of x².
#[allow(clippy::excessive_precision)]
const CLOSED_EL_SERIES: [f64; 39] = [
    0.1329807601338108926466486866447939561586,     // x^5
    -0.01994711402007163389699730299671909342379,   // x^7
    -0.008707073580189998923292473530313889986576,  // x^9
    0.00143139012644032558057156572430160161143,    // x^11
    8.961929384017874236129890971800350265109e-4,   // x^13
    -1.424920709881617976476462050786945312051e-4,  // x^15
    -9.023144748662805071076133396471117684953e-5,  // x^17
    1.430797998228288929668109123657202201483e-5,   // x^19
    9.132834135876773373286501996884020791463e-6,   // x^21
    -1.446760113212408223683350677695659656405e-6,  // x^23
    -9.250957663849024374213582426768057148682e-7,  // x^25
    1.465128911267009918430419579898158831414e-7,   // x^27
    9.372541998551877630040511729183903952466e-8,   // x^29
    -1.484297950165298460331787219458302776734e-8,  // x^31
    -9.496209081217271954218982319772620922377e-9,  // x^33
    1.503860708177372674896926489851884808687e-9,   // x^35
    9.62163057824945073544783127060498353476e-10,   // x^37
    -1.523717435872111468892671552066478972677e-10, // x^39
    -9.748739638871183844798190641237392749127e-11, // x^41
    1.543845494151333414854101094527646987191e-11,  // x^43
    9.877535771207589702470335280323074644941e-12,  // x^45
    -1.564241756521342555485954966143377387211e-12, // x^47
    -1.000803549417678215085021460157438339886e-12, // x^49
    1.584908067258304560606164105910844449768e-13,  // x^51
    1.014025985387896269992980819955642755799e-13,  // x^53
    -1.605847563875586735850630721229589245988e-14, // x^55
    -1.027423126576230020198262313711403122564e-14, // x^57
    1.627063746668654065151749571322013472958e-15,  // x^59
    1.040997271783168529125296031119853005919e-15,  // x^61
    -1.64856024356320753443973369742347116564e-16,  // x^63
    -1.054750757181841350888936648426917058374e-16, // x^65
    1.670340751030547202706021794947501208978e-17,  // x^67
    1.068685951583931729258663368873665716965e-17,  // x^69
    -1.69240901960063171896613711703040681914e-18,  // x^71
    -1.082805255546684259084292204151830446487e-18, // x^73
    1.714768850677412848798884079151956456257e-19,  // x^75
    1.097111101456898802627566496881821525399e-19,  // x^77
    -1.737424096223387833207045392570829909933e-20, // x^79
    -1.111605953866493941400353370333262676259e-20, // x^81
];

/// The paper's closed-form slopes; see the module doc.
pub fn closed_form(psi: impl Into<Dd>) -> Slopes {
    let psi = psi.into();
    if psi.hi == 0.0 {
        return Slopes::ZERO_PSI;
    }
    if psi.hi == f64::INFINITY {
        return Slopes::INFINITE_PSI;
    }
    closed_form_sq(psi.recip().hi, psi.mul(psi))
}

/// [`closed_form`] from x = 1/ψ and ψ² as for [`exact_sq`].
#[inline(always)]
pub(crate) fn closed_form_sq(x: f64, s: Dd) -> Slopes {
    if x == f64::INFINITY {
        // Subnormal ψ: √(2/π)/ψ itself overflows.
        return Slopes::ZERO_PSI;
    }
    let u = s.recip();
    let uf = u.hi;
    // S_pl = √(2/π) x e^(−u/2) + u erfc(x/√2) coth u
    let d_term = SQRT_2_OVER_PI * x * u.mul_f64(0.5).exp_neg();
    let u_coth = if uf < 1e-8 {
        1.0 + uf * uf / 3.0
    } else {
        uf / uf.tanh()
    };
    let e_term = if uf.is_finite() {
        u_coth * u.mul_f64(0.5).erfc_of_sqrt()
    } else {
        0.0
    };
    let plastic = d_term + e_term;
    if x < CLOSED_SLOPE_SERIES_X {
        let mut acc = 0.0;
        for c in CLOSED_EL_SERIES.iter().rev() {
            acc = acc * uf + c;
        }
        let elastic = acc * uf * uf * x;
        return Slopes {
            elastic,
            plastic,
            total: elastic + plastic,
        };
    }
    // S_tot = √(2/π) x + u/(e^(2u) − 1) + u erfc(√2 x)/(1 − e^(−2u))
    let total = if uf.is_finite() {
        SQRT_2_OVER_PI * x
            + uf / (2.0 * uf).exp_m1()
            + uf * u.mul_f64(2.0).erfc_of_sqrt() / -(-2.0 * uf).exp_m1()
    } else {
        // x² overflows (ψ < 1e-154): the Gaussian terms are far below x.
        SQRT_2_OVER_PI * x
    };
    Slopes {
        elastic: total - plastic,
        plastic,
        total,
    }
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
