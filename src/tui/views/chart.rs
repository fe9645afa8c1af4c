//! What every chart view shares: the title line, the legend, axes with
//! ticks and labels placed where ratatui's braille canvas puts the values,
//! and the datasets drawn over them.

use std::borrow::Cow;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Chart, Dataset, GraphType, Widget};

use rough_model::Axis;

use crate::physical::print::{fmt_decade, fmt_param, fmt_short};
use crate::tui::app::App;
use crate::tui::layout::Y_LABEL_W;
use crate::tui::plots::to_plot;
use crate::tui::theme::{CurveStyle, Theme};

/// The cell column the canvas puts a transformed x in (same arithmetic as
/// ratatui's grid of `dots` points per cell, which rounds to the nearest
/// point).
pub fn col_of(g: Rect, dots: (f64, f64), b: [f64; 2], x: f64) -> Option<u16> {
    let f = (x - b[0]) / (b[1] - b[0]);
    if !(0.0..=1.0).contains(&f) {
        return None;
    }
    let n = f64::from(g.width) * dots.0 - 1.0;
    Some(g.x + ((f * n).round() / dots.0) as u16)
}

/// The cell row the canvas puts a transformed y in.
pub fn row_of(g: Rect, dots: (f64, f64), b: [f64; 2], y: f64) -> Option<u16> {
    let f = (b[1] - y) / (b[1] - b[0]);
    if !(0.0..=1.0).contains(&f) {
        return None;
    }
    let n = f64::from(g.height) * dots.1 - 1.0;
    Some(g.y + ((f * n).round() / dots.1) as u16)
}

/// Tick positions and labels along a parameter's axis: decades on log
/// axes, tenths on Hurst.
fn x_ticks(axis: Axis, b: [f64; 2]) -> Vec<(f64, String)> {
    if axis.is_log() {
        let (lo, hi) = (b[0].ceil() as i32, b[1].floor() as i32);
        (lo..=hi)
            .map(|d| (f64::from(d), fmt_short(axis, 10f64.powi(d))))
            .collect()
    } else {
        Scale::linear(b, 10.0).ticks
    }
}

/// The title line: `spans`, then the marker's sample and value when the
/// marker lies inside the sweep.
pub fn title(app: &App, mut spans: Vec<Span<'static>>, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let g = t.glyphs;
    let axis = app.state.sweep.axis();
    for s in &mut spans {
        if let Cow::Owned(text) = g.text(&s.content) {
            s.content = Cow::Owned(text);
        }
    }
    if let Some(m) = app.marker() {
        let value = format!(" {} = {}", axis.symbol(), fmt_param(axis, m));
        let value = g.text(&value).into_owned();
        // The marker's value whole or not at all, never cut inside a number.
        let used: usize = spans.iter().map(Span::width).sum();
        let len = 2 + Span::raw(t.marker_line.sample).width() + Span::raw(&value).width();
        if used + len <= usize::from(area.width) {
            spans.push(Span::raw("  "));
            spans.push(Span::styled(t.marker_line.sample, t.marker_line.style));
            spans.push(Span::raw(value));
        }
    }
    Line::from(spans).render(Rect::new(area.x, area.y, area.width, 1), buf);
}

/// Legend: one line under the title, each curve's sample in its own style;
/// shorter samples and gaps when the full one does not fit.
pub fn legend(t: &Theme, curves: &[&CurveStyle], area: Rect, buf: &mut Buffer) {
    let named: Vec<(&CurveStyle, String)> =
        curves.iter().map(|c| (*c, c.name.to_string())).collect();
    legend_named(t, &named, area, buf);
}

/// [`legend`] with each curve's name given.
pub fn legend_named(t: &Theme, curves: &[(&CurveStyle, String)], area: Rect, buf: &mut Buffer) {
    let curves: Vec<(&CurveStyle, String)> = curves
        .iter()
        .map(|(c, name)| (*c, t.glyphs.text(name).into_owned()))
        .collect();
    let full: usize = curves
        .iter()
        .map(|(c, name)| c.sample.chars().count() + name.chars().count() + 3)
        .sum();
    let short = full > area.width as usize;
    let mut legend = Vec::new();
    for (c, name) in curves {
        let sample: String = if short {
            c.sample.chars().take(1).collect()
        } else {
            c.sample.into()
        };
        legend.push(Span::styled(format!("{sample} "), c.style));
        legend.push(Span::raw(format!(
            "{name}{}",
            if short { " " } else { "  " }
        )));
    }
    Line::from(legend).render(Rect::new(area.x, area.y + 1, area.width, 1), buf);
}

/// One axis of a chart: its range (in plot coordinates: log10 on log
/// axes) and its labelled ticks.
pub struct Scale {
    pub bounds: [f64; 2],
    pub ticks: Vec<(f64, String)>,
}

impl Scale {
    /// Whole decades of a log axis, labelled 1e-3, 0.01, 0.1, 1, 10 ….
    pub fn decades(bounds: [f64; 2]) -> Scale {
        let (lo, hi) = (bounds[0].ceil() as i32, bounds[1].floor() as i32);
        let ticks = (lo..=hi).map(|d| (f64::from(d), fmt_decade(d))).collect();
        Scale { bounds, ticks }
    }

    /// A parameter's axis: [`x_ticks`].
    pub fn of_axis(axis: Axis, bounds: [f64; 2]) -> Scale {
        Scale {
            bounds,
            ticks: x_ticks(axis, bounds),
        }
    }

    /// A linear axis with `per` ticks per unit, labelled with one decimal.
    pub fn linear(bounds: [f64; 2], per: f64) -> Scale {
        let (lo, hi) = (
            (bounds[0] * per).ceil() as i32,
            (bounds[1] * per).floor() as i32,
        );
        let ticks = (lo..=hi)
            .map(|k| (f64::from(k) / per, format!("{:.1}", f64::from(k) / per)))
            .collect();
        Scale { bounds, ticks }
    }
}

/// Axes, ticks and labels around the graph `g` inside the panel `area`:
/// `y`'s labels right-aligned left of the axis, `x`'s under it, and
/// `x_name` at the right end of the x labels.
pub fn axes(
    t: &Theme,
    (x, y): (&Scale, &Scale),
    x_name: &str,
    (area, g): (Rect, Rect),
    buf: &mut Buffer,
) {
    let glyphs = t.glyphs;
    let f = glyphs.frame();
    let dots = glyphs.dots();
    let ax = g.x - 1;
    let ay = g.bottom();
    for row in g.y..g.bottom() {
        buf[(ax, row)].set_symbol(f.vertical);
    }
    buf[(ax, ay)].set_symbol(f.corner);
    for col in g.x..g.right() {
        buf[(col, ay)].set_symbol(f.horizontal);
    }
    for (v, label) in &y.ticks {
        let label = glyphs.text(label);
        if let Some(row) = row_of(g, dots, y.bounds, *v) {
            buf[(ax, row)].set_symbol(f.y_tick);
            // "100 nm" loses its space rather than its unit.
            let label = if label.chars().count() > usize::from(Y_LABEL_W) {
                label.replace(' ', "")
            } else {
                label.into_owned()
            };
            let label = format!("{label:>w$}", w = Y_LABEL_W as usize);
            buf.set_stringn(area.x, row, label, Y_LABEL_W as usize, Style::new());
        }
    }
    // Every tick drawn is labelled: the first stride (every tick, every
    // second, …) at which all labels fit side by side.
    let placed: Vec<(u16, u16, Cow<str>)> = x
        .ticks
        .iter()
        .filter_map(|(v, label)| {
            let col = col_of(g, dots, x.bounds, *v)?;
            let label = glyphs.text(label);
            let w = label.chars().count() as u16;
            Some((col, col.saturating_sub(w / 2).max(area.x), label))
        })
        .collect();
    let fits = |stride: usize| {
        let mut free_from = area.x;
        placed.iter().step_by(stride).all(|(_, start, label)| {
            let w = label.chars().count() as u16;
            let ok = *start >= free_from && start + w <= area.right();
            free_from = start + w + 1;
            ok
        })
    };
    let stride = [1, 2, 3, 4, 5, 10]
        .into_iter()
        .find(|&s| fits(s))
        .unwrap_or(placed.len().max(1));
    let mut free_from = area.x;
    for (col, start, label) in placed.iter().step_by(stride) {
        let w = label.chars().count() as u16;
        if *start >= free_from && start + w <= area.right() {
            buf[(*col, ay)].set_symbol(f.x_tick);
            buf.set_stringn(*start, ay + 1, label, w as usize, Style::new());
            free_from = start + w + 1;
        }
    }
    let x_name = glyphs.text(x_name);
    let w = x_name.chars().count() as u16;
    let nx = area.right().saturating_sub(w + 1);
    if nx >= free_from {
        buf.set_stringn(nx, ay + 1, &x_name, usize::from(w), t.title);
    }
}

/// A curve as a line dataset in its style.
pub fn dataset<'a>(c: &CurveStyle, data: &'a [(f64, f64)]) -> Dataset<'a> {
    Dataset::default()
        .marker(c.marker)
        .graph_type(GraphType::Line)
        .style(c.style)
        .data(data)
}

/// The marker's vertical line across `y_bounds`, empty when the marker lies
/// outside the sweep.
pub fn marker_line(app: &App, y_bounds: [f64; 2]) -> Vec<(f64, f64)> {
    let axis = app.state.sweep.axis();
    app.marker()
        .map(|m| {
            let x = to_plot(axis.is_log(), m);
            vec![(x, y_bounds[0]), (x, y_bounds[1])]
        })
        .unwrap_or_default()
}

/// Draws `sets` into the graph, later sets over earlier ones.
pub fn plot(
    sets: Vec<Dataset>,
    (x_bounds, y_bounds): ([f64; 2], [f64; 2]),
    g: Rect,
    buf: &mut Buffer,
) {
    Chart::new(sets)
        .x_axis(ratatui::widgets::Axis::default().bounds(x_bounds))
        .y_axis(ratatui::widgets::Axis::default().bounds(y_bounds))
        .legend_position(None)
        .render(g, buf);
}

/// While a poll's answer waits (see `Classroom::marks_hidden`): `what`
/// "wait for the reveal: they would answer the poll", wrapped in the
/// middle of `area` (the graph a view leaves empty); whether it does.
pub fn withheld(app: &App, what: &str, area: Rect, buf: &mut Buffer) -> bool {
    let Some(until) = app.class.marks_wait() else {
        return false;
    };
    let g = app.theme.glyphs;
    let text = format!("{what} wait for {until}: they would answer the poll");
    let text = g.text(&text);
    let w = usize::from(area.width.saturating_sub(4)).max(1);
    let lines = crate::tui::wrap::wrap(&text, w, usize::from(area.height), g.cut());
    let top = area.y + area.height.saturating_sub(lines.len() as u16) / 2;
    for (i, l) in lines.iter().enumerate() {
        let y = top + i as u16;
        if y >= area.bottom() {
            break;
        }
        let lw = Span::raw(l.as_str()).width() as u16;
        let x = area.x + area.width.saturating_sub(lw) / 2;
        Line::styled(l.clone(), app.theme.dim).render(Rect::new(x, y, lw.min(area.width), 1), buf);
    }
    true
}
