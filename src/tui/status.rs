//! The status row and, below it, the footer row: a prompt with its cursor and
//! its reason for refusing; a status message wrapped over both rows when it
//! is longer than the terminal is wide, so the reason is always visible.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Widget};

use super::app::{App, Message, Mode, Status};
use super::glyphs::Glyphs;
use super::line_edit::LineEdit;
use crate::physical::print::{fmt_param, fmt_short};
use crate::physical::value;
use crate::scene::{State, View};
use rough_model::Axis;

/// Advice that holds only in some states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hint {
    /// R* is swept while the size effect is off, so the curves are flat.
    RStarNeedsSizeEffect,
    /// The swept parameter was typed outside the sweep: no marker shows.
    MarkerOffSweep,
}

impl Hint {
    pub fn text(self) -> &'static str {
        match self {
            Hint::RStarNeedsSizeEffect => "R* acts only with the size effect: press e",
            Hint::MarkerOffSweep => {
                "outside the sweep: no marker on the chart; the readout is there"
            }
        }
    }

    /// Whether the hint still applies to `state`.
    pub fn applies(self, state: &State) -> bool {
        match self {
            Hint::RStarNeedsSizeEffect => state.sweep.axis() == Axis::RStar && !state.size_effect,
            Hint::MarkerOffSweep => {
                let s = &state.sweep;
                let v = state.params.get(s.axis());
                !(v >= s.from() && v <= s.to())
            }
        }
    }
}

/// The text field with its cursor cell in reverse video, in at most
/// `width` cells: a longer text scrolls so that the cursor stays in sight,
/// `glyphs`' cut mark ("…") marking what is cut off. Where text is drawn in
/// ASCII a character outside it shows as `?`, one cell as it is one place
/// of the cursor.
fn field(line: &LineEdit, width: usize, glyphs: Glyphs) -> Vec<Span<'static>> {
    // The text and, at its end, the cell the cursor takes there.
    let mut cells: Vec<char> = line
        .text()
        .chars()
        .map(|c| {
            if glyphs.ascii_text() && !c.is_ascii() {
                '?'
            } else {
                c
            }
        })
        .collect();
    let n = cells.len();
    cells.push(' ');
    let cursor = line.cursor();
    let width = width.max(3);
    // The end cell only while the cursor is on it; a window of `width`
    // cells that keeps a cell right of the cursor.
    let end = if cursor == n { n + 1 } else { n };
    let from = (cursor + 2)
        .saturating_sub(width)
        .min(end.saturating_sub(width));
    let to = (from + width).min(end);
    let mut parts: [String; 3] = Default::default();
    for (k, c) in cells.iter().enumerate().take(to).skip(from) {
        let cut = (k == from && from > 0) || (k + 1 == to && to < end);
        let c = if cut && k != cursor { glyphs.cut() } else { *c };
        let part = match k.cmp(&cursor) {
            std::cmp::Ordering::Less => 0,
            std::cmp::Ordering::Equal => 1,
            std::cmp::Ordering::Greater => 2,
        };
        parts[part].push(c);
    }
    let [before, under, after] = parts;
    vec![
        Span::raw(before),
        Span::styled(under, Style::new().add_modifier(Modifier::REVERSED)),
        Span::raw(after),
    ]
}

/// `text` in at most `width` characters: when longer, its middle gives way
/// to `cut` ("…"), so that both what failed (the start) and why (the end)
/// show.
pub fn elide_middle(text: &str, width: usize, cut: char) -> String {
    let n = text.chars().count();
    if n <= width {
        return text.to_string();
    }
    if width < 2 {
        return [cut].iter().take(width).collect();
    }
    let head = (width - 1) / 3;
    let tail = width - 1 - head;
    let mut out: String = text.chars().take(head).collect();
    out.push(cut);
    out.extend(text.chars().skip(n - tail));
    out
}

/// `text`, notes joined by " · ", in at most `width` characters: the notes
/// that do not fit whole are left out, in their place at the end `cut`
/// ("· …"), so that no note loses its middle; a first note longer than
/// `width` alone has its middle elided ([`elide_middle`]).
pub fn fit_notes(text: &str, width: usize, cut: char) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let parts: Vec<&str> = text.split(" · ").collect();
    if parts[0].chars().count() + 4 > width {
        return elide_middle(text, width, cut);
    }
    let mut out = String::new();
    for p in &parts {
        let more = if out.is_empty() { 0 } else { 3 } + p.chars().count();
        // Room kept for the " · …" that says notes were left out.
        if out.chars().count() + more + 4 > width {
            continue;
        }
        if !out.is_empty() {
            out.push_str(" · ");
        }
        out.push_str(p);
    }
    out.push_str(" · ");
    out.push(cut);
    out
}

/// `status` is the status row, `below` the footer row under it.
pub fn render_status(app: &App, status: Rect, below: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let gl = t.glyphs;
    let error = app.status.as_ref().filter(|s| s.error);
    let first = match &app.mode {
        Mode::Prompt(line) => {
            let mut spans = vec![Span::styled("save as: ", t.title)];
            spans.extend(field(
                line,
                usize::from(status.width).saturating_sub(13),
                gl,
            ));
            spans.push(Span::raw(".ron"));
            Line::from(spans)
        }
        Mode::Value(axis, line) => {
            let name = gl.text(axis.symbol()).into_owned();
            let mut spans = vec![Span::styled(format!("{name} = "), t.title)];
            spans.extend(field(line, usize::from(status.width) / 3, gl));
            let units = if value::is_length(*axis) {
                "units m cm mm µm nm pm · "
            } else {
                ""
            };
            let (lo, hi) = app.range(*axis);
            let text = format!(
                "   {units}now {} · slider {}…{}",
                fmt_param(*axis, app.state.params.get(*axis)),
                fmt_short(*axis, lo),
                fmt_short(*axis, hi)
            );
            spans.push(Span::styled(gl.text(&text).into_owned(), t.dim));
            Line::from(spans)
        }
        Mode::Truth(axis, line) => {
            let mut spans = vec![Span::styled(
                gl.text(&format!("poll: the true {} = ", axis.symbol()))
                    .into_owned(),
                t.title,
            )];
            spans.extend(field(line, usize::from(status.width) / 3, gl));
            let s = &app.state.sweep;
            spans.push(Span::styled(
                gl.text(&format!(
                    "   the class answers with the marker, {}…{}",
                    fmt_short(*axis, s.from()),
                    fmt_short(*axis, s.to())
                ))
                .into_owned(),
                t.dim,
            ));
            Line::from(spans)
        }
        Mode::Main | Mode::Help | Mode::Class => {
            let w = usize::from(status.width);
            let (text, style) = match &app.status {
                Some(s) => (s.text.clone(), if s.error { t.error } else { t.ok }),
                // The ghost's line where the ghost is drawn (the slopes).
                None => match app.ghost.as_ref().filter(|_| app.view == View::Slopes) {
                    Some(g) => (format!("┄ {} · g clears it", g.label(&app.state)), t.dim),
                    None => (
                        format!(
                            "? help · the {} slider moves the marker · the readout is at the \
                             marker",
                            gl.swept()
                        ),
                        t.dim,
                    ),
                },
            };
            let text = gl.text(&text);
            // Too long for one row: continued on the footer's row; if even
            // two rows are too few, the notes that do not fit whole are
            // left out (the side panel lists them all).
            let text = fit_notes(&text, 2 * w, gl.cut());
            let (first, rest): (String, String) = (
                text.chars().take(w).collect(),
                text.chars().skip(w).collect(),
            );
            if !rest.is_empty() {
                Clear.render(below, buf);
                Line::styled(rest, style).render(below, buf);
            }
            let line = Line::styled(first, style);
            line.render(status, buf);
            return;
        }
    };
    first.render(status, buf);
    // The prompt's reason for a refusal, over the footer (its keys).
    if let Some(e) = error {
        // The prompt says what is being done; the row says why not.
        let why = e.text.strip_prefix("cannot save: ").unwrap_or(&e.text);
        let why = gl.text(why);
        Clear.render(below, buf);
        Line::styled(
            elide_middle(&why, usize::from(below.width), gl.cut()),
            t.error,
        )
        .render(below, buf);
    }
}

/// A message goes with the state it describes: "loaded fig1", "saved …"
/// or a refusal no longer hold once the scene, the slider or the view
/// changes (the action then sets its own message, if any). Hints clear
/// themselves when their condition goes.
pub(super) fn clear_stale(app: &mut App, msg: Message) {
    let moves = matches!(
        msg,
        Message::Step { .. }
            | Message::SelectPrev
            | Message::SelectNext
            | Message::CycleSweep
            | Message::ToggleModel
            | Message::ToggleSizeEffect
            | Message::ToggleMoments
            | Message::NextView
            | Message::PrevView
            | Message::NextMapY
    );
    // What the drawing is ("drawing in ASCII …", "colour off …") holds
    // until the drawing changes, whatever the scene does.
    let about_drawing =
        |s: &Status| s.text.starts_with("drawing in ") || s.text.starts_with("colour ");
    if moves
        && app
            .status
            .as_ref()
            .is_some_and(|s| s.hint.is_none() && !about_drawing(s))
    {
        app.status = None;
    }
}

#[cfg(test)]
mod tests {
    use super::{elide_middle, field, fit_notes, Glyphs, LineEdit};

    fn shown(text: &str, left: usize, width: usize) -> String {
        let mut l = LineEdit::new(text, 200);
        for _ in 0..left {
            l.apply(crate::tui::line_edit::Edit::Left);
        }
        field(&l, width, Glyphs::Braille)
            .iter()
            .map(|s| s.content.to_string())
            .collect()
    }

    #[test]
    fn a_long_field_scrolls_to_keep_the_cursor_in_sight() {
        assert_eq!(shown("abc", 0, 10), "abc ");
        assert_eq!(shown("abc", 1, 10), "abc");
        let long = "0123456789abcdefghij";
        assert_eq!(shown(long, 0, 10), "…cdefghij ");
        assert_eq!(shown(long, 20, 10), "012345678…");
        assert_eq!(shown(long, 10, 10), "…3456789a…");
    }

    #[test]
    fn long_texts_keep_their_start_and_end() {
        assert_eq!(elide_middle("short", 10, '…'), "short");
        assert_eq!(elide_middle("0123456789abcdef", 10, '…'), "012…abcdef");
        assert_eq!(
            elide_middle("0123456789abcdef", 10, '…').chars().count(),
            10
        );
        assert_eq!(elide_middle("abc", 1, '…'), "…");
        assert_eq!(elide_middle("abc", 0, '…'), "");
        // Notes that do not fit are left out whole, never cut in the middle.
        let warn = "warning: rms slope 4.1e3 at the largest ζ is above 10";
        let text = format!("{warn} · heights read in µm (the width's unit) · 3 points filled");
        assert_eq!(fit_notes(&text, 70, '…'), format!("{warn} · …"));
        assert_eq!(
            fit_notes(&text, 80, '…'),
            format!("{warn} · 3 points filled · …")
        );
        assert_eq!(fit_notes(&text, 200, '…'), text);
        assert_eq!(fit_notes("0123456789abcdef", 10, '…'), "012…abcdef");
        assert_eq!(elide_middle("0123456789abcdef", 10, '~'), "012~abcdef");
    }
}
