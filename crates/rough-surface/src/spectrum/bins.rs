//! The log-binned spectrum for display, binned exactly as
//! SurfaceTopography's `power_spectrum_from_area` / `_from_profile` do
//! (`Support.Regression.make_grid` with 'log' collocation, 10 edges per
//! decade, and `bin_average`): edges equally spaced in log10 from 0.01
//! decade below the smallest wavevector to 0.01 decade above the largest;
//! a point belongs to the bin whose upper edge is the first edge ≥ |q|;
//! each bin reports the mean |q| and the mean PSD of its points; empty
//! bins are left out.

/// Edges per decade (SurfaceTopography's default).
pub(crate) const PER_DECADE: f64 = 10.0;

/// Log-spaced bins between `min` and `max` (1/m) accumulating weighted
/// (q, C) points.
pub(crate) struct Bins {
    edges: Vec<f64>,
    /// Per bin: Σ weight, Σ weight·q, Σ weight·C.
    sums: Vec<[f64; 3]>,
}

impl Bins {
    pub fn new(min: f64, max: f64) -> Bins {
        // make_grid: nb_points = ceil((log10 max − log10 min + 1) · 10)
        // edges, np.linspace(log10 min − 0.01, log10 max + 0.01, nb_points).
        let n = ((max.log10() - min.log10() + 1.0) * PER_DECADE).ceil() as usize;
        let n = n.max(2);
        let (a, b) = (min.log10() - 0.01, max.log10() + 0.01);
        let step = (b - a) / (n - 1) as f64;
        let edges: Vec<f64> = (0..n)
            .map(|i| {
                let e = if i == n - 1 { b } else { i as f64 * step + a };
                10f64.powf(e)
            })
            .collect();
        Bins {
            sums: vec![[0.0; 3]; n - 1],
            edges,
        }
    }

    /// Adds a point of PSD `c` at |q| = `q`, counted `weight` times.
    #[inline]
    pub fn add(&mut self, q: f64, c: f64, weight: f64) {
        // np.searchsorted(edges, q): the first edge ≥ q; bins 1..n−1 kept.
        let i = self.edges.partition_point(|&e| e < q);
        if i == 0 || i == self.edges.len() {
            return;
        }
        let s = &mut self.sums[i - 1];
        s[0] += weight;
        s[1] += weight * q;
        s[2] += weight * c;
    }

    /// Adds the points of `other` (bins made with the same edges).
    pub fn merge(&mut self, other: &Bins) {
        debug_assert_eq!(self.edges, other.edges);
        for (s, o) in self.sums.iter_mut().zip(&other.sums) {
            for k in 0..3 {
                s[k] += o[k];
            }
        }
    }

    /// (mean q, mean C) of every non-empty bin, q increasing.
    pub fn finish(&self) -> Vec<(f64, f64)> {
        self.sums
            .iter()
            .filter(|s| s[0] > 0.0)
            .map(|s| (s[1] / s[0], s[2] / s[0]))
            .collect()
    }

    /// How many points (weights) each bin [`Bins::finish`] reports holds.
    pub fn counts(&self) -> Vec<f64> {
        self.sums
            .iter()
            .filter(|s| s[0] > 0.0)
            .map(|s| s[0])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bins_follow_make_grid() {
        // min 1, max 100: ceil(3 · 10) = 30 edges from 10^−0.01 to 10^2.01.
        let b = Bins::new(1.0, 100.0);
        assert_eq!(b.edges.len(), 30);
        assert!((b.edges[0] - 10f64.powf(-0.01)).abs() < 1e-15);
        assert_eq!(b.edges[29], 10f64.powf(2.01));
        let mut b = b;
        b.add(1.0, 4.0, 1.0);
        b.add(1.01, 2.0, 2.0);
        b.add(1e3, 1.0, 1.0); // beyond the last edge: dropped
        let s = b.finish();
        assert_eq!(s.len(), 1);
        assert!((s[0].0 - (1.0 + 2.02) / 3.0).abs() < 1e-15);
        assert!((s[0].1 - 8.0 / 3.0).abs() < 1e-15);
    }
}
