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
    // While a poll's answer waits, the index that gives it is not drawn
    // (the legend says it comes after the reveal).
    let withheld = app.class.withheld(app.state.size_effect).indices;
    let wait = |c: &CurveStyle| {
        let short = c.name.split_whitespace().next().unwrap_or(c.name);
        format!("{short} ?")
    };
    // Eq. 13 is a power law's: not listed on a measured surface.
    let styles = [&t.psi_gw, &t.psi_p, &t.psi_star, &asy];
    let mut curves: Vec<(&CurveStyle, String)> = styles
        .iter()
        .zip(withheld)
        .take(if app.state.is_measured() { 3 } else { 4 })
        .map(|(c, w)| (*c, if w { wait(c) } else { c.name.to_string() }))
        .collect();
    curves.push((&t.psi_one, t.psi_one.name.to_string()));
    chart::legend_named(t, &curves, area, buf);
    let (x, y) = (Scale::of_axis(axis, p.x_bounds), Scale::decades(p.y_bounds));
    chart::axes(t, (&x, &y), axis.symbol(), (area, g), buf);

    let marker = chart::marker_line(app, p.y_bounds);
    let one = [(p.x_bounds[0], 0.0), (p.x_bounds[1], 0.0)];
    let mut sets = vec![
        chart::dataset(&t.psi_one, &one),
        chart::dataset(&t.marker_line, &marker),
    ];
    // Drawn in this order: eq. 13 under Ψ*.
    for (i, c, data) in [
        (0, &t.psi_gw, &p.psi_gw),
        (3, &t.psi_asy, &p.psi_star_asymptotic),
        (1, &t.psi_p, &p.psi_p),
        (2, &t.psi_star, &p.psi_star),
    ] {
        if !withheld[i] {
            sets.push(chart::dataset(c, data));
        }
    }
    chart::plot(sets, (p.x_bounds, p.y_bounds), g, buf);
}
