//! Curves that coincide: which cells of the graph each curve's line passes
//! through, and which curve a later-drawn one hides, so that the legend can
//! say so ("total = Persson here") instead of listing a curve nobody finds.

use std::collections::HashSet;

use ratatui::layout::Rect;

use super::chart::{col_of, row_of};
use crate::tui::plots::Plot;

/// What the slopes view's legend needs of where its curves lie: for each
/// curve (elastic, plastic, total, Persson's, in drawing order) the later
/// curve it lies under ([`hidden_under`]) and whether it shows at all.
/// Tracing the curves through the cells takes ~70 µs, so it is computed
/// with the curves ([`crate::tui::app::App`] keeps it next to the plot)
/// and only for the graph and dot grid it was made for.
#[derive(Clone, Debug, PartialEq)]
pub struct Cover {
    pub graph: Rect,
    pub dots: (f64, f64),
    pub under: Vec<Option<usize>>,
    pub empty: Vec<bool>,
}

impl Cover {
    /// The cover of `p`'s four curves on graph `g` with `dots` per cell.
    pub fn of(p: &Plot, g: Rect, dots: (f64, f64)) -> Cover {
        let bounds = (p.x_bounds, p.y_bounds);
        let cells: Vec<_> = [&p.elastic, &p.plastic, &p.total, &p.persson]
            .iter()
            .map(|data| cells(data, bounds, g, dots))
            .collect();
        Cover {
            graph: g,
            dots,
            under: hidden_under(&cells),
            empty: cells.iter().map(HashSet::is_empty).collect(),
        }
    }

    /// Makes `kept` the cover of `p` on `g` with `dots` per cell, unless it
    /// already is (`kept` is cleared whenever `p` changes).
    pub fn keep(kept: &mut Option<Cover>, p: &Plot, g: Rect, dots: (f64, f64)) {
        if !kept.as_ref().is_some_and(|c| c.fits(g, dots)) {
            *kept = Some(Cover::of(p, g, dots));
        }
    }

    /// Whether this cover was made for graph `g` with `dots` per cell.
    pub fn fits(&self, g: Rect, dots: (f64, f64)) -> bool {
        self.graph == g && self.dots == dots
    }
}

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
/// the later curve it lies under, when fewer than one in twenty of its
/// cells stay visible. A curve that parts from the one on top for longer
/// (fig2's total leaves Persson's line above ζ ≈ 2000) is listed on its
/// own: "total = Persson here" would not hold there.
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
            if visible * 20 >= own.len() {
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
    use crate::tui::app::{update, App, Message};
    use crate::tui::layout::Regions;
    use crate::tui::theme::Theme;

    #[test]
    fn the_cover_is_kept_with_the_curves() {
        let preset = crate::presets::load("fig3").unwrap();
        let mut app = App::new(preset, Theme::colored(), (120, 40));
        let g = Regions::of_size(app.size).unwrap().slopes_graph();
        let fits = |app: &App| {
            let dots = app.theme.glyphs.dots();
            let c = app.plot_cover.clone().unwrap();
            assert!(c.fits(g, dots));
            assert_eq!(c, Cover::of(&app.plot, g, dots));
            c
        };
        // fig3: elastic and total equal Persson's slope, drawn over them;
        // the plastic slope lies below the chart.
        let c = fits(&app);
        assert_eq!(c.under, vec![Some(3), None, Some(3), None]);
        assert_eq!(c.empty, vec![false, true, false, false]);
        // Kept while nothing it depends on changes ...
        update(&mut app, Message::SelectNext);
        assert_eq!(app.plot_cover, Some(c.clone()));
        // ... and made again for other glyphs, another size, other curves.
        update(&mut app, Message::CycleGlyphs);
        assert_ne!(app.plot_cover.as_ref().unwrap().dots, c.dots);
        fits(&app);
        update(&mut app, Message::Resize(100, 30));
        let g2 = Regions::of_size(app.size).unwrap().slopes_graph();
        assert!(app
            .plot_cover
            .as_ref()
            .unwrap()
            .fits(g2, app.theme.glyphs.dots()));
        update(&mut app, Message::Resize(120, 40));
        update(&mut app, Message::ToggleSizeEffect);
        fits(&app);
    }

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
