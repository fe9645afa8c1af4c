//! The lecturer's `P`: the poll for the projector, full screen. While it
//! is open, the question and how many answered in large type (and the
//! countdown, `t`); the answers themselves wait for the reveal, so the
//! room does not copy the crowd. Once revealed: the model's answer, the
//! median answer, the share within 10 % of the model's and how many
//! answered, in large type, over the answers' histogram along the sweep
//! with the model's value marked.

use std::time::Instant;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Span;
use ratatui::widgets::{Clear, Widget};

use super::class::glyphs;
use crate::class::{fmt_value, Tally, UNICODE};
use crate::tui::app::App;
use crate::tui::big;
use crate::tui::plots::to_plot;
use crate::tui::wrap::wrap;

/// One number of the projector: what it is, its value (the part large
/// type can write is written large), a note under it.
struct Figure {
    label: String,
    value: String,
    note: String,
    style: Style,
}

impl Figure {
    /// The value's part written large, and the rest (a unit, "nowhere").
    fn split(&self) -> (&str, &str) {
        let end = self
            .value
            .char_indices()
            .find(|(_, c)| !big::fits(&c.to_string()))
            .map_or(self.value.len(), |(i, _)| i);
        let (a, b) = self.value.split_at(end);
        let a = a.trim_end();
        if a.trim().is_empty() {
            ("", &self.value)
        } else {
            (a, b.trim())
        }
    }

    /// Columns it takes drawn large.
    fn width(&self, app: &App) -> u16 {
        let (large, rest) = self.split();
        let text = |s: &str| Span::raw(app.theme.glyphs.text(s).into_owned()).width() as u16;
        let mut w = big::width(large)
            .max(text(&self.label))
            .max(text(&self.note));
        if large.is_empty() {
            w = w.max(text(rest));
        } else if !rest.is_empty() {
            w = w.max(big::width(large) + 1 + text(rest));
        }
        w
    }
}

/// Rows a figure takes drawn large: its label, five rows, its note.
const FIGURE_ROWS: u16 = big::ROWS + 2;

/// `m:ss` left of the countdown, if one runs.
pub fn left(app: &App) -> Option<String> {
    let (until, _) = app.class.countdown?;
    let s = until
        .saturating_duration_since(Instant::now())
        .as_secs_f64()
        .ceil() as u64;
    Some(format!("{}:{:02}", s / 60, s % 60))
}

fn figures(app: &App, t: &Tally) -> Vec<Figure> {
    let q = &t.question;
    let sym = app.theme.glyphs.text(q.axis.symbol()).into_owned();
    let plain = Style::new().add_modifier(Modifier::BOLD);
    let colour = |c: Color| {
        if app.theme.color {
            plain.fg(c)
        } else {
            plain
        }
    };
    let answered = Figure {
        label: "answered".into(),
        value: format!("{}/{}", t.answers.len(), t.asked),
        note: String::new(),
        style: plain,
    };
    if !t.revealed {
        let mut v = vec![answered];
        if let Some(l) = left(app) {
            let up = l == "0:00";
            v.push(Figure {
                label: "time left".into(),
                value: l,
                note: if up {
                    "time: v reveals".into()
                } else {
                    String::new()
                },
                style: if up { colour(Color::Red) } else { plain },
            });
        }
        return v;
    }
    let n = t.answers.len();
    let nowhere = t.nowhere();
    let within = t.within();
    let median = match t.median() {
        Some(m) => fmt_value(q.axis, m),
        None => "—".into(),
    };
    vec![
        Figure {
            label: format!("the model: {sym} ="),
            value: fmt_value(q.axis, q.truth),
            note: String::new(),
            style: colour(Color::Yellow),
        },
        Figure {
            label: format!("median answer: {sym} ="),
            value: median,
            note: if nowhere > 0 {
                format!("{nowhere} answered nowhere")
            } else {
                String::new()
            },
            style: colour(Color::Cyan),
        },
        Figure {
            label: "within 10 % of it".into(),
            value: (100 * within + n / 2)
                .checked_div(n)
                .map_or("—".into(), |p| format!("{p}%")),
            note: format!("{within} of {n}"),
            style: colour(Color::Green),
        },
        answered,
    ]
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    Clear.render(area, buf);
    let g = app.theme.glyphs;
    let tx = |s: &str| g.text(s).into_owned();
    let title = app.theme.title;
    let dim = app.theme.dim;
    let tally = app.class.view.as_ref().and_then(|v| v.poll.as_ref());
    let keys = match tally {
        Some(t) if !t.revealed => "P closes · v reveals · t countdown · C cancels",
        Some(_) => "P closes · v asks again · d shows everyone the answers · S saves them",
        None => "P closes · v asks the class",
    };
    let keys = tx(keys);
    let bottom = area.bottom().saturating_sub(1);
    buf.set_stringn(area.x, bottom, &keys, usize::from(area.width), dim);
    let Some(t) = tally else {
        let say = tx("no poll yet: v asks the class, and its answers show here");
        buf.set_stringn(area.x, area.y, &say, usize::from(area.width), title);
        return;
    };
    // The question, wrapped.
    let q = t.question.text(&UNICODE);
    let q = if t.revealed {
        q
    } else {
        format!("Predict: {q}")
    };
    let lines = wrap(&tx(&q), usize::from(area.width.max(1)), 3, g.cut());
    let mut y = area.y;
    for l in &lines {
        buf.set_stringn(area.x, y, l, usize::from(area.width), title);
        y += 1;
    }
    y += 1;
    let figs = figures(app, t);
    // Large type where it leaves the histogram ten rows.
    let reserve = if t.revealed { 10 } else { 0 };
    let room = Rect::new(area.x, y, area.width, bottom.saturating_sub(y));
    y = draw_figures(app, &figs, room, reserve, buf);
    let hist = Rect::new(area.x, y + 1, area.width, bottom.saturating_sub(y + 2));
    if t.revealed {
        histogram(app, t, hist, buf);
    } else if hist.height > 0 {
        let say = tx("the answers show here at the reveal");
        let w = Span::raw(&say).width() as u16;
        let x = hist.x + hist.width.saturating_sub(w) / 2;
        buf.set_stringn(
            x,
            hist.y + hist.height / 2,
            &say,
            usize::from(hist.width),
            dim,
        );
    }
}

/// The figures in large type, as many a row as fit, if that leaves
/// `reserve` rows below (else one line each in plain type); the first row
/// below them.
fn draw_figures(app: &App, figs: &[Figure], area: Rect, reserve: u16, buf: &mut Buffer) -> u16 {
    let g = app.theme.glyphs;
    let tx = |s: &str| g.text(s).into_owned();
    let gap = 4;
    let widths: Vec<u16> = figs.iter().map(|f| f.width(app)).collect();
    // As many a row as the width allows, rows of equal count.
    let per_row = (1..=figs.len())
        .rev()
        .find(|&k| {
            widths
                .chunks(k)
                .all(|c| c.iter().sum::<u16>() + gap * (c.len() as u16 - 1) <= area.width)
        })
        .unwrap_or(1);
    let rows = figs.len().div_ceil(per_row) as u16;
    let large = rows * (FIGURE_ROWS + 1) + reserve <= area.height
        && widths.iter().all(|w| *w <= area.width);
    let mut y = area.y;
    if !large {
        for f in figs {
            let line = tx(&format!("{} {}  {}", f.label, f.value, f.note));
            buf.set_stringn(area.x, y, line.trim_end(), usize::from(area.width), f.style);
            y += 1;
        }
        return y;
    }
    for (chunk, ws) in figs.chunks(per_row).zip(widths.chunks(per_row)) {
        let used = ws.iter().sum::<u16>() + gap * (ws.len() as u16 - 1);
        let mut x = area.x + (area.width - used) / 2;
        for (f, w) in chunk.iter().zip(ws) {
            let label = tx(&f.label);
            buf.set_stringn(x, y, &label, usize::from(*w), app.theme.dim);
            let (large, rest) = f.split();
            if large.is_empty() {
                buf.set_stringn(x, y + 3, tx(rest), usize::from(*w), f.style);
            } else {
                big::draw(large, (x, y + 1), area, g.ascii_only(), f.style, buf);
                if !rest.is_empty() {
                    let rx = x + big::width(large) + 1;
                    buf.set_stringn(rx, y + big::ROWS, tx(rest), usize::from(*w), f.style);
                }
            }
            buf.set_stringn(
                x,
                y + 1 + big::ROWS,
                tx(&f.note),
                usize::from(*w),
                Style::new(),
            );
            x += w + gap;
        }
        y += FIGURE_ROWS + 1;
    }
    y
}

/// The answers along the sweep, bars two columns wide with their counts
/// over them, the model's value marked, the sweep's ends under the axis.
fn histogram(app: &App, t: &Tally, area: Rect, buf: &mut Buffer) {
    if area.height < 4 || area.width < 20 {
        return;
    }
    let g = app.theme.glyphs;
    let gl = glyphs(g);
    let axis = t.question.axis;
    let log = axis.is_log();
    let s = &t.sweep;
    let (lo, hi) = (to_plot(log, s.from()), to_plot(log, s.to()));
    let nbins = usize::from(area.width / 3).max(1);
    let bin = |v: f64| {
        let f = (to_plot(log, v) - lo) / (hi - lo);
        (0.0..=1.0)
            .contains(&f)
            .then(|| ((f * nbins as f64) as usize).min(nbins - 1))
    };
    let mut counts = vec![0usize; nbins];
    for &a in &t.answers {
        if let Some(b) = bin(a) {
            counts[b] += 1;
        }
    }
    let max = counts.iter().copied().max().unwrap_or(0);
    // Rows: the counts' row, the bars, the axis, the ends' labels, the
    // model's value.
    let bars_h = area.height - 4;
    let base = area.y + 1 + bars_h;
    let x0 = area.x + (area.width - 3 * nbins as u16) / 2;
    let bar = if app.theme.color {
        Style::new().fg(Color::Cyan)
    } else {
        Style::new()
    };
    for (i, &n) in counts.iter().enumerate() {
        if n == 0 {
            continue;
        }
        let x = x0 + 3 * i as u16;
        let eighths = (n * usize::from(bars_h) * 8).div_ceil(max).max(1);
        let full = (eighths / 8) as u16;
        for r in 0..bars_h {
            let left = eighths.saturating_sub(usize::from(r) * 8);
            if left == 0 {
                break;
            }
            let sym = gl.bars[left.min(8) - 1];
            for dx in 0..2 {
                buf[(x + dx, base - 1 - r)].set_symbol(sym).set_style(bar);
            }
        }
        let top = base - 1 - full.min(bars_h - 1);
        buf.set_stringn(
            x,
            top.saturating_sub(1).max(area.y),
            n.to_string(),
            3,
            app.theme.title,
        );
    }
    // The axis, and the model's value on it.
    let line = if g.ascii_only() { "-" } else { "─" };
    for x in x0..x0 + 3 * nbins as u16 {
        buf[(x, base)].set_symbol(line);
    }
    let ends = |v: f64| app.theme.glyphs.text(&fmt_value(axis, v)).into_owned();
    let right = ends(s.to());
    buf.set_stringn(x0, base + 1, ends(s.from()), 12, app.theme.dim);
    let rw = Span::raw(&right).width() as u16;
    let rx = (x0 + 3 * nbins as u16).saturating_sub(rw);
    buf.set_stringn(rx, base + 1, &right, 12, app.theme.dim);
    if bin(t.question.truth).is_some() {
        let f = (to_plot(log, t.question.truth) - lo) / (hi - lo);
        let x = x0 + ((f * (3 * nbins) as f64) as u16).min(3 * nbins as u16 - 1);
        let truth = if app.theme.color {
            Style::new().fg(Color::Yellow).add_modifier(Modifier::BOLD)
        } else {
            Style::new().add_modifier(Modifier::BOLD)
        };
        for r in 0..bars_h {
            let cell = &mut buf[(x, base - 1 - r)];
            if !gl.bars.contains(&cell.symbol()) {
                cell.set_symbol(gl.truth).set_style(truth);
            }
        }
        // An arrow under its column (the line may hide behind a bar), the
        // value beside it.
        let arrow = if g.ascii_only() { "^" } else { "▲" };
        buf[(x, base + 2)].set_symbol(arrow).set_style(truth);
        let label = g
            .text(&format!("the model: {}", fmt_value(axis, t.question.truth)))
            .into_owned();
        let lw = Span::raw(&label).width() as u16;
        let lx = if x + 2 + lw <= area.right() {
            x + 2
        } else {
            x.saturating_sub(lw + 1)
        };
        buf.set_stringn(lx, base + 2, &label, usize::from(area.width), truth);
    }
}
