//! A map read as its profiles along one direction (`--direction x|y`):
//! SurfaceTopography's `power_spectrum_from_profile` of a topography. The
//! map is detrended as a whole (mean, or the least-squares plane), each
//! profile along the direction windowed with the periodic Hann window of a
//! line scan (none if periodic) and transformed; the profile moments and
//! the display C1D are those of a line scan, averaged over the profiles.
//! Beside them the real-space Rq and RΔq of the profiles, SurfaceTopography's
//! `Rq` and `Rdq` of the topography (each profile about its own mean).

use std::f64::consts::PI;

use rough_fft::Planner;
use rough_model::{Dim, MomentTable};
use rustfft::num_complex::Complex;

use crate::error::Problem;
use crate::heights::detrend::Detrend;
use crate::heights::fill;
use crate::spectrum::bins::Bins;
use crate::spectrum::compute::{detrend, freq, window_1d, Computed};

/// A direction on a map: x along its rows, y across them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    X,
    Y,
}

impl Direction {
    pub fn name(self) -> &'static str {
        match self {
            Direction::X => "x",
            Direction::Y => "y",
        }
    }
}

/// The nx × ny map `h` (rows of nx along x) over lx × ly as its profiles
/// along `direction`; undefined points are filled first, on the map.
pub(crate) fn profiles(
    mut h: Vec<f64>,
    (nx, ny): (usize, usize),
    (lx, ly): (f64, f64),
    (periodic, mode): (bool, Detrend),
    direction: Direction,
) -> Result<Computed, Problem> {
    let notes: Vec<String> = fill::fill(&mut h, nx, ny, periodic)?.into_iter().collect();
    detrend(&mut h, nx, ny, mode)?;
    // Profiles as rows of n samples over l.
    let (h, n, count, l) = match direction {
        Direction::X => (h, nx, ny, lx),
        Direction::Y => {
            let mut t = vec![0.0; h.len()];
            transpose::transpose(&h, &mut t, nx, ny);
            (t, ny, nx, ly)
        }
    };
    let real = crate::spectrum::realspace::profiles(&h, n, l, periodic);
    let fft = Planner::new().forward(n);
    let mut power = vec![0.0; n];
    let mut buf = vec![Complex::new(0.0, 0.0); n];
    let mut row = vec![0.0; n];
    let mut s2 = 1.0;
    for r in h.chunks_exact(n) {
        row.copy_from_slice(r);
        if !periodic {
            s2 = window_1d(&mut row);
        }
        for (z, &v) in buf.iter_mut().zip(&row) {
            *z = Complex::new(v, 0.0);
        }
        fft.process(&mut buf);
        for (p, f) in power.iter_mut().zip(&buf) {
            *p += f.norm_sqr();
        }
    }
    let scale = s2 / (n as f64).powi(2) / count as f64;
    let dq = 2.0 * PI / l;
    crate::spectrum::compute::wavevectors(dq, PI * n as f64 / l, &format!("{l:e} m"))?;
    let mut bins = Bins::new(dq, PI * n as f64 / l);
    let mut terms = Vec::with_capacity(n - 1);
    for (k, p) in power.iter().enumerate().skip(1) {
        let w = p * scale;
        terms.push((freq(k, n, l), w));
        if k < n / 2 {
            bins.add(dq * k as f64, w * l, 1.0);
        }
    }
    let table = MomentTable::from_discrete(Dim::Profile, dq, terms).map_err(Problem::Table)?;
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

    /// A lay: a cosine along x only has no slope along y.
    #[test]
    fn a_lay_has_its_slope_across_it() {
        let (nx, ny, lx, ly) = (32, 16, 2.0, 1.0);
        let k = 2.0 * PI * 3.0 / lx;
        let h: Vec<f64> = (0..nx * ny)
            .map(|i| 0.5 * (k * lx * (i % nx) as f64 / nx as f64).cos())
            .collect();
        let x = profiles(
            h.clone(),
            (nx, ny),
            (lx, ly),
            (true, Detrend::Mean),
            Direction::X,
        )
        .unwrap();
        let s = x.table.sums(1e9);
        assert!((s[0] / 0.125 - 1.0).abs() < 1e-14, "{s:?}");
        assert!((s[1] / (0.125 * k * k) - 1.0).abs() < 1e-14, "{s:?}");
        let y = profiles(h, (nx, ny), (lx, ly), (true, Detrend::Mean), Direction::Y);
        // Every profile along y is flat.
        assert!(y.is_err() || y.unwrap().table.sums(1e9)[1] < 1e-25);
    }
}
