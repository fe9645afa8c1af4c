//! The height parameters a researcher compares first beside Sq (ISO
//! 25178-2 for a map, ISO 4287 for a profile), from the heights after the
//! detrend, without a window, as Sq is: Sa (Ra) the mean |h − mean|, Ssk
//! (Rsk) and Sku (Rku) the third and fourth central moments over Sq³ and
//! Sq⁴, Sz (Rz) the largest height minus the smallest — over the whole map
//! or line (one evaluation area, one sampling length); for a map read as
//! its profiles each profile about its own mean, Rz their mean.

/// Sa, Ssk, Sku and Sz of a map (Ra, Rsk, Rku and Rz of a profile).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Amplitude {
    /// Sa or Ra, m.
    pub mean_abs: f64,
    /// Ssk or Rsk.
    pub skewness: f64,
    /// Sku or Rku.
    pub kurtosis: f64,
    /// Sz or Rz, m.
    pub range: f64,
    /// The largest distance of a height from the mean (a profile's from
    /// its own mean), m: the worst spike or pit.
    pub peak: f64,
}

/// Sku above this says a few points rule the heights' fourth moment:
/// Gaussian heights have 3, the plateau-honed and turned surfaces of
/// practice 3–8 (ISO 13565-3's material-ratio examples), and the scan
/// scars and dust of AFM maps 100 and more.
pub const SPIKY_KURTOSIS: f64 = 10.0;

/// A height further than this many Sq from the mean is a spike: Gaussian
/// heights of N points reach about √(2 ln N) Sq, 6.4 at a billion points,
/// and 10 Sq has a chance of 1.5e-23 a point.
pub const SPIKE_SQ: f64 = 10.0;

/// The warning where heights `a`, of rms `sq`, over `n` points hold
/// spikes or scars ([`SPIKY_KURTOSIS`], [`SPIKE_SQ`]): their numbers, why
/// they matter and how to mark them so that they are filled.
pub(crate) fn scars(a: &Amplitude, sq: f64, n: usize) -> Option<String> {
    let spike = a.peak / sq;
    if !(a.kurtosis > SPIKY_KURTOSIS || spike > SPIKE_SQ) {
        return None;
    }
    let gauss = (2.0 * (n.max(2) as f64).ln()).sqrt();
    let g = |v: f64| {
        if v >= 100.0 {
            format!("{v:.0}")
        } else {
            format!("{v:.1}")
        }
    };
    Some(format!(
        "warning: spikes or scars: Sku {} and a point {} Sq from the mean (Gaussian \
         heights: Sku 3, at most about {:.1} Sq over {n} points) drive Sdq, the slopes and Ψ; \
         mark them in Gwyddion (Mark Scars, or Mask of Outliers) and save as .gwy: masked \
         points are filled",
        g(a.kurtosis),
        g(spike),
        gauss
    ))
}

/// Sums over a block of rows: |d|, d², d³, d⁴, the rows' ranges, the
/// block's smallest and largest height and largest |d|.
#[derive(Clone, Copy)]
struct Sums([f64; 5], f64, f64, f64);

impl Sums {
    fn add(self, o: Sums) -> Sums {
        let mut s = self.0;
        for (a, b) in s.iter_mut().zip(o.0) {
            *a += b;
        }
        Sums(s, self.1.min(o.1), self.2.max(o.2), self.3.max(o.3))
    }
}

/// The parameters of `h`, rows of `n`; `per_row` refers each row to its own
/// mean (a map's profiles), else all to the one mean.
pub(crate) fn of(h: &[f64], n: usize, per_row: bool) -> Amplitude {
    let rows = h.len() / n;
    let total = h.len() as f64;
    let mean = h.iter().sum::<f64>() / total;
    let block = |r: std::ops::Range<usize>| {
        let mut s = Sums([0.0; 5], f64::INFINITY, f64::NEG_INFINITY, 0.0);
        for row in h[r.start * n..r.end * n].chunks_exact(n) {
            let m = if per_row {
                row.iter().sum::<f64>() / n as f64
            } else {
                mean
            };
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for &v in row {
                let d = v - m;
                let d2 = d * d;
                s.0[0] += d.abs();
                s.0[1] += d2;
                s.0[2] += d2 * d;
                s.0[3] += d2 * d2;
                s.3 = s.3.max(d.abs());
                lo = lo.min(v);
                hi = hi.max(v);
            }
            s.0[4] += hi - lo;
            s.1 = s.1.min(lo);
            s.2 = s.2.max(hi);
        }
        s
    };
    let per = rows.div_ceil(crate::threads::count()).max(1);
    let s = std::thread::scope(|sc| {
        let block = &block;
        let parts: Vec<_> = (0..rows)
            .step_by(per)
            .map(|j0| sc.spawn(move || block(j0..(j0 + per).min(rows))))
            .collect();
        parts
            .into_iter()
            .map(|p| p.join().expect("height parameters"))
            .fold(
                Sums([0.0; 5], f64::INFINITY, f64::NEG_INFINITY, 0.0),
                Sums::add,
            )
    });
    let q2 = s.0[1] / total;
    Amplitude {
        mean_abs: s.0[0] / total,
        skewness: s.0[2] / total / q2.powf(1.5),
        kurtosis: s.0[3] / total / (q2 * q2),
        range: if per_row {
            s.0[4] / rows as f64
        } else {
            s.2 - s.1
        },
        peak: s.3,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sine_and_a_step() {
        // A sine of amplitude a over whole periods: Sa = 2a/π, Ssk 0,
        // Sku 3/2, Sz 2a.
        let (n, a) = (4096, 0.7);
        let h: Vec<f64> = (0..n)
            .map(|i| a * (2.0 * std::f64::consts::PI * i as f64 / n as f64).sin())
            .collect();
        let p = of(&h, n, false);
        assert!((p.mean_abs - 2.0 * a / std::f64::consts::PI).abs() < 1e-6);
        assert!(p.skewness.abs() < 1e-12);
        assert!((p.kurtosis - 1.5).abs() < 1e-12);
        assert!((p.range - 2.0 * a).abs() < 1e-6);
        // Two rows of different means: each about its own.
        let h = [0.0, 2.0, 10.0, 14.0];
        let p = of(&h, 2, true);
        assert_eq!((p.mean_abs, p.range), (1.5, 3.0));
        assert_eq!(of(&h, 2, false).range, 14.0);
        assert_eq!((p.peak, of(&h, 2, false).peak), (2.0, 7.5));
    }

    #[test]
    fn spikes_are_told() {
        // 9 999 heights of ±1 and one of 50: mean 0.0051, Sq 1.118, the
        // fourth moment (9999 + 50⁴)/10⁴ = 626 over Sq⁴ 1.562: Sku 401; the
        // spike 49.995 from the mean, 44.7 Sq.
        let mut h: Vec<f64> = (0..10_000)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        h[17] = 50.0;
        let a = of(&h, 100, false);
        let sq = (h.iter().map(|v| v * v).sum::<f64>() / 1e4
            - (h.iter().sum::<f64>() / 1e4).powi(2))
        .sqrt();
        let w = scars(&a, sq, h.len()).unwrap();
        assert_eq!(
            w,
            "warning: spikes or scars: Sku 401 and a point 44.7 Sq from the mean (Gaussian \
             heights: Sku 3, at most about 4.3 Sq over 10000 points) drive Sdq, the slopes and \
             Ψ; mark them in Gwyddion (Mark Scars, or Mask of Outliers) and save as .gwy: \
             masked points are filled"
        );
        // Whole on a 140-column status row's two rows.
        assert!(w.chars().count() < 264);
        h[17] = 1.0;
        assert!(scars(&of(&h, 100, false), 1.0, h.len()).is_none());
    }
}
