//! Surfaces for the contact solver: a periodic Gaussian surface with a
//! power-law spectrum synthesised from a seed, its moments as the realisation
//! has them, and the low-pass filter that keeps wavevectors q ≤ q_cut.
//!
//! Convention (Persson's): h(x) = Σ_q h_q e^{iq·x} on a cell of side L, with
//! ⟨|h_q|²⟩ = C(q) (2π/L)², so that ⟨h²⟩ = ∫ C(q) d²q.

use chacha20::rand_core::{Rng, SeedableRng};
use chacha20::ChaCha8Rng;
use rustfft::num_complex::Complex64;

use crate::fft::{signed, Fft2};
use crate::ContactError;

/// An isotropic power law C(q) = z q^(−2(1+hurst)) on q0 ≤ |q| ≤ q1, zero
/// beyond q1 and below q0 — or, with `rolloff`, flat at C(q0) below q0 (a
/// cell of several longest wavelengths: the roll-off of measured spectra).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerLaw {
    /// Amplitude Z, m^(2H)·m² … (the model's `Z`).
    pub z: f64,
    /// Hurst exponent, 0 < H ≤ 1.
    pub hurst: f64,
    /// Lower cutoff, 1/m.
    pub q0: f64,
    /// Upper cutoff ζ q0, 1/m.
    pub q1: f64,
    /// C(q) = C(q0) for 0 < q < q0 instead of 0.
    pub rolloff: bool,
}

impl PowerLaw {
    fn psd(&self, q: f64) -> f64 {
        // A relative margin keeps the wavevectors exactly on a cutoff in.
        let eps = 1e-9;
        if q > self.q1 * (1.0 + eps) || q == 0.0 {
            0.0
        } else if q < self.q0 * (1.0 - eps) {
            if self.rolloff {
                self.z * self.q0.powf(-2.0 * (1.0 + self.hurst))
            } else {
                0.0
            }
        } else {
            self.z * q.powf(-2.0 * (1.0 + self.hurst))
        }
    }
}

/// Standard normal deviates by Box–Muller on a ChaCha8 stream, so that a
/// seed gives the same surface on every platform and version.
struct Normal(ChaCha8Rng, Option<f64>);

impl Normal {
    fn next(&mut self) -> f64 {
        if let Some(v) = self.1.take() {
            return v;
        }
        let unit = |r: &mut ChaCha8Rng| ((r.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
        let (u1, u2) = (unit(&mut self.0), unit(&mut self.0));
        let rad = (-2.0 * u1.ln()).sqrt();
        let (s, c) = (2.0 * std::f64::consts::PI * u2).sin_cos();
        self.1 = Some(rad * s);
        rad * c
    }
}

fn check_grid(n: usize, length: f64) -> Result<(), ContactError> {
    if n < 2 || !n.is_power_of_two() {
        return Err(ContactError::Input(format!(
            "grid side {n}: must be a power of two, at least 2"
        )));
    }
    if !(length.is_finite() && length > 0.0) {
        return Err(ContactError::Input(format!(
            "cell side {length}: must be finite and positive"
        )));
    }
    Ok(())
}

/// Nodes per shortest wavelength of the reference grid a seed's noise is
/// drawn on ([`reference_grid`]).
pub const REFERENCE_PER_WAVELENGTH: f64 = 8.0;
/// Smallest reference grid side.
pub const REFERENCE_MIN: usize = 32;
/// Largest reference grid side; a band wider than it holds (more than
/// 512 shortest wavelengths a side) is drawn on the smallest grid holding
/// it.
pub const REFERENCE_MAX: usize = 4096;

/// The grid a seed's white noise is drawn on for a band reaching `span`
/// wavelengths a side (q1 L/2π): the power of two giving at least
/// [`REFERENCE_PER_WAVELENGTH`] nodes per shortest wavelength, at least
/// [`REFERENCE_MIN`], or beyond [`REFERENCE_MAX`] the smallest power of
/// two holding the band. It depends on the band only, never on the grid a
/// surface is asked for, so that a seed is one surface on every grid.
pub fn reference_grid(span: f64) -> usize {
    let top = span.floor().max(0.0) as usize;
    // A band of exactly k wavelengths (up to rounding) takes 8k nodes.
    let need = (REFERENCE_PER_WAVELENGTH * span * (1.0 - 1e-9))
        .ceil()
        .max(1.0);
    let n = if need <= REFERENCE_MAX as f64 {
        (need as usize).next_power_of_two().max(REFERENCE_MIN)
    } else {
        0
    };
    if n == 0 || n > REFERENCE_MAX {
        (2 * top + 2).next_power_of_two().max(REFERENCE_MIN)
    } else {
        n
    }
}

/// A periodic Gaussian surface on an n × n grid of side `length`: white
/// noise from `seed` on the band's [`reference_grid`], filtered by √C(q)
/// (every mode's amplitude random, its phase uniform), mean zero; on
/// another grid the same modes (so a seed is one surface on every grid
/// that holds the band — n more than twice the largest wavenumber
/// q1 L/2π — and a coarse grid's surface is the fine one's, sampled).
/// On the reference grid this is the white noise filtered there, as
/// roughtui has always drawn a seed's surface. Row-major, heights in the
/// units of √Z·q^…
pub fn synthesise(
    n: usize,
    length: f64,
    spectrum: &PowerLaw,
    seed: u64,
) -> Result<Vec<f64>, ContactError> {
    check_grid(n, length)?;
    let ok = |v: f64| v.is_finite() && v > 0.0;
    let valid = ok(spectrum.z)
        && ok(spectrum.q0)
        && ok(spectrum.q1)
        && spectrum.q1 >= spectrum.q0
        && spectrum.hurst > 0.0
        && spectrum.hurst <= 1.0;
    if !valid {
        return Err(ContactError::Input(format!(
            "power law {spectrum:?}: needs Z, q0 > 0, q1 ≥ q0 and 0 < H ≤ 1"
        )));
    }
    let dq = 2.0 * std::f64::consts::PI / length;
    let span = spectrum.q1 / dq * (1.0 + 1e-9);
    let top = span.floor();
    if !top.is_finite() || 2.0 * top + 2.0 > n as f64 {
        return Err(ContactError::Input(format!(
            "a {n} × {n} grid cannot hold wavevectors up to {top} × 2π/L: it needs at least {} \
             nodes a side (more than two per shortest wavelength)",
            2.0 * top + 2.0
        )));
    }
    let nr = reference_grid(spectrum.q1 / dq);
    // The seed's noise on the reference grid, filtered there:
    // ⟨|W_k|²⟩ = nr² for white noise; |H_k|² must be nr⁴ C dq².
    let mut rng = Normal(ChaCha8Rng::seed_from_u64(seed), None);
    let noise: Vec<f64> = (0..nr * nr).map(|_| rng.next()).collect();
    let mut fft = Fft2::new(nr);
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.m() * nr];
    fft.forward(&noise, &mut spec);
    drop(noise);
    let gain = nr as f64 * dq;
    for kx in 0..fft.m() {
        for ky in 0..nr {
            let q = dq * signed(kx, nr).hypot(signed(ky, nr));
            spec[kx * nr + ky] *= gain * spectrum.psd(q).sqrt();
        }
    }
    if nr == n {
        let mut h = vec![0.0; n * n];
        fft.inverse(&mut spec, &mut h);
        return Ok(h);
    }
    // The band's modes on the grid asked for (H_k scales as n²).
    let mut out = Fft2::new(n);
    let mut placed = vec![Complex64::new(0.0, 0.0); out.m() * n];
    let scale = (n as f64 / nr as f64).powi(2);
    let m = top as i64;
    for kx in 0..=m {
        for ky in -m..=m {
            let q = dq * (kx as f64).hypot(ky as f64);
            if spectrum.psd(q) == 0.0 {
                continue;
            }
            let (kx, from, to) = (
                kx as usize,
                ky.rem_euclid(nr as i64) as usize,
                ky.rem_euclid(n as i64) as usize,
            );
            placed[kx * n + to] = spec[kx * nr + from] * scale;
        }
    }
    let mut h = vec![0.0; n * n];
    out.inverse(&mut placed, &mut h);
    Ok(h)
}

/// Keep only the Fourier modes with |q| ≤ `q_cut` (the mean stays).
pub fn low_pass(h: &[f64], n: usize, length: f64, q_cut: f64) -> Result<Vec<f64>, ContactError> {
    check_grid(n, length)?;
    if h.len() != n * n {
        return Err(ContactError::Input(format!(
            "{} heights for a {n} × {n} grid",
            h.len()
        )));
    }
    let mut fft = Fft2::new(n);
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.m() * n];
    fft.forward(h, &mut spec);
    let dq = 2.0 * std::f64::consts::PI / length;
    for kx in 0..fft.m() {
        for ky in 0..n {
            if dq * signed(kx, n).hypot(signed(ky, n)) > q_cut * (1.0 + 1e-9) {
                spec[kx * n + ky] = Complex64::new(0.0, 0.0);
            }
        }
    }
    let mut out = vec![0.0; n * n];
    fft.inverse(&mut spec, &mut out);
    Ok(out)
}

/// The modes |q| ≤ `q_cut` of an n × n map of side `length` on a coarser
/// `n_out` × `n_out` grid of the same side (Fourier interpolation; with
/// `n_out` = n, [`low_pass`]). `q_cut` must lie below the coarse grid's
/// Nyquist wavenumber π n_out / L.
pub fn resample(
    h: &[f64],
    n: usize,
    length: f64,
    q_cut: f64,
    n_out: usize,
) -> Result<Vec<f64>, ContactError> {
    check_grid(n, length)?;
    check_grid(n_out, length)?;
    let dq = 2.0 * std::f64::consts::PI / length;
    if n_out > n || (n_out < n && q_cut >= dq * (n_out / 2) as f64) {
        return Err(ContactError::Input(format!(
            "cannot resample {n}² to {n_out}² keeping q ≤ {q_cut:e}: the grid must shrink \
             and keep the cutoff below its Nyquist wavenumber"
        )));
    }
    if n_out == n {
        return low_pass(h, n, length, q_cut);
    }
    if h.len() != n * n {
        return Err(ContactError::Input(format!(
            "{} heights for a {n} × {n} grid",
            h.len()
        )));
    }
    let mut fft = Fft2::new(n);
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.m() * n];
    fft.forward(h, &mut spec);
    let mut small = Fft2::new(n_out);
    let mut out_spec = vec![Complex64::new(0.0, 0.0); small.m() * n_out];
    let scale = (n_out as f64 / n as f64).powi(2);
    for kx in 0..small.m() {
        for ky in 0..n_out {
            let sy = signed(ky, n_out);
            if dq * (kx as f64).hypot(sy) > q_cut * (1.0 + 1e-9) {
                continue;
            }
            let src_y = if sy < 0.0 {
                (n as f64 + sy) as usize
            } else {
                ky
            };
            out_spec[kx * n_out + ky] = spec[kx * n + src_y] * scale;
        }
    }
    let mut out = vec![0.0; n_out * n_out];
    small.inverse(&mut out_spec, &mut out);
    Ok(out)
}

/// Spectral moments of a periodic map as the realisation has them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moments {
    /// rms height about the mean.
    pub h_rms: f64,
    /// rms gradient √⟨|∇h|²⟩ = √(2 m2), the model's h′.
    pub rms_slope: f64,
}

/// [`Moments`] of a periodic n × n map of side `length` (spectral slope).
pub fn moments(h: &[f64], n: usize, length: f64) -> Result<Moments, ContactError> {
    check_grid(n, length)?;
    let mut fft = Fft2::new(n);
    let m = fft.m();
    let mut spec = vec![Complex64::new(0.0, 0.0); m * n];
    fft.forward(h, &mut spec);
    let dq = 2.0 * std::f64::consts::PI / length;
    let (mut var, mut grad) = (0.0, 0.0);
    for kx in 0..m {
        // Half spectrum: the bins 1 … n/2−1 stand for their mirror images too.
        let w = if kx == 0 || kx == m - 1 { 1.0 } else { 2.0 };
        for ky in 0..n {
            if kx == 0 && ky == 0 {
                continue;
            }
            let q2 = dq * dq * (signed(kx, n).powi(2) + signed(ky, n).powi(2));
            let a = spec[kx * n + ky].norm_sqr() * w;
            var += a;
            grad += a * q2;
        }
    }
    let n4 = (n * n) as f64 * (n * n) as f64;
    Ok(Moments {
        h_rms: (var / n4).sqrt(),
        rms_slope: (grad / n4).sqrt(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seed_gives_the_stream_it_always_gave() {
        // rand_chacha 0.3.1's ChaCha8Rng::seed_from_u64, its first three
        // next_u64: the surfaces of every seed before the generator's crate
        // changed to chacha20's.
        for (seed, want) in [
            (
                1,
                [0x67094cea8ca40db1, 0x149406d8fc0e8e6b, 0x98b82b0336070665],
            ),
            (
                42,
                [0xae90bfb5395d5ba1, 0xf3453fc625799188, 0x6d71b708c5b6538c],
            ),
        ] {
            let mut r = ChaCha8Rng::seed_from_u64(seed);
            let got: [u64; 3] = std::array::from_fn(|_| r.next_u64());
            assert_eq!(got, want, "seed {seed}");
        }
    }

    #[test]
    fn resampling_keeps_the_modes_below_the_cutoff_exactly() {
        // Two modes kept (q = 3, 5 × 2π/L) and one filtered (q = 20).
        let (n, m, l) = (64, 16, 2.0);
        let tau = 2.0 * std::f64::consts::PI;
        let f = |x: f64, y: f64, all: bool| {
            (tau * 3.0 * x / l).cos()
                + 0.5 * (tau * (4.0 * x - 3.0 * y) / l).sin()
                + if all {
                    0.1 * (tau * 20.0 * y / l).cos()
                } else {
                    0.0
                }
        };
        let grid = |k: usize, all: bool| -> Vec<f64> {
            let d = l / k as f64;
            (0..k * k)
                .map(|i| f((i % k) as f64 * d, (i / k) as f64 * d, all))
                .collect()
        };
        let q_cut = 5.5 * tau / l;
        let got = resample(&grid(n, true), n, l, q_cut, m).unwrap();
        let want = grid(m, false);
        for (a, b) in got.iter().zip(&want) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
        assert!(resample(&grid(n, true), n, l, 9.0 * tau / l, m).is_err());
        assert!(resample(&grid(n, true), n, l, q_cut, 2 * n).is_err());
    }
}
