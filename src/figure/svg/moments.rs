//! The moments view as SVG: h_rms(ζ) (m), h′(ζ) and h″(ζ) (1/m) against ζ
//! on log-log axes, each in its own SI unit; on a measured surface the
//! real-space Sq and Sdq (Rq and RΔq) as dashed levels beside the
//! spectral h_rms and h′ they are compared with.

use super::legend::{Legend, Placed};
use super::{chart, line, positive_span, title, Area, Scale, Stroke};
use crate::figure::MomentSeries;
use crate::physical::short_number;
use crate::scene::State;
use plotters::prelude::RGBColor;

const H: RGBColor = RGBColor(0, 0, 0);
const SLOPE: RGBColor = RGBColor(0, 0, 255);
const CURV: RGBColor = RGBColor(255, 0, 0);
/// The real-space levels, dashed (their colours are dashed by the viewer
/// wherever they appear): Sq beside h_rms, Sdq beside h′.
pub(super) const SQ: RGBColor = RGBColor(96, 96, 96);
pub(super) const SDQ: RGBColor = RGBColor(96, 96, 255);

pub(super) fn draw(
    area: &Area,
    state: &State,
    points: usize,
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let s = MomentSeries::of(state, points)?;
    let real = state.surface.as_ref().and_then(|src| src.measured.real);
    let levels: Vec<f64> = real
        .iter()
        .flat_map(|r| [r.rms_height, r.rms_slope])
        .collect();
    let (lo, hi) = positive_span(
        s.h_rms
            .iter()
            .chain(&s.h_prime)
            .chain(&s.h_dprime)
            .chain(&levels),
    );
    let x = Scale::around(true, s.zeta[0], s.zeta[s.len() - 1], "ζ = q1/q0".into());
    let y = Scale::around(true, lo, hi, "h_rms (m), h′ (1), h″ (1/m)".into());
    let mut c = chart(area, &title(state, "moments"), (&x, &y), room)?;
    let mut lg = Legend::default();
    let xy = (&x, &y);
    let spectral = if state.is_measured() {
        " from the PSD up to ζ"
    } else {
        ""
    };
    let solid = Stroke::Solid;
    line(
        &mut c,
        &mut lg,
        xy,
        (&s.zeta, &s.h_rms),
        H,
        solid,
        &format!("h_rms = √m0{spectral}"),
    )?;
    line(
        &mut c,
        &mut lg,
        xy,
        (&s.zeta, &s.h_prime),
        SLOPE,
        solid,
        &format!("h′ = √(2 m2){spectral}"),
    )?;
    line(
        &mut c,
        &mut lg,
        xy,
        (&s.zeta, &s.h_dprime),
        CURV,
        solid,
        "h″ = √(8 m4/3)",
    )?;
    if let Some(r) = real {
        let (a, b) = r.names();
        let ends = [s.zeta[0], s.zeta[s.len() - 1]];
        let at = |v: f64| [v, v];
        let label = |n: &str, v: f64| format!("{n} = {} (real space, no window)", short_number(v));
        line(
            &mut c,
            &mut lg,
            xy,
            (&ends, &at(r.rms_height)),
            SQ,
            Stroke::Dashed,
            &label(a, r.rms_height),
        )?;
        line(
            &mut c,
            &mut lg,
            xy,
            (&ends, &at(r.rms_slope)),
            SDQ,
            Stroke::Dashed,
            &label(b, r.rms_slope),
        )?;
    }
    lg.draw(area, &c, room.is_some())
}
