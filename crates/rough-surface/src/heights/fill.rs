//! Undefined points of a map or a line (NaN: a `nan` or an empty cell in
//! a text file, a masked or invalid point of an instrument's file), filled
//! as SurfaceTopography's `interpolate_undefined_data` (method
//! `'harmonic'`) fills them: the undefined heights solve the discrete
//! Laplace equation Σ_{n ∈ N(p)} (h_n − h_p) = 0 at every undefined point
//! p, N(p) its nearest neighbours (four on a map, two on a line), the
//! defined points entering as fixed values. On non-periodic data a
//! neighbour outside the grid is dropped from the stencil (no flux across
//! the edge); on periodic data the grid wraps.
//!
//! SurfaceTopography solves the sparse system with a direct solver; here
//! the same symmetric positive definite system is solved by conjugate
//! gradients with a Jacobi preconditioner to a residual at the rounding
//! of the heights (the two agree to ~1e-14 of the heights' range). Every
//! component of undefined points touches a defined one as long as any
//! point is defined, so the system is never singular below the share
//! refused.

use crate::error::{percent, share, Problem};

/// The largest share of undefined points filled; above it the file is
/// refused ([`Problem::Undefined`]).
pub const MAX_UNDEFINED: f64 = 0.10;

/// Relative residual at which the iteration stops.
const TOL: f64 = 1e-15;

/// "312 undefined points (0.4 %) filled": the share with two significant
/// digits, never rounded to 0 or to 100.
pub(crate) fn note(count: usize, total: usize) -> String {
    format!(
        "{count} undefined point{} ({}) filled",
        if count == 1 { "" } else { "s" },
        share(count, total)
    )
}

/// Fills the NaN heights of an nx × ny grid (rows of nx; a line is
/// ny = 1). Returns the note to show, or `None` when every point was
/// defined; refuses a grid with more than [`MAX_UNDEFINED`] undefined
/// (or the share `--max-undefined` allows, which the note then names).
pub(crate) fn fill(
    h: &mut [f64],
    nx: usize,
    ny: usize,
    periodic: bool,
) -> Result<Option<String>, Problem> {
    debug_assert_eq!(h.len(), nx * ny);
    let count = h.iter().filter(|v| v.is_nan()).count();
    if count == 0 {
        return Ok(None);
    }
    let total = h.len();
    let allowed = crate::heights::allow::max_undefined();
    let limit = allowed.unwrap_or(MAX_UNDEFINED);
    if count as f64 > limit * total as f64 || count == total {
        return Err(Problem::Undefined {
            count,
            total,
            allowed: limit,
        });
    }
    solve(h, nx, ny, periodic);
    let mut note = note(count, total);
    // Said where the default would have refused.
    if let Some(a) = allowed.filter(|_| count as f64 > MAX_UNDEFINED * total as f64) {
        note.push_str(&format!(" (--max-undefined {})", percent(a)));
    }
    Ok(Some(note))
}

/// The neighbours of grid point (i, j) inside the stencil.
fn neighbours(i: usize, j: usize, nx: usize, ny: usize, periodic: bool) -> [Option<usize>; 4] {
    let at = |i: usize, j: usize| Some(j * nx + i);
    let step = |k: usize, n: usize, up: bool| -> Option<usize> {
        match (up, periodic) {
            _ if n == 1 => None,
            (true, _) if k + 1 < n => Some(k + 1),
            (true, true) => Some(0),
            (false, _) if k > 0 => Some(k - 1),
            (false, true) => Some(n - 1),
            _ => None,
        }
    };
    [
        step(i, nx, true).and_then(|i| at(i, j)),
        step(i, nx, false).and_then(|i| at(i, j)),
        step(j, ny, true).and_then(|j| at(i, j)),
        step(j, ny, false).and_then(|j| at(i, j)),
    ]
}

fn solve(h: &mut [f64], nx: usize, ny: usize, periodic: bool) {
    // Heights about the mean of the defined ones, for the rounding.
    let defined = h.iter().filter(|v| !v.is_nan());
    let n_def = (h.len() - h.iter().filter(|v| v.is_nan()).count()) as f64;
    let mean = defined.sum::<f64>() / n_def;
    // Each unknown's index, its grid points' unknown neighbours and the
    // right-hand side: A x = b with A = diag(legs) − adjacency.
    let unknowns: Vec<usize> = (0..h.len()).filter(|&k| h[k].is_nan()).collect();
    let mut index = vec![u32::MAX; 0];
    let use_map = unknowns.len() > 64;
    if use_map {
        index = vec![u32::MAX; h.len()];
        for (u, &k) in unknowns.iter().enumerate() {
            index[k] = u as u32;
        }
    }
    let find = |k: usize| -> Option<usize> {
        if use_map {
            let u = index[k];
            (u != u32::MAX).then_some(u as usize)
        } else {
            unknowns.iter().position(|&x| x == k)
        }
    };
    let m = unknowns.len();
    let mut diag = vec![0.0; m];
    let mut b = vec![0.0; m];
    // Up to four unknown neighbours per unknown (u32::MAX: none).
    let mut adj = vec![[u32::MAX; 4]; m];
    for (u, &k) in unknowns.iter().enumerate() {
        let (i, j) = (k % nx, k / nx);
        let mut a = 0;
        for n in neighbours(i, j, nx, ny, periodic).into_iter().flatten() {
            diag[u] += 1.0;
            if h[n].is_nan() {
                adj[u][a] = find(n).expect("an undefined neighbour is an unknown") as u32;
                a += 1;
            } else {
                b[u] += h[n] - mean;
            }
        }
    }
    let x = cg(&diag, &adj, &b);
    for (u, &k) in unknowns.iter().enumerate() {
        h[k] = x[u] + mean;
    }
}

/// y = A x.
fn apply(diag: &[f64], adj: &[[u32; 4]], x: &[f64], y: &mut [f64]) {
    for (u, (yu, a)) in y.iter_mut().zip(adj).enumerate() {
        let mut s = diag[u] * x[u];
        for &n in a.iter().take_while(|&&n| n != u32::MAX) {
            s -= x[n as usize];
        }
        *yu = s;
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Preconditioned conjugate gradients from the mean of the defined
/// neighbours.
fn cg(diag: &[f64], adj: &[[u32; 4]], b: &[f64]) -> Vec<f64> {
    let m = b.len();
    let mut x: Vec<f64> = b.iter().zip(diag).map(|(b, d)| b / d).collect();
    let mut ax = vec![0.0; m];
    apply(diag, adj, &x, &mut ax);
    let mut r: Vec<f64> = b.iter().zip(&ax).map(|(b, a)| b - a).collect();
    let bnorm = dot(b, b).sqrt().max(f64::MIN_POSITIVE);
    let mut z: Vec<f64> = r.iter().zip(diag).map(|(r, d)| r / d).collect();
    let mut p = z.clone();
    let mut rz = dot(&r, &z);
    let mut ap = vec![0.0; m];
    // CG converges in at most m steps in exact arithmetic; a few times
    // that bounds it with rounding.
    let mut best = (dot(&r, &r).sqrt(), x.clone());
    for _ in 0..(4 * m + 100) {
        let rn = dot(&r, &r).sqrt();
        if rn < best.0 {
            best = (rn, x.clone());
        }
        if rn <= TOL * bnorm || rz == 0.0 {
            return x;
        }
        apply(diag, adj, &p, &mut ap);
        let pap = dot(&p, &ap);
        if pap <= 0.0 {
            break;
        }
        let alpha = rz / pap;
        for k in 0..m {
            x[k] += alpha * p[k];
            r[k] -= alpha * ap[k];
        }
        for k in 0..m {
            z[k] = r[k] / diag[k];
        }
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for k in 0..m {
            p[k] = z[k] + beta * p[k];
        }
    }
    // Stalled at the rounding: the best iterate.
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_for_people() {
        assert_eq!(note(312, 78_000), "312 undefined points (0.4 %) filled");
        assert_eq!(note(1, 1_000_000), "1 undefined point (< 0.01 %) filled");
        assert_eq!(share(25, 1000), "2.5 %");
        assert_eq!(share(45, 1000), "4.5 %");
        assert_eq!(share(123, 100_000), "0.12 %");
        assert_eq!(share(100, 1000), "10 %");
        assert_eq!(share(125, 1000), "12.5 %");
    }

    #[test]
    fn a_line_fills_linearly() {
        // Harmonic on a line: straight between defined neighbours, flat
        // beyond the last one (no flux across the end).
        let mut h: Vec<f64> = (0..40).map(|k| k as f64).collect();
        h[1] = f64::NAN;
        h[2] = f64::NAN;
        h[39] = f64::NAN;
        let note = fill(&mut h, 40, 1, false).unwrap().unwrap();
        assert_eq!(note, "3 undefined points (7.5 %) filled");
        for (k, got) in h.iter().enumerate() {
            let want = k.min(38) as f64;
            assert!((got - want).abs() < 1e-13, "{h:?}");
        }
    }

    #[test]
    fn a_map_point_is_its_neighbours_mean() {
        let mut h: Vec<f64> = (0..64).map(|k| (k * k % 17) as f64).collect();
        h[27] = f64::NAN;
        fill(&mut h, 8, 8, false).unwrap();
        let want = (h[26] + h[28] + h[19] + h[35]) / 4.0;
        assert!((h[27] - want).abs() < 1e-14);
        // Periodic: the corner's neighbours wrap.
        let mut h: Vec<f64> = (0..64).map(|k| (k * k % 17) as f64).collect();
        h[0] = f64::NAN;
        fill(&mut h, 8, 8, true).unwrap();
        let want = (h[1] + h[7] + h[8] + h[56]) / 4.0;
        assert!((h[0] - want).abs() < 1e-14);
    }

    #[test]
    fn too_many_are_refused() {
        let mut h = vec![1.0; 100];
        h.iter_mut().take(11).for_each(|v| *v = f64::NAN);
        assert_eq!(
            fill(&mut h, 10, 10, false),
            Err(Problem::Undefined {
                count: 11,
                total: 100,
                allowed: MAX_UNDEFINED
            })
        );
        // --max-undefined 12 % fills them and says so.
        let note = crate::heights::allow::with(Some(0.12), || fill(&mut h, 10, 10, false));
        assert_eq!(
            note,
            Ok(Some(
                "11 undefined points (11 %) filled (--max-undefined 12 %)".into()
            ))
        );
        assert_eq!(percent(0.355), "35.5 %");
    }
}
