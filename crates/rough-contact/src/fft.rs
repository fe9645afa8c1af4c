//! Two-dimensional real-to-complex FFTs and the surface compliance as a
//! convolution: displacement u = K ∗ p evaluated in Fourier space.
//!
//! Layout: a real field is row-major, `n` rows of `n` samples. Its spectrum
//! is kept transposed, `m = n/2 + 1` rows (one per x-wavenumber) of `n`
//! complex values (one per y-wavenumber), so that both passes of the 2-D
//! transform run on contiguous rows and the product with the kernel needs no
//! transpose back.

use std::sync::Arc;

use rayon::prelude::*;
use rough_fft::{ComplexToReal, Fft, Planner, RealPlanner, RealToComplex};
use rustfft::num_complex::Complex64;

use crate::par::{min_len, CHUNKS};

/// One task's buffers.
struct Worker {
    real_row: Vec<f64>,
    scratch: Vec<Complex64>,
    /// [`STRIP`] columns of n values (for [`Fft2::convolve`]).
    strip: Vec<Complex64>,
}

/// A square real 2-D FFT of side `n` (a power of two ≥ 2). Its row and
/// column passes and transposes run on rayon's pool for large `n`, each
/// task on whole rows with buffers of its own.
pub(crate) struct Fft2 {
    n: usize,
    m: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
    rows: Vec<Complex64>,
    workers: Vec<Worker>,
}

impl Fft2 {
    pub(crate) fn new(n: usize) -> Self {
        let mut rp = RealPlanner::new();
        let mut cp = Planner::new();
        let r2c = rp.forward(n);
        let c2r = rp.inverse(n);
        let col_fwd = cp.forward(n);
        let col_inv = cp.inverse(n);
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
        let workers = (0..CHUNKS.min(n))
            .map(|_| Worker {
                real_row: vec![0.0; n],
                scratch: vec![Complex64::new(0.0, 0.0); scratch_len],
                strip: vec![Complex64::new(0.0, 0.0); STRIP * n],
            })
            .collect();
        Fft2 {
            n,
            m,
            r2c,
            c2r,
            col_fwd,
            col_inv,
            rows: vec![Complex64::new(0.0, 0.0); n * m],
            workers,
        }
    }

    pub(crate) fn n(&self) -> usize {
        self.n
    }

    /// Number of x-wavenumbers kept, n/2 + 1.
    pub(crate) fn m(&self) -> usize {
        self.m
    }

    /// Rows of `len` values per task so that every worker has a share.
    fn rows_per_task(&self, count: usize) -> usize {
        count.div_ceil(self.workers.len()).max(1)
    }

    fn min_tasks(&self) -> usize {
        min_len(self.n * self.n)
    }

    /// The real rows of `input` (each n long) transformed into the first
    /// rows of `self.rows` (each m long), `k` rows a task on every worker.
    fn rows_forward(&mut self, input: &[f64], k: usize) {
        let (n, m) = (self.n, self.m);
        let rows = input.len() / n;
        let r2c = &self.r2c;
        let min = self.min_tasks();
        self.rows[..rows * m]
            .par_chunks_mut(k * m)
            .zip(input.par_chunks(k * n))
            .zip(self.workers.par_iter_mut())
            .with_min_len(min)
            .for_each(|((dst, src), w)| {
                for (d, s) in dst.chunks_exact_mut(m).zip(src.chunks_exact(n)) {
                    w.real_row.copy_from_slice(s);
                    r2c.process_with_scratch(&mut w.real_row, d, &mut w.scratch)
                        .expect("buffer sizes fixed at planning");
                }
            });
    }

    /// Forward transform of the real field `input` (n × n, row-major) into
    /// `out` (m × n, transposed). Unnormalised.
    pub(crate) fn forward(&mut self, input: &[f64], out: &mut [Complex64]) {
        let (n, m) = (self.n, self.m);
        let min = self.min_tasks();
        let k = self.rows_per_task(n);
        self.rows_forward(input, k);
        transpose_par(&self.rows, out, n, m, min);
        let kc = self.rows_per_task(m);
        let col = &self.col_fwd;
        out.par_chunks_mut(kc * n)
            .zip(self.workers.par_iter_mut())
            .with_min_len(min)
            .for_each(|(c, w)| col.process_with_scratch(c, &mut w.scratch));
    }

    /// Inverse of [`Fft2::forward`], normalised so that
    /// `inverse(forward(f)) = f`. `spec` is used as workspace.
    pub(crate) fn inverse(&mut self, spec: &mut [Complex64], out: &mut [f64]) {
        let (n, m) = (self.n, self.m);
        let min = self.min_tasks();
        let kc = self.rows_per_task(m);
        let col = &self.col_inv;
        spec.par_chunks_mut(kc * n)
            .zip(self.workers.par_iter_mut())
            .with_min_len(min)
            .for_each(|(c, w)| col.process_with_scratch(c, &mut w.scratch));
        transpose_par(spec, &mut self.rows, m, n, min);
        let scale = 1.0 / (n * n) as f64;
        let k = self.rows_per_task(n);
        let c2r = &self.c2r;
        self.rows
            .par_chunks_mut(k * m)
            .zip(out.par_chunks_mut(k * n))
            .zip(self.workers.par_iter_mut())
            .with_min_len(min)
            .for_each(|((src, dst), w)| {
                for (row, o) in src.chunks_exact_mut(m).zip(dst.chunks_exact_mut(n)) {
                    // The DC and Nyquist bins of a real signal are real;
                    // rounding in the column pass leaves a residue that the
                    // c2r refuses.
                    row[0].im = 0.0;
                    if n.is_multiple_of(2) {
                        row[m - 1].im = 0.0;
                    }
                    c2r.process_with_scratch(row, &mut w.real_row, &mut w.scratch)
                        .expect("buffer sizes fixed at planning");
                    for (o, v) in o.iter_mut().zip(&w.real_row) {
                        *o = v * scale;
                    }
                }
            });
    }
}

/// A pointer that tasks writing disjoint parts of one buffer share.
#[derive(Clone, Copy)]
struct Shared(*mut Complex64);
// SAFETY: the tasks given a `Shared` write disjoint columns (see
// `Fft2::convolve`) and nothing reads the buffer until they have all ended.
unsafe impl Send for Shared {}
unsafe impl Sync for Shared {}

impl Shared {
    /// The pointer `k` elements on (a method, so that closures capture the
    /// `Shared`, not its raw field).
    fn at(self, k: usize) -> *mut Complex64 {
        self.0.wrapping_add(k)
    }
}

/// Columns a task transforms at once: 32 complex values are eight cache
/// lines of a row, and 32 columns of 1024 fit a core's L2 cache.
const STRIP: usize = 32;
/// Rows a strip's gather and scatter take at once: 16 rows of a strip's 32
/// columns (8 KiB) and the 32 columns' 16 values written (8 KiB) share the
/// first-level cache, where row by row each write fell in another line.
const TILE: usize = 16;

impl Fft2 {
    /// `out` = the periodic convolution of `input` with the kernel whose
    /// transform is `kernel` (real, transposed layout m × n as
    /// [`Compliance`] keeps it): rows r2c, then per strip of columns the
    /// column transform, the product and the inverse in cache, then rows
    /// c2r — no full transposes. `input` holds the field's first rows (the
    /// rest are zero) and `out` receives the first rows of the result.
    /// Returns Σ input·out over the rows both have.
    pub(crate) fn convolve(&mut self, input: &[f64], kernel: &[f64], out: &mut [f64]) -> f64 {
        let (n, m) = (self.n, self.m);
        let (rows_in, rows_out) = (input.len() / n, out.len() / n);
        let min = self.min_tasks();
        let k = rows_in.div_ceil(self.workers.len()).max(1);
        self.rows_forward(input, k);
        let tasks = self.workers.len();
        let per = m.div_ceil(tasks);
        let rows = Shared(self.rows.as_mut_ptr());
        let (fwd, inv) = (&self.col_fwd, &self.col_inv);
        self.workers
            .par_iter_mut()
            .enumerate()
            .with_min_len(min)
            .for_each(|(t, w)| {
                let (c0, c1) = ((t * per).min(m), ((t + 1) * per).min(m));
                for s0 in (c0..c1).step_by(STRIP) {
                    let s1 = (s0 + STRIP).min(c1);
                    let width = s1 - s0;
                    let buf = &mut w.strip[..width * n];
                    // Tiles of TILE rows: the rows read and the columns
                    // written stay in the core's first-level cache.
                    for y0 in (0..rows_in).step_by(TILE) {
                        for y in y0..(y0 + TILE).min(rows_in) {
                            // SAFETY: in bounds (y < rows_in ≤ n, s1 ≤ m);
                            // this task alone touches columns c0..c1.
                            let src =
                                unsafe { std::slice::from_raw_parts(rows.at(y * m + s0), width) };
                            for (c, v) in src.iter().enumerate() {
                                buf[c * n + y] = *v;
                            }
                        }
                    }
                    for c in 0..width {
                        buf[c * n + rows_in..(c + 1) * n].fill(Complex64::new(0.0, 0.0));
                    }
                    for c in 0..width {
                        let col = &mut buf[c * n..(c + 1) * n];
                        fwd.process_with_scratch(col, &mut w.scratch);
                        let kx = s0 + c;
                        for (v, k) in col.iter_mut().zip(&kernel[kx * n..(kx + 1) * n]) {
                            *v *= *k;
                        }
                        inv.process_with_scratch(col, &mut w.scratch);
                    }
                    for y0 in (0..rows_out).step_by(TILE) {
                        for y in y0..(y0 + TILE).min(rows_out) {
                            // SAFETY: as above.
                            let dst = unsafe {
                                std::slice::from_raw_parts_mut(rows.at(y * m + s0), width)
                            };
                            for (c, v) in dst.iter_mut().enumerate() {
                                *v = buf[c * n + y];
                            }
                        }
                    }
                }
            });
        let scale = 1.0 / (n * n) as f64;
        let c2r = &self.c2r;
        let k = rows_out.div_ceil(self.workers.len()).max(1);
        let dots: Vec<f64> = self.rows[..rows_out * m]
            .par_chunks_mut(k * m)
            .zip(out.par_chunks_mut(k * n))
            .zip(self.workers.par_iter_mut())
            .enumerate()
            .with_min_len(min)
            .map(|(t, ((src, dst), w))| {
                let mut dot = 0.0;
                for (r, (row, o)) in src
                    .chunks_exact_mut(m)
                    .zip(dst.chunks_exact_mut(n))
                    .enumerate()
                {
                    row[0].im = 0.0;
                    if n.is_multiple_of(2) {
                        row[m - 1].im = 0.0;
                    }
                    c2r.process_with_scratch(row, &mut w.real_row, &mut w.scratch)
                        .expect("buffer sizes fixed at planning");
                    for (o, v) in o.iter_mut().zip(&w.real_row) {
                        *o = v * scale;
                    }
                    let y = t * k + r;
                    if y < rows_in {
                        dot += o
                            .iter()
                            .zip(&input[y * n..(y + 1) * n])
                            .map(|(a, b)| a * b)
                            .sum::<f64>();
                    }
                }
                dot
            })
            .collect();
        dots.iter().sum()
    }
}

/// `input` (`rows` × `cols`, row-major) transposed into `out` (`cols` ×
/// `rows`), bands of output rows on rayon's pool.
fn transpose_par(input: &[Complex64], out: &mut [Complex64], rows: usize, cols: usize, min: usize) {
    if min > 1 {
        transpose::transpose(input, out, cols, rows);
        return;
    }
    let band = cols.div_ceil(CHUNKS).max(1);
    out.par_chunks_mut(band * rows)
        .enumerate()
        .for_each(|(b, dst)| {
            let c0 = b * band;
            let width = dst.len() / rows;
            // Tiles of 16 input rows keep both sides in cache.
            const TILE: usize = 16;
            for r0 in (0..rows).step_by(TILE) {
                let r1 = (r0 + TILE).min(rows);
                for c in 0..width {
                    let d = &mut dst[c * rows..(c + 1) * rows];
                    for r in r0..r1 {
                        d[r] = input[r * cols + c0 + c];
                    }
                }
            }
        });
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
    pub(crate) n: usize,
    pub(crate) fft: Fft2,
    /// Kernel in Fourier space, transposed layout (m × n_fft); real because
    /// both kernels are even.
    pub(crate) kernel: Vec<f64>,
    /// The free boundary's padded input rows (n × 2n) and output rows.
    pub(crate) padded: Option<Vec<f64>>,
    out: Vec<f64>,
    /// The periodic kernel in real space, made at its first use
    /// (`crate::sparse`).
    pub(crate) real: Option<Vec<f64>>,
    /// 1/K(0), computed once ([`Compliance::diagonal_inverse`]).
    diagonal_inverse: f64,
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
            fft,
            kernel,
            padded: None,
            out: vec![],
            real: None,
            diagonal_inverse: 0.0,
        }
        .with_diagonal()
    }

    fn with_diagonal(mut self) -> Self {
        self.diagonal_inverse = self.diagonal();
        self
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
            fft,
            kernel,
            padded: Some(vec![0.0; n * nf]),
            out: vec![0.0; n * nf],
            real: None,
            diagonal_inverse: 0.0,
        }
        .with_diagonal()
    }

    /// 1 / K(0): the inverse of a node's displacement under its own unit
    /// pressure, a natural step length when no better one is known.
    pub(crate) fn diagonal_inverse(&self) -> f64 {
        self.diagonal_inverse
    }

    fn diagonal(&self) -> f64 {
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
        let _ = self.apply_dot(p, u);
    }

    /// u = K ∗ p and ⟨p, u⟩.
    pub(crate) fn apply_dot(&mut self, p: &[f64], u: &mut [f64]) -> f64 {
        let n = self.n;
        match self.padded.take() {
            None => self.fft.convolve(p, &self.kernel, u),
            Some(mut buf) => {
                // The window's rows, zero-padded to the 2n-wide grid; the
                // padded rows below are zero and not computed.
                let nf = self.fft.n();
                for y in 0..n {
                    let row = &mut buf[y * nf..(y + 1) * nf];
                    row[..n].copy_from_slice(&p[y * n..(y + 1) * n]);
                    row[n..].iter_mut().for_each(|v| *v = 0.0);
                }
                let mut out = std::mem::take(&mut self.out);
                let dot = self.fft.convolve(&buf, &self.kernel, &mut out);
                for y in 0..n {
                    u[y * n..(y + 1) * n].copy_from_slice(&out[y * nf..y * nf + n]);
                }
                self.out = out;
                self.padded = Some(buf);
                dot
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
    fn convolution_equals_the_direct_sum() {
        // A kernel even in x and y (real transform) and a field, 64 × 64
        // (two strips of columns), against the sum done directly.
        let n = 64;
        let k_real: Vec<f64> = (0..n * n)
            .map(|i| {
                let (x, y) = (signed(i % n, n), signed(i / n, n));
                1.0 / (1.0 + x * x + 2.0 * y * y)
            })
            .collect();
        let f: Vec<f64> = (0..n * n).map(|i| ((i * 37 % 11) as f64).sin()).collect();
        let mut t = Fft2::new(n);
        let mut spec = vec![Complex64::new(0.0, 0.0); t.m() * n];
        t.forward(&k_real, &mut spec);
        let kernel: Vec<f64> = spec.iter().map(|c| c.re).collect();
        let mut got = vec![0.0; n * n];
        let dot = t.convolve(&f, &kernel, &mut got);
        let mut want_dot = 0.0;
        for y in 0..n {
            for x in 0..n {
                let mut v = 0.0;
                for yy in 0..n {
                    for xx in 0..n {
                        let k = ((y + n - yy) % n) * n + (x + n - xx) % n;
                        v += k_real[k] * f[yy * n + xx];
                    }
                }
                assert!(
                    (got[y * n + x] - v).abs() < 1e-12 * (1.0 + v.abs()),
                    "{x},{y}"
                );
                want_dot += v * f[y * n + x];
            }
        }
        assert!((dot - want_dot).abs() < 1e-12 * want_dot.abs());
        // The first rows of a field whose others are zero.
        let half: Vec<f64> = f[..n * n / 2].to_vec();
        let mut full = f.clone();
        full[n * n / 2..].iter_mut().for_each(|v| *v = 0.0);
        let (mut a, mut b) = (vec![0.0; n * n], vec![0.0; n * n / 4]);
        t.convolve(&full, &kernel, &mut a);
        t.convolve(&half, &kernel, &mut b);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-13, "{x} {y}");
        }
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
