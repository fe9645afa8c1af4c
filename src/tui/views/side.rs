//! The left column: the parameter sliders and the readout at the marker.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use rough_model::Axis;

use crate::physical::print::{fmt_len, fmt_num, fmt_param, fmt_rel, fmt_share, fmt_short};
use crate::physical::short_number;
use crate::tui::app::App;
use crate::tui::glyphs::SliderBar;
use crate::tui::theme::CurveStyle;

pub fn render_sliders(app: &App, area: Rect, rows: u16, buf: &mut Buffer) {
    let t = &app.theme;
    let g = t.glyphs;
    Line::styled("Parameters", t.title).render(Rect { height: 1, ..area }, buf);
    let swept = app.state.sweep.axis();
    let roughness = app.state.roughness();
    for (i, axis) in Axis::ALL.into_iter().enumerate() {
        let y = area.y + 1 + i as u16 * rows;
        if y >= area.bottom() {
            break;
        }
        if !roughness.is_parameter(axis) {
            render_measured(app, axis, Rect::new(area.x, y, area.width, rows), buf);
            continue;
        }
        let selected = i == app.selected;
        let (lo, hi) = app.range(axis);
        let v = app.state.params.get(axis);
        let text = format!(
            "{}{:<5}{} {:>9}  {}",
            if selected { g.selected() } else { "  " },
            g.text(axis.symbol()),
            if axis == swept { g.swept() } else { ' ' },
            g.text(&fmt_param(axis, v)),
            g.text(&format!("{}…{}", fmt_short(axis, lo), fmt_short(axis, hi))),
        );
        let style = if selected { t.selected } else { Style::new() };
        let row = Rect::new(area.x, y, area.width, 1);
        buf.set_style(row, style);
        Line::styled(format!("{text:<w$}", w = area.width as usize), style).render(row, buf);
        if rows > 1 && y + 1 < area.bottom() {
            let width = area.width.saturating_sub(4) as usize;
            let bar = slider_bar(g.slider_bar(), axis, v, (lo, hi), width);
            let bar_style = if selected { t.title } else { t.dim };
            Line::styled(format!("   {bar}"), bar_style)
                .render(Rect::new(area.x, y + 1, area.width, 1), buf);
        }
    }
}

/// "0.81±0.03": a fit's H with its standard error.
pub fn hurst_se(f: &rough_surface::PowerLawFit) -> String {
    if f.hurst_se.is_finite() {
        format!("{:.2}±{:.2}", f.hurst, f.hurst_se)
    } else {
        format!("{:.2}", f.hurst)
    }
}

/// A line the data fixes on a measured surface, read-only (dim): h_rms as
/// √m0 at the cutoff, H as a least-squares power-law fit over the fit band
/// with its standard error and band, or why it is not self-affine there;
/// with two rows per slider, the fitted power law's h_rms and points (or
/// what h_rms is) under it.
fn render_measured(app: &App, axis: Axis, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let r = &app.readout;
    // Two digits: the band's ends fit the panel at 80 columns.
    let q = |v: f64| format!("{v:.1e}");
    let dash = if t.glyphs.ascii_text() { "-" } else { "…" };
    let (first, second) = match axis {
        Axis::Hurst => match r.fit {
            Some(f) => {
                let band = format!("q {}{dash}{}", q(f.fit.q_lo), q(f.fit.q_hi));
                let first = match f.fit.verdict().words() {
                    // ASCII writes ± as "+-": one column less around it,
                    // so that the band stays whole at 80 columns.
                    None if t.glyphs.ascii_text() => format!(
                        "  {:<5} {:>10} {band}",
                        "H fit",
                        hurst_se(&f.fit).replace('±', "+-")
                    ),
                    None => format!("  {:<5}  {:>9}  {band}", "H fit", hurst_se(&f.fit)),
                    Some(_) => format!(
                        "  {:<5}  {:>9}  not self-affine",
                        "H fit",
                        format!("({})", fmt_num(f.fit.hurst))
                    ),
                };
                let second = match (f.fit.verdict().words(), f.h_rms) {
                    (Some(w), _) => format!("   {w}; {band}"),
                    (None, Some(h)) => {
                        format!("   h_rms of the fitted power law {}", fmt_len(h))
                    }
                    (None, None) => format!("   {} pts", f.fit.points),
                };
                (first, second)
            }
            None => (
                format!("  {:<5}  {:>9}  too few points", "H fit", "—"),
                "   no power law fits the fit band".into(),
            ),
        },
        _ => (
            format!(
                "  {:<5}  {:>9}  √m0 at ζ",
                axis.symbol(),
                fmt_len(r.surface.spectrum.h_rms_actual)
            ),
            "   measured, not a parameter".into(),
        ),
    };
    let (first, second) = (t.glyphs.text(&first), t.glyphs.text(&second));
    let w = usize::from(area.width);
    Line::styled(format!("{first:<w$}"), t.dim).render(Rect { height: 1, ..area }, buf);
    if area.height > 1 {
        Line::styled(second.into_owned(), t.dim)
            .render(Rect::new(area.x, area.y + 1, area.width, 1), buf);
    }
}

/// "├───●────┤", the knob at the value's place in the range.
pub(super) fn slider_bar(
    g: SliderBar,
    axis: Axis,
    v: f64,
    (lo, hi): (f64, f64),
    width: usize,
) -> String {
    if width < 3 {
        return String::new();
    }
    let inner = width - 2;
    let f = if axis.is_log() && v > 0.0 {
        (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
    } else {
        (v - lo) / (hi - lo)
    };
    let mut cells = vec![g.line; inner];
    if f.is_nan() || f < 0.0 {
        cells[0] = g.below;
    } else if f > 1.0 {
        cells[inner - 1] = g.above;
    } else {
        let k = ((f * (inner - 1) as f64).round() as usize).min(inner - 1);
        cells[k] = g.knob;
    }
    let mut s = String::with_capacity(width * 3);
    s.push(g.left);
    s.extend(cells);
    s.push(g.right);
    s
}

/// What stands for a value while an open poll asks for it.
const HIDDEN: &str = "?";

/// Two labelled values on a line, in columns `w` wide (label, value,
/// label).
fn pair(w: [usize; 3], l1: &str, v1: String, l2: &str, v2: String) -> String {
    let [a, b, c] = w;
    format!("{l1:<a$}{v1:<b$}{l2:<c$}{v2}")
}

pub fn render_readout(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let g = t.glyphs;
    let r = &app.readout;
    let ix = &r.surface.indices;
    let sp = &r.surface.spectrum;
    let s = &app.state;
    // Labels and values as the glyph set writes them, before they are
    // padded into columns (wider columns for the ASCII names).
    let tx = |text: &str| g.text(text).into_owned();
    let num = |v: f64| tx(&fmt_num(v));
    // While a claim's poll is open (or a step hides its claims) the values
    // at the marker wait: the share and the slopes that make it give a
    // share's ½ or the total's minimum, the indices a Ψ = 1; and each
    // brackets the others' answers as the regime marks do (the share is
    // a function of the index in use).
    let hide = app.class.marks_hidden();
    let (hide_psi, hide_slopes) = (hide, hide);
    let psi = |v: f64| if hide_psi { HIDDEN.into() } else { num(v) };
    let slope = |v: f64| if hide_slopes { HIDDEN.into() } else { num(v) };
    let len = |m: f64| tx(&fmt_len(m));
    let w = if g.ascii_text() {
        [8, 10, 8]
    } else {
        [6, 10, 7]
    };
    let pair = |l1: &str, v1: String, l2: &str, v2: String| pair(w, &tx(l1), v1, &tx(l2), v2);
    let asym = match (ix.psi_star_asymptotic, ix.asymptotic_deviation()) {
        _ if hide_psi => HIDDEN.into(),
        (Some(a), Some(d)) => format!("{} ({:+.1}% vs Ψ*)", fmt_num(a), d * 100.0),
        (Some(a), None) => fmt_num(a),
        (None, _) if s.is_measured() => "n/a on measured data".into(),
        (None, _) => "n/a (R* = 0 or H = 1)".into(),
    };
    let sl = &r.slopes;
    let o = &r.other;
    let regime = sl.regime();
    let curve = |c: &CurveStyle, label: &str, v: f64| {
        vec![
            Span::styled(format!("{label:<6}"), c.style),
            Span::raw(format!("{:<10}", slope(v))),
        ]
    };
    let mut slopes1 = curve(&t.elastic, "S_el", sl.elastic);
    slopes1.extend(curve(&t.plastic, "S_pl", sl.plastic));
    let mut slopes2 = curve(&t.total, "S_tot", sl.total);
    slopes2.extend(curve(&t.persson, "S_P", r.persson));
    let mut lines = vec![
        Line::styled("Readout", t.title),
        Line::raw(pair("Ψ_GW", psi(ix.psi_gw), "Ψ_P", psi(ix.psi_p))),
        Line::raw(pair(
            "Ψ*",
            psi(ix.psi_star),
            "H_y/H0",
            num(ix.hardness_ratio),
        )),
        Line::raw(format!("{:<w$}{}", tx("Ψ*asy"), tx(&asym), w = w[0])),
        Line::raw(pair("R_s", len(sp.r_s), "λ1", len(sp.lambda1))),
        spectral_line(app, &tx, sp.h_rms_actual, sp.rms_slope),
        Line::raw(pair(
            "ε",
            num(2.0 * sp.rms_slope),
            "d_rep",
            len(4.0 * sp.rms_slope / sp.rms_curvature),
        )),
        Line::styled(
            tx(&format!(
                // The ASCII names are longer: no "=" to fit 34 columns.
                "marker: {} {}{} ({})",
                if s.size_effect { "Ψ*" } else { "Ψ_P" },
                if g.ascii_text() { "" } else { "= " },
                psi(r.psi),
                s.model.label()
            )),
            t.title,
        ),
        Line::from(slopes1),
        Line::from(slopes2),
        if hide_slopes {
            // (At most 34 columns: the readout's.)
            Line::raw(format!(
                "plastic {HIDDEN}  (until {})",
                match app.class.marks_wait() {
                    Some("the reveal") | None => "the reveal",
                    Some(_) => "the next poll",
                }
            ))
        } else {
            Line::from(vec![
                Span::raw(format!("plastic {}  ", fmt_share(sl.plastic_share()))),
                Span::styled(regime.label(), t.regime()),
            ])
        },
        Line::raw(format!("{} at the marker:", s.model.other().label())),
        Line::raw(tx(&format!(
            " el {}  pl {}  tot {}",
            fmt_rel(o.elastic, sl.elastic),
            fmt_rel(o.plastic, sl.plastic),
            fmt_rel(o.total, sl.total)
        ))),
    ];
    let mut at = 7;
    if let Some(rs) = s.surface.as_ref().and_then(|src| src.measured.real) {
        let (a, b) = rs.names();
        lines.insert(
            6,
            Line::raw(pair(a, len(rs.rms_height), b, num(rs.rms_slope))),
        );
        at += 1;
        // Where there is room: Sa and Sz, Ssk and Sku beside them.
        if usize::from(area.height) > lines.len() + 2 {
            let [sa, ssk, sku, sz] = rs.amplitude_names();
            let p = rs.amplitude;
            lines.insert(7, Line::raw(pair(sa, len(p.mean_abs), sz, len(p.range))));
            lines.insert(
                8,
                Line::raw(pair(ssk, num(p.skewness), sku, num(p.kurtosis))),
            );
            at += 2;
        }
    }
    // Where there is room: the longest wavelength (the power law's q0,
    // set with q0=… or l=… at the value prompt; a surface's own).
    if usize::from(area.height) > lines.len() {
        let q0 = s.params.q0();
        let l = std::f64::consts::TAU / q0;
        lines.insert(
            at,
            Line::raw(pair(
                "q0",
                tx(&format!("{}/m", short_number(q0))),
                "L",
                len(l),
            )),
        );
    }
    // What the reader assumed or repaired, under the readout: each note
    // wrapped to the panel's width, the rows left shared among the notes
    // still to come (a note cut short ends in the glyph set's cut mark).
    if let Some(src) = &s.surface {
        let width = usize::from(area.width);
        let notes = src.notes();
        for (k, n) in notes.iter().enumerate() {
            let left = usize::from(area.height).saturating_sub(lines.len());
            let rows = (left / (notes.len() - k)).max(1);
            for l in crate::tui::wrap::wrap(&tx(n), width, rows, t.glyphs.cut()) {
                lines.push(Line::styled(l, t.dim));
            }
        }
    }
    Paragraph::new(lines).render(area, buf);
}

/// The spectral h_rms and h′: on a measured surface named as from the PSD
/// up to ζ (beside Sq and Sdq), else as the power law's.
fn spectral_line<'a>(app: &App, tx: &dyn Fn(&str) -> String, h: f64, slope: f64) -> Line<'a> {
    if app.state.is_measured() {
        Line::raw(tx(&format!(
            "h_rms(ζ) {:<8} h′(ζ) {}",
            fmt_len(h),
            fmt_num(slope)
        )))
    } else {
        let w = if app.theme.glyphs.ascii_text() {
            [8, 10, 8]
        } else {
            [6, 10, 7]
        };
        Line::raw(pair(
            w,
            &tx("h_rms"),
            tx(&fmt_len(h)),
            &tx("h′"),
            tx(&fmt_num(slope)),
        ))
    }
}
