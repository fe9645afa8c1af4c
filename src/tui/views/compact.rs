//! A served student's screen below the explorer's 80×24, down to 40×10:
//! no chart, but what following and answering need — the scene, the poll's
//! line (the question, the answer sent, the reveal), the marker's slider
//! and its value, the status and the keys that act here.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

use super::side::slider_bar;
use crate::class::UNICODE;
use crate::physical::print::{fmt_param, fmt_short};
use crate::tui::app::App;
use crate::tui::wrap::wrap;

/// The smallest terminal the compact screen draws in.
pub const MIN: (u16, u16) = (40, 10);

/// Whether `app` draws the compact screen: a served student's terminal
/// below the explorer's smallest size but at least [`MIN`].
pub fn applies(app: &App) -> bool {
    app.student && app.too_small() && app.size.0 >= MIN.0 && app.size.1 >= MIN.1
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let g = t.glyphs;
    let w = usize::from(area.width);
    let tx = |s: &str| g.text(s).into_owned();
    let mut lines = vec![Line::styled(
        tx(&format!(" roughtui [{}]", app.state.name)),
        t.title,
    )];
    match app.class.asked.as_ref() {
        Some(a) => {
            let style = if a.revealed { t.ok } else { t.title };
            let text = tx(&a.line(&UNICODE, usize::MAX));
            for l in wrap(&text, w, 4, g.cut()) {
                lines.push(Line::styled(l, style));
            }
        }
        None => lines.push(Line::styled(
            tx("the charts need 80×24: enlarge to see them"),
            t.dim,
        )),
    }
    lines.push(Line::raw(""));
    let axis = app.selected_axis();
    let (lo, hi) = app.range(axis);
    let v = app.state.params.get(axis);
    lines.push(Line::styled(
        tx(&format!(
            "{} = {}   ({}…{})",
            axis.symbol(),
            fmt_param(axis, v).trim(),
            fmt_short(axis, lo),
            fmt_short(axis, hi)
        )),
        t.selected,
    ));
    let bar = slider_bar(
        g.slider_bar(),
        axis,
        v,
        (lo, hi),
        w.saturating_sub(2).min(60),
    );
    lines.push(Line::styled(format!(" {bar}"), t.title));
    let top = area.height.saturating_sub(2);
    Paragraph::new(lines).render(
        Rect {
            height: top,
            ..area
        },
        buf,
    );
    if let Some(s) = &app.status {
        let style = if s.error { t.error } else { t.ok };
        Line::styled(tx(&s.text), style)
            .render(Rect::new(area.x, area.y + top, area.width, 1), buf);
    }
    let mut keys = Vec::new();
    match app.class.asked {
        Some(a) if a.revealed => keys.push("⏎ dismiss"),
        Some(_) => keys.push("⏎ answer"),
        None => {}
    }
    keys.push("←→ move");
    if app.lecturer_keys {
        keys.push("f follow");
    }
    keys.push("q quit");
    Line::styled(tx(&keys.join("  ")), t.dim).render(
        Rect::new(area.x, area.y + area.height - 1, area.width, 1),
        buf,
    );
}
