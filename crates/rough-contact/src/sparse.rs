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

#[cfg(test)]
mod tests {
    use crate::fft::Compliance;

    /// u followed node by node equals u computed afresh by a transform.
    #[test]
    fn nodes_added_through_the_real_kernel_match_a_transform() {
        let n = 64;
        let mut op = Compliance::periodic(n, 2.0, 1.0);
        let p: Vec<f64> = (0..n * n)
            .map(|i| ((i * 37 % 101) as f64 * 0.01).sin().max(0.0))
            .collect();
        let mut u = vec![0.0; n * n];
        op.apply(&p, &mut u);
        let off = [
            (0, 0.3),
            (n * n - 1, -0.2),
            (17 * n + 5, 1.5),
            (33 * n + 63, 0.05),
        ];
        assert!(op.add_nodes(&mut u, &off));
        let mut q = p.clone();
        for &(j, d) in &off {
            q[j] += d;
        }
        let mut want = vec![0.0; n * n];
        op.apply(&q, &mut want);
        let scale = want.iter().map(|v| v.abs()).fold(0.0, f64::max);
        for (a, b) in u.iter().zip(&want) {
            assert!((a - b).abs() <= 1e-12 * scale, "{a} {b}");
        }
        // A free boundary has no periodic kernel: u is left alone.
        let mut free = Compliance::free(16, 1.0, 1.0);
        let mut v = vec![1.0; 256];
        assert!(!free.add_nodes(&mut v, &[(3, 1.0)]));
        assert!(v.iter().all(|x| *x == 1.0));
    }
}
