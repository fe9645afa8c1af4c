//! u = Kp followed node by node: after a step that moved a few nodes off
//! the plain conjugate-gradient step, u += Σ δⱼ G(· − xⱼ) with G the
//! compliance's periodic real-space kernel, cheaper than a transform while
//! the nodes are few ([`crate::step::SPARSE_MAX`]).

use rayon::prelude::*;
use rustfft::num_complex::Complex64;

use crate::fft::Compliance;

impl Compliance {
    /// The periodic real-space kernel G (n × n, row-major): u = G ∗ p.
    /// `None` on a free boundary (its padded grid is not the window's).
    pub(crate) fn real_kernel(&mut self) -> Option<&[f64]> {
        if self.padded.is_some() {
            return None;
        }
        if self.real.is_none() {
            let n = self.n;
            let mut spec: Vec<Complex64> = self
                .kernel
                .iter()
                .map(|&k| Complex64::new(k, 0.0))
                .collect();
            let mut g = vec![0.0; n * n];
            self.fft.inverse(&mut spec, &mut g);
            self.real = Some(g);
        }
        self.real.as_deref()
    }

    /// u += Σ δ G(· − x) over `off` (node, δ); false (u untouched) on a
    /// free boundary.
    pub(crate) fn add_nodes(&mut self, u: &mut [f64], off: &[(usize, f64)]) -> bool {
        let n = self.n;
        let Some(g) = self.real_kernel() else {
            return false;
        };
        let rows = n.div_ceil(crate::par::CHUNKS).max(1);
        let min = crate::par::min_len(n * n);
        u.par_chunks_mut(rows * n)
            .enumerate()
            .with_min_len(min)
            .for_each(|(k, u)| {
                for (r, row) in u.chunks_exact_mut(n).enumerate() {
                    let y = k * rows + r;
                    for &(j, d) in off {
                        let (xj, yj) = (j % n, j / n);
                        let gy = (y + n - yj) % n;
                        let grow = &g[gy * n..(gy + 1) * n];
                        // x ≥ xj reads G from 0, x < xj from n − xj.
                        for (v, k) in row[xj..].iter_mut().zip(&grow[..n - xj]) {
                            *v += d * k;
                        }
                        for (v, k) in row[..xj].iter_mut().zip(&grow[n - xj..]) {
                            *v += d * k;
                        }
                    }
                }
            });
        true
    }
}
