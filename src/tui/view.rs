//! Drawing: `impl Widget for &App`, split into `(area, buf)` helpers. Reads
//! the app, never changes it.

use ratatui::buffer::Buffer;
use ratatui::layout::{Alignment, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Chart, Dataset, GraphType, Paragraph, Widget, Wrap};

use rough_model::Axis;

use super::app::{to_plot, App, Mode};
use super::keys;
use super::theme::CurveStyle;
use super::{help, status};

/// The smallest terminal the explorer draws in; below it, a short message.
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// The screen's regions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Areas {
    pub header: Rect,
    pub sliders: Rect,
    pub readout: Rect,
    pub chart: Rect,
    pub status: Rect,
    pub footer: Rect,
    /// Rows per slider (2 adds a position bar).
    pub slider_rows: u16,
}

/// The regions for a terminal of `size`, or `None` if it is too small.
pub fn areas(size: (u16, u16)) -> Option<Areas> {
    let (w, h) = size;
    if w < MIN_SIZE.0 || h < MIN_SIZE.1 {
        return None;
    }
    let left = (w * 2 / 5).clamp(34, 44);
    let main_h = h - 3;
    let slider_rows = if main_h >= 27 { 2 } else { 1 };
    let sliders_h = 1 + 5 * slider_rows;
    Some(Areas {
        header: Rect::new(0, 0, w, 1),
        sliders: Rect::new(0, 1, left, sliders_h),
        readout: Rect::new(0, 1 + sliders_h, left, main_h - sliders_h),
        chart: Rect::new(left + 1, 1, w - left - 1, main_h),
        status: Rect::new(0, h - 2, w, 1),
        footer: Rect::new(0, h - 1, w, 1),
        slider_rows,
    })
}

/// Columns left of the graph for the y labels and the axis line.
const Y_LABEL_W: u16 = 5;

/// The braille graph inside the chart panel: below the title and legend,
/// right of the y labels and axis, above the x axis and its labels.
pub fn graph_area(size: (u16, u16)) -> Option<Rect> {
    Some(graph_in(areas(size)?.chart))
}

fn graph_in(c: Rect) -> Rect {
    Rect::new(
        c.x + Y_LABEL_W + 1,
        c.y + 2,
        c.width.saturating_sub(Y_LABEL_W + 1 + 2),
        c.height.saturating_sub(4),
    )
}

// ---------------------------------------------------------------- numbers

/// Three significant digits; scientific outside 1e-3 … 1e5.
pub fn fmt_num(v: f64) -> String {
    if v.is_nan() {
        return "—".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "∞".into() } else { "-∞".into() };
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e5).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.2e}")
    }
}

fn length_unit(m: f64) -> (f64, &'static str) {
    let a = m.abs();
    if a < 1e-6 {
        (1e9, "nm")
    } else if a < 1e-3 {
        (1e6, "µm")
    } else if a < 1.0 {
        (1e3, "mm")
    } else {
        (1.0, "m")
    }
}

/// A length in m with a readable unit: "20.0 nm", "19.7 µm", "1.00 mm".
pub fn fmt_len(m: f64) -> String {
    if !m.is_finite() || m == 0.0 {
        return format!("{} m", fmt_num(m));
    }
    let (k, u) = length_unit(m);
    format!("{} {u}", fmt_num(m * k))
}

fn is_whole(v: f64) -> bool {
    (v - v.round()).abs() < 1e-9 * v.abs().max(1.0)
}

/// A short form for range ends and axis labels: "1 nm", "10 mm", "1e-4", "0.05".
pub fn fmt_short(axis: Axis, v: f64) -> String {
    if matches!(axis, Axis::HRms | Axis::RStar) && v.is_finite() && v > 0.0 {
        let (k, u) = length_unit(v);
        let s = v * k;
        return if is_whole(s) {
            format!("{} {u}", s.round())
        } else {
            format!("{} {u}", fmt_num(s))
        };
    }
    let d = v.log10();
    if v > 0.0 && is_whole(d) && axis.is_log() {
        return fmt_decade(d.round() as i32);
    }
    if is_whole(v) {
        return format!("{}", v.round());
    }
    let s = format!("{v}");
    if s.len() <= 5 {
        s
    } else {
        fmt_num(v)
    }
}

/// A decade label: 0.01, 0.1, 1, 10, 100, else 1e-3, 1e3 ….
pub fn fmt_decade(d: i32) -> String {
    match d {
        -2 => "0.01".into(),
        -1 => "0.1".into(),
        0 => "1".into(),
        1 => "10".into(),
        2 => "100".into(),
        _ => format!("1e{d}"),
    }
}

/// The parameter's value with its unit.
pub fn fmt_param(axis: Axis, v: f64) -> String {
    match axis {
        Axis::HRms | Axis::RStar => fmt_len(v),
        _ => fmt_num(v),
    }
}

pub fn axis_name(axis: Axis) -> &'static str {
    match axis {
        Axis::H0OverE => "H0/E",
        Axis::HRms => "h_rms",
        Axis::Zeta => "ζ",
        Axis::Hurst => "H",
        Axis::RStar => "R*",
    }
}

/// How far `other` lies from `this`, in per cent or as a ratio.
pub fn fmt_rel(other: f64, this: f64) -> String {
    if other == this {
        return "±0%".into();
    }
    if !(this.is_finite() && other.is_finite()) || this == 0.0 {
        return "n/a".into();
    }
    let d = other / this - 1.0;
    if d.abs() < 10.0 {
        format!("{:+.1}%", d * 100.0)
    } else {
        format!("×{}", fmt_num(other / this))
    }
}

// ---------------------------------------------------------------- widget

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let Some(a) = areas((area.width, area.height)) else {
            render_too_small(area, buf);
            return;
        };
        let a = offset(a, area);
        render_header(self, a.header, buf);
        render_sliders(self, a.sliders, a.slider_rows, buf);
        render_readout(self, a.readout, buf);
        render_chart(self, a.chart, buf);
        render_footer(self, a.footer, buf);
        status::render_status(self, a.status, a.footer, buf);
        if self.mode == Mode::Help {
            help::render_help(self, area, buf);
        }
    }
}

fn offset(mut a: Areas, area: Rect) -> Areas {
    for r in [
        &mut a.header,
        &mut a.sliders,
        &mut a.readout,
        &mut a.chart,
        &mut a.status,
        &mut a.footer,
    ] {
        r.x += area.x;
        r.y += area.y;
    }
    a
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
    let psi_name = if s.size_effect { "Ψ*" } else { "Ψ_P" };
    let line = Line::from(vec![
        Span::styled(" roughtui ", t.title),
        Span::styled(format!("[{name}]"), t.selected),
        Span::raw(format!(
            "  sweep {} {}…{} · {} · size effect {} (ψ = {psi_name})",
            axis_name(axis),
            fmt_short(axis, s.sweep.from()),
            fmt_short(axis, s.sweep.to()),
            s.model.label(),
            if s.size_effect { "on" } else { "off" },
        )),
    ]);
    line.render(area, buf);
}

fn render_sliders(app: &App, area: Rect, rows: u16, buf: &mut Buffer) {
    let t = &app.theme;
    Line::styled("Parameters", t.title).render(Rect { height: 1, ..area }, buf);
    let swept = app.state.sweep.axis();
    for (i, axis) in Axis::ALL.into_iter().enumerate() {
        let y = area.y + 1 + i as u16 * rows;
        if y >= area.bottom() {
            break;
        }
        let selected = i == app.selected;
        let (lo, hi) = app.range(axis);
        let v = app.state.params.get(axis);
        let text = format!(
            "{}{:<5}{} {:>9}  {}…{}",
            if selected { "▶ " } else { "  " },
            axis_name(axis),
            if axis == swept { "↔" } else { " " },
            fmt_param(axis, v),
            fmt_short(axis, lo),
            fmt_short(axis, hi),
        );
        let style = if selected { t.selected } else { Style::new() };
        let row = Rect::new(area.x, y, area.width, 1);
        buf.set_style(row, style);
        Line::styled(format!("{text:<w$}", w = area.width as usize), style).render(row, buf);
        if rows > 1 && y + 1 < area.bottom() {
            let bar = slider_bar(axis, v, (lo, hi), area.width.saturating_sub(4) as usize);
            let bar_style = if selected { t.title } else { t.dim };
            Line::styled(format!("   {bar}"), bar_style)
                .render(Rect::new(area.x, y + 1, area.width, 1), buf);
        }
    }
}

/// "├───●────┤", the knob at the value's place in the range.
fn slider_bar(axis: Axis, v: f64, (lo, hi): (f64, f64), width: usize) -> String {
    if width < 3 {
        return String::new();
    }
    let inner = width - 2;
    let f = if axis.is_log() && v > 0.0 {
        (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
    } else {
        (v - lo) / (hi - lo)
    };
    let mut cells = vec!['─'; inner];
    if f.is_nan() || f < 0.0 {
        cells[0] = '◂';
    } else if f > 1.0 {
        cells[inner - 1] = '▸';
    } else {
        let k = ((f * (inner - 1) as f64).round() as usize).min(inner - 1);
        cells[k] = '●';
    }
    let mut s = String::with_capacity(width * 3);
    s.push('├');
    s.extend(cells);
    s.push('┤');
    s
}

fn pair(l1: &str, v1: String, l2: &str, v2: String) -> String {
    format!("{l1:<6}{v1:<10}{l2:<7}{v2}")
}

fn render_readout(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let r = &app.readout;
    let ix = &r.surface.indices;
    let sp = &r.surface.spectrum;
    let s = &app.state;
    let asym = match (ix.psi_star_asymptotic, ix.asymptotic_deviation()) {
        (Some(a), Some(d)) => format!("{} ({:+.1}% vs Ψ*)", fmt_num(a), d * 100.0),
        (Some(a), None) => fmt_num(a),
        (None, _) => "n/a (R* = 0 or H = 1)".into(),
    };
    let sl = &r.slopes;
    let o = &r.other;
    let regime = sl.regime();
    let curve = |c: &CurveStyle, label: &str, v: f64| {
        vec![
            Span::styled(format!("{label:<6}"), c.style),
            Span::raw(format!("{:<10}", fmt_num(v))),
        ]
    };
    let mut slopes1 = curve(&t.elastic, "S_el", sl.elastic);
    slopes1.extend(curve(&t.plastic, "S_pl", sl.plastic));
    let mut slopes2 = curve(&t.total, "S_tot", sl.total);
    slopes2.extend(curve(&t.persson, "S_P", r.persson));
    let lines = vec![
        Line::styled("Readout", t.title),
        Line::raw(pair("Ψ_GW", fmt_num(ix.psi_gw), "Ψ_P", fmt_num(ix.psi_p))),
        Line::raw(pair(
            "Ψ*",
            fmt_num(ix.psi_star),
            "H_y/H0",
            fmt_num(ix.hardness_ratio),
        )),
        Line::raw(format!("{:<6}{asym}", "Ψ*asy")),
        Line::raw(pair("R_s", fmt_len(sp.r_s), "λ1", fmt_len(sp.lambda1))),
        Line::raw(pair(
            "h_rms",
            fmt_len(sp.h_rms_actual),
            "h′",
            fmt_num(sp.rms_slope),
        )),
        Line::styled(
            format!("at marker: ψ = {} ({})", fmt_num(r.psi), s.model.label()),
            t.title,
        ),
        Line::from(slopes1),
        Line::from(slopes2),
        Line::from(vec![
            Span::raw(format!("plastic {:.1}%  ", sl.plastic_share() * 100.0)),
            Span::styled(regime.label(), t.regime(regime)),
        ]),
        Line::raw(format!("{} at the marker:", s.model.other().label())),
        Line::raw(format!(
            " el {}  pl {}  tot {}",
            fmt_rel(o.elastic, sl.elastic),
            fmt_rel(o.plastic, sl.plastic),
            fmt_rel(o.total, sl.total)
        )),
    ];
    Paragraph::new(lines).render(area, buf);
}

/// The cell column the canvas puts a transformed x in (same arithmetic as
/// ratatui's braille grid).
fn col_of(g: Rect, b: [f64; 2], x: f64) -> Option<u16> {
    let f = (x - b[0]) / (b[1] - b[0]);
    if !(0.0..=1.0).contains(&f) {
        return None;
    }
    let dots = f64::from(g.width) * 2.0 - 1.0;
    Some(g.x + ((f * dots) as u16) / 2)
}

fn row_of(g: Rect, b: [f64; 2], y: f64) -> Option<u16> {
    let f = (b[1] - y) / (b[1] - b[0]);
    if !(0.0..=1.0).contains(&f) {
        return None;
    }
    let dots = f64::from(g.height) * 4.0 - 1.0;
    Some(g.y + ((f * dots) as u16) / 4)
}

/// Tick positions and labels along x: decades on log axes, tenths on Hurst.
fn x_ticks(axis: Axis, b: [f64; 2]) -> Vec<(f64, String)> {
    if axis.is_log() {
        let (lo, hi) = (b[0].ceil() as i32, b[1].floor() as i32);
        (lo..=hi)
            .map(|d| (f64::from(d), fmt_short(axis, 10f64.powi(d))))
            .collect()
    } else {
        let (lo, hi) = ((b[0] * 10.0).ceil() as i32, (b[1] * 10.0).floor() as i32);
        (lo..=hi)
            .map(|k| (f64::from(k) / 10.0, format!("{:.1}", f64::from(k) / 10.0)))
            .collect()
    }
}

fn render_chart(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let axis = app.state.sweep.axis();
    let g = graph_in(area);
    if g.width < 2 || g.height < 2 {
        return;
    }
    let p = &app.plot;
    let norm = if app.state.size_effect { "H_y" } else { "H0" };
    let mut title = vec![Span::styled(
        format!("slope {norm}·dA/dp̄/A0 vs {}", axis_name(axis)),
        t.title,
    )];
    if let Some(m) = app.marker() {
        title.push(Span::raw("  "));
        title.push(Span::styled(t.marker_line.sample, t.marker_line.style));
        title.push(Span::raw(format!(
            " {} = {}",
            axis_name(axis),
            fmt_param(axis, m)
        )));
    }
    Line::from(title).render(Rect::new(area.x, area.y, area.width, 1), buf);

    // Legend: one line, each curve's sample in its own style; shorter
    // samples and gaps when the full one does not fit.
    let curves = [&t.elastic, &t.plastic, &t.total, &t.persson];
    let full: usize = curves
        .iter()
        .map(|c| c.sample.chars().count() + c.name.chars().count() + 3)
        .sum();
    let short = full > area.width as usize;
    let mut legend = Vec::new();
    for c in curves {
        let sample: String = if short {
            c.sample.chars().take(1).collect()
        } else {
            c.sample.into()
        };
        legend.push(Span::styled(format!("{sample} "), c.style));
        legend.push(Span::raw(format!(
            "{}{}",
            c.name,
            if short { " " } else { "  " }
        )));
    }
    Line::from(legend).render(Rect::new(area.x, area.y + 1, area.width, 1), buf);

    // Axes, ticks and labels, placed where the canvas puts the values.
    let ax = g.x - 1;
    let ay = g.bottom();
    for y in g.y..g.bottom() {
        buf[(ax, y)].set_symbol("│");
    }
    buf[(ax, ay)].set_symbol("└");
    for x in g.x..g.right() {
        buf[(x, ay)].set_symbol("─");
    }
    let (ylo, yhi) = (p.y_bounds[0] as i32, p.y_bounds[1] as i32);
    for d in ylo..=yhi {
        if let Some(row) = row_of(g, p.y_bounds, f64::from(d)) {
            buf[(ax, row)].set_symbol("┤");
            let label = format!("{:>w$}", fmt_decade(d), w = Y_LABEL_W as usize);
            buf.set_stringn(area.x, row, label, Y_LABEL_W as usize, Style::new());
        }
    }
    let mut free_from = area.x;
    for (v, label) in x_ticks(axis, p.x_bounds) {
        let Some(col) = col_of(g, p.x_bounds, v) else {
            continue;
        };
        buf[(col, ay)].set_symbol("┬");
        let w = label.chars().count() as u16;
        let start = col.saturating_sub(w / 2).max(area.x);
        if start >= free_from && start + w <= area.right() {
            buf.set_stringn(start, ay + 1, &label, w as usize, Style::new());
            free_from = start + w + 1;
        }
    }
    let name = axis_name(axis);
    let nx = area.right().saturating_sub(name.chars().count() as u16 + 1);
    if nx >= free_from {
        buf.set_stringn(nx, ay + 1, name, 8, t.title);
    }

    // The curves, over the marker line.
    let dataset = |c: &CurveStyle, data| {
        Dataset::default()
            .marker(c.marker)
            .graph_type(GraphType::Line)
            .style(c.style)
            .data(data)
    };
    let marker_data: Vec<(f64, f64)> = app
        .marker()
        .map(|m| {
            let x = to_plot(axis.is_log(), m);
            vec![(x, p.y_bounds[0]), (x, p.y_bounds[1])]
        })
        .unwrap_or_default();
    let mut sets = vec![dataset(&t.marker_line, &marker_data)];
    sets.push(dataset(&t.persson, &p.persson));
    sets.push(dataset(&t.elastic, &p.elastic));
    sets.push(dataset(&t.plastic, &p.plastic));
    sets.push(dataset(&t.total, &p.total));
    Chart::new(sets)
        .x_axis(ratatui::widgets::Axis::default().bounds(p.x_bounds))
        .y_axis(ratatui::widgets::Axis::default().bounds(p.y_bounds))
        .legend_position(None)
        .render(g, buf);
}

fn render_footer(app: &App, area: Rect, buf: &mut Buffer) {
    let mut text = String::new();
    for entry in keys::footer(&app.mode) {
        let extra = if text.is_empty() { 0 } else { 2 };
        if text.chars().count() + extra + entry.chars().count() > area.width as usize {
            break;
        }
        if !text.is_empty() {
            text.push_str("  ");
        }
        text.push_str(entry);
    }
    Line::styled(text, app.theme.dim).render(area, buf);
}
