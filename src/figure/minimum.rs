//! Interior minima of a smooth curve sampled along a sweep: bracketed on
//! the sample grid, narrowed by golden-section search, then polished by
//! Newton steps on a five-point derivative.
//!
//! Why the polish: comparing values locates a minimum only to about
//! √ε relative (near it f changes by f″δ²/2, which drowns in rounding once
//! δ ≲ √(2ε f/f″) ≈ 1e-8). The derivative changes sign linearly there, so
//! its root is determined to about ε·f/(h f″) with the stencil's step h;
//! with h ≤ 1e-3 in ln x the stencil's own error (h⁴ f⁽⁵⁾/30) stays below
//! that, and the location comes out within ~1e-12 relative.

/// Golden-section iterations stop once the bracket is this narrow
/// (relative to its position, in the search variable).
const GOLDEN_TOL: f64 = 1e-12;

/// The largest step of the derivative stencil, in the search variable.
const STENCIL_STEP: f64 = 1e-3;

/// A local minimum of `f` on the grid `xs` (values `vs`), searched in
/// u = `to_u(x)` (ln x on log axes) and returned as (x, f(x)), for the
/// sample `i` lower than both neighbours. `None` when the neighbours are
/// within rounding of the minimum (a plateau: the place is not determined).
pub fn refine(
    xs: &[f64],
    vs: &[f64],
    i: usize,
    log: bool,
    f: &dyn Fn(f64) -> f64,
) -> Option<(f64, f64)> {
    let to_u = |x: f64| if log { x.ln() } else { x };
    let to_x = |u: f64| if log { u.exp() } else { u };
    let g = |u: f64| f(to_x(u));
    let (lo, hi) = (to_u(xs[i - 1]), to_u(xs[i + 1]));
    let u = golden(lo, hi, &g);
    let u = polish(u, lo, hi, &g);
    let (x, v) = (to_x(u), g(u));
    // Both bracket ends must rise above the minimum by more than rounding.
    let rise = |w: f64| w - v > 1e-12 * v.abs();
    if !(v.is_finite() && rise(vs[i - 1]) && rise(vs[i + 1])) {
        return None;
    }
    Some((x, v))
}

/// The interior sample indices of `vs` lower than the sample before and no
/// higher than the one after (NaN never qualifies).
pub fn bracketed(vs: &[f64]) -> impl Iterator<Item = usize> + '_ {
    (1..vs.len().saturating_sub(1)).filter(|&i| vs[i - 1] > vs[i] && vs[i + 1] >= vs[i])
}

/// Golden-section search for the minimum of `g` in [a, b].
fn golden(mut a: f64, mut b: f64, g: &dyn Fn(f64) -> f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut gc, mut gd) = (g(c), g(d));
    for _ in 0..200 {
        if (b - a).abs() <= GOLDEN_TOL * a.abs().max(b.abs()).max(1.0) {
            break;
        }
        if gc < gd {
            b = d;
            d = c;
            gd = gc;
            c = b - r * (b - a);
            gc = g(c);
        } else {
            a = c;
            c = d;
            gc = gd;
            d = a + r * (b - a);
            gd = g(d);
        }
    }
    0.5 * (a + b)
}

/// Newton steps on g′ = 0 from `u` (already within ~1e-8), with g′ from a
/// five-point stencil and g″ from three points, kept inside [lo, hi]. A
/// step that is not small (bad curvature, noise) is refused: `u` stays.
fn polish(mut u: f64, lo: f64, hi: f64, g: &dyn Fn(f64) -> f64) -> f64 {
    let h = STENCIL_STEP.min((hi - lo) / 8.0);
    for _ in 0..2 {
        if u - 2.0 * h < lo || u + 2.0 * h > hi {
            break;
        }
        let (m2, m1, c, p1, p2) = (g(u - 2.0 * h), g(u - h), g(u), g(u + h), g(u + 2.0 * h));
        let d1 = (m2 - 8.0 * m1 + 8.0 * p1 - p2) / (12.0 * h);
        let d2 = (m1 - 2.0 * c + p1) / (h * h);
        let step = d1 / d2;
        if !(d2 > 0.0 && step.abs() < 0.1 * h) {
            break;
        }
        u -= step;
    }
    u
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
        (0..n)
            .map(|i| (lo.ln() + (hi.ln() - lo.ln()) * i as f64 / (n - 1) as f64).exp())
            .collect()
    }

    #[test]
    fn a_known_minimum_to_1e_13() {
        // f = (ln x − ln 3.19)² + 3.91 has its minimum at x = 3.19.
        let at = 3.19f64;
        let f = |x: f64| (x.ln() - at.ln()).powi(2) + 3.91;
        let xs = grid(1.0, 1e4, 256);
        let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let found: Vec<_> = bracketed(&vs)
            .filter_map(|i| refine(&xs, &vs, i, true, &f))
            .collect();
        assert_eq!(found.len(), 1);
        let (x, v) = found[0];
        assert!((x / at - 1.0).abs() < 1e-13, "{x}");
        assert_eq!(v, 3.91);
    }

    #[test]
    fn an_asymmetric_minimum_beats_value_comparisons() {
        // f = x + 1/x² has f′ = 1 − 2/x³ = 0 at x = 2^(1/3); golden
        // section alone stops ~1e-8 away.
        let at = 2f64.cbrt();
        let f = |x: f64| x + 1.0 / (x * x);
        let xs = grid(0.5, 5.0, 64);
        let vs: Vec<f64> = xs.iter().map(|&x| f(x)).collect();
        let i = bracketed(&vs).next().unwrap();
        let (x, _) = refine(&xs, &vs, i, true, &f).unwrap();
        assert!((x / at - 1.0).abs() < 1e-12, "{x} vs {at}");
    }

    #[test]
    fn plateaus_and_monotone_curves_have_no_minimum() {
        let xs = grid(1.0, 10.0, 16);
        let flat = vec![1.0; 16];
        assert_eq!(bracketed(&flat).count(), 0);
        // A dip of one ulp is rounding, not a minimum.
        let mut dip = flat.clone();
        dip[5] = 1.0 - f64::EPSILON / 2.0;
        let f = |x: f64| {
            if (x - xs[5]).abs() < 1e-9 {
                dip[5]
            } else {
                1.0
            }
        };
        let i = bracketed(&dip).next().unwrap();
        assert_eq!(refine(&xs, &dip, i, true, &f), None);
        let down: Vec<f64> = xs.iter().map(|x| 1.0 / x).collect();
        assert_eq!(bracketed(&down).count(), 0);
        let nan = vec![2.0, f64::NAN, 2.0];
        assert_eq!(bracketed(&nan).count(), 0);
    }
}
