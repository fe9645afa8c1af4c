//! A measured surface's spectrum as SVG: the data on log-log axes, the
//! power law fitted over the fit band dashed across it, the band's ends
//! as grey guides, and the cutoff q1 = ζ q0.

use plotters::prelude::*;

use super::legend::{Legend, Placed};
use super::{chart_with_top, guide, line, plot_err, title, Area, Chart, Scale, Stroke};
use crate::figure::scene_text::short_length;
use crate::figure::SpectrumSeries;
use crate::physical::short_number;
use crate::scene::State;

const DATA: RGBColor = RGBColor(0, 0, 0);
/// The fit is dashed: the colour of the dashed curves (`super::DASHED`).
const FIT: RGBColor = super::PSI_ASY;
const CUTOFF: RGBColor = RGBColor(0, 0, 255);
const BAND: RGBColor = RGBColor(150, 150, 150);

/// Ticks and labels of λ = 2π/q above the plot, at whole decades of λ
/// (and its halves, 2 and 5, where fewer than three decades show).
fn wavelength_axis(area: &Area, c: &Chart, x: &Scale) -> anyhow::Result<()> {
    let (lmin, lmax) = (std::f64::consts::TAU / x.hi, std::f64::consts::TAU / x.lo);
    let (a, b) = (lmin.log10().floor() as i32, lmax.log10().ceil() as i32);
    let steps: &[f64] = if b - a < 3 { &[1.0, 2.0, 5.0] } else { &[1.0] };
    let (xr, yr) = c.plotting_area().get_pixel_range();
    let (ox, oy) = area.get_base_pixel();
    let top = yr.start - oy;
    let font = ("sans-serif", 13).into_font();
    for k in a..=b {
        for m in steps {
            let l = m * 10f64.powi(k);
            if l < lmin || l > lmax {
                continue;
            }
            let q = std::f64::consts::TAU / l;
            let (px, _) = c.backend_coord(&(x.to(q), 0.0));
            if px < xr.start || px > xr.end {
                continue;
            }
            let px = px - ox;
            area.draw(&PathElement::new(vec![(px, top), (px, top - 5)], BLACK))
                .map_err(plot_err)?;
            let label = short_length(l);
            let w = (label.chars().count() as f64 * 6.5) as i32;
            area.draw(&Text::new(label, (px - w / 2, top - 20), font.clone()))
                .map_err(plot_err)?;
        }
    }
    area.draw(&Text::new(
        "wavelength λ = 2π/q",
        (xr.end - ox - 130, top - 36),
        ("sans-serif", 13).into_font(),
    ))
    .map_err(plot_err)?;
    Ok(())
}

pub(super) fn draw(area: &Area, state: &State, room: Option<u32>) -> anyhow::Result<Placed> {
    let s = SpectrumSeries::of(state)?;
    let (qlo, qhi) = super::positive_span(s.q.iter());
    let (plo, phi) = super::positive_span(s.psd.iter());
    // The q axis ends where the data do; the wavelength λ = 2π/q above it.
    let x = Scale {
        log: true,
        lo: qlo,
        // q1 at the data's end (the largest ζ) is still on the axis.
        hi: qhi.max(qlo * 1.01).max(s.q1.min(qhi * 1.01)),
        desc: "wavevector q (1/m)".into(),
    };
    let y = Scale::around(true, plo, phi, s.psd_label().into());
    let mut c = chart_with_top(area, &title(state, "spectrum"), (&x, &y), room, 30)?;
    wavelength_axis(area, &c, &x)?;
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
        // The legend names the fit; its band and h_rms are said in full
        // under the chart ([`fit_line`]).
        let label = match f.verdict().words() {
            Some(w) => format!("power law fit: {} — {w}", hurst_words(&f)),
            None => format!("power law fit: {}", hurst_words(&f)),
        };
        line(&mut c, &mut lg, xy, (&qs, &ys), FIT, Stroke::Dashed, &label)?;
        let r = y.range();
        let mut named = false;
        for q in [f.q_lo, f.q_hi] {
            if x.contains(q) {
                let band = format!(
                    "the fit band {}…{} /m",
                    short_number(f.q_lo),
                    short_number(f.q_hi)
                );
                let label = (!named).then_some(band.as_str());
                named = true;
                guide(
                    &mut c,
                    &mut lg,
                    (x.to(q), r.start),
                    (x.to(q), r.end),
                    BAND,
                    label,
                )?;
            }
        }
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

/// The fit said in full under the chart: "The power law fitted over the
/// fit band 1e5…1e9 /m: H = 0.8 ± 0.01, h_rms of the fitted power law
/// 1.982e-8 m (5 points)."; `None` without a fit.
pub(super) fn fit_line(state: &State) -> Option<String> {
    let s = SpectrumSeries::of(state).ok()?;
    let f = s.power_law?;
    Some(format!(
        "The power law fitted over the fit band {}…{} /m: {}.",
        short_number(f.q_lo),
        short_number(f.q_hi),
        fit_words(&f, s.fit_h_rms)
    ))
}

/// "H = 0.81 ± 0.03", or "H = 0.81" without a standard error.
fn hurst_words(f: &rough_surface::PowerLawFit) -> String {
    if f.hurst_se.is_finite() {
        format!(
            "H = {} ± {}",
            short_number(f.hurst),
            short_number(f.hurst_se)
        )
    } else {
        format!("H = {}", short_number(f.hurst))
    }
}

/// "H = 0.81 ± 0.03, h_rms of the fitted power law 12 nm (18 points)" (a
/// length as the scene line prints one), or
/// why the band is not self-affine.
pub fn fit_words(f: &rough_surface::PowerLawFit, h_rms: Option<f64>) -> String {
    let h = hurst_words(f);
    match (f.verdict().words(), h_rms) {
        (Some(w), _) => format!("{h} — {w} ({} points)", f.points),
        (None, Some(hr)) => format!(
            "{h}, h_rms of the fitted power law {} ({} points)",
            short_length(hr),
            f.points
        ),
        (None, None) => format!("{h} ({} points)", f.points),
    }
}
