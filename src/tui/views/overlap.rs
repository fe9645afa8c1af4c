//! Curves that coincide: which cells of the graph each curve's line passes
//! through, and which curve a later-drawn one hides, so that the legend can
//! say so ("total = Persson here") instead of listing a curve nobody finds.

use std::collections::HashSet;

use ratatui::layout::Rect;

use super::chart::{col_of, row_of};

/// The cells (column, row) the line through `points` passes through, with
/// the canvas's own arithmetic on a grid of `dots` points per cell;
/// segments are sampled at every point.
pub fn cells(
    points: &[(f64, f64)],
    (xb, yb): ([f64; 2], [f64; 2]),
    g: Rect,
    dots: (f64, f64),
) -> HashSet<(u16, u16)> {
    let mut out = HashSet::new();
    let dots_x = f64::from(g.width) * dots.0 / (xb[1] - xb[0]);
    let dots_y = f64::from(g.height) * dots.1 / (yb[1] - yb[0]);
    let mut put = |x: f64, y: f64| {
        if let (Some(c), Some(r)) = (col_of(g, dots, xb, x), row_of(g, dots, yb, y)) {
            out.insert((c, r));
        }
    };
    for w in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        let n = ((x1 - x0).abs() * dots_x)
            .max((y1 - y0).abs() * dots_y)
            .ceil()
            .clamp(1.0, 4096.0) as usize;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            put(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
        }
    }
    if let [(x, y)] = points {
        put(*x, *y);
    }
    out
}

/// For curves drawn in order (later over earlier): for each, the index of
/// the later curve it lies under, when fewer than a quarter of its cells
/// stay visible.
pub fn hidden_under(curves: &[HashSet<(u16, u16)>]) -> Vec<Option<usize>> {
    (0..curves.len())
        .map(|i| {
            let own = &curves[i];
            if own.is_empty() {
                return None;
            }
            let later = &curves[i + 1..];
            let visible = own
                .iter()
                .filter(|c| !later.iter().any(|l| l.contains(c)))
                .count();
            if visible * 4 >= own.len() {
                return None;
            }
            later
                .iter()
                .enumerate()
                .map(|(j, l)| (i + 1 + j, own.intersection(l).count()))
                .max_by_key(|&(j, n)| (n, j))
                .map(|(j, _)| j)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_curve_under_another_is_found() {
        let g = Rect::new(0, 0, 20, 10);
        let b = ([0.0, 1.0], [0.0, 1.0]);
        let line = |y0: f64, y1: f64| cells(&[(0.0, y0), (1.0, y1)], b, g, (2.0, 4.0));
        let a = line(0.0, 1.0);
        let same = line(0.0, 1.0);
        let other = line(1.0, 0.0);
        assert!(a.len() >= 20, "{}", a.len());
        assert_eq!(
            hidden_under(&[a.clone(), other.clone(), same]),
            vec![Some(2), None, None]
        );
        assert_eq!(hidden_under(&[a, other]), vec![None, None]);
        assert_eq!(hidden_under(&[HashSet::new()]), vec![None]);
    }
}
