//! The load view: contact areas A/A0 against the load p̄/H from 0 to 1 at
//! the current parameters (elastic, plastic, total, for the model in use),
//! with the initial-slope line of the slopes view drawn from the origin.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;

use super::chart::{self, Scale};
use crate::physical::print::fmt_num;
use crate::tui::app::App;

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let s = &app.state;
    let p = &app.load;
    let (h, psi_name) = if s.size_effect {
        ("H_y", "Ψ*")
    } else {
        ("H0", "Ψ_P")
    };
    // At the marker the areas give the share (and Ψ): while a claim's
    // poll is open they wait, as the readout's values do.
    let hidden = app.class.marks_hidden();
    let (psi, slope) = if hidden {
        ("?".into(), "?".into())
    } else {
        (fmt_num(app.readout.psi), fmt_num(p.slope))
    };
    let gl = t.glyphs;
    let mut title = format!("A/A0 vs p̄/{h} · {psi_name} {psi} · initial slope {slope}");
    if Span::raw(gl.text(&title)).width() > usize::from(area.width) {
        // At 80 columns: the legend's "initial slope" is S_tot, named short.
        title = format!("A/A0 vs p̄/{h} · {psi_name} {psi} · S_tot {slope}");
    }
    let title = vec![Span::styled(title, t.title)];
    chart::title(app, title, area, buf);
    if !hidden {
        chart::legend(
            t,
            &[&t.elastic, &t.plastic, &t.total, &t.tangent],
            area,
            buf,
        );
    }
    let bounds = [0.0, 1.0];
    let (x, y) = (Scale::linear(bounds, 5.0), Scale::linear(bounds, 5.0));
    chart::axes(t, (&x, &y), &format!("p̄/{h}"), (area, g), buf);
    if hidden {
        chart::withheld(app, "the areas at the marker", g, buf);
        return;
    }
    let sets = vec![
        chart::dataset(&t.tangent, &p.tangent),
        chart::dataset(&t.elastic, &p.elastic),
        chart::dataset(&t.plastic, &p.plastic),
        chart::dataset(&t.total, &p.total),
    ];
    chart::plot(sets, (bounds, bounds), g, buf);
}
