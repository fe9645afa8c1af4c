//! The default Hurst fit band: the self-affine stretch of a spectrum,
//! found from the data rather than taken from the cutoff on screen.
//!
//! The log-log spectrum (log-binned for maps and lines) is cut into at
//! most [`MAX_SEGMENTS`] straight pieces by weighted least squares
//! (dynamic programming, each piece at least [`MIN_POINTS`] bins), the
//! number of pieces chosen by the Bayesian information criterion. Each bin
//! weighs √modes, the square root of the Fourier modes it averages: the
//! full count (the scatter of a bin's ln C falls as 1/√modes) lets the
//! many-mode bins at large q, bent slightly by the window, outweigh a
//! roll-off plateau of a few bins at small q. The band is the longest
//! piece (in decades of q) that is straight (its points within
//! [`POOR_DECADES`] rms of its line) and whose slope is that
//! of a self-affine surface, 0 ≤ H ≤ 1 widened by [`H_SLACK`] on both
//! sides: a roll-off plateau (slope 0: H = −1 for areal data) and a noise
//! floor are not, and neither is the steep fall past a short cutoff or the
//! window's leakage there; failing that, the longest self-affine piece,
//! then the longest piece; its ends then lose the points that lie far off
//! its line, while their plain (unweighted) rms passes [`POOR_DECADES`].
//! Before that,
//! numerical zeros are dropped: everything from the first point that lies
//! more than [`CLIFF`] decades below its neighbour (a periodic surface
//! generated with a short cutoff has nothing but rounding past it).

use rough_model::Dim;

/// A fit whose points lie further than this from its line, rms in decades
/// of C (a factor 1.26), is not a power law over the band.
pub const POOR_DECADES: f64 = 0.1;

/// Most straight pieces the spectrum is cut into.
const MAX_SEGMENTS: usize = 5;
/// Fewest bins in a piece.
const MIN_POINTS: usize = 3;
/// How far outside [0, 1] a piece's H may lie and still be the band.
const H_SLACK: f64 = 0.3;
/// A drop between neighbouring bins, decades, that only rounding makes.
const CLIFF: f64 = 4.0;
/// Neighbouring pieces whose slopes differ by less than this many combined
/// standard errors are one.
const MERGE: f64 = 2.0;
/// Points above which a long table is merged into groups first.
const MAX_POINTS: usize = 240;

/// Weighted sums of a run of points, for O(1) least squares.
#[derive(Clone, Copy, Default)]
struct Sums {
    w: f64,
    x: f64,
    y: f64,
    xx: f64,
    xy: f64,
    yy: f64,
}

impl Sums {
    fn add(&self, (x, y, w): (f64, f64, f64)) -> Sums {
        Sums {
            w: self.w + w,
            x: self.x + w * x,
            y: self.y + w * y,
            xx: self.xx + w * x * x,
            xy: self.xy + w * x * y,
            yy: self.yy + w * y * y,
        }
    }

    fn minus(&self, o: &Sums) -> Sums {
        Sums {
            w: self.w - o.w,
            x: self.x - o.x,
            y: self.y - o.y,
            xx: self.xx - o.xx,
            xy: self.xy - o.xy,
            yy: self.yy - o.yy,
        }
    }

    /// (slope, weighted residual sum of squares) of the least-squares line.
    fn line(&self) -> (f64, f64) {
        let sxx = self.xx - self.x * self.x / self.w;
        let sxy = self.xy - self.x * self.y / self.w;
        let syy = self.yy - self.y * self.y / self.w;
        if sxx <= 0.0 {
            return (f64::NAN, syy.max(0.0));
        }
        let slope = sxy / sxx;
        (slope, (syy - slope * sxy).max(0.0))
    }
}

/// H of a log-log slope.
pub(crate) fn hurst(dim: Dim, slope: f64) -> f64 {
    match dim {
        Dim::Areal => -slope / 2.0 - 1.0,
        Dim::Profile => (-slope - 1.0) / 2.0,
    }
}

/// (ln q, ln C, weight) of the usable points: C > 0, before the first
/// cliff; long tables merged into groups of neighbours.
fn points(spectrum: &[(f64, f64)], modes: &[f64]) -> Vec<(f64, f64, f64)> {
    let mut pts: Vec<(f64, f64, f64)> = Vec::with_capacity(spectrum.len());
    for (i, &(q, c)) in spectrum.iter().enumerate() {
        if !(q > 0.0 && c > 0.0 && q.is_finite() && c.is_finite()) {
            continue;
        }
        let m = modes.get(i).copied().unwrap_or(1.0).max(1.0);
        let p = (q.ln(), c.ln(), m.sqrt());
        if let Some(last) = pts.last() {
            if (last.1 - p.1) > CLIFF * std::f64::consts::LN_10 {
                break;
            }
        }
        pts.push(p);
    }
    if pts.len() > MAX_POINTS {
        let k = pts.len().div_ceil(MAX_POINTS);
        pts = pts
            .chunks(k)
            .map(|g| {
                let n = g.len() as f64;
                let w: f64 = g.iter().map(|p| p.2).sum();
                (
                    g.iter().map(|p| p.0).sum::<f64>() / n,
                    g.iter().map(|p| p.1).sum::<f64>() / n,
                    w,
                )
            })
            .collect();
    }
    pts
}

/// The self-affine stretch of `spectrum` (q increasing, weights `modes`
/// or none), as [q_lo, q_hi] in 1/m; `None` with fewer than
/// [`MIN_POINTS`] usable points.
pub(crate) fn self_affine(dim: Dim, spectrum: &[(f64, f64)], modes: &[f64]) -> Option<(f64, f64)> {
    let pts = points(spectrum, modes);
    let n = pts.len();
    if n < MIN_POINTS {
        return None;
    }
    let mut pre = vec![Sums::default(); n + 1];
    for (i, &p) in pts.iter().enumerate() {
        pre[i + 1] = pre[i].add(p);
    }
    let cost = |i: usize, j: usize| pre[j].minus(&pre[i]).line().1;
    // best[k][j]: the least cost of the first j points in k + 1 pieces;
    // from[k][j]: where the last piece starts.
    let kmax = MAX_SEGMENTS.min(n / MIN_POINTS);
    let mut best = vec![vec![f64::INFINITY; n + 1]; kmax];
    let mut from = vec![vec![0usize; n + 1]; kmax];
    for (j, b) in best[0].iter_mut().enumerate().skip(MIN_POINTS) {
        *b = cost(0, j);
    }
    for k in 1..kmax {
        for j in (k + 1) * MIN_POINTS..=n {
            for i in k * MIN_POINTS..=j - MIN_POINTS {
                let c = best[k - 1][i] + cost(i, j);
                if c < best[k][j] {
                    best[k][j] = c;
                    from[k][j] = i;
                }
            }
        }
    }
    // The number of pieces by BIC (3 K − 1 parameters); a floor under the
    // residual so that an exact power law does not ask for more pieces.
    let total: f64 = pts.iter().map(|p| p.2).sum();
    let floor = 1e-12 * total;
    let bic = |k: usize| {
        let ssr = best[k][n].max(floor);
        n as f64 * (ssr / n as f64).ln() + (3 * (k + 1) - 1) as f64 * (n as f64).ln()
    };
    let k = (0..kmax)
        .filter(|&k| best[k][n].is_finite())
        .min_by(|&a, &b| bic(a).total_cmp(&bic(b)))?;
    let mut pieces: Vec<(usize, usize)> = Vec::with_capacity(k + 1);
    let mut j = n;
    for kk in (0..=k).rev() {
        let i = if kk == 0 { 0 } else { from[kk][j] };
        pieces.push((i, j));
        j = i;
    }
    let span = |&(i, j): &(usize, usize)| pts[j - 1].0 - pts[i].0;
    let plausible = |&(i, j): &(usize, usize)| {
        let h = hurst(dim, pre[j].minus(&pre[i]).line().0);
        h > -H_SLACK && h < 1.0 + H_SLACK
    };
    let longest = |it: &mut dyn Iterator<Item = &(usize, usize)>| {
        it.max_by(|a, b| span(a).total_cmp(&span(b))).copied()
    };
    // Straight as the fit judges it: weighed by the full mode counts.
    let mut full = vec![Sums::default(); n + 1];
    for (i, &(x, y, w)) in pts.iter().enumerate() {
        full[i + 1] = full[i].add((x, y, w * w));
    }
    let straight = |&(i, j): &(usize, usize)| {
        let s = full[j].minus(&full[i]);
        (s.line().1 / s.w).sqrt() / std::f64::consts::LN_10 <= POOR_DECADES
    };
    let (mut i, mut j) = longest(&mut pieces.iter().filter(|p| plausible(p) && straight(p)))
        .or_else(|| longest(&mut pieces.iter().filter(|p| plausible(p))))
        .or_else(|| longest(&mut pieces.iter()))?;
    // Neighbours of the same slope, within twice their combined standard
    // error, belong to the band: the pieces of a noisy power law. The
    // errors assume every point's variance is σ²/modes, σ the band's.
    let sums = |i: usize, j: usize| full[j].minus(&full[i]);
    let sxx = |s: &Sums| s.xx - s.x * s.x / s.w;
    pieces.reverse();
    loop {
        let at = pieces.iter().position(|&p| p == (i, j))?;
        let band = sums(i, j);
        let (s, ssr) = band.line();
        let var = ssr / ((j - i) as f64 - 2.0).max(1.0);
        let e = (var / sxx(&band)).sqrt();
        let same = |&(a, b): &(usize, usize)| {
            let piece = sums(a, b);
            let (t, f) = (piece.line().0, (var / sxx(&piece)).sqrt());
            (s - t).abs() <= MERGE * (e * e + f * f).sqrt()
                && plausible(&(a.min(i), b.max(j)))
                && straight(&(a.min(i), b.max(j)))
        };
        let left = at.checked_sub(1).map(|k| pieces[k]).filter(same);
        let right = pieces.get(at + 1).copied().filter(same);
        match (left, right) {
            (Some((a, _)), _) => {
                pieces.splice(at - 1..=at, [(a, j)]);
                i = a;
            }
            (None, Some((_, b))) => {
                pieces.splice(at..=at + 1, [(i, b)]);
                j = b;
            }
            (None, None) => break,
        }
    }
    // The points as drawn, every one counting the same: the band's ends
    // lose points while their plain rms from the line passes
    // [`POOR_DECADES`] (few-mode bins at small q, scattered a decade, hide
    // in the mode-weighted rms), the end farther from the line first, as
    // long as the fit keeps its points and half a decade.
    let plain = |i: usize, j: usize| -> (f64, f64, f64) {
        let s = sums(i, j);
        let (slope, _) = s.line();
        let (mx, my) = (s.x / s.w, s.y / s.w);
        let r = |k: usize| (pts[k].1 - my - slope * (pts[k].0 - mx)).abs();
        let rms = ((i..j).map(|k| r(k).powi(2)).sum::<f64>() / (j - i) as f64).sqrt();
        (rms / std::f64::consts::LN_10, r(i), r(j - 1))
    };
    let decades = |i: usize, j: usize| (pts[j - 1].0 - pts[i].0) / std::f64::consts::LN_10;
    loop {
        let (rms, first, last) = plain(i, j);
        if rms <= POOR_DECADES || j - i <= crate::limits::MIN_FIT_POINTS {
            break;
        }
        let (a, b) = if first >= last {
            (i + 1, j)
        } else {
            (i, j - 1)
        };
        if decades(a, b) < crate::limits::MIN_FIT_DECADES {
            break;
        }
        (i, j) = (a, b);
    }
    // The spectrum's own wavevectors (not their logarithms' round trip).
    let nearest = |x: f64| {
        spectrum
            .iter()
            .map(|p| p.0)
            .filter(|q| *q > 0.0)
            .min_by(|a, b| (a.ln() - x).abs().total_cmp(&(b.ln() - x).abs()))
            .unwrap_or(x.exp())
    };
    Some((nearest(pts[i].0), nearest(pts[j - 1].0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plateau_power_law_and_cliff() {
        // Plateau to q = 4, C ∝ q^−3.6 (H 0.8) to 128, rounding beyond.
        let spectrum: Vec<(f64, f64)> = (0..40)
            .map(|i| {
                let q = 10f64.powf(0.1 * i as f64);
                let c = if q < 4.0 {
                    4f64.powf(-3.6)
                } else if q <= 128.0 {
                    q.powf(-3.6)
                } else {
                    1e-30 * (1.0 + 0.5 * (i as f64).sin())
                };
                (q, c)
            })
            .collect();
        let (lo, hi) = self_affine(Dim::Areal, &spectrum, &[]).unwrap();
        assert!((3.9..=5.1).contains(&lo), "{lo}");
        assert!((100.0..=128.0).contains(&hi), "{hi}");
    }
}
