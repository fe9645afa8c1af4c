//! Drawing: `impl Widget for &App`, split into `(area, buf)` helpers, one
//! view per file. Reads the app, never changes it; where things go comes
//! from [`Regions`].

mod chart;
pub mod class;
pub mod compact;
pub mod contact;
mod indices;
mod join;
mod load;
mod map;
pub(crate) mod overlap;
mod projector;
mod side;
pub use side::hurst_se;
mod slopes;
mod spectrum;

pub use map::{ansi16, contour_color, share_color};

use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::app::{App, Mode};
use super::glyphs::Glyphs;
use super::keys;
use super::layout::{Regions, MIN_SIZE};
use super::{help, status};
use crate::class::{ClaimsRow, UNICODE};
use crate::figure::{Claim, View};
use crate::physical::print::fmt_short;
use crate::tui::wrap::wrap;

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        if self.class.join_shown {
            return join::render(self, area, buf);
        }
        if self.class.projector && self.mode == Mode::Main {
            return projector::render(self, area, buf);
        }
        let rows = crate::tui::caption::rows(self);
        let Some(r) = Regions::with_caption(area, rows) else {
            if compact::applies(self) {
                compact::render(self, area, buf);
            } else {
                render_too_small(self, area, buf);
            }
            return;
        };
        render_header(self, r.header, buf);
        render_caption(self, r.caption, buf);
        side::render_sliders(self, r.sliders, r.slider_rows, buf);
        side::render_readout(self, r.readout, buf);
        let chart = (r.chart, r.graph_of(self.view));
        match self.view {
            View::Slopes => slopes::render(self, chart, buf),
            View::Indices => indices::render(self, chart, buf),
            View::Map => map::render(self, chart, buf),
            View::Load => load::render(self, chart, buf),
            View::Spectrum => spectrum::render(self, chart, buf),
            View::Contact => contact::render(self, chart, buf),
        }
        class::render_poll(self, chart, buf);
        render_footer(self, r.footer, buf);
        status::render_status(self, r.status, r.footer, buf);
        if self.mode == Mode::Help {
            help::render_help(self, area, buf);
        }
        if self.mode == Mode::Class {
            class::render_list(self, area, buf);
        }
        super::scenes::render(self, area, buf);
    }
}

fn render_too_small(app: &App, area: Rect, buf: &mut Buffer) {
    if area.width == 0 || area.height == 0 {
        return;
    }
    let text = format!(
        "enlarge the terminal to {}×{} (now {}×{}) · q quits",
        MIN_SIZE.0, MIN_SIZE.1, area.width, area.height
    );
    let text = app.theme.glyphs.text(&text).into_owned();
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
    let g = t.glyphs;
    let axis = s.sweep.axis();
    // A snapshot's name is untrusted text: no control characters reach the
    // terminal, and in ASCII names nothing else outside ASCII.
    let clean = |text: &str| -> String {
        let text: String = text
            .chars()
            .map(|c| if c.is_control() { '�' } else { c })
            .collect();
        g.text(&text).into_owned()
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
        let text = format!(
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
        );
        g.text(&text).into_owned()
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
        name = name.chars().take(keep).chain([g.cut()]).collect();
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
/// where the figure's claims hold at the current parameters. In a served
/// class the lecturer's class line comes first, and a student's poll line
/// stands in for the claims.
fn render_caption(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let g = t.glyphs;
    let mut lines: Vec<Line> = class::class_line(app).into_iter().collect();
    if let Some(step) = &app.class.step {
        lines.push(Line::styled(g.text(&step.text()).into_owned(), t.title));
    }
    let rows = usize::from(area.height.saturating_sub(1)).saturating_sub(lines.len());
    // While a poll is open the caption (which may name the answer) waits.
    // (A lesson's captions are its author's, written for the poll.)
    let text = g.text(crate::tui::caption::text(app));
    lines.extend(
        wrap(&text, usize::from(area.width), rows, g.cut())
            .into_iter()
            .map(|l| Line::styled(l, t.dim)),
    );
    lines.resize(usize::from(area.height.saturating_sub(1)), Line::raw(""));
    let last = match app.class.claims_row() {
        ClaimsRow::Asked(a) => class::poll_line(app, a, usize::from(area.width)),
        ClaimsRow::Open(tally) => class::open_poll_line(app, tally),
        ClaimsRow::Asks(q) => {
            // A lesson's step about to poll: its question, not its answer.
            let how = if app.class.view.is_some() || app.class.lesson.is_some() {
                " · v opens the poll"
            } else {
                ""
            };
            let text = format!("this step asks: {}{how}", q.text(&UNICODE));
            Line::styled(g.text(&text).into_owned(), t.title)
        }
        // A lesson's step before a poll: the claims would answer it.
        ClaimsRow::Waiting => Line::styled(
            g.text("(this step's claims show after the lesson's next poll)")
                .into_owned(),
            t.claims,
        ),
        ClaimsRow::Claims => Line::styled(
            claims_line(&app.claims, usize::from(area.width), g),
            t.claims,
        ),
    };
    lines.push(last);
    Paragraph::new(lines).render(area, buf);
}

/// The claims joined by " · " in at most `width` columns. Whole claims
/// only: one that does not fit is left out, never cut inside its number.
/// Of three ways to write them — full sentences; each in full where it
/// fits, else short; all short ("Ψ_P = 1 at E/H0 = 191.2" for "Ψ_P falls
/// below 1 at H0/E = 0.00523 (E/H0 = 191.2)") — the first that shows the
/// most claims.
pub fn claims_line(claims: &[Claim], width: usize, g: Glyphs) -> String {
    let fits = |s: &str| Span::raw(s).width() <= width;
    let dot = g.text(" · ");
    let fit = |forms: &dyn Fn(&Claim) -> Vec<String>| {
        let (mut line, mut shown) = (String::new(), 0);
        for c in claims {
            let joined = |text: &String| {
                let text = g.text(text);
                if line.is_empty() {
                    text.into_owned()
                } else {
                    format!("{line}{dot}{text}")
                }
            };
            if let Some(next) = forms(c).iter().map(joined).find(|l| fits(l)) {
                line = next;
                shown += 1;
            }
        }
        (shown, line)
    };
    let full = fit(&|c| vec![c.text()]);
    let either = fit(&|c| vec![c.text(), c.short_text()]);
    let short = fit(&|c| vec![c.short_text()]);
    // max_by_key keeps the last of equals: list the preferred last.
    [short, either, full]
        .into_iter()
        .enumerate()
        .max_by_key(|(k, (shown, _))| (*shown, *k))
        .map(|(_, (_, line))| line)
        .unwrap_or_default()
}

fn render_footer(app: &App, area: Rect, buf: &mut Buffer) {
    let text = keys::footer(app, usize::from(area.width));
    Line::styled(text, app.theme.dim).render(area, buf);
}

#[cfg(test)]
mod tests {
    use super::claims_line;
    use crate::figure::{claims, Claim};
    use crate::tui::glyphs::Glyphs;

    fn preset(name: &str) -> Vec<Claim> {
        claims(&crate::presets::load(name).unwrap())
    }

    #[test]
    fn claims_are_whole_and_as_many_as_fit() {
        let fig4 = preset("fig4");
        // All in full when they fit.
        let all = claims_line(&fig4, 200, Glyphs::Braille);
        assert_eq!(all.matches(" · ").count(), 2, "{all}");
        // Full sentences keep the place when short ones show no more.
        assert_eq!(
            claims_line(&fig4, 80, Glyphs::Braille),
            "plastic share falls below ½ at ζ = 1.698e4 · Ψ* falls below 1 at ζ = 5324"
        );
        // Short forms when they show more; whole claims only, at any width.
        let fig1 = preset("fig1");
        assert_eq!(
            claims_line(&fig1, 60, Glyphs::Braille),
            "plastic share ½ at E/H0 = 120.2 · Ψ_P = 1 at E/H0 = 191.2"
        );
        for w in 0..200 {
            let line = claims_line(&fig1, w, Glyphs::Braille);
            assert!(line.chars().count() <= w, "{w}: {line}");
            for part in line.split(" · ").filter(|p| !p.is_empty()) {
                assert!(
                    fig1.iter()
                        .any(|c| c.text() == part || c.short_text() == part),
                    "{w}: {part}"
                );
            }
        }
        assert_eq!(claims_line(&[], 80, Glyphs::Braille), "");
        // In ASCII the names are spelled out, and still whole.
        assert_eq!(
            claims_line(&fig1, 80, Glyphs::Ascii),
            "plastic share 1/2 at E/H0 = 120.2 | Psi_P = 1 at E/H0 = 191.2"
        );
    }
}
