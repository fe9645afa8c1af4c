//! Form removal before the spectrum and the real-space numbers, as
//! SurfaceTopography's `detrend` modes do it (`Uniform/Detrending.py`):
//!
//! - `none`: the heights as read;
//! - `mean` (its `center`): the mean subtracted;
//! - `plane` (its `height`, the default of both): the least-squares plane
//!   a + b ξ + c η, or line a + b ξ along a line scan;
//! - `curvature` (its `curvature`): the least-squares quadratic
//!   a0 + a1 ξ + a2 η + a3 ξ² + a4 η² + a5 ξη, or a0 + a1 ξ + a2 ξ² along a
//!   line scan,
//!
//! in the normalised coordinates ξ = i/Nx, η = j/Ny. A periodic surface
//! takes `mean` by default and refuses a tilt or a curvature (it would no
//! longer be periodic). Least squares over the full grid (undefined points
//! are filled before): the normal equations in centred coordinates, whose
//! sums factor into sums along each axis.

use crate::error::Problem;

/// What is removed from the heights before anything is computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Detrend {
    None,
    Mean,
    #[default]
    Plane,
    Curvature,
}

impl Detrend {
    /// The name `--detrend` takes and snapshots record.
    pub fn name(self) -> &'static str {
        match self {
            Detrend::None => "none",
            Detrend::Mean => "mean",
            Detrend::Plane => "plane",
            Detrend::Curvature => "curvature",
        }
    }

    /// The mode named `s` ([`Detrend::name`]).
    pub fn parse(s: &str) -> Option<Detrend> {
        [
            Detrend::None,
            Detrend::Mean,
            Detrend::Plane,
            Detrend::Curvature,
        ]
        .into_iter()
        .find(|d| d.name() == s)
    }

    /// What was removed, for people: "plane removed", "line removed" (a
    /// line scan's plane), "nothing removed".
    pub fn words(self, line: bool) -> &'static str {
        match (self, line) {
            (Detrend::None, _) => "nothing removed",
            (Detrend::Mean, _) => "mean removed",
            (Detrend::Plane, false) => "plane removed",
            (Detrend::Plane, true) => "line removed",
            (Detrend::Curvature, false) => "quadratic removed",
            (Detrend::Curvature, true) => "parabola removed",
        }
    }
}

/// Centred powers: for each of the n points k/n − mean, its powers 1 … 4
/// summed, and the points themselves.
struct Axis {
    u: Vec<f64>,
    /// Σ u^p, p = 0 … 4.
    s: [f64; 5],
}

impl Axis {
    fn new(n: usize) -> Axis {
        let c = (n as f64 - 1.0) / 2.0;
        let u: Vec<f64> = (0..n).map(|k| (k as f64 - c) / n as f64).collect();
        let mut s = [0.0; 5];
        for &v in &u {
            let mut p = 1.0;
            for sp in &mut s {
                *sp += p;
                p *= v;
            }
        }
        Axis { u, s }
    }
}

/// Solves the symmetric positive definite system `a x = b` (n × n, row
/// major) by Gaussian elimination with partial pivoting; `None` if it is
/// singular.
fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    for k in 0..N {
        let p = (k..N).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[p][k] == 0.0 {
            return None;
        }
        a.swap(k, p);
        b.swap(k, p);
        let (pivot, rows) = a.split_at_mut(k + 1);
        let (pivot, bk) = (pivot[k], b[k]);
        for (row, bi) in rows.iter_mut().zip(&mut b[k + 1..]) {
            let f = row[k] / pivot[k];
            for (x, p) in row[k..].iter_mut().zip(&pivot[k..]) {
                *x -= f * p;
            }
            *bi -= f * bk;
        }
    }
    let mut x = [0.0; N];
    for k in (0..N).rev() {
        let s: f64 = (k + 1..N).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    Some(x)
}

/// Removes the least-squares quadratic from nx × ny heights (rows of nx;
/// a line when ny = 1, then a parabola in x).
pub(crate) fn remove_quadratic(h: &mut [f64], nx: usize, ny: usize) -> Result<(), Problem> {
    let (ax, ay) = (Axis::new(nx), Axis::new(ny));
    if ny == 1 {
        // Basis 1, u, u².
        let s = &ax.s;
        let a = [[s[0], s[1], s[2]], [s[1], s[2], s[3]], [s[2], s[3], s[4]]];
        let mut b = [0.0; 3];
        for (v, &u) in h.iter().zip(&ax.u) {
            b[0] += v;
            b[1] += v * u;
            b[2] += v * u * u;
        }
        let c = solve(a, b).ok_or(Problem::Quadratic)?;
        for (v, &u) in h.iter_mut().zip(&ax.u) {
            *v -= c[0] + c[1] * u + c[2] * u * u;
        }
        return Ok(());
    }
    // Basis 1, u, v, u², v², uv: Σ over the grid of a product of powers
    // is the product of the sums along each axis.
    let pw: [(usize, usize); 6] = [(0, 0), (1, 0), (0, 1), (2, 0), (0, 2), (1, 1)];
    let mut a = [[0.0; 6]; 6];
    for (r, &(p, q)) in pw.iter().enumerate() {
        for (c, &(s, t)) in pw.iter().enumerate() {
            a[r][c] = ax.s[p + s] * ay.s[q + t];
        }
    }
    let mut b = [0.0; 6];
    for (j, row) in h.chunks_exact(nx).enumerate() {
        let v = ay.u[j];
        // Σ_i h u^p along the row, p = 0 … 2.
        let mut r = [0.0; 3];
        for (x, &u) in row.iter().zip(&ax.u) {
            r[0] += x;
            r[1] += x * u;
            r[2] += x * u * u;
        }
        b[0] += r[0];
        b[1] += r[1];
        b[2] += r[0] * v;
        b[3] += r[2];
        b[4] += r[0] * v * v;
        b[5] += r[1] * v;
    }
    let c = solve(a, b).ok_or(Problem::Quadratic)?;
    for (j, row) in h.chunks_exact_mut(nx).enumerate() {
        let v = ay.u[j];
        let base = c[0] + c[2] * v + c[4] * v * v;
        let (lin, cross) = (c[1], c[5] * v);
        for (x, &u) in row.iter_mut().zip(&ax.u) {
            *x -= base + (lin + cross) * u + c[3] * u * u;
        }
    }
    Ok(())
}

/// Refuses `mode` on periodic data where it would remove a tilt.
pub(crate) fn check_periodic(mode: Detrend, periodic: bool) -> Result<(), Problem> {
    if periodic && matches!(mode, Detrend::Plane | Detrend::Curvature) {
        return Err(Problem::Option(format!(
            "--detrend {} removes a tilt, which would leave a periodic surface no longer \
             periodic: give --detrend mean or none with --periodic, or leave out --periodic",
            mode.name()
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quadratic_is_removed_to_the_rounding() {
        let (nx, ny) = (7, 5);
        let f = |i: usize, j: usize| {
            let (x, y) = (i as f64 / nx as f64, j as f64 / ny as f64);
            3.0 + 2.0 * x - y + 5.0 * x * x + 0.5 * y * y - 4.0 * x * y
        };
        let mut h: Vec<f64> = (0..nx * ny).map(|k| f(k % nx, k / nx)).collect();
        remove_quadratic(&mut h, nx, ny).unwrap();
        assert!(h.iter().all(|v| v.abs() < 1e-13), "{h:?}");
        // A parabola along a line.
        let n = 9;
        let mut h: Vec<f64> = (0..n)
            .map(|i| {
                let x = i as f64 / n as f64;
                1.0 - x + 7.0 * x * x
            })
            .collect();
        remove_quadratic(&mut h, n, 1).unwrap();
        assert!(h.iter().all(|v| v.abs() < 1e-13), "{h:?}");
        assert_eq!(Detrend::parse("curvature"), Some(Detrend::Curvature));
        assert_eq!(Detrend::parse("tilt"), None);
        assert_eq!(Detrend::default(), Detrend::Plane);
    }
}
