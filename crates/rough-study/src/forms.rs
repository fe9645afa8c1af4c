//! Other ways to the initial slopes, in plain f64 with a fixed number of
//! terms: for comparison with the shipped [`rough_model::exact`] and
//! [`rough_model::closed_form`] (the model's tests, `roughtui bench`), not
//! for use. Each series converges only on its own side of x² ≈ π (x = 1/ψ)
//! and loses digits on the other; the shipped exact method picks per ψ. All
//! take a finite ψ > 0.

use libm::erfc;
use rough_model::slopes::SQRT_2_OVER_PI;
use rough_model::Slopes;

/// Image sums in x = 1/ψ, `terms` terms per sum:
/// S_tot = √(2/π)x(1 + 2Σ_{n=1..N} e^(−2n²x²)),
/// S_pl = 2√(2/π)x Σ_{j=0..N−1} e^(−(2j+1)²x²/2),
/// S_el = √(2/π)x(1 + 2Σ_{m=1..N} (−1)^m e^(−m²x²/2)).
pub fn image(psi: f64, terms: u32) -> Slopes {
    let x = 1.0 / psi;
    let u = x * x;
    let (mut tot, mut pl, mut el) = (1.0, 0.0, 1.0);
    for n in 1..=terms {
        let n = f64::from(n);
        tot += 2.0 * (-2.0 * n * n * u).exp();
        let j = 2.0 * n - 1.0;
        pl += 2.0 * (-j * j * u / 2.0).exp();
        let sign = if (n as u64) % 2 == 1 { -1.0 } else { 1.0 };
        el += sign * 2.0 * (-n * n * u / 2.0).exp();
    }
    let pref = SQRT_2_OVER_PI * x;
    Slopes {
        elastic: pref * el,
        plastic: if pl == 0.0 { 0.0 } else { pref * pl },
        total: pref * tot,
    }
}

/// Fourier (Poisson-summed) sums in ψ, `terms` terms per sum:
/// S_tot = 1 + 2Σ_{k=1..K} e^(−π²k²ψ²/2), S_pl = 1 + 2Σ (−1)^k e^(…),
/// S_el = 4Σ_{k odd ≤ K} e^(…).
pub fn fourier(psi: f64, terms: u32) -> Slopes {
    let a = std::f64::consts::PI.powi(2) * psi * psi / 2.0;
    let (mut tot, mut pl, mut el) = (1.0, 1.0, 0.0);
    for k in 1..=terms {
        let t = (-a * f64::from(k * k)).exp();
        tot += 2.0 * t;
        if k % 2 == 1 {
            pl -= 2.0 * t;
            el += 4.0 * t;
        } else {
            pl += 2.0 * t;
        }
    }
    Slopes {
        elastic: el,
        plastic: pl,
        total: tot,
    }
}

/// The closed form exactly as the paper writes it:
/// S_tot = √(2/π) x + x²/(e^{2x²} − 1) + x² erfc(√2 x)/(1 − e^{−2x²}),
/// S_pl = √(2/π) x e^{−x²/2} + x² erfc(x/√2) coth(x²), S_el = S_tot − S_pl.
pub fn closed_naive(psi: f64) -> Slopes {
    let x = 1.0 / psi;
    let u = x * x;
    let s2 = std::f64::consts::SQRT_2;
    let tot = SQRT_2_OVER_PI * x
        + u / ((2.0 * u).exp() - 1.0)
        + u * erfc(s2 * x) / (1.0 - (-2.0 * u).exp());
    let pl = SQRT_2_OVER_PI * x * (-0.5 * u).exp() + u * erfc(x / s2) / u.tanh();
    Slopes {
        elastic: tot - pl,
        plastic: pl,
        total: tot,
    }
}
