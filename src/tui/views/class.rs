//! The class, drawn like any other panel: the lecturer's class line over
//! the caption, a student's poll line in place of the claims, the poll's
//! answers as a histogram along the chart's x axis, and the class list.
//! Their text goes through the session's [`Glyphs`] (ASCII names outside
//! braille), their drawing characters come from a [`ClassGlyphs`] chosen
//! by it, so the ASCII set stays all ASCII.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

use super::chart;
use crate::class::{duration, Asked, ClassGlyphs, Tally, ASCII, UNICODE};
use crate::figure::View;
use crate::tui::app::App;
use crate::tui::glyphs::Glyphs;
use crate::tui::plots::to_plot;

/// The histogram's characters in the half-block and block sets: only the
/// blocks every console font has.
const BLOCKS: ClassGlyphs = ClassGlyphs {
    bars: ["▄", "▄", "▄", "▄", "█", "█", "█", "█"],
    truth: "│",
    ..ASCII
};

/// The class panels' drawing characters for a glyph set.
pub fn glyphs(g: Glyphs) -> &'static ClassGlyphs {
    match g {
        Glyphs::Braille => &UNICODE,
        Glyphs::Half | Glyphs::Block => &BLOCKS,
        Glyphs::Ascii => &ASCII,
    }
}

/// `text` as the session's glyphs write it.
fn text(app: &App, text: &str) -> String {
    app.theme.glyphs.text(text).into_owned()
}

/// The lecturer's class line ("31 students · 28 following · …").
pub fn class_line(app: &App) -> Option<Line<'static>> {
    let v = app.class.view.as_ref()?;
    Some(Line::styled(text(app, &v.line(&UNICODE)), app.theme.title))
}

/// A student's poll line, which stands in for the claims while a poll is on.
pub fn poll_line(app: &App, a: &Asked, width: usize) -> Line<'static> {
    let style = if a.revealed {
        app.theme.ok
    } else {
        app.theme.title
    };
    // Fitted to the width as it will be written.
    let mut line = text(app, &a.line(&UNICODE, width));
    if Span::raw(&line).width() > width {
        line = text(app, &a.line(&UNICODE, width.saturating_sub(8)));
    }
    Line::styled(line, style)
}

/// The lecturer's line in place of the claims while a poll is open
/// ("poll open: 23/31 answered"): the screen is on the projector.
pub fn open_poll_line(app: &App, t: &Tally) -> Line<'static> {
    let line = format!(
        "poll open: {}/{} answered{}v reveals{}C cancels",
        t.answers.len(),
        t.asked,
        UNICODE.sep,
        UNICODE.sep
    );
    Line::styled(text(app, &line), app.theme.title)
}

fn bar_style(app: &App) -> Style {
    if app.theme.color {
        Style::new().fg(Color::Cyan)
    } else {
        Style::new()
    }
}

/// Histogram cells per column of `width`: counts of `answers` by the
/// column the chart (drawn with `dots` points per cell) puts them in.
pub fn bins(answers: &[f64], log: bool, dots: (f64, f64), bounds: [f64; 2], g: Rect) -> Vec<usize> {
    let mut bins = vec![0; usize::from(g.width)];
    for &v in answers {
        if let Some(col) = chart::col_of(g, dots, bounds, to_plot(log, v)) {
            if let Some(b) = bins.get_mut(usize::from(col - g.x)) {
                *b += 1;
            }
        }
    }
    bins
}

/// The lecturer's poll on the chart: the answers as a histogram along the
/// x axis (where the chart's x axis is the polled parameter), the count,
/// and after the reveal the true value's column.
pub fn render_poll(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    // The lecturer's tally, or the answers the lecturer showed everyone.
    let lecturer = app.class.view.as_ref().and_then(|v| v.poll.as_ref());
    let Some(t) = lecturer.or(app.class.tally.as_ref()) else {
        return;
    };
    // A revealed poll's answers show on its own sweep only.
    if t.revealed && t.sweep != app.state.sweep {
        return;
    }
    let gl = glyphs(app.theme.glyphs);
    let dots = app.theme.glyphs.dots();
    let axis = t.question.axis;
    let along = app.state.sweep.axis() == axis && app.view != View::Load;
    let mut label = format!(" {} ", t.count(&UNICODE));
    if !along {
        label.push_str(&format!("· on a chart along {} ", axis.symbol()));
    }
    let label = text(app, &label);
    let w = Span::raw(&label).width() as u16;
    let x = g.right().saturating_sub(w).max(area.x);
    buf.set_stringn(
        x,
        g.y,
        &label,
        usize::from(area.right() - x),
        app.theme.title.add_modifier(Modifier::REVERSED),
    );
    if !along || g.height < 2 {
        return;
    }
    let s = &app.state.sweep;
    let log = axis.is_log();
    let bounds = [to_plot(log, s.from()), to_plot(log, s.to())];
    let bins = bins(&t.answers, log, dots, bounds, g);
    let max = bins.iter().copied().max().unwrap_or(0);
    let rows = (g.height / 2).max(1);
    let style = bar_style(app);
    if max > 0 {
        for (i, &n) in bins.iter().enumerate() {
            if n == 0 {
                continue;
            }
            // In eighths of a cell, at least one.
            let eighths = (n * usize::from(rows) * 8).div_ceil(max).max(1);
            let col = g.x + i as u16;
            for r in 0..rows {
                let left = eighths.saturating_sub(usize::from(r) * 8);
                if left == 0 {
                    break;
                }
                let sym = gl.bars[left.min(8) - 1];
                buf[(col, g.bottom() - 1 - r)]
                    .set_symbol(sym)
                    .set_style(style);
            }
        }
    }
    if t.revealed {
        if let Some(col) = chart::col_of(g, dots, bounds, to_plot(log, t.question.truth)) {
            let truth = Style::new().fg(Color::Yellow).add_modifier(Modifier::BOLD);
            for r in 0..rows {
                let cell = &mut buf[(col, g.bottom() - 1 - r)];
                if !gl.bars.contains(&cell.symbol()) {
                    cell.set_symbol(gl.truth).set_style(truth);
                }
            }
        }
    }
}

/// The class list: name, following or not, how they reach the class (ssh,
/// web, phone), terminal size, marker set and idle time of each student,
/// in pages when the class is long.
pub fn render_list(app: &App, area: Rect, buf: &mut Buffer) {
    let Some(v) = &app.class.view else {
        return;
    };
    let g = &UNICODE;
    let t = &app.theme;
    // 78 columns a row, 80 with the frame: the list fits an 80×24 terminal.
    let header = format!(
        " {:<32}  {:<12}  {:<5}  {:>7} {:<7} {:>6}",
        "name", "state", "via", "size", "marker", "idle"
    );
    let rows: Vec<String> = v
        .seats
        .iter()
        .map(|s| {
            // 32 columns as written (ASCII names are longer: ζ is zeta).
            let mut name = text(app, &s.name);
            if Span::raw(&name).width() > 32 {
                let mut cut = String::new();
                for c in name.chars() {
                    if Span::raw(format!("{cut}{c}")).width() > 31 {
                        break;
                    }
                    cut.push(c);
                }
                cut.push(app.theme.glyphs.cut());
                name = cut;
            }
            let pad = 32usize.saturating_sub(Span::raw(&name).width());
            let size = if s.via == "phone" {
                text(app, "—")
            } else {
                text(app, &format!("{}{}{}", s.size.0, g.times, s.size.1))
            };
            format!(
                " {name}{}  {:<12}  {:<5}  {size:>7} {:<7} {:>6}",
                " ".repeat(pad),
                s.state.label(),
                s.via,
                text(app, &s.marker),
                duration(s.idle),
            )
        })
        .collect();
    let w = 80.min(area.width);
    let h = (rows.len() as u16 + 3).clamp(4, area.height);
    let per_page = usize::from(h - 3).max(1);
    let pages = rows.len().div_ceil(per_page).max(1);
    // The page of the chosen student, → ← paging on from there.
    let chosen = app.class.chosen.min(rows.len().saturating_sub(1));
    let page = (app.help_page + chosen / per_page) % pages;
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    // The keys and the page first: the class line may be cut.
    let mut title = format!(" w closes{}↑↓ x removes", g.sep);
    if pages > 1 {
        title.push_str(&format!("{}page {}/{pages}", g.sep, page + 1));
    }
    title.push_str(&format!("{}{} ", g.sep, v.line(g)));
    let title = text(app, &title);
    let mut lines = vec![Line::styled(header, t.title)];
    if rows.is_empty() {
        lines.push(Line::raw(" no students yet"));
    }
    lines.extend(
        rows.into_iter()
            .enumerate()
            .skip(page * per_page)
            .take(per_page)
            .map(|(i, row)| {
                if i == chosen {
                    Line::styled(row, t.selected)
                } else {
                    Line::raw(row)
                }
            }),
    );
    Clear.render(r, buf);
    Paragraph::new(lines)
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_set(app.theme.glyphs.border())
                .title(title),
        )
        .render(r, buf);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_fall_in_the_columns_the_chart_puts_them() {
        let g = Rect::new(10, 0, 40, 10);
        let b = bins(
            &[1.0, 1.0, 1e4, 100.0, 1e5, 0.5],
            true,
            (2.0, 4.0),
            [0.0, 4.0],
            g,
        );
        assert_eq!(b.iter().sum::<usize>(), 4, "outside the sweep: not drawn");
        assert_eq!(b[0], 2);
        assert_eq!(b[39], 1);
        assert_eq!(b[20], 1);
    }
}
