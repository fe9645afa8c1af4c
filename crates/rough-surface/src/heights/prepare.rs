//! A map's heights made ready for its FFT in passes over the grid, on
//! several threads: the mean (periodic) or the least-squares plane removed,
//! then (between the two, the real-space Sq and Sdq are taken) the radial
//! Hann window of SurfaceTopography applied, as
//! [`crate::spectrum::compute`]'s `detrend` and `window_2d` do one step at a time
//! (same formulas; sums in another order, so equal to the rounding).

use std::f64::consts::PI;

use crate::error::Problem;
use crate::heights::detrend::Detrend;

/// The residual rms below which detrended heights count as nothing left
/// (relative to the heights' rms about their mean): rounding leaves ~1e-16.
pub(crate) const FLAT: f64 = 1e-10;

/// Rows per thread's block.
fn per(ny: usize) -> usize {
    ny.div_ceil(crate::threads::count()).max(1)
}

/// Pass one, per block of rows from `j0`: Σh, Σ(i − cx)h, Σ(j − cy)h and
/// whether every height equals `first`.
fn sums(block: &[f64], nx: usize, j0: usize, (cx, cy): (f64, f64), first: f64) -> [f64; 4] {
    let (mut s, mut sx, mut sy, mut same) = (0.0, 0.0, 0.0, true);
    for (k, row) in block.chunks_exact(nx).enumerate() {
        let mut r = 0.0;
        for (i, &v) in row.iter().enumerate() {
            sx += (i as f64 - cx) * v;
            r += v;
            same &= v == first;
        }
        s += r;
        sy += ((j0 + k) as f64 - cy) * r;
    }
    [s, sx, sy, f64::from(u8::from(same))]
}

/// The form `mode` removed in place (nothing, the mean, the least-squares
/// plane or quadratic); refuses flat heights as `detrend` does.
pub(crate) fn detrend(
    h: &mut [f64],
    (nx, ny): (usize, usize),
    mode: Detrend,
) -> Result<(), Problem> {
    let n = (nx * ny) as f64;
    let c = ((nx as f64 - 1.0) / 2.0, (ny as f64 - 1.0) / 2.0);
    let per = per(ny);
    let first = h[0];
    let parts: Vec<[f64; 4]> = std::thread::scope(|s| {
        let handles: Vec<_> = h
            .chunks(per * nx)
            .enumerate()
            .map(|(b, block)| s.spawn(move || sums(block, nx, b * per, c, first)))
            .collect();
        handles
            .into_iter()
            .map(|t| t.join().expect("sums"))
            .collect()
    });
    if parts.iter().all(|p| p[3] == 1.0) {
        return Err(Problem::Flat { plane: false });
    }
    let total = |k: usize| parts.iter().map(|p| p[k]).sum::<f64>();
    let mean = total(0) / n;
    match mode {
        Detrend::None => return Ok(()),
        Detrend::Mean => {
            h.iter_mut().for_each(|v| *v -= mean);
            return Ok(());
        }
        Detrend::Curvature => {
            let var = h.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n;
            crate::heights::detrend::remove_quadratic(h, nx, ny)?;
            let rest = h.iter().map(|v| v * v).sum::<f64>() / n;
            if rest <= FLAT * FLAT * var {
                return Err(Problem::Quadratic);
            }
            return Ok(());
        }
        Detrend::Plane => {}
    }
    let sxx: f64 = (0..nx).map(|i| (i as f64 - c.0).powi(2)).sum::<f64>() * ny as f64;
    let syy: f64 = (0..ny).map(|j| (j as f64 - c.1).powi(2)).sum::<f64>() * nx as f64;
    let b = if sxx > 0.0 { total(1) / sxx } else { 0.0 };
    let cy = if syy > 0.0 { total(2) / syy } else { 0.0 };
    let parts: Vec<[f64; 2]> = std::thread::scope(|s| {
        let handles: Vec<_> = h
            .chunks_mut(per * nx)
            .enumerate()
            .map(|(blk, block)| {
                s.spawn(move || {
                    let (mut var, mut rest) = (0.0, 0.0);
                    for (k, row) in block.chunks_exact_mut(nx).enumerate() {
                        let j = blk * per + k;
                        let base = mean + cy * (j as f64 - c.1);
                        for (i, v) in row.iter_mut().enumerate() {
                            var += (*v - mean) * (*v - mean);
                            *v -= base + b * (i as f64 - c.0);
                            rest += *v * *v;
                        }
                    }
                    [var, rest]
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|t| t.join().expect("plane"))
            .collect()
    });
    let total = |k: usize| parts.iter().map(|p| p[k]).sum::<f64>();
    let (var, rest) = (total(0) / n, total(1) / n);
    if rest <= FLAT * FLAT * var {
        return Err(Problem::Flat { plane: true });
    }
    Ok(())
}

/// SurfaceTopography's radial Hann window applied to detrended heights;
/// returns its normalisation s² = N / Σ w².
pub(crate) fn window(h: &mut [f64], (nx, ny): (usize, usize), (lx, ly): (f64, f64)) -> f64 {
    let n = (nx * ny) as f64;
    let per = per(ny);
    // get_window_2D: r from grid point (nx//2, ny//2) in physical units,
    // w = 0.5 + 0.5 cos(π r / r_max) for r ≤ r_max = min(Lx, Ly)/2, else 0.
    let maxr = lx.min(ly) / 2.0;
    let wy = (ny / 2) as f64;
    // |i − nx/2| takes each value d at most twice: one cosine for both.
    let far = (nx / 2).max(nx - 1 - nx / 2);
    let ax: Vec<f64> = (0..=far)
        .map(|d| (lx * d as f64 / nx as f64).powi(2))
        .collect();
    let parts: Vec<f64> = std::thread::scope(|s| {
        let handles: Vec<_> = h
            .chunks_mut(per * nx)
            .enumerate()
            .map(|(blk, block)| {
                let ax = &ax;
                s.spawn(move || {
                    let mut sw = 0.0;
                    let mut w = vec![0.0; far + 1];
                    for (k, row) in block.chunks_exact_mut(nx).enumerate() {
                        let j = blk * per + k;
                        let ay = (ly * (j as f64 - wy) / ny as f64).powi(2);
                        for (d, wd) in w.iter_mut().enumerate() {
                            let r = (ax[d] + ay).sqrt();
                            *wd = if r > maxr {
                                0.0
                            } else {
                                0.5 + 0.5 * (PI * r / maxr).cos()
                            };
                        }
                        for (i, v) in row.iter_mut().enumerate() {
                            let wi = w[i.abs_diff(nx / 2)];
                            *v *= wi;
                            sw += wi * wi;
                        }
                    }
                    sw
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|t| t.join().expect("window"))
            .collect()
    });
    n / parts.iter().sum::<f64>()
}

/// A map's heights as a contact simulation needs them: undefined points
/// filled, the mean (periodic) or the least-squares plane removed, no
/// window. Row-major, `nx` heights a row along x, `ny` rows; metres.
///
/// Kept only when asked ([`crate::read_heights`]): the map's own vector
/// (periodic maps: the buffer the spectrum was computed from, no copy) or
/// one copy taken before the window (other maps): 8 bytes a point, 128 MiB
/// for a 4096² map.
#[derive(PartialEq)]
pub struct Heights {
    pub nx: usize,
    pub ny: usize,
    pub lx: f64,
    pub ly: f64,
    /// Read with `--periodic`.
    pub periodic: bool,
    pub z: Vec<f64>,
}

/// The dimensions only: a map's heights are too many to print.
impl std::fmt::Debug for Heights {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "Heights({} × {}, {} m × {} m, periodic: {})",
            self.nx, self.ny, self.lx, self.ly, self.periodic
        )
    }
}

std::thread_local! {
    /// Set while [`crate::read_heights`] reads on this thread.
    pub(crate) static KEEP_HEIGHTS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether the read under way keeps a map's heights ([`crate::read_heights`]).
pub(crate) fn keeping_heights() -> bool {
    KEEP_HEIGHTS.with(|k| k.get())
}
