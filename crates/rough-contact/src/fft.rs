//! Two-dimensional real-to-complex FFTs and the surface compliance as a
//! convolution: displacement u = K ∗ p evaluated in Fourier space.
//!
//! Layout: a real field is row-major, `n` rows of `n` samples. Its spectrum
//! is kept transposed, `m = n/2 + 1` rows (one per x-wavenumber) of `n`
//! complex values (one per y-wavenumber), so that both passes of the 2-D
//! transform run on contiguous rows and the product with the kernel needs no
//! transpose back.

use std::sync::Arc;

use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

/// A square real 2-D FFT of side `n` (a power of two ≥ 2).
pub(crate) struct Fft2 {
    n: usize,
    m: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    rows: Vec<Complex64>,
    real_row: Vec<f64>,
    scratch: Vec<Complex64>,
}

impl Fft2 {
    pub(crate) fn new(n: usize) -> Self {
        let mut rp = RealFftPlanner::<f64>::new();
        let mut cp = FftPlanner::<f64>::new();
        let r2c = rp.plan_fft_forward(n);
        let c2r = rp.plan_fft_inverse(n);
        let col_fwd = cp.plan_fft_forward(n);
        let col_inv = cp.plan_fft_inverse(n);
        let m = n / 2 + 1;
        let scratch_len = [
            r2c.get_scratch_len(),
            c2r.get_scratch_len(),
            col_fwd.get_inplace_scratch_len(),
            col_inv.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        Fft2 {
            n,
            m,
            r2c,
            c2r,
            col_fwd,
            col_inv,
            rows: vec![Complex64::new(0.0, 0.0); n * m],
            real_row: vec![0.0; n],
            scratch: vec![Complex64::new(0.0, 0.0); scratch_len],
        }
    }

    pub(crate) fn n(&self) -> usize {
        self.n
    }

    /// Number of x-wavenumbers kept, n/2 + 1.
    pub(crate) fn m(&self) -> usize {
        self.m
    }

    /// Forward transform of the real field `input` (n × n, row-major) into
    /// `out` (m × n, transposed). Unnormalised.
    pub(crate) fn forward(&mut self, input: &[f64], out: &mut [Complex64]) {
        let (n, m) = (self.n, self.m);
        for y in 0..n {
            self.real_row.copy_from_slice(&input[y * n..(y + 1) * n]);
            let dst = &mut self.rows[y * m..(y + 1) * m];
            self.r2c
                .process_with_scratch(&mut self.real_row, dst, &mut self.scratch)
                .expect("buffer sizes fixed at planning");
        }
        transpose::transpose(&self.rows, out, m, n);
        self.col_fwd.process_with_scratch(out, &mut self.scratch);
    }

    /// Inverse of [`Fft2::forward`], normalised so that
    /// `inverse(forward(f)) = f`. `spec` is used as workspace.
    pub(crate) fn inverse(&mut self, spec: &mut [Complex64], out: &mut [f64]) {
        let (n, m) = (self.n, self.m);
        self.col_inv.process_with_scratch(spec, &mut self.scratch);
        transpose::transpose(spec, &mut self.rows, n, m);
        let scale = 1.0 / (n * n) as f64;
        for y in 0..n {
            let row = &mut self.rows[y * m..(y + 1) * m];
            // The DC and Nyquist bins of a real signal are real; rounding in
            // the column pass leaves a residue that the c2r refuses.
            row[0].im = 0.0;
            if n.is_multiple_of(2) {
                row[m - 1].im = 0.0;
            }
            self.c2r
                .process_with_scratch(row, &mut self.real_row, &mut self.scratch)
                .expect("buffer sizes fixed at planning");
            for (o, v) in out[y * n..(y + 1) * n].iter_mut().zip(&self.real_row) {
                *o = v * scale;
            }
        }
    }
}

/// Signed wavenumber index of FFT bin `k` of an `n`-point transform.
pub(crate) fn signed(k: usize, n: usize) -> f64 {
    if k <= n / 2 {
        k as f64
    } else {
        k as f64 - n as f64
    }
}

/// The compliance operator u = K ∗ p on an `n` × `n` window.
pub(crate) struct Compliance {
    n: usize,
    fft: Fft2,
    /// Kernel in Fourier space, transposed layout (m × n_fft); real because
    /// both kernels are even.
    kernel: Vec<f64>,
    padded: Option<Vec<f64>>,
    spec: Vec<Complex64>,
}

impl Compliance {
    /// Periodic cell of side `length`: ũ(q) = 2 p̃(q)/(E* |q|), ũ(0) = 0.
    pub(crate) fn periodic(n: usize, length: f64, e_star: f64) -> Self {
        let fft = Fft2::new(n);
        let m = fft.m();
        let dq = 2.0 * std::f64::consts::PI / length;
        let mut kernel = vec![0.0; m * n];
        for kx in 0..m {
            for ky in 0..n {
                let qx = signed(kx, n) * dq;
                let qy = signed(ky, n) * dq;
                let q = qx.hypot(qy);
                kernel[kx * n + ky] = if q > 0.0 { 2.0 / (e_star * q) } else { 0.0 };
            }
        }
        Compliance {
            n,
            spec: vec![Complex64::new(0.0, 0.0); m * n],
            fft,
            kernel,
            padded: None,
        }
    }

    /// Non-periodic window of side `length` on an elastic half-space that
    /// extends beyond it, pressure zero outside: Love's influence
    /// coefficients of uniform pressure on each square cell, convolved on a
    /// zero-padded 2n × 2n grid (no wrap-around).
    pub(crate) fn free(n: usize, length: f64, e_star: f64) -> Self {
        let nf = 2 * n;
        let dx = length / n as f64;
        let mut coeff = vec![0.0; nf * nf];
        for iy in 0..nf {
            for ix in 0..nf {
                let x = signed(ix, nf) * dx;
                let y = signed(iy, nf) * dx;
                coeff[iy * nf + ix] = love(x, y, dx / 2.0) / (std::f64::consts::PI * e_star);
            }
        }
        let mut fft = Fft2::new(nf);
        let m = fft.m();
        let mut spec = vec![Complex64::new(0.0, 0.0); m * nf];
        fft.forward(&coeff, &mut spec);
        let kernel = spec.iter().map(|c| c.re).collect();
        Compliance {
            n,
            spec,
            fft,
            kernel,
            padded: Some(vec![0.0; nf * nf]),
        }
    }

    /// 1 / K(0): the inverse of a node's displacement under its own unit
    /// pressure, a natural step length when no better one is known.
    pub(crate) fn diagonal_inverse(&self) -> f64 {
        let nf = self.fft.n();
        let m = self.fft.m();
        let mut sum = 0.0;
        for kx in 0..m {
            let w = if kx == 0 || (nf.is_multiple_of(2) && kx == m - 1) {
                1.0
            } else {
                2.0
            };
            sum += w * self.kernel[kx * nf..(kx + 1) * nf].iter().sum::<f64>();
        }
        (nf * nf) as f64 / sum
    }

    /// The largest eigenvalue of K, the Lipschitz constant of the gradient.
    pub(crate) fn max_eigenvalue(&self) -> f64 {
        self.kernel.iter().cloned().fold(0.0, f64::max)
    }

    /// u = K ∗ p, both n × n row-major.
    pub(crate) fn apply(&mut self, p: &[f64], u: &mut [f64]) {
        let n = self.n;
        match &mut self.padded {
            None => {
                self.fft.forward(p, &mut self.spec);
                for (s, k) in self.spec.iter_mut().zip(&self.kernel) {
                    *s *= *k;
                }
                self.fft.inverse(&mut self.spec, u);
            }
            Some(buf) => {
                let nf = self.fft.n();
                buf.iter_mut().for_each(|v| *v = 0.0);
                for y in 0..n {
                    buf[y * nf..y * nf + n].copy_from_slice(&p[y * n..(y + 1) * n]);
                }
                self.fft.forward(buf, &mut self.spec);
                for (s, k) in self.spec.iter_mut().zip(&self.kernel) {
                    *s *= *k;
                }
                self.fft.inverse(&mut self.spec, buf);
                for y in 0..n {
                    u[y * n..(y + 1) * n].copy_from_slice(&buf[y * nf..y * nf + n]);
                }
            }
        }
    }
}

/// ∫∫ dA/r over the square |ξ| ≤ a, |η| ≤ a seen from (x, y) (Love 1929).
fn love(x: f64, y: f64, a: f64) -> f64 {
    // Primitive F(u, v) of 1/√(u² + v²): u asinh(v/|u|) + v asinh(u/|v|).
    fn prim(u: f64, v: f64) -> f64 {
        let mut s = 0.0;
        if u != 0.0 {
            s += u * (v / u.abs()).asinh();
        }
        if v != 0.0 {
            s += v * (u / v.abs()).asinh();
        }
        s
    }
    prim(x + a, y + a) - prim(x + a, y - a) - prim(x - a, y + a) + prim(x - a, y - a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn love_centre_is_closed_form() {
        // ∫∫ over a square of side 2a seen from its centre: 8 a asinh(1).
        let v = love(0.0, 0.0, 0.5);
        assert!((v - 4.0 * 1f64.asinh()).abs() < 1e-14, "{v}");
    }

    #[test]
    fn fft_round_trip() {
        let n = 8;
        let f: Vec<f64> = (0..n * n).map(|i| ((i * 37 % 11) as f64).sin()).collect();
        let mut t = Fft2::new(n);
        let mut s = vec![Complex64::new(0.0, 0.0); t.m() * n];
        t.forward(&f, &mut s);
        let mut g = vec![0.0; n * n];
        t.inverse(&mut s, &mut g);
        for (a, b) in f.iter().zip(&g) {
            assert!((a - b).abs() < 1e-13);
        }
    }
}
