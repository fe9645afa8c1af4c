//! A measured surface's spectrum as SVG: the data on log-log axes, the
//! power law fitted over the fit band dashed across it, the band's ends
//! as grey guides, and the cutoff q1 = ζ q0.

use plotters::prelude::*;

use super::{chart, guide, line, plot_err, title, Area, Scale, Stroke};
use crate::figure::{short_number, SpectrumSeries};
use crate::snapshot::State;

const DATA: RGBColor = RGBColor(0, 0, 0);
const FIT: RGBColor = RGBColor(230, 120, 0);
const CUTOFF: RGBColor = RGBColor(0, 0, 255);
const BAND: RGBColor = RGBColor(150, 150, 150);

pub(super) fn draw(area: &Area, state: &State) -> anyhow::Result<()> {
    let s = SpectrumSeries::of(state)?;
    let (qlo, qhi) = super::positive_span(s.q.iter());
    let (plo, phi) = super::positive_span(s.psd.iter());
    let x = Scale::around(true, qlo, qhi, "wavevector q (1/m)".into());
    let y = Scale::around(true, plo, phi, s.psd_label().into());
    let mut c = chart(area, &title(state, "spectrum"), &x, &y)?;
    let xy = (&x, &y);
    let data_label = match s.dim {
        rough_model::Dim::Areal => "data C^iso(q)",
        rough_model::Dim::Profile => "data C1D(q)",
    };
    line(&mut c, xy, (&s.q, &s.psd), DATA, Stroke::Solid, data_label)?;
    c.draw_series(
        s.q.iter()
            .zip(&s.psd)
            .filter(|(q, p)| x.contains(**q) && y.contains(**p))
            .map(|(q, p)| Circle::new((x.to(*q), y.to(*p)), 2, DATA.filled())),
    )
    .map_err(plot_err)?;
    if let Some(f) = s.power_law {
        // Sampled across the band, so that the part inside the chart is
        // drawn where an end lies outside it.
        let (a, b) = (f.q_lo.log10(), f.q_hi.log10());
        let qs: Vec<f64> = (0..=200)
            .map(|i| 10f64.powf(a + (b - a) * f64::from(i) / 200.0))
            .collect();
        let ys: Vec<f64> = qs
            .iter()
            .map(|&q| s.fit_at(q).unwrap_or(f64::NAN))
            .collect();
        let label = format!(
            "power law fitted over the fit band {}…{} /m: {}",
            short_number(f.q_lo),
            short_number(f.q_hi),
            fit_words(&f, s.fit_h_rms)
        );
        line(&mut c, xy, (&qs, &ys), FIT, Stroke::Dashed, &label)?;
        let r = y.range();
        for q in [f.q_lo, f.q_hi] {
            if x.contains(q) {
                guide(&mut c, (x.to(q), r.start), (x.to(q), r.end), BAND)?;
            }
        }
    }
    let r = y.range();
    if x.contains(s.q1) {
        let q1 = x.to(s.q1);
        guide(&mut c, (q1, r.start), (q1, r.end), CUTOFF)?;
        // A labelled sample for the legend: the guide itself has none.
        c.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
            .map_err(plot_err)?
            .label(format!(
                "cutoff q1 = ζ q0 = {} /m (ζ = {})",
                short_number(s.q1),
                short_number(s.q1 / s.q0)
            ))
            .legend(|(px, py)| PathElement::new(vec![(px, py), (px + 20, py)], CUTOFF));
    }
    // The data fall from the upper left: the legend goes right.
    super::legend_at(&mut c, SeriesLabelPosition::UpperRight)
}

/// "H = 0.81 ± 0.03, h_rms of the fitted power law 12 nm (18 points)", or
/// why the band is not self-affine.
pub fn fit_words(f: &rough_surface::PowerLawFit, h_rms: Option<f64>) -> String {
    let h = if f.hurst_se.is_finite() {
        format!(
            "H = {} ± {}",
            short_number(f.hurst),
            short_number(f.hurst_se)
        )
    } else {
        format!("H = {}", short_number(f.hurst))
    };
    match (f.verdict().words(), h_rms) {
        (Some(w), _) => format!("{h} — {w} ({} points)", f.points),
        (None, Some(hr)) => format!(
            "{h}, h_rms of the fitted power law {} m ({} points)",
            short_number(hr),
            f.points
        ),
        (None, None) => format!("{h} ({} points)", f.points),
    }
}
