//! The closed form as `rough_model` computed it before its fast path: kept
//! for `roughtui bench`, whose row shows what the double-double exponents,
//! the two libm erfc calls and the 39-term series cost.

use rough_model::slopes::SQRT_2_OVER_PI;
use rough_model::{Dd, Slopes};

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

/// The closed form as shipped until the fast path replaced it, for ψ > 0
/// finite: ψ² and every exponent argument as a double-double, libm's erfc
/// (two exponentials each) with a double-double correction of its argument,
/// eight exponential-class calls in all (e^(−u/2), tanh, two expm1, two
/// erfc), and S_el from its 39-term Taylor series for x < 1. About the
/// accuracy of [`rough_model::closed_form`]; `roughtui bench` shows its time.
pub fn closed_previous(psi: f64) -> Slopes {
    let psi = Dd::from_f64(psi);
    let x = psi.recip().hi;
    let s = psi * psi;
    if x == f64::INFINITY {
        // Subnormal ψ: √(2/π)/ψ itself overflows.
        return Slopes {
            elastic: f64::INFINITY,
            plastic: 0.0,
            total: f64::INFINITY,
        };
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
