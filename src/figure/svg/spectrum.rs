//! A measured surface's spectrum as SVG: the data on log-log axes, the
//! power law fitted over [q0, q1] dashed, and the cutoff q1 = ζ q0.

use plotters::prelude::*;

use super::legend::{Legend, Placed};
use super::{chart, guide, line, plot_err, title, Area, Scale, Stroke};
use crate::figure::{short_number, SpectrumSeries};
use crate::snapshot::State;

const DATA: RGBColor = RGBColor(0, 0, 0);
const FIT: RGBColor = RGBColor(230, 120, 0);
const CUTOFF: RGBColor = RGBColor(0, 0, 255);

pub(super) fn draw(area: &Area, state: &State, room: Option<u32>) -> anyhow::Result<Placed> {
    let s = SpectrumSeries::of(state)?;
    let (qlo, qhi) = super::positive_span(s.q.iter());
    let (plo, phi) = super::positive_span(s.psd.iter());
    let x = Scale::around(true, qlo, qhi, "wavevector q (1/m)".into());
    let y = Scale::around(true, plo, phi, s.psd_label().into());
    let mut c = chart(area, &title(state, "spectrum"), (&x, &y), room)?;
    let mut lg = Legend::default();
    let xy = (&x, &y);
    let data_label = match s.dim {
        rough_model::Dim::Areal => "data C^iso(q)",
        rough_model::Dim::Profile => "data C1D(q)",
    };
    line(
        &mut c,
        &mut lg,
        xy,
        (&s.q, &s.psd),
        DATA,
        Stroke::Solid,
        data_label,
    )?;
    c.draw_series(
        s.q.iter()
            .zip(&s.psd)
            .filter(|(q, p)| x.contains(**q) && y.contains(**p))
            .map(|(q, p)| Circle::new((x.to(*q), y.to(*p)), 2, DATA.filled())),
    )
    .map_err(plot_err)?;
    if let Some(f) = s.power_law {
        // Sampled, so that the part inside the chart is drawn where an end
        // lies outside it.
        let (a, b) = (s.q0.log10(), s.q1.min(qhi).log10());
        let qs: Vec<f64> = (0..=200)
            .map(|i| 10f64.powf(a + (b - a) * f64::from(i) / 200.0))
            .collect();
        let ys: Vec<f64> = qs
            .iter()
            .map(|&q| s.fit_at(q).unwrap_or(f64::NAN))
            .collect();
        let amp = s
            .fit_h_rms
            .map(|h| format!(", h_rms {} m", short_number(h)))
            .unwrap_or_default();
        let label = format!(
            "power law fitted over q0…q1: H = {}{amp} ({} points)",
            short_number(f.hurst),
            f.points
        );
        line(&mut c, &mut lg, xy, (&qs, &ys), FIT, Stroke::Dashed, &label)?;
    }
    let r = y.range();
    if x.contains(s.q1) {
        let q1 = x.to(s.q1);
        let label = format!(
            "cutoff q1 = ζ q0 = {} /m (ζ = {})",
            short_number(s.q1),
            short_number(s.q1 / s.q0)
        );
        guide(
            &mut c,
            &mut lg,
            (q1, r.start),
            (q1, r.end),
            CUTOFF,
            Some(&label),
        )?;
    }
    lg.draw(area, &c, room.is_some())
}
