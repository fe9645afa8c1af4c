//! The spectrum view (measured surfaces only): the data's PSD against the
//! wavevector on log-log axes, the power law fitted over the fit band (its
//! ends drawn as guides; `[ ]` `{ }` move them, `b` finds the band again),
//! and the cutoff q1 = ζ q0 as the marker: the band the model's moments
//! sum over, and how far the data is from a power law there.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::chart::{self, Scale};
use crate::physical::print::{fmt_decade, fmt_num};
use crate::tui::app::App;
use crate::tui::theme::CurveStyle;

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    if g.width < 2 || g.height < 2 {
        return;
    }
    let p = &app.spectrum;
    let zeta = app.state.params.zeta();
    let glyphs = t.glyphs;
    let mut title = format!("{} vs q", p.label);
    if let Some(f) = app.readout.fit {
        match f.fit.verdict().words() {
            None => title.push_str(&format!(" · H {}", super::side::hurst_se(&f.fit))),
            Some(_) => title.push_str(&format!(
                " · H {:.2}: not self-affine over the band",
                f.fit.hurst
            )),
        }
    }
    if let Some(a) = anisotropy(app) {
        title.push_str(&a);
    }
    let mut title = glyphs.text(&title).into_owned();
    // The cutoff whole, or left out, never cut inside its number.
    let q1 = format!(
        "  {} q1 = {}/m (ζ {})",
        t.marker_line.sample,
        fmt_num(10f64.powf(p.q1)),
        fmt_num(zeta)
    );
    let q1 = glyphs.text(&q1);
    if Span::raw(&title).width() + Span::raw(q1.as_ref()).width() <= usize::from(area.width) {
        title.push_str(&q1);
    }
    // Not chart::title: the marker here is q1, named in the title itself.
    Line::styled(title, t.title).render(Rect::new(area.x, area.y, area.width, 1), buf);
    let data = CurveStyle {
        name: "data",
        ..t.elastic
    };
    let fit = CurveStyle {
        name: "fit",
        ..t.psi_asy
    };
    let band_style = CurveStyle {
        name: "fit band",
        ..t.ghost
    };
    let cut = CurveStyle {
        name: "q1 = ζ q0",
        ..t.marker_line
    };
    chart::legend(t, &[&data, &fit, &band_style, &cut], area, buf);
    let rows = f64::from(g.height.max(1));
    let x = Scale::decades(p.x_bounds);
    let y = thinned(p.y_bounds, rows);
    chart::axes(t, (&x, &y), "q 1/m", (area, g), buf);
    let cutoff = [(p.q1, p.y_bounds[0]), (p.q1, p.y_bounds[1])];
    let cutoff: &[(f64, f64)] = if p.q1 >= p.x_bounds[0] && p.q1 <= p.x_bounds[1] {
        &cutoff
    } else {
        &[]
    };
    let edge = |q: f64| [(q, p.y_bounds[0]), (q, p.y_bounds[1])];
    let edges: Vec<[(f64, f64); 2]> = p
        .band
        .iter()
        .flatten()
        .filter(|q| **q >= p.x_bounds[0] && **q <= p.x_bounds[1])
        .map(|&q| edge(q))
        .collect();
    let mut sets: Vec<_> = edges
        .iter()
        .map(|e| chart::dataset(&band_style, e))
        .collect();
    sets.extend([
        chart::dataset(&cut, cutoff),
        chart::dataset(&data, &p.data),
        // The fit over the data, so that the band it spans shows.
        chart::dataset(&fit, &p.fit),
    ]);
    chart::plot(sets, (p.x_bounds, p.y_bounds), g, buf);
}

/// " · anisotropic: h′x/h′y = 3.4, Ψ_P across 11.3, along 0.73" for a
/// map whose rms slopes along x and y differ by more than 1.5 (Ψ_P of the
/// profiles across and along the lay over the whole band, at the scene's
/// H0/E); nothing otherwise.
pub fn anisotropy(app: &App) -> Option<String> {
    let s = app.state.surface.as_ref()?.measured.slopes?;
    if !s.anisotropic() {
        return None;
    }
    let h0e = app.state.params.h0_over_e();
    let psi = |m: f64| m / std::f64::consts::SQRT_2 / h0e;
    let (across, along) = (psi(s.x.max(s.y)), psi(s.x.min(s.y)));
    Some(format!(
        " · anisotropic: h′x/h′y = {:.2}, Ψ_P across {}, along {}",
        s.ratio(),
        fmt_num(across),
        fmt_num(along)
    ))
}

/// Decade ticks every k decades (k = 1, 2, 5, 10, …), so that labels lie
/// about three rows apart or more.
fn thinned(bounds: [f64; 2], rows: f64) -> Scale {
    let decades = (bounds[1] - bounds[0]).max(1.0);
    let want = 2.5 * decades / rows;
    let k = [1, 2, 5, 10, 20, 50, 100]
        .into_iter()
        .find(|&k| f64::from(k) >= want)
        .unwrap_or(100);
    let (lo, hi) = (bounds[0].ceil() as i32, bounds[1].floor() as i32);
    let ticks = (lo..=hi)
        .filter(|d| d.rem_euclid(k) == 0)
        .map(|d| (f64::from(d), fmt_decade(d)))
        .collect();
    Scale { bounds, ticks }
}
