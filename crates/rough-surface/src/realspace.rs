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
//!
//! Beside them the ISO 25178-2 (maps) and ISO 4287 (profiles) height
//! parameters of the same heights h about their mean m, over the N points:
//! Sa = Σ|h − m|/N, Ssk = Σ(h − m)³/(N Sq³), Sku = Σ(h − m)⁴/(N Sq⁴) and
//! Sz = max h − min h (Ra, Rsk, Rku, Rz for a line, Rz over the whole
//! profile as one sampling length). SurfaceTopography computes Sq and the
//! heights' `min` and `max`; the others are its detrended heights' moments.

/// Real-space rms height and rms slope (gradient for maps), and the
/// height parameters beside them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RealSpace {
    /// A map's (Sq, Sdq) rather than a line's (Rq, RΔq).
    pub areal: bool,
    /// Sq or Rq, m.
    pub rms_height: f64,
    /// Sdq or RΔq, dimensionless.
    pub rms_slope: f64,
    /// Sa or Ra: the mean absolute height about the mean, m.
    pub mean_abs_height: f64,
    /// Ssk or Rsk: the skewness of the heights.
    pub skewness: f64,
    /// Sku or Rku: the kurtosis of the heights (3 for Gaussian ones).
    pub kurtosis: f64,
    /// Sz or Rz: the highest peak to the lowest valley, m.
    pub max_height: f64,
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
    /// or Ra, Rsk, Rku, Rz (lines).
    pub fn heights(&self) -> [(&'static str, f64); 4] {
        let n = if self.areal {
            ["Sa", "Ssk", "Sku", "Sz"]
        } else {
            ["Ra", "Rsk", "Rku", "Rz"]
        };
        [
            (n[0], self.mean_abs_height),
            (n[1], self.skewness),
            (n[2], self.kurtosis),
            (n[3], self.max_height),
        ]
    }
}

/// Sums of the heights' deviations from their mean and their extremes.
#[derive(Clone, Copy)]
struct Sums {
    abs: f64,
    squares: f64,
    cubes: f64,
    fourths: f64,
    min: f64,
    max: f64,
    /// Σ of the squared differences (the slope's sum).
    slope: f64,
}

impl Sums {
    const ZERO: Sums = Sums {
        abs: 0.0,
        squares: 0.0,
        cubes: 0.0,
        fourths: 0.0,
        min: f64::INFINITY,
        max: f64::NEG_INFINITY,
        slope: 0.0,
    };

    /// The deviations of `h` from `mean` added.
    fn add(mut self, h: &[f64], mean: f64) -> Sums {
        for &v in h {
            let d = v - mean;
            let d2 = d * d;
            self.abs += d.abs();
            self.squares += d2;
            self.cubes += d2 * d;
            self.fourths += d2 * d2;
            self.min = self.min.min(v);
            self.max = self.max.max(v);
        }
        self
    }

    fn join(self, o: Sums) -> Sums {
        Sums {
            abs: self.abs + o.abs,
            squares: self.squares + o.squares,
            cubes: self.cubes + o.cubes,
            fourths: self.fourths + o.fourths,
            min: self.min.min(o.min),
            max: self.max.max(o.max),
            slope: self.slope + o.slope,
        }
    }

    /// The numbers of `n` heights whose slope sum has `pairs` terms.
    fn finish(self, areal: bool, n: usize, pairs: usize) -> RealSpace {
        let n = n as f64;
        let var = self.squares / n;
        RealSpace {
            areal,
            rms_height: var.sqrt(),
            rms_slope: (self.slope / pairs as f64).sqrt(),
            mean_abs_height: self.abs / n,
            skewness: self.cubes / n / (var * var.sqrt()),
            kurtosis: self.fourths / n / (var * var),
            max_height: self.max - self.min,
        }
    }
}

/// `f` over blocks of the rows 0..ny, each block on a thread of its own,
/// the blocks' results joined.
fn rows_fold<T, F>(ny: usize, f: F, join: fn(T, T) -> T) -> Option<T>
where
    T: Send,
    F: Fn(std::ops::Range<usize>) -> T + Sync,
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
            .reduce(join)
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
    let sum = rows_fold(
        ny,
        |r| h[r.start * nx..r.end * nx].iter().sum::<f64>(),
        |a, b| a + b,
    )
    .unwrap_or(0.0);
    let mean = sum / h.len() as f64;
    let sums = rows_fold(
        ny,
        |r| {
            let mut s = Sums::ZERO.add(&h[r.start * nx..r.end * nx], mean);
            for j in r.start..r.end.min(jy) {
                let row = &h[j * nx..(j + 1) * nx];
                let next = &h[((j + 1) % ny) * nx..((j + 1) % ny + 1) * nx];
                for i in 0..ix {
                    let v = row[i];
                    let right = if i + 1 == nx { row[0] } else { row[i + 1] };
                    let gx = (right - v) / dx;
                    let gy = (next[i] - v) / dy;
                    s.slope += gx * gx + gy * gy;
                }
            }
            s
        },
        Sums::join,
    )
    .unwrap_or(Sums::ZERO);
    sums.finish(true, h.len(), ix * jy)
}

/// A map's `count` profiles of n detrended heights over l each (rows of
/// n), as SurfaceTopography's `Rq` and `Rdq` of a topography take them:
/// each profile about its own mean, the differences along it (n − 1 a
/// profile, n wrapping around when periodic; its derivative of a map that
/// is not periodic leaves out the last profile too, as the gradient's
/// stencil does); Ra, Rsk, Rku about the same means, Rz the profiles' mean
/// peak-to-valley height.
pub(crate) fn profiles(h: &[f64], n: usize, l: f64, periodic: bool) -> RealSpace {
    let dx = l / n as f64;
    let count = h.len() / n;
    let (m, sloped) = if periodic {
        (n, count)
    } else {
        (n - 1, count - 1)
    };
    let (mut s, mut range) = (Sums::ZERO, 0.0);
    for (j, row) in h.chunks_exact(n).enumerate() {
        let mean = row.iter().sum::<f64>() / n as f64;
        let one = Sums::ZERO.add(row, mean);
        range += one.max - one.min;
        s = s.join(one);
        if j < sloped {
            s.slope += (0..m)
                .map(|i| ((row[(i + 1) % n] - row[i]) / dx).powi(2))
                .sum::<f64>();
        }
    }
    let mut r = s.finish(false, h.len(), m * sloped);
    r.max_height = range / count as f64;
    r
}

/// A line of n detrended heights over l.
pub(crate) fn profile(h: &[f64], l: f64, periodic: bool) -> RealSpace {
    let n = h.len();
    let dx = l / n as f64;
    let m = if periodic { n } else { n - 1 };
    let mean = h.iter().sum::<f64>() / n as f64;
    let mut s = Sums::ZERO.add(h, mean);
    s.slope = (0..m).map(|i| ((h[(i + 1) % n] - h[i]) / dx).powi(2)).sum();
    s.finish(false, n, m)
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
        // Its height parameters: Sa = 2a/π, no skew, Sku = 3/2, Sz = 2a.
        let [sa, ssk, sku, sz] = r.heights();
        assert_eq!((sa.0, ssk.0, sku.0, sz.0), ("Sa", "Ssk", "Sku", "Sz"));
        // The mean of |cos| over the 16 samples.
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
