//! Any view as a self-contained SVG document, drawn with `plotters`' SVG
//! backend: log axes with decade labels, units, a legend, the paper's
//! colours (elastic black, plastic blue, total red, Persson green) and the
//! caption under the chart, with the claims located live under it.

mod map;
mod moments;
mod spectrum;

use anyhow::anyhow;
use plotters::coord::types::RangedCoordf64;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use rough_model::{Axis, Curves, Scene};

use super::{axis_unit, FigureOptions, IndexSeries, LoadCurve, View};
use crate::figure::short_number;
use crate::snapshot::State;

/// Picture size in pixels (SVG user units).
pub const SIZE: (u32, u32) = (900, 600);

/// Least height kept under the chart for the caption and the claims.
const CAPTION_H: u32 = 70;

/// Characters per caption line, and pixels per line.
const CAPTION_W: usize = 110;
const LINE_H: u32 = 18;

/// The claims' colour: the dark green of "checked" text.
const CLAIMS: RGBColor = RGBColor(0, 110, 0);

/// The paper's colours.
pub const ELASTIC: RGBColor = RGBColor(0, 0, 0);
pub const PLASTIC: RGBColor = RGBColor(0, 0, 255);
pub const TOTAL: RGBColor = RGBColor(255, 0, 0);
pub const PERSSON: RGBColor = RGBColor(0, 160, 0);
const GREY: RGBColor = RGBColor(150, 150, 150);
const PSI_GW: RGBColor = RGBColor(128, 0, 128);
const PSI_ASY: RGBColor = RGBColor(230, 120, 0);

/// `view` of `state` as an SVG document (UTF-8 text).
pub fn render_svg(view: View, state: &State, opts: &FigureOptions) -> anyhow::Result<String> {
    render_with(state, |chart_area| match view {
        View::Slopes => slopes(chart_area, state, opts),
        View::Indices => indices(chart_area, state, opts),
        View::Map => map::draw(chart_area, state, opts),
        View::Load => load(chart_area, state, opts),
        View::Spectrum => spectrum::draw(chart_area, state),
    })
}

/// The moments of `state` against ζ (`export --view moments`) as SVG.
pub fn render_moments_svg(state: &State, points: usize) -> anyhow::Result<String> {
    render_with(state, |chart_area| moments::draw(chart_area, state, points))
}

/// A picture of `state`: `draw` fills the chart, the caption goes under it.
fn render_with(
    state: &State,
    draw: impl FnOnce(&Area) -> anyhow::Result<()>,
) -> anyhow::Result<String> {
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let lines = caption_lines(state);
        let caption_h = CAPTION_H.max(2 * 8 + LINE_H * lines.len() as u32);
        let (chart_area, caption_area) = root.split_vertically(SIZE.1 - caption_h);
        draw(&chart_area)?;
        caption(&caption_area, &lines)?;
        root.present().map_err(plot_err)?;
    }
    Ok(crisp_rects(buf))
}

/// Adjacent filled rectangles (the map's cells) would show hairline seams
/// where viewers anti-alias their shared edges; rectangles are drawn with
/// crisp edges, curves and text stay smooth.
fn crisp_rects(mut svg: String) -> String {
    if let Some(end) = svg
        .find("<svg")
        .and_then(|at| svg[at..].find('>').map(|e| at + e + 1))
    {
        svg.insert_str(end, "\n<style>rect{shape-rendering:crispEdges}</style>");
    }
    svg
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn plot_err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow!("cannot draw the picture: {e}")
}

/// One axis of a chart: drawn in log10 of the value on log axes, so that
/// every chart has the same coordinate type; labels show the values.
#[derive(Clone, Debug)]
pub(crate) struct Scale {
    pub log: bool,
    /// Ends in data units (> 0 on log axes).
    pub lo: f64,
    pub hi: f64,
    pub desc: String,
}

impl Scale {
    fn to(&self, v: f64) -> f64 {
        if self.log {
            v.log10()
        } else {
            v
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.to(self.lo)..self.to(self.hi)
    }

    /// A label for drawn coordinate `u`: decades on log axes (other ticks
    /// unlabelled), short numbers on linear ones.
    fn label(&self, u: f64) -> String {
        if !self.log {
            return short_number(u);
        }
        if (u - u.round()).abs() > 1e-9 {
            return String::new();
        }
        short_number(format!("1e{}", u.round()).parse().unwrap_or(f64::NAN))
    }

    /// The whole decades around `[lo, hi]` (log) or the range itself.
    fn around(log: bool, lo: f64, hi: f64, desc: String) -> Scale {
        let (lo, hi) = if log {
            let a = lo.log10().floor();
            let b = hi.log10().ceil().max(a + 1.0);
            (10f64.powf(a), 10f64.powf(b))
        } else {
            (lo, hi)
        };
        Scale { log, lo, hi, desc }
    }

    fn contains(&self, v: f64) -> bool {
        v.is_finite() && (!self.log || v > 0.0) && {
            let u = self.to(v);
            let r = self.range();
            u >= r.start - 1e-9 && u <= r.end + 1e-9
        }
    }
}

/// The description of a parameter axis: "ζ", "h_rms (m)".
pub(crate) fn axis_desc(axis: Axis) -> String {
    match axis_unit(axis) {
        "" => axis.symbol().to_string(),
        u => format!("{} ({u})", axis.symbol()),
    }
}

/// A chart on `area` with the given scales, mesh drawn, and a title.
fn chart<'a, 'b>(
    area: &'a Area<'b>,
    title: &str,
    x: &Scale,
    y: &Scale,
) -> anyhow::Result<Chart<'a, 'b>> {
    let mut c = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x.range(), y.range())
        .map_err(plot_err)?;
    let (xl, yl) = (|u: &f64| x.label(*u), |u: &f64| y.label(*u));
    let ticks = |s: &Scale| {
        if s.log {
            // One tick per decade (at most 12 labels).
            ((s.to(s.hi) - s.to(s.lo)).round() as usize + 1).min(12)
        } else {
            6
        }
    };
    c.configure_mesh()
        .x_desc(x.desc.as_str())
        .y_desc(y.desc.as_str())
        .x_labels(ticks(x))
        .y_labels(ticks(y))
        .x_label_formatter(&xl)
        .y_label_formatter(&yl)
        .light_line_style(WHITE)
        .bold_line_style(RGBColor(225, 225, 225))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .draw()
        .map_err(plot_err)?;
    Ok(c)
}

/// How a curve is stroked: solid, or dashed so that it stays visible on
/// top of a curve it coincides with (Persson's line on the total, eq. 13
/// on Ψ*).
#[derive(Clone, Copy, PartialEq)]
enum Stroke {
    Solid,
    Dashed,
}

/// Draws `ys` against `xs` as a labelled line, broken where a point is
/// undefined or off the chart.
fn line(
    c: &mut Chart,
    (x, y): (&Scale, &Scale),
    (xs, ys): (&[f64], &[f64]),
    colour: RGBColor,
    stroke: Stroke,
    label: &str,
) -> anyhow::Result<()> {
    let mut segs: Vec<Vec<(f64, f64)>> = vec![vec![]];
    for (&a, &b) in xs.iter().zip(ys) {
        if x.contains(a) && y.contains(b) {
            if let Some(s) = segs.last_mut() {
                s.push((x.to(a), y.to(b)));
            }
        } else if segs.last().is_some_and(|s| !s.is_empty()) {
            segs.push(vec![]);
        }
    }
    let segs = segs.into_iter().filter(|s| s.len() > 1);
    let style = colour.stroke_width(2);
    let anno = if stroke == Stroke::Dashed {
        c.draw_series(segs.map(move |s| DashedPathElement::new(s, 9, 6, style)))
    } else {
        c.draw_series(segs.map(move |s| PathElement::new(s, style)))
    }
    .map_err(plot_err)?;
    anno.label(label).legend(move |(px, py)| {
        DashedPathElement::new(
            vec![(px, py), (px + 20, py)],
            if stroke == Stroke::Dashed { 5 } else { 20 },
            if stroke == Stroke::Dashed { 3 } else { 0 },
            style,
        )
    });
    Ok(())
}

/// A thin unlabelled guide line between two data points.
fn guide(c: &mut Chart, a: (f64, f64), b: (f64, f64), colour: RGBColor) -> anyhow::Result<()> {
    c.draw_series(std::iter::once(PathElement::new(vec![a, b], colour)))
        .map_err(plot_err)?;
    Ok(())
}

fn legend<'a, 'b: 'a>(c: &mut Chart<'a, 'b>) -> anyhow::Result<()> {
    legend_at(c, SeriesLabelPosition::UpperLeft)
}

fn legend_at<'a, 'b: 'a>(c: &mut Chart<'a, 'b>, at: SeriesLabelPosition) -> anyhow::Result<()> {
    c.configure_series_labels()
        .position(at)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .draw()
        .map_err(plot_err)
}

/// "fig2 · closed form, asymptotic moments, size effect off"; a measured
/// surface's moments are "measured".
fn title(state: &State, what: &str) -> String {
    let moments = if state.is_measured() {
        "measured"
    } else {
        state.moments.label()
    };
    format!(
        "{} — {what} ({}, {moments} moments, size effect {})",
        state.name,
        state.model.label(),
        if state.size_effect { "on" } else { "off" }
    )
}

/// Finite positive values' (min, max); (1, 10) when there are none.
fn positive_span<'a>(vals: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (lo, hi) = vals
        .filter(|v| v.is_finite() && **v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    if hi > 0.0 {
        (lo, hi)
    } else {
        (1.0, 10.0)
    }
}

/// Whether two curves lie within 0.1 % of each other wherever both are
/// finite (then one hides the other on the chart).
fn coincide(a: &[f64], b: &[f64]) -> bool {
    a.iter()
        .zip(b)
        .filter(|(u, v)| u.is_finite() && v.is_finite())
        .all(|(u, v)| (u - v).abs() <= 1e-3 * v.abs())
}

fn x_scale(state: &State) -> Scale {
    let s = &state.sweep;
    Scale {
        log: s.axis().is_log(),
        lo: s.from(),
        hi: s.to(),
        desc: axis_desc(s.axis()),
    }
}

/// A vertical guide at the current value of the swept parameter.
fn marker(c: &mut Chart, state: &State, x: &Scale, y: &Scale) -> anyhow::Result<()> {
    let v = state.params.get(state.sweep.axis());
    if x.contains(v) {
        let r = y.range();
        guide(c, (x.to(v), r.start), (x.to(v), r.end), GREY)?;
    }
    Ok(())
}

fn slopes(area: &Area, state: &State, opts: &FigureOptions) -> anyhow::Result<()> {
    let s = Scene::compute(&state.scene_spec(Curves::ALL, opts.points))?;
    let x = x_scale(state);
    let (_, hi) = positive_span(s.elastic.iter().chain(&s.total).chain(&s.persson_elastic));
    let (lo, _) = positive_span(
        s.plastic
            .iter()
            .chain(&s.elastic)
            .filter(|v| **v >= hi * 1e-4),
    );
    let y = Scale::around(true, lo, hi, "initial slope H·dA/(A0·dp̄)".into());
    let mut c = chart(area, &title(state, "initial slopes"), &x, &y)?;
    marker(&mut c, state, &x, &y)?;
    let xy = (&x, &y);
    let solid = Stroke::Solid;
    // Every listed curve can be found: say where one lies under another
    // or below the chart.
    let el = if coincide(&s.elastic, &s.total) {
        "elastic (= total here)"
    } else {
        "elastic"
    };
    let pl = if s.plastic.iter().any(|&v| y.contains(v)) {
        "plastic"
    } else {
        "plastic (below the chart here)"
    };
    line(&mut c, xy, (&s.x, &s.elastic), ELASTIC, solid, el)?;
    line(&mut c, xy, (&s.x, &s.plastic), PLASTIC, solid, pl)?;
    line(&mut c, xy, (&s.x, &s.total), TOTAL, solid, "total")?;
    let persson = (&s.x[..], &s.persson_elastic[..]);
    let dashed = Stroke::Dashed;
    line(
        &mut c,
        xy,
        persson,
        PERSSON,
        dashed,
        "Persson elastic √(2/π)/ψ",
    )?;
    legend(&mut c)
}

fn indices(area: &Area, state: &State, opts: &FigureOptions) -> anyhow::Result<()> {
    let s = IndexSeries::compute(state, opts.points)?;
    let asy: Vec<f64> = s
        .psi_star_asymptotic
        .iter()
        .map(|v| v.unwrap_or(f64::NAN))
        .collect();
    let x = x_scale(state);
    let (lo, hi) = positive_span(s.psi_gw.iter().chain(&s.psi_p).chain(&s.psi_star));
    let y = Scale::around(true, lo.min(0.5).max(hi * 1e-8), hi.max(2.0), "Ψ".into());
    let mut c = chart(area, &title(state, "plasticity indices"), &x, &y)?;
    marker(&mut c, state, &x, &y)?;
    let r = x.range();
    guide(&mut c, (r.start, 0.0), (r.end, 0.0), GREY)?;
    let xy = (&x, &y);
    let solid = Stroke::Solid;
    line(
        &mut c,
        xy,
        (&s.x, &s.psi_gw),
        PSI_GW,
        solid,
        "Ψ_GW (Greenwood–Williamson)",
    )?;
    line(
        &mut c,
        xy,
        (&s.x, &s.psi_p),
        PLASTIC,
        solid,
        "Ψ_P (Persson, H0)",
    )?;
    line(
        &mut c,
        xy,
        (&s.x, &s.psi_star),
        TOTAL,
        solid,
        "Ψ* (size-dependent H_y)",
    )?;
    // Eq. 13 is a power law's: no line on a measured surface.
    if !state.is_measured() {
        let dashed = Stroke::Dashed;
        line(&mut c, xy, (&s.x, &asy), PSI_ASY, dashed, "Ψ*asy (eq. 13)")?;
    }
    legend(&mut c)
}

fn load(area: &Area, state: &State, opts: &FigureOptions) -> anyhow::Result<()> {
    let l = LoadCurve::compute(state, opts.points)?;
    let h = if state.size_effect { "H_y" } else { "H0" };
    let x = Scale {
        log: false,
        lo: 0.0,
        hi: 1.0,
        desc: format!("load p̄/H (H = {h})"),
    };
    let y = Scale {
        log: false,
        lo: 0.0,
        hi: 1.0,
        desc: "contact area A/A0".into(),
    };
    let what = format!("areas against load at ψ = {}", short_number(l.psi));
    let mut c = chart(area, &title(state, &what), &x, &y)?;
    let (tx, ty) = l.tangent_end();
    let tangent = TOTAL.mix(0.5).stroke_width(1);
    c.draw_series(std::iter::once(PathElement::new(
        vec![(0.0, 0.0), (tx, ty)],
        tangent,
    )))
    .map_err(plot_err)?
    .label(format!(
        "initial slope S_tot = {} (from the origin)",
        short_number(l.slopes.total)
    ))
    .legend(move |(px, py)| PathElement::new(vec![(px, py), (px + 20, py)], tangent));
    let xy = (&x, &y);
    let solid = Stroke::Solid;
    line(&mut c, xy, (&l.load, &l.elastic), ELASTIC, solid, "elastic")?;
    line(&mut c, xy, (&l.load, &l.plastic), PLASTIC, solid, "plastic")?;
    line(&mut c, xy, (&l.load, &l.total), TOTAL, solid, "total")?;
    legend(&mut c)
}

/// The state's caption (or its name) wrapped for under the chart, then
/// the claims (as on the explorer's caption row, in full), each line with
/// its colour.
fn caption_lines(state: &State) -> Vec<(String, RGBColor)> {
    let text = state.caption.as_deref().unwrap_or(state.name.as_str());
    let claims = crate::figure::claims(state).into_iter().map(|c| c.text());
    let mut lines: Vec<_> = wrap(text, CAPTION_W)
        .into_iter()
        .map(|l| (l, BLACK))
        .collect();
    // Claims are packed whole, never broken inside one.
    let mut row = String::new();
    for c in claims {
        if !row.is_empty() && row.chars().count() + 3 + c.chars().count() > CAPTION_W {
            lines.push((std::mem::take(&mut row), CLAIMS));
        }
        row = if row.is_empty() {
            c
        } else {
            format!("{row} · {c}")
        };
    }
    if !row.is_empty() {
        lines.push((row, CLAIMS));
    }
    lines
}

/// `lines` under the chart.
fn caption(area: &Area, lines: &[(String, RGBColor)]) -> anyhow::Result<()> {
    let mut y = 8;
    for (l, colour) in lines {
        let font = ("sans-serif", 14).into_font().color(colour);
        area.draw(&Text::new(l.as_str(), (20, y), font))
            .map_err(plot_err)?;
        y += LINE_H as i32;
    }
    Ok(())
}

/// `text` in lines of at most `width` characters, broken at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = vec![];
    let mut cur = String::new();
    for w in text.split_whitespace() {
        if !cur.is_empty() && cur.chars().count() + 1 + w.chars().count() > width {
            lines.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(w);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::wrap;

    #[test]
    fn legend_says_where_a_curve_hides() {
        use super::*;
        let svg = |name: &str| {
            let s = crate::presets::load(name).unwrap();
            render_svg(View::Slopes, &s, &FigureOptions::default()).unwrap()
        };
        let fig3 = svg("fig3");
        assert!(fig3.contains("elastic (= total here)"));
        assert!(fig3.contains("plastic (below the chart here)"));
        let fig2 = svg("fig2");
        assert!(!fig2.contains("= total here") && !fig2.contains("below the chart"));
    }

    #[test]
    fn wrap_breaks_at_spaces() {
        assert_eq!(wrap("aa bb cc", 5), ["aa bb", "cc"]);
        assert_eq!(wrap("", 5), Vec::<String>::new());
        assert_eq!(wrap("longword x", 3), ["longword", "x"]);
    }
}
