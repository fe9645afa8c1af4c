//! The paper's closed-form slopes (three Gaussians, Appendix A), with x = 1/ψ,
//! u = x², z = x/√2 (docs/model.md):
//!
//! - S_tot = √(2/π) x + u/(e^(2u) − 1) + u erfc(√2 x)/(1 − e^(−2u))
//! - S_pl  = √(2/π) x e^(−u/2) + u erfc(z) coth u
//! - S_el  = S_tot − S_pl
//!
//! Evaluated with one exponential, one erfcx table at two arguments and a few
//! polynomials, to within 1e-15 relative of the mpmath reference over the
//! whole range of ψ (`roughtui bench`; the tests assert 2e-15). The choices,
//! each against the error budget of ~1e-16 per ingredient:
//!
//! 1. **One exponential.** E = e^(−u/2) is the only transcendental call; the
//!    other Gaussian is F = e^(−2u) = (E²)², and the erfc's exponentials are E
//!    and F again (3). The powers lose nothing here: F is used only where
//!    u ≥ 1, as 1 ± F with F ≤ e^(−2) and in the term u F (…)/(1 − F) of S_tot,
//!    which is below 3 % of S_tot where it is used; F's ~3 ulp (four times E's
//!    error plus two roundings) reach the slopes as ≤ 0.3 ulp. Where
//!    1 − e^(−2u) would cancel (u < 1) no exponential is used at all (4).
//! 2. **Double-double only in the exponent.** E's relative error is (u/2)·δu,
//!    and u reaches ~1390 where S_pl is still above 1e-300: an f64 u (δu up to
//!    1.1e-16) would cost up to 8e-14. So u = 1/ψ² carries its rounding error
//!    u.lo (two FMAs on x = fl(1/ψ)), and E = e^(−u.hi/2)(1 − u.lo/2) is as good
//!    as `exp` itself. Nothing else needs it: erfcx, the polynomials and the
//!    prefactor x are well conditioned (relative error in, the same out).
//! 3. **One erfc argument family.** erfc(z) = E·erfcx(z) and erfc(2z) =
//!    F·erfcx(2z), and erfcx comes from one table K(v) = √2 t erfcx(t) at
//!    v = 1/t = √2 ψ and ψ/√2: products of ψ, no division, no exponential
//!    inside erfc (libm's erfc takes two), and no overflow (erfcx(t) ~
//!    1/(t√π)). Then S_pl = x E (√(2/π) + K(√2ψ) coth u) and
//!    S_tot = √(2/π) x + F/(1 − F)·(u + x K(ψ/√2)/2): sums of positive terms.
//! 4. **Polynomials where the closed form cancels.** S_el falls like x⁵ while
//!    S_tot and S_pl tend to 1, so the difference loses 18× at x = 1 and 3.6×
//!    at x = 1.5. Both slopes share the even part u coth u, so S_el is odd in
//!    x: S_el = x u² R_el(u), S_pl = P(u) + x u R_pl(u), S_tot = S_pl + S_el,
//!    with R_el, R_pl, P degree-15 Chebyshev fits in u (poles at u = ±iπ;
//!    `scripts/gen_closed_fits.py`, errors ≤ 6e-17). For u < 1 that is all
//!    (no exponential, no division); for 1 ≤ u < 9/4 S_pl and S_tot come from
//!    (3) and S_el from its fit; from u = 9/4 on the difference loses ≤ 3.6×.
//! 5. **Cut-offs.** For u ≥ 24 the F term of S_tot is below 1e-20 of it; for
//!    u ≥ 1600 (x ≥ 40) S_pl < 1e-340 is 0 and S_el = S_tot = √(2/π) x.
//!
//! Every polynomial and double-double step uses `mul_add`, so the values are
//! the same bits with or without hardware FMA (which only makes them faster).

use super::closed_fits::{K_PIECES, P_EVEN, R_EL_LOW, R_EL_MID, R_PL};
use super::{Slopes, SQRT_2_OVER_PI};
use crate::dd::Dd;

/// Below u = 1 the slopes are the fits alone (choice 4).
const U_LOW: f64 = 1.0;
/// Below u = 9/4 (x = 1.5) S_el is its fit (choice 4).
const U_MID: f64 = 2.25;
/// From u = 24 on S_tot = √(2/π) x (choice 5).
const U_TOTAL_GAUSSIANS: f64 = 24.0;
/// From u = 1600 on S_pl = 0 (choice 5).
const U_NO_PLASTIC: f64 = 1600.0;

#[inline(always)]
fn horner<const N: usize>(c: &[f64; N], d: f64) -> f64 {
    let mut acc = c[N - 1];
    for k in (0..N - 1).rev() {
        acc = acc.mul_add(d, c[k]);
    }
    acc
}

/// K(v) = √2 t erfcx(t) at v = 1/t in [1/32, 23/16] (t ≥ 0.69).
#[inline(always)]
fn k_of(v: f64) -> f64 {
    let i = ((v * 16.0) as usize).min(K_PIECES.len() - 1);
    let (centre, c) = &K_PIECES[i];
    horner(c, v - centre)
}

/// The closed-form slopes at ψ > 0 (finite), x = 1/ψ (finite, to ~1 ulp) and
/// u = 1/ψ² as a double-double (u.hi may be +∞).
#[inline(always)]
pub(crate) fn closed_parts(psi: f64, x: f64, u: Dd) -> Slopes {
    let uh = u.hi;
    if uh < U_LOW {
        let d = uh - 0.5;
        let xu = x * uh;
        let plastic = horner(&R_PL, d).mul_add(xu, horner(&P_EVEN, d));
        let elastic = xu * uh * horner(&R_EL_LOW, d);
        return Slopes {
            elastic,
            plastic,
            total: plastic + elastic,
        };
    }
    if uh >= U_NO_PLASTIC {
        let total = SQRT_2_OVER_PI * x;
        return Slopes {
            elastic: total,
            plastic: 0.0,
            total,
        };
    }
    let e0 = (-0.5 * uh).exp();
    let e = e0.mul_add(-0.5 * u.lo, e0);
    let e2 = e * e;
    let f = e2 * e2;
    let over = 1.0 / (1.0 - f);
    let coth = (1.0 + f) * over;
    let k1 = k_of(std::f64::consts::SQRT_2 * psi);
    let plastic = x * e * k1.mul_add(coth, SQRT_2_OVER_PI);
    if uh < U_MID {
        let elastic = x * uh * uh * horner(&R_EL_MID, uh - 1.625);
        return Slopes {
            elastic,
            plastic,
            total: plastic + elastic,
        };
    }
    let total = if uh < U_TOTAL_GAUSSIANS {
        let k2 = k_of(std::f64::consts::FRAC_1_SQRT_2 * psi);
        (f * over).mul_add((0.5 * x).mul_add(k2, uh), SQRT_2_OVER_PI * x)
    } else {
        SQRT_2_OVER_PI * x
    };
    Slopes {
        elastic: total - plastic,
        plastic,
        total,
    }
}

/// x = fl(1/ψ) and u = 1/ψ² as a double-double (u.hi the nearest double),
/// for ψ = `psi` (> 0, finite, 1/ψ finite): with η = 1 − xψ (exact by FMA),
/// 1/ψ = x(1 + η + …), so u = x²(1 + 2η) to 2^-106. (fl(x²) alone would be
/// ~3 ulp off, and S_el ∝ x u² would show it.)
#[inline(always)]
pub(crate) fn x_and_u(psi: Dd) -> (f64, Dd) {
    let x = 1.0 / psi.hi;
    let eta = (-x).mul_add(psi.hi, 1.0) - x * psi.lo;
    let p = x * x;
    if p == f64::INFINITY {
        return (x, Dd::new(p, 0.0));
    }
    let e = x.mul_add(x, -p) + 2.0 * eta * p;
    let uh = p + e;
    (x, Dd::new(uh, e - (uh - p)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(psi: f64) -> Slopes {
        let (x, u) = x_and_u(Dd::from_f64(psi));
        closed_parts(psi, x, u)
    }

    /// Where the evaluation changes form (u = 1, 9/4, 24, 1600), the two
    /// sides meet: the neighbouring doubles of ψ give slopes within 2e-15
    /// plus what the slopes themselves move over two ulp of ψ (S_el ∝ ψ^-5
    /// near u = 1, S_pl ∝ e^(−u/2) moves u times as fast as ψ). Accuracy on
    /// each side is the reference tests' business.
    #[test]
    fn forms_meet_at_their_seams() {
        for u in [U_LOW, U_MID, U_TOTAL_GAUSSIANS, U_NO_PLASTIC] {
            let psi = 1.0 / u.sqrt();
            let (p, q) = (psi.next_down(), psi.next_up());
            let (a, b) = (at(p), at(q));
            let tol = 2e-15 + (u + 6.0) * (q - p) / psi;
            for (name, x, y) in [
                ("elastic", a.elastic, b.elastic),
                ("plastic", a.plastic, b.plastic),
                ("total", a.total, b.total),
            ] {
                let tiny = x.abs().max(y.abs()) < 1e-300;
                assert!(
                    tiny || ((x - y) / y).abs() < tol,
                    "{name} at u = {u}: {x:e} vs {y:e}"
                );
            }
        }
    }

    /// x_and_u's u is 1/ψ² to double-double accuracy, u.hi the nearest double.
    #[test]
    fn u_is_one_over_psi_squared() {
        for psi in [0.3, 1.0 / 3.0, 0.953, 7.1e-3, 1e-150] {
            let (x, u) = x_and_u(Dd::from_f64(psi));
            assert_eq!(x, 1.0 / psi);
            // ψ²u = 1: (ψ·u.hi)·ψ + ψ²·u.lo, each product exact enough here.
            let p = Dd::prod(psi, u.hi) * Dd::from_f64(psi) + Dd::from_f64(psi * psi * u.lo);
            assert!((p.to_f64() - 1.0).abs() < 1e-30, "ψ = {psi}: {p:?}");
            assert!(u.lo.abs() <= 0.5 * f64::EPSILON * u.hi);
        }
    }
}
