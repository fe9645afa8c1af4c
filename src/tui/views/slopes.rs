//! The slopes view: the paper's curves, H·dA/dp̄/A0 against the swept
//! parameter for elastic, plastic, total and Persson's elastic slope.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;

use super::chart::{self, Scale};
use crate::tui::app::App;

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let axis = app.state.sweep.axis();
    if g.width < 2 || g.height < 2 {
        return;
    }
    let p = &app.plot;
    let norm = if app.state.size_effect { "H_y" } else { "H0" };
    let title = vec![Span::styled(
        format!("slope {norm}·dA/dp̄/A0 vs {}", axis.symbol()),
        t.title,
    )];
    chart::title(app, title, area, buf);
    chart::legend(&[&t.elastic, &t.plastic, &t.total, &t.persson], area, buf);
    let (x, y) = (Scale::of_axis(axis, p.x_bounds), Scale::decades(p.y_bounds));
    chart::axes(t, (&x, &y), axis.symbol(), (area, g), buf);

    // The curves, over the marker line.
    let marker = chart::marker_line(app, p.y_bounds);
    let sets = vec![
        chart::dataset(&t.marker_line, &marker),
        chart::dataset(&t.persson, &p.persson),
        chart::dataset(&t.elastic, &p.elastic),
        chart::dataset(&t.plastic, &p.plastic),
        chart::dataset(&t.total, &p.total),
    ];
    chart::plot(sets, (p.x_bounds, p.y_bounds), g, buf);
}
