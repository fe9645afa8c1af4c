//! The asperities of a contact: its patches (connected nodes in contact)
//! and the curvature radius of the surface under each, for a hardness that
//! depends on the scale of the asperity a node belongs to.
//!
//! A patch's radius is that of the paraboloid fitted by least squares to
//! the undeformed heights over the patch, h ≈ c0 + c1 x + c2 y + c3 x² +
//! c4 xy + c5 y², R = 1/κ with κ = −(c3 + c5) its mean curvature: a large
//! patch on a big asperity sees that asperity's shape (the finer roughness
//! on it averages out), a small one the fine scale it sits on. A patch of
//! fewer than [`MIN_FIT`] nodes takes the curvature at its highest node,
//! −∇²h/2 computed spectrally (exact for the band-limited surface).
//!
//! A node's summit ([`summits`], [`summit_radii`]) is the finest-scale
//! reading: the local maximum steepest ascent takes it to, and the
//! curvature −∇²h/2 there.

use std::collections::VecDeque;

use rustfft::num_complex::Complex64;

use crate::fft::{signed, Fft2};

/// Nodes a patch needs for its own paraboloid (six coefficients, and a
/// margin over them).
pub const MIN_FIT: usize = 9;

/// The contact patches of a pressure field: 4-connected nodes with p > 0 on
/// the periodic grid.
#[derive(Clone, Debug, PartialEq)]
pub struct Patches {
    /// Each node's patch (`u32::MAX` out of contact), n × n row-major.
    pub label: Vec<u32>,
    /// Nodes in each patch.
    pub size: Vec<usize>,
}

impl Patches {
    /// The patches of `pressure` (n × n).
    pub fn of(pressure: &[f64], n: usize) -> Patches {
        let mut label = vec![u32::MAX; n * n];
        let mut size = vec![];
        let mut queue = VecDeque::new();
        for start in 0..n * n {
            if pressure[start] <= 0.0 || label[start] != u32::MAX {
                continue;
            }
            let id = size.len() as u32;
            let mut count = 0;
            label[start] = id;
            queue.push_back(start);
            while let Some(i) = queue.pop_front() {
                count += 1;
                let (x, y) = (i % n, i / n);
                for j in [
                    y * n + (x + 1) % n,
                    y * n + (x + n - 1) % n,
                    ((y + 1) % n) * n + x,
                    ((y + n - 1) % n) * n + x,
                ] {
                    if pressure[j] > 0.0 && label[j] == u32::MAX {
                        label[j] = id;
                        queue.push_back(j);
                    }
                }
            }
            size.push(count);
        }
        Patches { label, size }
    }

    pub fn count(&self) -> usize {
        self.size.len()
    }

    /// Each node's nearest patch (4-connected steps on the periodic grid,
    /// ties to the patch reached first): the asperity a node out of this
    /// contact belongs to. All `u32::MAX` when there is no patch.
    pub fn nearest(&self, n: usize) -> Vec<u32> {
        let mut out = self.label.clone();
        let mut queue: VecDeque<usize> = (0..n * n).filter(|&i| out[i] != u32::MAX).collect();
        while let Some(i) = queue.pop_front() {
            let (x, y) = (i % n, i / n);
            for j in [
                y * n + (x + 1) % n,
                y * n + (x + n - 1) % n,
                ((y + 1) % n) * n + x,
                ((y + n - 1) % n) * n + x,
            ] {
                if out[j] == u32::MAX {
                    out[j] = out[i];
                    queue.push_back(j);
                }
            }
        }
        out
    }
}

/// −∇²h/2 of the periodic n × n map `h` of side `length` (the mean
/// curvature of the surface where it is a summit), by FFT.
pub fn mean_curvature(h: &[f64], n: usize, length: f64) -> Vec<f64> {
    let mut fft = Fft2::new(n);
    let m = fft.m();
    let mut spec = vec![Complex64::new(0.0, 0.0); m * n];
    fft.forward(h, &mut spec);
    let dq = std::f64::consts::TAU / length;
    for kx in 0..m {
        for ky in 0..n {
            // On the Nyquist lines the mode's sine part is not on the grid:
            // its curvature is that of its cosine part, kept as it is.
            let q2 = dq * dq * (signed(kx, n).powi(2) + signed(ky, n).powi(2));
            spec[kx * n + ky] *= 0.5 * q2;
        }
    }
    let mut out = vec![0.0; n * n];
    fft.inverse(&mut spec, &mut out);
    out
}

/// The summit each node of the periodic n × n map `h` belongs to: the local
/// maximum that steepest ascent reaches from it (at each step the
/// 8-neighbour of steepest rise, (h_j − h_i)/distance; a node with no
/// higher neighbour is a summit, its own). The index of that summit's node,
/// n × n row-major.
pub fn summits(h: &[f64], n: usize) -> Vec<u32> {
    let d = std::f64::consts::SQRT_2;
    let steps: [(usize, usize, f64); 8] = [
        (1, 0, 1.0),
        (n - 1, 0, 1.0),
        (0, 1, 1.0),
        (0, n - 1, 1.0),
        (1, 1, d),
        (n - 1, 1, d),
        (1, n - 1, d),
        (n - 1, n - 1, d),
    ];
    let mut up: Vec<u32> = (0..n * n)
        .map(|i| {
            let (x, y) = (i % n, i / n);
            let mut best = (0.0, i);
            for &(dx, dy, dist) in &steps {
                let j = ((y + dy) % n) * n + (x + dx) % n;
                let rise = (h[j] - h[i]) / dist;
                if rise > best.0 {
                    best = (rise, j);
                }
            }
            best.1 as u32
        })
        .collect();
    // Follow each path to its top, pointing every node on it there (each
    // step rises, so a path ends).
    let mut path = vec![];
    for i in 0..n * n {
        let mut j = i;
        while up[j] as usize != j {
            path.push(j);
            j = up[j] as usize;
        }
        for k in path.drain(..) {
            up[k] = j as u32;
        }
    }
    up
}

/// Each node's summit radius: 1/(−∇²h/2) at the summit steepest ascent
/// takes it to ([`summits`]; ∞ where that summit is not convex), in the
/// units of `length`.
pub fn summit_radii(h: &[f64], n: usize, length: f64) -> Vec<f64> {
    let top = summits(h, n);
    let curvature = mean_curvature(h, n, length);
    top.iter()
        .map(|&t| {
            let k = curvature[t as usize];
            if k > 0.0 {
                1.0 / k
            } else {
                f64::INFINITY
            }
        })
        .collect()
}

/// The curvature radius (in the units of `length`) of the surface under
/// each patch; ∞ where the surface is not convex there, or where the patch
/// spans the cell (percolates: its asperity is the whole cell).
pub fn patch_radii(h: &[f64], n: usize, length: f64, patches: &Patches) -> Vec<f64> {
    let dx = length / n as f64;
    let k = patches.count();
    // Normal equations of the fit, unwrapped coordinates per patch
    // (relative to its first node, so a patch across the cell's edge is
    // whole), and each patch's highest node.
    let mut origin = vec![usize::MAX; k];
    let mut ata = vec![[0.0f64; 21]; k];
    let mut atb = vec![[0.0f64; 6]; k];
    let mut top = vec![(f64::NEG_INFINITY, 0usize); k];
    // Unwrap by walking each patch from its first node.
    let mut pos = vec![(0i64, 0i64); n * n];
    let mut visited = vec![false; n * n];
    // A patch whose unwrapped extent reaches the cell's side wraps around
    // it (it percolates): its asperity is the cell itself.
    let mut spans = vec![false; k];
    let mut queue = VecDeque::new();
    for start in 0..n * n {
        let id = patches.label[start];
        if id == u32::MAX || origin[id as usize] != usize::MAX {
            continue;
        }
        origin[id as usize] = start;
        pos[start] = ((start % n) as i64, (start / n) as i64);
        let mut seen = vec![start];
        queue.push_back(start);
        visited[start] = true;
        let (mut lo, mut hi) = (pos[start], pos[start]);
        while let Some(i) = queue.pop_front() {
            let (px, py) = pos[i];
            let (x, y) = (i % n, i / n);
            for (j, dx_, dy_) in [
                (y * n + (x + 1) % n, 1, 0),
                (y * n + (x + n - 1) % n, -1, 0),
                (((y + 1) % n) * n + x, 0, 1),
                (((y + n - 1) % n) * n + x, 0, -1),
            ] {
                if patches.label[j] == id && !visited[j] {
                    visited[j] = true;
                    pos[j] = (px + dx_, py + dy_);
                    lo = (lo.0.min(pos[j].0), lo.1.min(pos[j].1));
                    hi = (hi.0.max(pos[j].0), hi.1.max(pos[j].1));
                    seen.push(j);
                    queue.push_back(j);
                }
            }
        }
        spans[id as usize] = hi.0 - lo.0 >= n as i64 - 1 || hi.1 - lo.1 >= n as i64 - 1;
        let (ox, oy) = pos[start];
        let p = id as usize;
        for &i in &seen {
            let (x, y) = ((pos[i].0 - ox) as f64 * dx, (pos[i].1 - oy) as f64 * dx);
            let row = [1.0, x, y, x * x, x * y, y * y];
            let mut t = 0;
            for a in 0..6 {
                for b in a..6 {
                    ata[p][t] += row[a] * row[b];
                    t += 1;
                }
                atb[p][a] += row[a] * h[i];
            }
            if h[i] > top[p].0 {
                top[p] = (h[i], i);
            }
        }
    }
    let curvature = mean_curvature(h, n, length);
    (0..k)
        .map(|p| {
            if spans[p] {
                return f64::INFINITY;
            }
            let kappa = if patches.size[p] >= MIN_FIT {
                fit_curvature(&ata[p], &atb[p]).unwrap_or(curvature[top[p].1])
            } else {
                curvature[top[p].1]
            };
            if kappa > 0.0 {
                1.0 / kappa
            } else {
                f64::INFINITY
            }
        })
        .collect()
}

/// −(c3 + c5) of the least-squares paraboloid from its normal equations
/// (upper triangle, row by row), by Gaussian elimination with pivoting;
/// `None` if they are singular (a patch on one row of nodes).
#[allow(clippy::needless_range_loop)] // a matrix's rows and columns
fn fit_curvature(ata: &[f64; 21], atb: &[f64; 6]) -> Option<f64> {
    let mut a = [[0.0f64; 7]; 6];
    let mut t = 0;
    for r in 0..6 {
        for c in r..6 {
            a[r][c] = ata[t];
            a[c][r] = ata[t];
            t += 1;
        }
        a[r][6] = atb[r];
    }
    // Scale columns so that the x², xy, y² terms are comparable with 1.
    let scale: Vec<f64> = (0..6)
        .map(|c| a[c][c].sqrt().max(f64::MIN_POSITIVE))
        .collect();
    for r in 0..6 {
        for c in 0..6 {
            a[r][c] /= scale[r] * scale[c];
        }
        a[r][6] /= scale[r];
    }
    for col in 0..6 {
        let piv = (col..6).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[piv][col].abs() < 1e-12 {
            return None;
        }
        a.swap(col, piv);
        for r in 0..6 {
            if r != col {
                let f = a[r][col] / a[col][col];
                for c in col..7 {
                    a[r][c] -= f * a[col][c];
                }
            }
        }
    }
    let coef = |i: usize| a[i][6] / a[i][i] / scale[i];
    Some(-(coef(3) + coef(5)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patches_join_across_the_edge_and_count_their_nodes() {
        let n = 8;
        let mut p = vec![0.0; n * n];
        // One patch across the left/right edge (x = 7, 0, 1 on row 3) and
        // one single node.
        for x in [7, 0, 1] {
            p[3 * n + x] = 1.0;
        }
        p[6 * n + 4] = 1.0;
        let pt = Patches::of(&p, n);
        assert_eq!(pt.count(), 2);
        let mut sizes = pt.size.clone();
        sizes.sort();
        assert_eq!(sizes, [1, 3]);
        assert_eq!(pt.label[3 * n + 7], pt.label[3 * n + 1]);
        let near = pt.nearest(n);
        assert!(near.iter().all(|&l| l != u32::MAX));
        assert_eq!(near[5 * n + 4], pt.label[6 * n + 4]);
        assert_eq!(near[2 * n], pt.label[3 * n]);
    }

    #[test]
    fn every_node_climbs_to_its_summit() {
        // Two bumps on a 16 × 16 cell: cos(2πx/L)·cos(2πy/L) has its
        // maxima at (0, 0) and (8, 8), its minima at (8, 0) and (0, 8).
        let n = 16;
        let w = std::f64::consts::TAU / n as f64;
        let h: Vec<f64> = (0..n * n)
            .map(|i| ((i % n) as f64 * w).cos() * ((i / n) as f64 * w).cos())
            .collect();
        let top = summits(&h, n);
        assert_eq!(top[0], 0);
        assert_eq!(top[8 * n + 8], (8 * n + 8) as u32);
        assert_eq!(top[n + 1], 0);
        assert_eq!(top[15 * n + 15], 0, "across the corner");
        assert_eq!(top[7 * n + 6], (8 * n + 8) as u32);
        let tops: std::collections::BTreeSet<u32> = top.iter().copied().collect();
        // Saddles and minima climb too; only the two maxima are tops.
        assert!(tops.len() <= 2 + 4, "{tops:?}");
        // The radius at a top: −∇²h/2 = (2π/L)² at a crest of this surface
        // (L = 1).
        let r = summit_radii(&h, n, 1.0);
        let want = 1.0 / std::f64::consts::TAU.powi(2);
        assert!((r[n + 1] / want - 1.0).abs() < 1e-12, "{}", r[n + 1]);
    }

    #[test]
    fn a_paraboloid_patch_gives_its_radius() {
        // h = −(x² + y²)/(2R) around the cell's centre, R = 0.3: a patch of
        // radius 0.1 (the fit) and the curvature of a cosine (spectral).
        let (n, l, r) = (64, 1.0, 0.3);
        let dx = l / n as f64;
        let h: Vec<f64> = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64 * dx - 0.5, (i / n) as f64 * dx - 0.5);
                -(x * x + y * y) / (2.0 * r)
            })
            .collect();
        let p: Vec<f64> = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64 * dx - 0.5, (i / n) as f64 * dx - 0.5);
                if x * x + y * y < 0.01 {
                    1.0
                } else {
                    0.0
                }
            })
            .collect();
        let pt = Patches::of(&p, n);
        assert_eq!(pt.count(), 1);
        let radii = patch_radii(&h, n, l, &pt);
        assert!((radii[0] / r - 1.0).abs() < 1e-9, "{radii:?}");
        // cos(2π x) has −h''/2 = 2π² at its crest.
        let c: Vec<f64> = (0..n * n)
            .map(|i| (std::f64::consts::TAU * (i % n) as f64 * dx).cos())
            .collect();
        let k = mean_curvature(&c, n, l);
        let want = 2.0 * std::f64::consts::PI.powi(2);
        assert!((k[0] / want - 1.0).abs() < 1e-12, "{}", k[0]);
    }
}
