//! The index view: Ψ_GW, Ψ_P, Ψ* and eq. 13's Ψ*asy against the swept
//! parameter on log axes, with a line at Ψ = 1 — the paper's point that Ψ_P
//! grows with magnification while Ψ* falls, read as a picture.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;

use super::chart::{self, Scale};
use crate::tui::app::App;

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let axis = app.state.sweep.axis();
    let p = &app.indices;
    let title = vec![Span::styled(
        format!("plasticity indices vs {}", axis.symbol()),
        t.title,
    )];
    chart::title(app, title, area, buf);
    let curves = [&t.psi_gw, &t.psi_p, &t.psi_star, &t.psi_asy, &t.psi_one];
    chart::legend(&curves, area, buf);
    let (x, y) = (Scale::of_axis(axis, p.x_bounds), Scale::decades(p.y_bounds));
    chart::axes(t, (&x, &y), axis.symbol(), (area, g), buf);

    let marker = chart::marker_line(app, p.y_bounds);
    let one = [(p.x_bounds[0], 0.0), (p.x_bounds[1], 0.0)];
    let sets = vec![
        chart::dataset(&t.psi_one, &one),
        chart::dataset(&t.marker_line, &marker),
        chart::dataset(&t.psi_gw, &p.psi_gw),
        chart::dataset(&t.psi_asy, &p.psi_star_asymptotic),
        chart::dataset(&t.psi_p, &p.psi_p),
        chart::dataset(&t.psi_star, &p.psi_star),
    ];
    chart::plot(sets, (p.x_bounds, p.y_bounds), g, buf);
}
