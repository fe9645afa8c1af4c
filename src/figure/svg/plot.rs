//! A chart of curves and points given as data (the contact simulation's
//! pictures): the same axes, ticks, colours, legend placement and
//! sub-pixel curves as the explorer's views, points as dots with their
//! standard deviation as error bars where there is one.

use plotters::prelude::*;

use super::legend::{Legend, Placed, Sample};
use super::{chart, line, plot_err, Area, Chart, Scale, Stroke};

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Mark {
    Line(Stroke),
    /// Filled dots of this radius (px).
    Dots(u32),
}

/// One series: `y` against `x` (data units), ± `sd` where given.
pub(crate) struct Series<'a> {
    pub label: String,
    pub colour: RGBColor,
    pub mark: Mark,
    pub x: &'a [f64],
    pub y: &'a [f64],
    pub sd: Option<&'a [f64]>,
}

/// The chart on `area`: `series` in order (the first drawn first, listed
/// first), the legend where no curve, dot or bar passes.
pub(crate) fn draw(
    area: &Area,
    title: &str,
    (x, y): (&Scale, &Scale),
    series: &[Series],
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let mut c = chart(area, title, (x, y), room)?;
    let mut lg = Legend::default();
    for s in series {
        match s.mark {
            Mark::Line(stroke) => line(
                &mut c,
                &mut lg,
                (x, y),
                (s.x, s.y),
                s.colour,
                stroke,
                &s.label,
            )?,
            Mark::Dots(r) => dots(&mut c, &mut lg, (x, y), s, r)?,
        }
    }
    lg.draw(area, &c, room.is_some())
}

/// `s` as dots of radius `r` with its error bars, where they are on the
/// chart; listed in the legend when any is.
fn dots(
    c: &mut Chart,
    lg: &mut Legend,
    (x, y): (&Scale, &Scale),
    s: &Series,
    r: u32,
) -> anyhow::Result<()> {
    let mut pts = vec![];
    for (i, (&a, &b)) in s.x.iter().zip(s.y).enumerate() {
        if !(x.contains(a) && y.contains(b)) {
            continue;
        }
        let p = (x.to(a), y.to(b));
        if let Some(sd) = s.sd.and_then(|sd| sd.get(i)).filter(|v| **v > 0.0) {
            // ± one standard deviation, cut at the chart's ends (a log
            // axis has no place for b − sd ≤ 0).
            let clamp = |v: f64| {
                let r = y.range();
                if y.log && v <= 0.0 {
                    r.start
                } else {
                    y.to(v).clamp(r.start, r.end)
                }
            };
            let (lo, hi) = (clamp(b - sd), clamp(b + sd));
            let bar = vec![(p.0, lo), (p.0, hi)];
            lg.paths.push(bar.clone());
            c.draw_series(std::iter::once(PathElement::new(
                bar,
                s.colour.stroke_width(1),
            )))
            .map_err(plot_err)?;
        }
        pts.push(p);
    }
    if pts.is_empty() {
        return Ok(());
    }
    lg.dots.extend(pts.iter().map(|p| (*p, r as i32)));
    c.draw_series(pts.iter().map(|p| Circle::new(*p, r, s.colour.filled())))
        .map_err(plot_err)?;
    lg.add(s.label.clone(), s.colour, Sample::Dot(r));
    Ok(())
}

impl Scale {
    /// A scale over the data `[lo, hi]` with a margin of `pad` of its
    /// drawn span at either end, so that a point at an end is drawn
    /// whole (a dot cut in half by the axis reads as a mistake).
    pub(crate) fn padded(log: bool, lo: f64, hi: f64, pad: f64, desc: String) -> Scale {
        let t = |v: f64| if log { v.log10() } else { v };
        let back = |u: f64| if log { 10f64.powf(u) } else { u };
        let (a, b) = (t(lo), t(hi));
        let m = if b > a { (b - a) * pad } else { 0.5 };
        Scale {
            log,
            lo: back(a - m),
            hi: back(b + m),
            desc,
        }
    }
}
