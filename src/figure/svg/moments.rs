//! The moments view as SVG: one panel per quantity, each on its own log
//! axis in its own unit — h_rms(ζ) (m), h′(ζ) (dimensionless) and h″(ζ)
//! (1/m) — stacked over one ζ axis that ends where the data do; on a
//! measured surface the real-space Sq and Sdq (Rq and RΔq) as dashed
//! levels in the panels of the spectral h_rms and h′ they are compared
//! with.

use super::legend::{Legend, Placed};
use super::{line, panel, positive_span, top_title, Area, Scale, Stroke};
use crate::figure::MomentSeries;
use crate::physical::{short_length, short_number};
use crate::scene::State;
use plotters::prelude::RGBColor;

const H: RGBColor = RGBColor(0, 0, 0);
const SLOPE: RGBColor = RGBColor(0, 0, 255);
const CURV: RGBColor = RGBColor(255, 0, 0);
/// The real-space levels, dashed (their colours are dashed by the viewer
/// wherever they appear): Sq beside h_rms, Sdq beside h′.
pub(super) const SQ: RGBColor = RGBColor(96, 96, 96);
pub(super) const SDQ: RGBColor = RGBColor(96, 96, 255);

/// Height of the title above the panels, and of the ζ axis' labels and
/// description under the last.
const TITLE_H: u32 = 45;
const X_AXIS_H: u32 = 59;

/// One panel: a quantity, its axis' description, its colour and label,
/// and the real-space level beside it (name, value, its words).
struct Quantity<'a> {
    values: &'a [f64],
    desc: &'static str,
    colour: RGBColor,
    label: String,
    level: Option<(RGBColor, String, f64)>,
}

pub(super) fn draw(
    area: &Area,
    state: &State,
    points: usize,
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let s = MomentSeries::of(state, points)?;
    let real = state.surface.as_ref().and_then(|src| src.measured.real);
    // Where the numbers come from is said under the chart: the labels
    // stay short, so that each panel's legend finds room inside it.
    let level = |colour, name: &str, v: f64, text: String| {
        Some((colour, format!("{name} = {text} (real space)"), v))
    };
    let names = real.map(|r| r.names());
    let panels = [
        Quantity {
            values: &s.h_rms,
            desc: "h_rms (m)",
            colour: H,
            label: "h_rms = √m0".into(),
            level: real.and_then(|r| {
                let n = names.map_or("Sq", |n| n.0);
                level(SQ, n, r.rms_height, short_length(r.rms_height))
            }),
        },
        Quantity {
            values: &s.h_prime,
            desc: "h′ (1)",
            colour: SLOPE,
            label: "h′ = √(2 m2)".into(),
            level: real.and_then(|r| {
                let n = names.map_or("Sdq", |n| n.1);
                level(SDQ, n, r.rms_slope, short_number(r.rms_slope))
            }),
        },
        Quantity {
            values: &s.h_dprime,
            desc: "h″ (1/m)",
            colour: CURV,
            label: "h″ = √(8 m4/3)".into(),
            level: None,
        },
    ];
    top_title(area, &super::title(state, "moments"))?;
    let h = area.dim_in_pixel().1;
    let each = (h.saturating_sub(TITLE_H + X_AXIS_H) / 3).max(40);
    let (_, rest) = area.split_vertically(TITLE_H);
    let (first, rest) = rest.split_vertically(each);
    let (second, third) = rest.split_vertically(each);
    // The ζ axis ends where the data do (not at the next decade).
    let ends = [s.zeta[0], s.zeta[s.len() - 1]];
    let x = Scale {
        log: true,
        lo: ends[0],
        hi: ends[1].max(ends[0] * 1.0001),
        desc: "ζ = q1/q0".into(),
    };
    let mut placed = Placed::Inside;
    for (k, (a, q)) in [first, second, third].iter().zip(&panels).enumerate() {
        let levels: Vec<f64> = q.level.iter().map(|l| l.2).collect();
        let (lo, hi) = positive_span(q.values.iter().chain(&levels));
        let y = Scale::around(true, lo, hi, q.desc.into());
        let mut c = panel(a, (&x, &y), room, k == 2)?;
        let mut lg = Legend::default();
        let xy = (&x, &y);
        line(
            &mut c,
            &mut lg,
            xy,
            (&s.zeta, q.values),
            q.colour,
            Stroke::Solid,
            &q.label,
        )?;
        if let Some((colour, label, v)) = &q.level {
            line(
                &mut c,
                &mut lg,
                xy,
                (&ends, &[*v, *v]),
                *colour,
                Stroke::Dashed,
                label,
            )?;
        }
        if let Placed::NoRoom(r) = lg.draw(a, &c, room.is_some())? {
            placed = match placed {
                Placed::NoRoom(p) => Placed::NoRoom(p.max(r)),
                Placed::Inside => Placed::NoRoom(r),
            };
        }
    }
    Ok(placed)
}
