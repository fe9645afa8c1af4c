//! Drawing: `impl Widget for &App`, split into `(area, buf)` helpers, one
//! view per file. Reads the app, never changes it; where things go comes
//! from [`Regions`].

mod chart;
mod indices;
mod load;
mod map;
mod overlap;
mod side;
mod slopes;
mod spectrum;

use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::app::{App, Mode};
use super::fmt::{fmt_short, wrap};
use super::keys;
use super::layout::{Regions, MIN_SIZE};
use super::{help, status};
use crate::figure::View;

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let Some(r) = Regions::of(area) else {
            render_too_small(area, buf);
            return;
        };
        render_header(self, r.header, buf);
        render_caption(self, r.caption, buf);
        side::render_sliders(self, r.sliders, r.slider_rows, buf);
        side::render_readout(self, r.readout, buf);
        let chart = (r.chart, r.graph);
        match self.view {
            View::Slopes => slopes::render(self, chart, buf),
            View::Indices => indices::render(self, chart, buf),
            View::Map => map::render(self, chart, buf),
            View::Load => load::render(self, chart, buf),
            View::Spectrum => spectrum::render(self, chart, buf),
        }
        render_footer(self, r.footer, buf);
        status::render_status(self, r.status, r.footer, buf);
        if self.mode == Mode::Help {
            help::render_help(self, area, buf);
        }
    }
}

fn render_too_small(area: Rect, buf: &mut Buffer) {
    if area.width == 0 || area.height == 0 {
        return;
    }
    let text = format!(
        "enlarge the terminal to {}×{} (now {}×{}) · q quits",
        MIN_SIZE.0, MIN_SIZE.1, area.width, area.height
    );
    let y = area.y + area.height.saturating_sub(2) / 2;
    let r = Rect::new(area.x, y, area.width, area.height - (y - area.y));
    Paragraph::new(text)
        .alignment(Alignment::Center)
        .wrap(Wrap { trim: true })
        .render(r, buf);
}

fn render_header(app: &App, area: Rect, buf: &mut Buffer) {
    let s = &app.state;
    let t = &app.theme;
    let axis = s.sweep.axis();
    // A snapshot's name is untrusted text: no control characters reach the terminal.
    let clean = |text: &str| -> String {
        text.chars()
            .map(|c| if c.is_control() { '�' } else { c })
            .collect()
    };
    let mut name = clean(&s.name);
    // Where the name and file do not both fit, the file alone.
    let mut file_only = None;
    if let Some(f) = &app.file {
        // A file saved under the scene's name is named once.
        let f = clean(f);
        let stem = std::path::Path::new(&f).file_stem();
        if stem.and_then(|x| x.to_str()) != Some(name.as_str()) {
            name = format!("{name} · {f}");
            file_only = Some(f);
        } else {
            name = f;
        }
    }
    let star = if app.modified { "*" } else { "" };
    let scene = |moments: &str| {
        format!(
            "  {} {}…{} · {} · {}{moments} · size effect {}",
            axis.symbol(),
            fmt_short(axis, s.sweep.from()),
            fmt_short(axis, s.sweep.to()),
            s.model.label(),
            if s.is_measured() {
                "measured"
            } else {
                s.moments.label()
            },
            if s.size_effect { "on" } else { "off" },
        )
    };
    // At 80 columns: first the word "moments" goes, then the end of a long
    // name, rather than the end of the scene (the size effect's state).
    let width = |text: &str| Span::raw(text).width();
    let room = |rest: &str| {
        usize::from(area.width).saturating_sub(" roughtui []".len() + star.len() + width(rest))
    };
    let mut rest = scene(" moments");
    if width(&name) > room(&rest) {
        rest = scene("");
    }
    let room = room(&rest);
    if width(&name) > room {
        name = file_only.unwrap_or(name);
    }
    if width(&name) > room {
        let keep = room.saturating_sub(1);
        name = name.chars().take(keep).chain(['…']).collect();
    }
    let name = format!("[{name}{star}]");
    let line = Line::from(vec![
        Span::styled(" roughtui ", t.title),
        Span::styled(name, t.selected),
        Span::raw(rest),
    ]);
    line.render(area, buf);
}

/// The caption, wrapped over all rows but the last, and on the last row
/// where the figure's claims hold at the current parameters.
fn render_caption(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let rows = usize::from(area.height.saturating_sub(1));
    let text = app.state.caption.as_deref().unwrap_or("");
    let mut lines: Vec<Line> = wrap(text, usize::from(area.width), rows)
        .into_iter()
        .map(|l| Line::styled(l, t.dim))
        .collect();
    lines.resize(rows, Line::raw(""));
    // Whole claims only: one that does not fit is left out, never cut
    // inside its number.
    let mut claims = String::new();
    for c in &app.claims {
        let next = if claims.is_empty() {
            c.text()
        } else {
            format!("{claims} · {}", c.text())
        };
        if Span::raw(&next).width() <= usize::from(area.width) {
            claims = next;
        }
    }
    lines.push(Line::styled(claims, t.ok));
    Paragraph::new(lines).render(area, buf);
}

fn render_footer(app: &App, area: Rect, buf: &mut Buffer) {
    let text = keys::footer(app, usize::from(area.width));
    Line::styled(text, app.theme.dim).render(area, buf);
}
