//! The index view: Ψ_GW, Ψ_P, Ψ* and eq. 13's Ψ*asy against the swept
//! parameter on log axes, with a line at Ψ = 1 — the paper's point that Ψ_P
//! grows with magnification while Ψ* falls, read as a picture.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;

use super::chart::{self, Scale};
use crate::tui::app::App;
use crate::tui::theme::CurveStyle;

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
    // Eq. 13 drawn under Ψ* where they meet: the legend says so when they
    // meet everywhere (within a braille dot row).
    let dot = (p.y_bounds[1] - p.y_bounds[0]) / (t.glyphs.dots().1 * f64::from(g.height));
    let under = !p.psi_star_asymptotic.is_empty()
        && p.psi_star_asymptotic.len() == p.psi_star.len()
        && (p.psi_star_asymptotic.iter().zip(&p.psi_star)).all(|(a, b)| (a.1 - b.1).abs() < dot);
    let asy = CurveStyle {
        name: if under {
            "eq.13 under Ψ*"
        } else {
            t.psi_asy.name
        },
        ..t.psi_asy
    };
    // Eq. 13 is a power law's: not listed on a measured surface.
    let curves: Vec<&CurveStyle> = if app.state.is_measured() {
        vec![&t.psi_gw, &t.psi_p, &t.psi_star, &t.psi_one]
    } else {
        vec![&t.psi_gw, &t.psi_p, &t.psi_star, &asy, &t.psi_one]
    };
    chart::legend(t, &curves, area, buf);
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
