//! From heights to the moment table and the display spectrum, as
//! SurfaceTopography computes them (docs/model.md, "Measured surfaces"):
//!
//! - periodic data: the mean removed, no window; otherwise the
//!   least-squares plane (line: straight line) removed and the Hann window
//!   applied — for maps the radial window of `FFTTricks.get_window_2D`,
//!   for lines scipy's periodic `hann` — scaled so that the mean of its
//!   square is 1;
//! - the FFT F of the (windowed) heights, N = Nx Ny samples. With
//!   SurfaceTopography's PSD C(q) = |Δx Δy F(q)|²/(Lx Ly) and its sums
//!   M_α = (1/(Lx Ly)) Σ_q |q|^α C(q), each wavevector's term is
//!   w = C/(Lx Ly) = |F|² (Δx Δy)²/(Lx Ly)² = |F|²/N², independent of the
//!   sizes (lines: C1D = |Δx F|²/L, w = C1D/L = |F|²/N²);
//! - wavevectors q = 2π k/L as `np.fft.fftfreq` computes them, all of the
//!   FFT grid but q = 0.
//!
//! The input is real, so maps are transformed two rows at a time (one
//! complex FFT of h_r + i h_(r+1)) and only the half spectrum
//! 0 ≤ kx ≤ Nx/2 is kept, its mirrored points counted twice.

use std::f64::consts::PI;
use std::sync::Arc;

use rough_fft::Planner;
use rough_model::{Dim, MomentTable};
use rustfft::num_complex::Complex;
use rustfft::Fft;

use crate::error::Problem;
use crate::heights::detrend::Detrend;
use crate::heights::fill;
use crate::heights::prepare;
use crate::spectrum::anisotropy::Slopes;
use crate::spectrum::bins::Bins;
use crate::spectrum::realspace::{self, RealSpace};

/// What a surface's heights give the model and the screen.
pub(crate) struct Computed {
    pub table: MomentTable,
    pub spectrum: Vec<(f64, f64)>,
    /// What was repaired or noticed on the way ([`crate::Measured::notes`]).
    pub notes: Vec<String>,
    /// A map's rms slopes along x and y ([`crate::Measured::slopes`]).
    pub slopes: Option<Slopes>,
    /// Sq and Sdq (maps), Rq and RΔq (lines); `None` for PSD tables.
    pub real: Option<RealSpace>,
    /// The Fourier modes in each point of `spectrum` (empty for tables).
    pub modes: Vec<f64>,
    /// A map's detrended heights ([`crate::Measured::heights`]).
    pub heights: Option<Arc<prepare::Heights>>,
}

/// Refuses constant heights; returns their mean and variance.
fn moments(h: &[f64]) -> Result<(f64, f64), Problem> {
    if h.iter().all(|&v| v == h[0]) {
        return Err(Problem::Flat { plane: false });
    }
    let n = h.len() as f64;
    let mean = h.iter().sum::<f64>() / n;
    let var = h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n;
    Ok((mean, var))
}

/// Removes the least-squares plane a + b x + c y over the grid (rows of
/// `nx`); on a full grid, centred coordinates decouple the normal
/// equations.
fn remove_plane(h: &mut [f64], nx: usize, ny: usize, mean: f64) {
    let cx = (nx as f64 - 1.0) / 2.0;
    let cy = (ny as f64 - 1.0) / 2.0;
    let sxx: f64 = (0..nx).map(|i| (i as f64 - cx).powi(2)).sum::<f64>() * ny as f64;
    let syy: f64 = (0..ny).map(|j| (j as f64 - cy).powi(2)).sum::<f64>() * nx as f64;
    let (mut sxh, mut syh) = (0.0, 0.0);
    for (j, row) in h.chunks_exact(nx).enumerate() {
        let y = j as f64 - cy;
        let mut r = 0.0;
        for (i, &v) in row.iter().enumerate() {
            sxh += (i as f64 - cx) * v;
            r += v;
        }
        syh += y * r;
    }
    let b = if sxx > 0.0 { sxh / sxx } else { 0.0 };
    let c = if syy > 0.0 { syh / syy } else { 0.0 };
    for (j, row) in h.chunks_exact_mut(nx).enumerate() {
        let base = mean + c * (j as f64 - cy);
        for (i, v) in row.iter_mut().enumerate() {
            *v -= base + b * (i as f64 - cx);
        }
    }
}

/// The form `mode` removed (nothing, the mean, the plane or the
/// quadratic); refuses what is flat after it.
pub(crate) fn detrend(h: &mut [f64], nx: usize, ny: usize, mode: Detrend) -> Result<(), Problem> {
    let (mean, var) = moments(h)?;
    let flat = match mode {
        Detrend::None => return Ok(()),
        Detrend::Mean => {
            h.iter_mut().for_each(|v| *v -= mean);
            return Ok(());
        }
        Detrend::Plane => {
            remove_plane(h, nx, ny, mean);
            Problem::Flat { plane: true }
        }
        Detrend::Curvature => {
            crate::heights::detrend::remove_quadratic(h, nx, ny)?;
            Problem::Quadratic
        }
    };
    let rest = h.iter().map(|v| v * v).sum::<f64>() / h.len() as f64;
    if rest <= crate::heights::prepare::FLAT * crate::heights::prepare::FLAT * var {
        return Err(flat);
    }
    Ok(())
}

/// scipy.signal.get_window('hann', n): the periodic Hann window; returns
/// s² = n / Σ w².
pub(crate) fn window_1d(h: &mut [f64]) -> f64 {
    let n = h.len();
    let mut sum = 0.0;
    for (k, v) in h.iter_mut().enumerate() {
        let w = 0.5 - 0.5 * (2.0 * PI * k as f64 / n as f64).cos();
        *v *= w;
        sum += w * w;
    }
    n as f64 / sum
}

/// |q| of index k on an axis of n samples spanning l, as
/// 2π · np.fft.fftfreq(n, l/n) gives it.
pub(crate) fn freq(k: usize, n: usize, l: f64) -> f64 {
    let val = 1.0 / (n as f64 * (l / n as f64));
    let k = k.min(n - k);
    2.0 * PI * (k as f64 * val)
}

/// The row FFTs of real rows (nx each, ny rows), two at a time, as the
/// half spectrum kx = 0..=nx/2, row after row (ny × nh).
fn rows_half(h: &[f64], nx: usize, ny: usize, fft: &Arc<dyn Fft<f64>>) -> Vec<Complex<f64>> {
    let nh = nx / 2 + 1;
    let mut out = vec![Complex::new(0.0, 0.0); ny * nh];
    let pairs = ny.div_ceil(2);
    let per = pairs.div_ceil(crate::threads::count()).max(1);
    std::thread::scope(|s| {
        for (t, block) in out.chunks_mut(2 * per * nh).enumerate() {
            let fft = Arc::clone(fft);
            s.spawn(move || {
                let mut buf = vec![Complex::new(0.0, 0.0); nx];
                let mut scratch = vec![Complex::new(0.0, 0.0); fft.get_inplace_scratch_len()];
                let r0 = 2 * per * t;
                for (p, pair) in block.chunks_mut(2 * nh).enumerate() {
                    let r = r0 + 2 * p;
                    let a = &h[r * nx..(r + 1) * nx];
                    let b = (r + 1 < ny).then(|| &h[(r + 1) * nx..(r + 2) * nx]);
                    for (i, z) in buf.iter_mut().enumerate() {
                        *z = Complex::new(a[i], b.map_or(0.0, |b| b[i]));
                    }
                    fft.process_with_scratch(&mut buf, &mut scratch);
                    let (ra, rb) = pair.split_at_mut(nh.min(pair.len()));
                    for k in 0..nh {
                        let z = buf[k];
                        let zc = buf[(nx - k) % nx].conj();
                        ra[k] = (z + zc) * 0.5;
                        if !rb.is_empty() {
                            // (z − zc)/(2i)
                            let d = (z - zc) * 0.5;
                            rb[k] = Complex::new(d.im, -d.re);
                        }
                    }
                }
            });
        }
    });
    out
}

/// A map of nx × ny heights (rows of nx along x, one row per y) spanning
/// lx × ly metres, `mode` removed; undefined points (NaN) are filled first.
pub(crate) fn map(
    mut h: Vec<f64>,
    (nx, ny): (usize, usize),
    (lx, ly): (f64, f64),
    periodic: bool,
    mode: Detrend,
) -> Result<Computed, Problem> {
    let notes: Vec<String> = fill::fill(&mut h, nx, ny, periodic)?.into_iter().collect();
    prepare::detrend(&mut h, (nx, ny), mode)?;
    let real = realspace::areal(&h, nx, ny, lx, ly, periodic);
    let keep = |z: Vec<f64>| {
        let (nx, ny, lx, ly, periodic) = (nx, ny, lx, ly, periodic);
        Arc::new(prepare::Heights {
            nx,
            ny,
            lx,
            ly,
            periodic,
            z,
        })
    };
    // Only when asked ([`crate::read_heights`]): a 4096² map's heights are
    // 128 MiB, which the explorer does not hold unless the contact
    // simulation wants them. Periodic maps are not windowed: their buffer
    // is kept after the FFT; other maps' are copied before the window.
    let wanted = crate::heights::prepare::keeping_heights();
    let copy = (wanted && !periodic).then(|| keep(h.clone()));
    let s2 = if periodic {
        1.0
    } else {
        prepare::window(&mut h, (nx, ny), (lx, ly))
    };
    let mut planner = Planner::new();
    let nh = nx / 2 + 1;
    let half = rows_half(&h, nx, ny, &planner.forward(nx));
    let heights = if wanted {
        Some(copy.unwrap_or_else(|| keep(h)))
    } else {
        drop(h);
        None
    };
    let fft_y = planner.forward(ny);

    let n2 = ((nx * ny) as f64).powi(2);
    let scale = s2 / n2;
    let area = lx * ly;
    // power_spectrum_from_area's radial average: radii as resample_radial
    // computes them, from min(2π/Lx, 2π/Ly) to π min(Nx/Lx, Ny/Ly).
    let (gx, gy) = (
        2.0 * PI * nx as f64 / lx / nx as f64,
        2.0 * PI * ny as f64 / ly / ny as f64,
    );
    let qmax = PI * (nx as f64 / lx).min(ny as f64 / ly);
    wavevectors(gx.min(gy), qmax, &format!("{lx:e} m × {ly:e} m"))?;
    // ky and ny − ky lie at the same |q|: one term for both. Blocks of kx
    // on several threads, each with its own bins and slope sums.
    let qy: Vec<f64> = (0..=ny / 2).map(|j| freq(j, ny, ly)).collect();
    let ry: Vec<f64> = (0..=ny / 2).map(|j| gy * j as f64).collect();
    let my = ny / 2 + 1;
    // Every (kx, ky) of the half grid; (0, 0), the mean, is dropped below.
    let mut terms = vec![(0.0, 0.0); nh * my];
    let per = nh.div_ceil(crate::threads::count()).max(1);
    // The column FFTs a few columns at a time, gathered from the row-major
    // half spectrum (no transposed copy), each column's terms made at once.
    const COLS: usize = 8;
    let parts: Vec<(Bins, f64, f64)> = std::thread::scope(|s| {
        let handles: Vec<_> = terms
            .chunks_mut(per * my)
            .enumerate()
            .map(|(b, out)| {
                let (qy, ry, half) = (&qy, &ry, &half);
                let fft = Arc::clone(&fft_y);
                s.spawn(move || {
                    let mut bins = Bins::new(gx.min(gy), qmax);
                    let (mut m2x, mut m2y) = (0.0, 0.0);
                    let mut buf = vec![Complex::new(0.0, 0.0); COLS * ny];
                    let mut scratch = vec![Complex::new(0.0, 0.0); fft.get_inplace_scratch_len()];
                    let k0 = b * per;
                    for (c, out) in out.chunks_mut(my).enumerate() {
                        let kx = k0 + c;
                        let slot = c % COLS;
                        if slot == 0 {
                            let n = COLS.min(nh - kx);
                            for (j, row) in half.chunks_exact(nh).enumerate() {
                                for (m, z) in row[kx..kx + n].iter().enumerate() {
                                    buf[m * ny + j] = *z;
                                }
                            }
                            fft.process_with_scratch(&mut buf[..n * ny], &mut scratch);
                        }
                        let col = &buf[slot * ny..(slot + 1) * ny];
                        let mult = if kx == 0 || 2 * kx == nx { 1.0 } else { 2.0 };
                        let qx = freq(kx, nx, lx);
                        let rx = gx * kx as f64;
                        for (ky, term) in out.iter_mut().enumerate() {
                            if kx == 0 && ky == 0 {
                                continue;
                            }
                            let (w, count) = if ky == 0 || 2 * ky == ny {
                                (col[ky].norm_sqr() * scale, 1.0)
                            } else {
                                ((col[ky].norm_sqr() + col[ny - ky].norm_sqr()) * scale, 2.0)
                            };
                            *term = ((qx * qx + qy[ky] * qy[ky]).sqrt(), mult * w);
                            m2x += mult * w * qx * qx;
                            m2y += mult * w * qy[ky] * qy[ky];
                            bins.add(
                                (rx * rx + ry[ky] * ry[ky]).sqrt(),
                                w * area / count,
                                mult * count,
                            );
                        }
                    }
                    // Sorted here, on this thread: the table's own sort
                    // then finds the merged terms in order.
                    out.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
                    (bins, m2x, m2y)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("terms"))
            .collect()
    });
    drop(half);
    let merged = merge_sorted(&terms, per * my);
    drop(terms);
    let (mut bins, mut m2x, mut m2y) = (Bins::new(gx.min(gy), qmax), 0.0, 0.0);
    for (b, x, y) in &parts {
        bins.merge(b);
        m2x += x;
        m2y += y;
    }
    let q0 = 2.0 * PI / lx.max(ly);
    let table = MomentTable::from_discrete(Dim::Areal, q0, merged).map_err(Problem::Table)?;
    let slopes = Slopes {
        x: m2x.sqrt(),
        y: m2y.sqrt(),
    };
    let mut notes = notes;
    notes.extend(slopes.note());
    Ok(Computed {
        table,
        spectrum: bins.finish(),
        notes,
        slopes: Some(slopes),
        real: Some(real),
        modes: bins.counts(),
        heights,
    })
}

/// The terms of `all`, sorted by q in blocks of `block`, merged in order;
/// the mean's place (q = 0) left out.
fn merge_sorted(all: &[(f64, f64)], block: usize) -> Vec<(f64, f64)> {
    let mut heads: Vec<&[(f64, f64)]> = all.chunks(block).collect();
    let mut out = Vec::with_capacity(all.len());
    loop {
        let mut best: Option<usize> = None;
        for (k, h) in heads.iter().enumerate() {
            if let Some(&(q, _)) = h.first() {
                if best.is_none_or(|b| q < heads[b][0].0) {
                    best = Some(k);
                }
            }
        }
        let Some(b) = best else { break };
        let (first, rest) = heads[b].split_first().expect("a head");
        if first.0 > 0.0 {
            out.push(*first);
        }
        heads[b] = rest;
    }
    out
}

/// Refuses sizes that give no finite wavevector range from `lo` to `hi`
/// (a file whose header claims a zero, infinite or vanishing size).
pub(crate) fn wavevectors(lo: f64, hi: f64, size: &str) -> Result<(), Problem> {
    if lo.is_finite() && hi.is_finite() && lo > 0.0 && hi >= lo {
        Ok(())
    } else {
        Err(Problem::BadHeader(format!(
            "the size {size} gives no finite range of wavevectors (from {lo:e} to {hi:e} 1/m): \
             the file's lateral size or pixel size cannot be right"
        )))
    }
}

/// A line of n heights spanning l metres, `mode` removed; undefined
/// points (NaN) are filled first.
pub(crate) fn line(
    mut h: Vec<f64>,
    l: f64,
    periodic: bool,
    mode: Detrend,
) -> Result<Computed, Problem> {
    let n = h.len();
    let notes: Vec<String> = fill::fill(&mut h, n, 1, periodic)?.into_iter().collect();
    detrend(&mut h, n, 1, mode)?;
    let real = realspace::profile(&h, l, periodic);
    let s2 = if periodic { 1.0 } else { window_1d(&mut h) };
    let mut buf: Vec<Complex<f64>> = h.iter().map(|&v| Complex::new(v, 0.0)).collect();
    drop(h);
    Planner::new().forward(n).process(&mut buf);
    let scale = s2 / (n as f64).powi(2);
    // power_spectrum_from_profile: q = dq·k for 1 ≤ k < n//2, C1D = |Δx F|²/L,
    // binned from dq to π n/L.
    let dq = 2.0 * PI / l;
    wavevectors(dq, PI * n as f64 / l, &format!("{l:e} m"))?;
    let mut bins = Bins::new(dq, PI * n as f64 / l);
    let mut terms = Vec::with_capacity(n - 1);
    for (k, f) in buf.iter().enumerate().skip(1) {
        let w = f.norm_sqr() * scale;
        terms.push((freq(k, n, l), w));
        if k < n / 2 {
            bins.add(dq * k as f64, w * l, 1.0);
        }
    }
    let table =
        MomentTable::from_discrete(Dim::Profile, 2.0 * PI / l, terms).map_err(Problem::Table)?;
    Ok(Computed {
        table,
        spectrum: bins.finish(),
        notes,
        slopes: None,
        real: Some(real),
        modes: bins.counts(),
        heights: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A single cosine: its moments are known in closed form.
    #[test]
    fn periodic_cosine_moments() {
        let (nx, ny, lx, ly) = (16, 8, 2.0, 1.0);
        let (a, kx, ky) = (0.3, 3.0, 2.0);
        let (qx, qy) = (2.0 * PI * kx / lx, 2.0 * PI * ky / ly);
        let mut h = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = (lx * i as f64 / nx as f64, ly * j as f64 / ny as f64);
                h.push(1.0 + a * (qx * x + qy * y).cos());
            }
        }
        let c = map(h, (nx, ny), (lx, ly), true, Detrend::Mean).unwrap();
        let q2 = qx * qx + qy * qy;
        let s = c.table.sums(1e9);
        let rel = |x: f64, y: f64| ((x - y) / y).abs();
        assert!(rel(s[0], a * a / 2.0) < 1e-14, "{s:?}");
        assert!(rel(s[1], a * a / 2.0 * q2) < 1e-14);
        assert!(rel(s[2], a * a / 2.0 * q2 * q2) < 1e-14);
        assert_eq!(c.table.q0(), PI);
        // Below the cosine's wavevector only rounding is left.
        assert!(c.table.sums(0.99 * q2.sqrt())[0] < 1e-30);
    }

    #[test]
    fn odd_sizes_and_lines() {
        // Parseval on an odd grid and a line: M0 is the mean square.
        let (nx, ny) = (7, 5);
        let h: Vec<f64> = (0..nx * ny).map(|i| ((i * 37 % 11) as f64).sin()).collect();
        let mean = h.iter().sum::<f64>() / h.len() as f64;
        let ms = h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / h.len() as f64;
        let c = map(h.clone(), (nx, ny), (1.0, 1.0), true, Detrend::Mean).unwrap();
        assert!((c.table.sums(1e9)[0] / ms - 1.0).abs() < 1e-14);
        let c = line(h, 3.0, true, Detrend::Mean).unwrap();
        assert!((c.table.sums(1e9)[0] / ms - 1.0).abs() < 1e-14);
    }

    #[test]
    fn flat_surfaces_are_refused() {
        assert_eq!(
            map(vec![2.0; 16], (4, 4), (1.0, 1.0), false, Detrend::Plane).err(),
            Some(Problem::Flat { plane: false })
        );
        let plane: Vec<f64> = (0..20)
            .map(|i| 1.0 + 0.5 * (i % 5) as f64 - 0.25 * (i / 5) as f64)
            .collect();
        assert_eq!(
            map(plane, (5, 4), (1.0, 1.0), false, Detrend::Plane).err(),
            Some(Problem::Flat { plane: true })
        );
    }
}
