//! The real-space numbers a researcher compares first, as Gwyddion and
//! contact.engineering report them (SurfaceTopography 1.27.1's
//! `Uniform/ScalarParameters.py`), from the heights after the same detrend
//! as the spectrum (mean for periodic data, else the least-squares plane
//! or line) and without a window:
//!
//! - maps: Sq = `rms_height_from_area`, the rms of h about its mean; Sdq =
//!   `rms_gradient`, √⟨(∂h/∂x)² + (∂h/∂y)²⟩ with first-order upwind
//!   differences (h_(i+1) − h_i)/Δ; periodic data wrap around, otherwise both
//!   derivatives are trimmed to the (nx − 1) × (ny − 1) points whose stencils
//!   lie inside the data;
//! - line scans: Rq = `rms_height_from_profile`, Rq about the mean; RΔq =
//!   `rms_slope_from_profile`, the rms of the same difference (n − 1 of them,
//!   or n wrapping around when periodic).

use crate::spectrum::amplitude::Amplitude;

/// Real-space rms height and rms slope (gradient for maps).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RealSpace {
    /// A map's (Sq, Sdq) rather than a line's (Rq, RΔq).
    pub areal: bool,
    /// Sq or Rq, m.
    pub rms_height: f64,
    /// Sdq or RΔq, dimensionless.
    pub rms_slope: f64,
    /// Sa, Ssk, Sku, Sz (Ra, Rsk, Rku, Rz).
    pub amplitude: Amplitude,
}

impl RealSpace {
    /// The names, (height, slope): ("Sq", "Sdq") or ("Rq", "RΔq").
    pub fn names(&self) -> (&'static str, &'static str) {
        if self.areal {
            ("Sq", "Sdq")
        } else {
            ("Rq", "RΔq")
        }
    }

    /// The height parameters' names and values: Sa, Ssk, Sku, Sz (maps)
    /// or Ra, Rsk, Rku, Rz (lines, profiles).
    pub fn heights(&self) -> [(&'static str, f64); 4] {
        let [a, sk, ku, z] = self.amplitude_names();
        let p = self.amplitude;
        [
            (a, p.mean_abs),
            (sk, p.skewness),
            (ku, p.kurtosis),
            (z, p.range),
        ]
    }

    /// The amplitude parameters' names: ["Sa", "Ssk", "Sku", "Sz"] or
    /// ["Ra", "Rsk", "Rku", "Rz"].
    pub fn amplitude_names(&self) -> [&'static str; 4] {
        if self.areal {
            ["Sa", "Ssk", "Sku", "Sz"]
        } else {
            ["Ra", "Rsk", "Rku", "Rz"]
        }
    }
}

fn rms_about_mean(h: &[f64]) -> f64 {
    let n = h.len() as f64;
    let mean = h.iter().sum::<f64>() / n;
    (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt()
}

/// Σ f over blocks of the rows 0..ny, each block on a thread of its own.
fn rows_sum<F>(ny: usize, f: F) -> (f64, f64)
where
    F: Fn(std::ops::Range<usize>) -> (f64, f64) + Sync,
{
    let per = ny.div_ceil(crate::threads::count()).max(1);
    std::thread::scope(|s| {
        let f = &f;
        let parts: Vec<_> = (0..ny)
            .step_by(per)
            .map(|j0| s.spawn(move || f(j0..(j0 + per).min(ny))))
            .collect();
        parts
            .into_iter()
            .map(|p| p.join().expect("real-space sums"))
            .fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
    })
}

/// A map of nx × ny detrended heights (rows of nx along x) over lx × ly.
pub(crate) fn areal(
    h: &[f64],
    nx: usize,
    ny: usize,
    lx: f64,
    ly: f64,
    periodic: bool,
) -> RealSpace {
    let (dx, dy) = (lx / nx as f64, ly / ny as f64);
    let (ix, jy) = if periodic { (nx, ny) } else { (nx - 1, ny - 1) };
    let n = h.len() as f64;
    let (sum, _) = rows_sum(ny, |r| (h[r.start * nx..r.end * nx].iter().sum(), 0.0));
    let mean = sum / n;
    let (squares, gradient) = rows_sum(ny, |r| {
        let squares = h[r.start * nx..r.end * nx]
            .iter()
            .map(|v| (v - mean).powi(2))
            .sum();
        let mut sum = 0.0;
        for j in r.start..r.end.min(jy) {
            let row = &h[j * nx..(j + 1) * nx];
            let next = &h[((j + 1) % ny) * nx..((j + 1) % ny + 1) * nx];
            for i in 0..ix {
                let v = row[i];
                let right = if i + 1 == nx { row[0] } else { row[i + 1] };
                let gx = (right - v) / dx;
                let gy = (next[i] - v) / dy;
                sum += gx * gx + gy * gy;
            }
        }
        (squares, sum)
    });
    RealSpace {
        areal: true,
        rms_height: (squares / n).sqrt(),
        rms_slope: (gradient / (ix * jy) as f64).sqrt(),
        amplitude: crate::spectrum::amplitude::of(h, nx, false),
    }
}

/// A line of n detrended heights over l.
pub(crate) fn profile(h: &[f64], l: f64, periodic: bool) -> RealSpace {
    let n = h.len();
    let dx = l / n as f64;
    let m = if periodic { n } else { n - 1 };
    let sum: f64 = (0..m).map(|i| ((h[(i + 1) % n] - h[i]) / dx).powi(2)).sum();
    RealSpace {
        areal: false,
        rms_height: rms_about_mean(h),
        rms_slope: (sum / m as f64).sqrt(),
        amplitude: crate::spectrum::amplitude::of(h, n, false),
    }
}

/// A map's profiles, rows of `n` samples over `l` (the map detrended as a
/// whole), as SurfaceTopography's `Rq` and `Rdq` of a topography
/// (`rms_height_from_profile`, `rms_slope_from_profile`) take them: each
/// profile about its own mean, the differences along it (n − 1 a profile,
/// n wrapping around when periodic; its derivative of a map that is not
/// periodic leaves out the last profile too, as the gradient's stencil
/// does).
pub(crate) fn profiles(h: &[f64], n: usize, l: f64, periodic: bool) -> RealSpace {
    let dx = l / n as f64;
    let count = h.len() / n;
    let (m, sloped) = if periodic {
        (n, count)
    } else {
        (n - 1, count - 1)
    };
    let (mut squares, mut slopes) = (0.0, 0.0);
    for (j, row) in h.chunks_exact(n).enumerate() {
        let mean = row.iter().sum::<f64>() / n as f64;
        squares += row.iter().map(|v| (v - mean).powi(2)).sum::<f64>();
        if j < sloped {
            slopes += (0..m)
                .map(|i| ((row[(i + 1) % n] - row[i]) / dx).powi(2))
                .sum::<f64>();
        }
    }
    RealSpace {
        areal: false,
        rms_height: (squares / h.len() as f64).sqrt(),
        rms_slope: (slopes / (m * sloped) as f64).sqrt(),
        amplitude: crate::spectrum::amplitude::of(h, n, true),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tilted_line_and_a_periodic_cosine() {
        // Differences of a line of slope 2: RΔq = 2 exactly.
        let h: Vec<f64> = (0..8).map(|i| 2.0 * i as f64 * 0.5).collect();
        let r = profile(&h, 4.0, false);
        assert!((r.rms_slope - 2.0).abs() < 1e-15);
        // A periodic cosine of amplitude a: Sq = a/√2.
        let (nx, ny, a) = (16, 4, 0.3);
        let h: Vec<f64> = (0..nx * ny)
            .map(|k| a * (2.0 * std::f64::consts::PI * (k % nx) as f64 / nx as f64).cos())
            .collect();
        let r = areal(&h, nx, ny, 1.0, 1.0, true);
        assert!((r.rms_height - a / 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(r.names(), ("Sq", "Sdq"));
        // Its height parameters: Sa = a · mean |cos|, no skew, Sku = 3/2,
        // Sz = 2a.
        let [sa, ssk, sku, sz] = r.heights();
        assert_eq!((sa.0, ssk.0, sku.0, sz.0), ("Sa", "Ssk", "Sku", "Sz"));
        let mean_abs = (0..nx)
            .map(|i| {
                (2.0 * std::f64::consts::PI * i as f64 / nx as f64)
                    .cos()
                    .abs()
            })
            .sum::<f64>()
            / nx as f64;
        assert!((sa.1 - a * mean_abs).abs() < 1e-15);
        assert!(
            ssk.1.abs() < 1e-14 && (sku.1 - 1.5).abs() < 1e-14,
            "{ssk:?} {sku:?}"
        );
        assert!((sz.1 - 2.0 * a).abs() < 1e-15);
    }
}
