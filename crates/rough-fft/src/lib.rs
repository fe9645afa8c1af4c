//! The FFT planners of `f64` — rustfft's of complex transforms, realfft's
//! of real ones — behind functions that are not generic, so that their
//! code (every algorithm a planner may choose, for AVX, SSE and plain
//! CPUs) is compiled here once rather than in each crate that plans a
//! transform: it was a third of rough-surface's code and more than half
//! of rough-contact's. The transforms are rustfft's and realfft's own, the
//! same ones their planners give; they are called through the same trait
//! objects as before.

use std::sync::Arc;

pub use realfft::{ComplexToReal, RealToComplex};
pub use rustfft::num_complex;
pub use rustfft::Fft;

/// rustfft's planner of complex transforms of `f64` (it keeps what it has
/// planned, for the next transform of a size).
pub struct Planner(rustfft::FftPlanner<f64>);

impl Planner {
    #[allow(clippy::new_without_default)]
    pub fn new() -> Planner {
        Planner(rustfft::FftPlanner::new())
    }

    /// The forward transform of `n` points.
    pub fn forward(&mut self, n: usize) -> Arc<dyn Fft<f64>> {
        self.0.plan_fft_forward(n)
    }

    /// The inverse transform of `n` points (not normalised).
    pub fn inverse(&mut self, n: usize) -> Arc<dyn Fft<f64>> {
        self.0.plan_fft_inverse(n)
    }
}

/// realfft's planner of real-to-complex and complex-to-real transforms of
/// `f64`.
pub struct RealPlanner(realfft::RealFftPlanner<f64>);

impl RealPlanner {
    #[allow(clippy::new_without_default)]
    pub fn new() -> RealPlanner {
        RealPlanner(realfft::RealFftPlanner::new())
    }

    /// The real-to-complex transform of `n` real points.
    pub fn forward(&mut self, n: usize) -> Arc<dyn RealToComplex<f64>> {
        self.0.plan_fft_forward(n)
    }

    /// The complex-to-real transform back to `n` real points (not
    /// normalised).
    pub fn inverse(&mut self, n: usize) -> Arc<dyn ComplexToReal<f64>> {
        self.0.plan_fft_inverse(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_complex::Complex64;

    #[test]
    fn the_transforms_are_the_planners_own() {
        // A cosine of 3 cycles on 16 points: 8 at ±3, nothing elsewhere.
        let x: Vec<f64> = (0..16)
            .map(|k| (2.0 * std::f64::consts::PI * 3.0 * k as f64 / 16.0).cos())
            .collect();
        let mut c: Vec<Complex64> = x.iter().map(|&v| Complex64::new(v, 0.0)).collect();
        Planner::new().forward(16).process(&mut c);
        for (k, v) in c.iter().enumerate() {
            let want = if k == 3 || k == 13 { 8.0 } else { 0.0 };
            assert!(
                (v.re - want).abs() < 1e-12 && v.im.abs() < 1e-12,
                "{k}: {v}"
            );
        }
        let mut p = RealPlanner::new();
        let (r2c, c2r) = (p.forward(16), p.inverse(16));
        let mut input = x.clone();
        let mut half = r2c.make_output_vec();
        r2c.process(&mut input, &mut half).unwrap();
        assert_eq!(half.len(), 9);
        assert!((half[3].re - 8.0).abs() < 1e-12);
        let mut back = c2r.make_output_vec();
        c2r.process(&mut half, &mut back).unwrap();
        for (b, v) in back.iter().zip(&x) {
            assert!((b / 16.0 - v).abs() < 1e-12);
        }
    }
}
