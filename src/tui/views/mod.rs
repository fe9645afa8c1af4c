//! Drawing: `impl Widget for &App`, split into `(area, buf)` helpers, one
//! view per file. Reads the app, never changes it; where things go comes
//! from [`Regions`].

mod chart;
mod indices;
mod load;
mod map;
mod side;
mod slopes;

use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget, Wrap};

use super::app::{App, Mode};
use super::fmt::{fmt_short, wrap};
use super::keys::{self, Context};
use super::layout::{Regions, MIN_SIZE};
use crate::figure::{View, ELASTIC_BELOW, PLASTIC_ABOVE};

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
        }
        render_status(self, r.status, buf);
        render_footer(self, r.footer, buf);
        if self.mode == Mode::Help {
            render_help(self, area, buf);
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
    let clean: String = s
        .name
        .chars()
        .map(|c| if c.is_control() { '�' } else { c })
        .collect();
    let name = if app.modified {
        format!("{clean}*")
    } else {
        clean
    };
    let line = Line::from(vec![
        Span::styled(" roughtui ", t.title),
        Span::styled(format!("[{name}]"), t.selected),
        Span::raw(format!(
            "  {} {}…{} · {} · {} moments · size effect {}",
            axis.symbol(),
            fmt_short(axis, s.sweep.from()),
            fmt_short(axis, s.sweep.to()),
            s.model.label(),
            s.moments.label(),
            if s.size_effect { "on" } else { "off" },
        )),
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
    let claims: Vec<String> = app.claims.iter().map(|c| c.text()).collect();
    lines.push(Line::styled(claims.join(" · "), t.ok));
    Paragraph::new(lines).render(area, buf);
}

fn render_status(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let line = match (&app.mode, &app.status) {
        (Mode::Prompt(stem), status) => {
            let mut spans = vec![
                Span::styled("save as: ", t.title),
                Span::raw(stem.clone()),
                Span::styled(" ", Style::new().add_modifier(Modifier::REVERSED)),
                Span::raw(".ron  (Enter saves, Esc cancels)"),
            ];
            if let Some(s) = status.as_ref().filter(|s| s.error) {
                spans.push(Span::styled(format!("  {}", s.text), t.error));
            }
            Line::from(spans)
        }
        (_, Some(s)) => Line::styled(s.text.clone(), if s.error { t.error } else { t.ok }),
        (_, None) => Line::styled(
            "? help · the ↔ slider moves the marker · the readout is at the marker",
            t.dim,
        ),
    };
    line.render(area, buf);
}

fn render_footer(app: &App, area: Rect, buf: &mut Buffer) {
    let text = keys::footer(&app.mode, usize::from(area.width));
    Line::styled(text, app.theme.dim).render(area, buf);
}

fn render_help(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let mut lines = Vec::new();
    let mut prompt_heading = false;
    for b in keys::BINDINGS {
        if b.context == Context::Prompt && !prompt_heading {
            lines.push(Line::styled("in the save prompt:", t.title));
            prompt_heading = true;
        }
        lines.push(Line::from(vec![
            Span::styled(format!(" {:<12}", b.label), t.title),
            Span::raw(b.help),
        ]));
    }
    lines.push(Line::styled(
        format!(
            "regimes: elastic < {:.0}% < elasto-plastic < {:.0}% < plastic",
            ELASTIC_BELOW * 100.0,
            PLASTIC_ABOVE * 100.0
        ),
        t.title,
    ));
    lines.push(Line::raw(
        " (plastic share S_pl/S_tot): this program's thresholds; the paper sets none",
    ));
    let h = (lines.len() as u16 + 2).min(area.height);
    let w = 78.min(area.width);
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    Clear.render(r, buf);
    Paragraph::new(lines)
        .block(
            Block::default()
                .borders(Borders::ALL)
                .title(" keys · Esc or ? closes "),
        )
        .render(r, buf);
}
