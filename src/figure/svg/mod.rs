//! Any view as a self-contained SVG document, drawn with `plotters`' SVG
//! backend: log axes with decade labels, units, a legend, the paper's
//! colours (elastic black, plastic blue, total red, Persson green) and the
//! caption under the chart, with the claims located live under it.

mod caption;
mod contact;
mod contact_map;
mod curves;
mod entry;
mod fine;
mod legend;
mod map;
mod moments;
mod phone;
mod plot;
mod spectrum;
mod wrap;

use anyhow::anyhow;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use rough_model::Axis;

use super::{axis_unit, FigureOptions, View};
use crate::figure::scene_text;
use crate::physical::short_number;
use crate::scene::State;
use caption::{caption, caption_lines, SCENE};
pub use contact::{
    contact_span, render_contact, render_contact_slopes, render_contact_sweep, sweep_span,
    ContactLoads, ContactSlopes, ContactSweep,
};
pub use contact_map::{render_contact_map, ContactMap};
use legend::{Legend, Placed, Sample};
pub use phone::{phone_note, render_phone, render_phone_with, LegendEntry, Picture, UPRIGHT, WIDE};
use wrap::wrap;

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
/// The indices' Ψ = 1 line: darker than the marker's grey and dashed
/// (1-px strokes of this colour are dashed by the viewer).
const THRESHOLD: RGBColor = RGBColor(80, 80, 80);
const PSI_GW: RGBColor = RGBColor(128, 0, 128);
const PSI_ASY: RGBColor = RGBColor(230, 120, 0);

/// The colours only dashed curves have (Persson's line, eq. 13, the
/// spectrum's fit, the moments' real-space levels): their 2-px strokes are
/// dashed by the viewer.
const DASHED: [RGBColor; 4] = [PERSSON, PSI_ASY, moments::SQ, moments::SDQ];

/// `svg` with every 2-px stroke of a [`DASHED`] colour dashed 9 on, 6 off.
fn dash(mut svg: String) -> String {
    for RGBColor(r, g, b) in DASHED {
        let stroke = format!("stroke=\"#{r:02X}{g:02X}{b:02X}\" stroke-width=\"2\"");
        svg = svg.replace(&stroke, &format!("{stroke} stroke-dasharray=\"9 6\""));
    }
    let RGBColor(r, g, b) = THRESHOLD;
    let stroke = format!("stroke=\"#{r:02X}{g:02X}{b:02X}\" stroke-width=\"1\"");
    svg.replace(&stroke, &format!("{stroke} stroke-dasharray=\"6 4\""))
}

/// `view` of `state` as an SVG document (UTF-8 text). Under the chart: the
/// scene's parameters, the view's caption and, where the view shows the
/// sweep, the claims; the full parameter set also goes into `<desc>`.
pub fn render_svg(view: View, state: &State, opts: &FigureOptions) -> anyhow::Result<String> {
    let draw = |area: &Area, room| match view {
        View::Slopes => curves::slopes(area, state, opts, room),
        View::Indices => curves::indices(area, state, opts, room),
        View::Map => map::draw(area, state, opts).map(|()| Placed::Inside),
        View::Load => curves::load(area, state, opts, room),
        View::Spectrum => spectrum::draw(area, state, room),
        View::Contact => Err(anyhow::anyhow!(
            "the contact view's picture is drawn by crate::contact (export --view contact \
             --format svg, contact-map)"
        )),
    };
    let title = format!("{} — {} view", state.name, view.name());
    let desc = scene_text::full_lines(state, view, opts);
    render(&draw, &caption_lines(view, state, opts), &title, &desc)
}

/// The moments of `state` against ζ (`export --view moments`) as SVG, with
/// the scene under the chart and in `<desc>` as every picture has it.
pub fn render_moments_svg(state: &State, points: usize) -> anyhow::Result<String> {
    let draw = |area: &Area, room| moments::draw(area, state, points, room);
    let s = crate::figure::MomentSeries::of(state, points)?;
    let (from, to) = (s.zeta[0], s.zeta[s.len() - 1]);
    let span = format!("cutoffs = zeta from {from:?} to {to:?}, {points} points (log-spaced)");
    let mut desc = scene_text::full_lines_of(state, "moments", span);
    desc.extend(crate::figure::moment_comments(state));
    let short = format!("moments at ζ {} … {}", short_number(from), short_number(to));
    let what = if state.is_measured() {
        "The spectrum's moments against the cutoff ζ, summed from the PSD up to ζ (after the \
         detrend and window): h_rms = √m0, the rms slope h′ = √(2 m2) and the rms curvature \
         h″ = √(8 m4/3), each in its own panel and unit; dashed, the real-space Sq and Sdq \
         (Rq and RΔq of a line scan; after the detrend, no window)."
    } else {
        "The spectrum's moments against the cutoff ζ: h_rms = √m0, the rms slope h′ = √(2 m2) \
         and the rms curvature h″ = √(8 m4/3), each in its own panel and unit."
    };
    let lines = under(state, Some(short), what);
    render(&draw, &lines, &format!("{} — moments", state.name), &desc)
}

/// The lines under a picture that is not one of the explorer's views: the
/// scene in short with what the picture spans (`span`), then `what` it
/// shows.
fn under(state: &State, span: Option<String>, what: &str) -> Vec<(String, RGBColor)> {
    let mut lines: Vec<(String, RGBColor)> = scene_text::short_lines_of(state, span)
        .iter()
        .flat_map(|l| wrap(l, CAPTION_W))
        .map(|l| (l, SCENE))
        .collect();
    lines.extend(wrap(what, CAPTION_W).into_iter().map(|l| (l, BLACK)));
    lines
}

/// A picture: `draw` fills the chart (the legend inside the plot where no
/// line passes, else the picture is drawn again with the plot narrower
/// and the legend right of it), `lines` go under it, `title` and `desc`
/// into the document's head.
fn render(
    draw: &dyn Fn(&Area, Option<u32>) -> anyhow::Result<Placed>,
    lines: &[(String, RGBColor)],
    title: &str,
    desc: &[String],
) -> anyhow::Result<String> {
    let buf = match render_once(draw, lines, None)? {
        (buf, Placed::Inside) => buf,
        (_, Placed::NoRoom(room)) => render_once(draw, lines, Some(room))?.0,
    };
    // (A phone's picture: its page says the scene.)
    let desc = if phone::size().is_some() {
        &[][..]
    } else {
        desc
    };
    let head = format!(
        "\n<title>{}</title>\n<desc>{}</desc>\n<style>rect{{shape-rendering:crispEdges}}</style>",
        xml_text(title),
        xml_text(&desc.join("\n"))
    );
    Ok(after_svg_tag(dash(buf), &head))
}

/// One drawing of the picture, `room` pixels kept right of the plot for
/// the legend (inside the plot when `None`), and where the legend went.
fn render_once(
    draw: &dyn Fn(&Area, Option<u32>) -> anyhow::Result<Placed>,
    lines: &[(String, RGBColor)],
    room: Option<u32>,
) -> anyhow::Result<(String, Placed)> {
    let mut buf = String::new();
    fine::start();
    phone::start();
    let placed = {
        // A phone's picture: its shape, nothing under the chart.
        let phone = phone::size();
        let size = phone.unwrap_or(SIZE);
        let root = SVGBackend::with_string(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let placed = if phone.is_some() {
            draw(&root, room)?
        } else {
            let caption_h = CAPTION_H.max(2 * 8 + LINE_H * lines.len() as u32);
            let (chart_area, caption_area) = root.split_vertically(SIZE.1 - caption_h);
            let placed = draw(&chart_area, room)?;
            caption(&caption_area, lines)?;
            placed
        };
        root.present().map_err(plot_err)?;
        placed
    };
    Ok((fine::apply(&buf), placed))
}

/// `text` with XML's special characters escaped, for element content.
fn xml_text(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// `svg` with `head` inserted right after the opening `<svg …>` tag. It
/// holds the title, the description and a style: adjacent filled
/// rectangles (the map's cells) would show hairline seams where viewers
/// anti-alias their shared edges, so rectangles are drawn with crisp
/// edges, curves and text stay smooth.
fn after_svg_tag(mut svg: String, head: &str) -> String {
    if let Some(end) = svg
        .find("<svg")
        .and_then(|at| svg[at..].find('>').map(|e| at + e + 1))
    {
        svg.insert_str(end, head);
    }
    svg
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// What a view leaves out while a poll's answer waits, said in the middle
/// of the plot `c`: "`what` wait for the reveal: they would answer the
/// poll".
fn waits(area: &Area, c: &Chart, what: &str) -> anyhow::Result<()> {
    let (xr, yr) = c.plotting_area().get_pixel_range();
    let (ox, oy) = area.get_base_pixel();
    let (cx, cy) = ((xr.start + xr.end) / 2 - ox, (yr.start + yr.end) / 2 - oy);
    let chars = ((xr.end - xr.start) as f64 / 8.0) as usize;
    let text = format!("{what} wait for the reveal: they would answer the poll");
    let lines = wrap(&text, chars.max(12));
    let style =
        ("sans-serif", 16)
            .into_font()
            .color(&GREY)
            .pos(plotters::style::text_anchor::Pos::new(
                plotters::style::text_anchor::HPos::Center,
                plotters::style::text_anchor::VPos::Center,
            ));
    let top = cy - (lines.len() as i32 - 1) * 11;
    for (i, l) in lines.iter().enumerate() {
        area.draw(&Text::new(
            l.clone(),
            (cx, top + 22 * i as i32),
            style.clone(),
        ))
        .map_err(plot_err)?;
    }
    Ok(())
}

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
    /// unlabelled), short numbers on linear ones. One style per axis: plain
    /// (0.01 … 1000) when every decade on it is, else powers of ten
    /// (10⁻⁴ … 10⁴) for all of them.
    fn label(&self, u: f64) -> String {
        if !self.log {
            return short_number(u);
        }
        if (u - u.round()).abs() > 1e-9 {
            return String::new();
        }
        let k = u.round() as i32;
        let (a, b) = (self.lo.log10().floor(), self.hi.log10().ceil());
        if a >= -2.0 && b <= 3.0 {
            short_number(10f64.powi(k))
        } else {
            power_of_ten(k)
        }
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

/// "10⁻⁴", "10⁰", "10¹²": a power of ten with a superscript exponent.
pub(crate) fn power_of_ten(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits: String = k
        .unsigned_abs()
        .to_string()
        .bytes()
        .map(|d| SUP[usize::from(d - b'0')])
        .collect();
    format!("10{}{digits}", if k < 0 { "⁻" } else { "" })
}

/// The description of a parameter axis: "ζ", "h_rms (m)".
pub(crate) fn axis_desc(axis: Axis) -> String {
    match axis_unit(axis) {
        "" => axis.symbol().to_string(),
        u => format!("{} ({u})", axis.symbol()),
    }
}

/// A chart on `area` with the given scales, mesh drawn, and a title;
/// `room` pixels kept right of the plot for a legend outside it.
fn chart<'a, 'b>(
    area: &'a Area<'b>,
    title: &str,
    xy: (&Scale, &Scale),
    room: Option<u32>,
) -> anyhow::Result<Chart<'a, 'b>> {
    chart_with_top(area, title, xy, room, 0)
}

/// [`chart`] with `top` pixels between the title and the plot (for a
/// second axis above it).
fn chart_with_top<'a, 'b>(
    area: &'a Area<'b>,
    title: &str,
    (x, y): (&Scale, &Scale),
    room: Option<u32>,
    top: u32,
) -> anyhow::Result<Chart<'a, 'b>> {
    // The title centred on the picture, not on the plot (which a legend
    // right of it makes narrower): drawn here, where plotters' caption
    // would go; with `top`, above the room kept for a second axis
    // (plotters would label the q axis there too).
    top_title(area, title)?;
    let mut c = ChartBuilder::on(area)
        .margin(15)
        .margin_top(if top == 0 { TITLE_H } else { 15 + 30 + top })
        .margin_right(15 + room.unwrap_or(0))
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x.range(), y.range())
        .map_err(plot_err)?;
    mesh(&mut c, (x, y))?;
    Ok(c)
}

/// Pixels from the picture's top to the plot's, under the title (where
/// plotters' own caption would put the plot).
const TITLE_H: u32 = 41;

/// `title` centred at the top of `area`, where plotters puts a chart's
/// caption, cut to fit as [`fit_title`] cuts it.
fn top_title(area: &Area, title: &str) -> anyhow::Result<()> {
    let max = ((f64::from(area.dim_in_pixel().0) - 30.0) / TITLE_CHAR_W) as usize;
    let w = area.dim_in_pixel().0 as i32;
    let style = ("sans-serif", 20).into_font().into_text_style(area).pos(
        plotters::style::text_anchor::Pos::new(
            plotters::style::text_anchor::HPos::Center,
            plotters::style::text_anchor::VPos::Top,
        ),
    );
    area.draw(&Text::new(fit_title(title, max), (w / 2, 15), style))
        .map_err(plot_err)?;
    Ok(())
}

/// One panel of several stacked on `area` (no title; the x axis' labels
/// and description only when `x_labels`, under the last).
fn panel<'a, 'b>(
    area: &'a Area<'b>,
    (x, y): (&Scale, &Scale),
    room: Option<u32>,
    x_labels: bool,
) -> anyhow::Result<Chart<'a, 'b>> {
    let mut c = ChartBuilder::on(area)
        .margin(15)
        .margin_top(10)
        .margin_bottom(if x_labels { 15 } else { 10 })
        .margin_right(15 + room.unwrap_or(0))
        .x_label_area_size(if x_labels { 50 } else { 0 })
        .y_label_area_size(70)
        .build_cartesian_2d(x.range(), y.range())
        .map_err(plot_err)?;
    mesh(&mut c, (x, y))?;
    Ok(c)
}

/// The grid, ticks, labels and axis descriptions every chart has: one
/// labelled tick per decade on log axes, six on linear ones.
fn mesh(c: &mut Chart, (x, y): (&Scale, &Scale)) -> anyhow::Result<()> {
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
    Ok(())
}

/// How a curve is stroked: solid, or dashed so that it stays visible on
/// top of a curve it coincides with (Persson's line on the total, eq. 13
/// on Ψ*).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Stroke {
    Solid,
    Dashed,
}

/// Draws `ys` against `xs` as a line listed in the legend as `label`,
/// broken where a point is undefined or off the chart.
fn line(
    c: &mut Chart,
    lg: &mut Legend,
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
    let segs: Vec<_> = segs.into_iter().filter(|s| s.len() > 1).collect();
    if segs.is_empty() {
        // Nothing of it is on the chart: not listed either.
        return Ok(());
    }
    let style = colour.stroke_width(2);
    lg.paths.extend(segs.iter().cloned());
    // A dashed curve is one path the viewer dashes (`stroke-dasharray`,
    // added by colour in `render_svg`): smooth dashes, not pixel-rounded
    // pieces.
    debug_assert!(stroke == Stroke::Solid || DASHED.contains(&colour));
    for s in segs {
        fine::path(c, s, style)?;
    }
    let sample = match stroke {
        Stroke::Dashed => Sample::Dashed,
        Stroke::Solid => Sample::Solid(2),
    };
    lg.add(label, colour, sample);
    Ok(())
}

/// A thin guide line between two data points, listed in the legend as
/// `label` when it has one.
fn guide(
    c: &mut Chart,
    lg: &mut Legend,
    a: (f64, f64),
    b: (f64, f64),
    colour: RGBColor,
    label: Option<&str>,
) -> anyhow::Result<()> {
    c.draw_series(std::iter::once(PathElement::new(vec![a, b], colour)))
        .map_err(plot_err)?;
    lg.paths.push(vec![a, b]);
    if let Some(l) = label {
        lg.add(l, colour, Sample::Solid(1));
    }
    Ok(())
}

/// "fig2 — initial slopes": the scene's name and what the view shows (the
/// settings are on the scene line under the chart).
fn title(state: &State, what: &str) -> String {
    format!("{} — {what}", state.name)
}

/// Pixels per character of the title: plotters writes its 20-point font as
/// 16.13 px, and digits, the widest common glyphs of a sans-serif, are
/// 0.64 em (10.3 px): a bound for names, not an average.
pub(crate) const TITLE_CHAR_W: f64 = 10.5;

/// `title` cut to `max` characters so that it is never clipped: the
/// scene's name (before " — ") gives way first, ending in "…", then what
/// the view shows.
pub(crate) fn fit_title(title: &str, max: usize) -> String {
    let n = title.chars().count();
    if n <= max {
        return title.to_string();
    }
    let cut = |s: &str, keep: usize| -> String {
        s.chars().take(keep).chain(std::iter::once('…')).collect()
    };
    match title.split_once(" — ") {
        Some((name, what)) if what.chars().count() + 5 <= max => {
            let keep = max - what.chars().count() - 4;
            format!("{} — {what}", cut(name, keep))
        }
        _ => cut(title, max.saturating_sub(1)),
    }
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

#[cfg(test)]
#[path = "mod_tests.rs"]
mod tests;
