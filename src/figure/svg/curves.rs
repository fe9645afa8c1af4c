//! The slopes, indices and load pictures: curves on log or linear axes
//! with the marker, the guides and the legend.

use plotters::prelude::*;
use rough_model::{Curves, Scene};

use super::legend::{Legend, Placed, Sample};
use super::{
    chart, coincide, guide, line, plot_err, positive_span, title, x_scale, Area, Chart, Scale,
    Stroke, ELASTIC, GREY, PERSSON, PLASTIC, PSI_ASY, PSI_GW, THRESHOLD, TOTAL,
};
use crate::figure::{FigureOptions, IndexSeries, LoadCurve};
use crate::physical::short_number;
use crate::scene::State;

/// A vertical guide at the current value of the swept parameter, named
/// in the legend ("ζ = 128, the marker") when it is on the chart.
fn marker(
    c: &mut Chart,
    lg: &mut Legend,
    state: &State,
    (x, y): (&Scale, &Scale),
) -> anyhow::Result<()> {
    let axis = state.sweep.axis();
    let v = state.params.get(axis);
    if x.contains(v) {
        let r = y.range();
        let label = format!(
            "{} = {}, the marker",
            axis.symbol(),
            crate::figure::scene_text::short_value(axis, v)
        );
        guide(
            c,
            lg,
            (x.to(v), r.start),
            (x.to(v), r.end),
            GREY,
            Some(&label),
        )?;
    }
    Ok(())
}

/// `c` two thirds of the way to white: a sample that reads as absent.
fn pale(RGBColor(r, g, b): RGBColor) -> RGBColor {
    let p = |v: u8| v + ((255 - u16::from(v)) * 2 / 3) as u8;
    RGBColor(p(r), p(g), p(b))
}

/// A curve left out while a poll's answer waits: listed, saying so.
fn withheld_entry(lg: &mut Legend, name: &str, colour: RGBColor, stroke: Stroke) {
    let short = name.split_whitespace().next().unwrap_or(name);
    let sample = match stroke {
        Stroke::Dashed => Sample::Dashed,
        Stroke::Solid => Sample::Solid(2),
    };
    lg.add(
        format!("{short}: {}", crate::figure::Withheld::CURVE_WAITS),
        pale(colour),
        sample,
    );
}

pub(super) fn slopes(
    area: &Area,
    state: &State,
    opts: &FigureOptions,
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let s = Scene::compute(&state.scene_spec(Curves::ALL, opts.points))?;
    let x = x_scale(state);
    // Fitted to the curves drawn: while a poll's answer waits, the range
    // says nothing of those left out.
    let w = opts.withheld;
    let drawn = |k: usize, ys: &'_ [f64]| -> Vec<f64> {
        if w.slopes[k] {
            Vec::new()
        } else {
            ys.to_vec()
        }
    };
    let (el, pl, tot, per) = (
        drawn(0, &s.elastic),
        drawn(1, &s.plastic),
        drawn(2, &s.total),
        drawn(3, &s.persson_elastic),
    );
    let (_, hi) = positive_span(el.iter().chain(&tot).chain(&per));
    let (lo, _) = positive_span(
        pl.iter()
            .chain(&el)
            .chain(&tot)
            .chain(&per)
            .filter(|v| **v >= hi * 1e-4),
    );
    // The hardness by its own name (H alone is the Hurst exponent).
    let norm = state.hardness_name();
    let y = Scale::around(true, lo, hi, format!("initial slope {norm}·dA/(A0·dp̄)"));
    let mut c = chart(area, &title(state, "initial slopes"), (&x, &y), room)?;
    let mut lg = Legend::default();
    marker(&mut c, &mut lg, state, (&x, &y))?;
    let xy = (&x, &y);
    // Every listed curve can be found: say where one lies under another
    // or below the chart (not while a poll's answer waits: that says it).
    let el = if coincide(&s.elastic, &s.total) && !w.marks {
        "elastic (= total here)"
    } else {
        "elastic"
    };
    let pl = if s.plastic.iter().any(|&v| y.contains(v)) || w.marks {
        "plastic"
    } else {
        "plastic (below the chart here)"
    };
    // ψ by its name: the index in use.
    let psi = state.index_name();
    let persson_name = format!("Persson elastic √(2/π)/{psi}");
    let curves = [
        (&s.elastic, ELASTIC, Stroke::Solid, el),
        (&s.plastic, PLASTIC, Stroke::Solid, pl),
        (&s.total, TOTAL, Stroke::Solid, "total"),
        (
            &s.persson_elastic,
            PERSSON,
            Stroke::Dashed,
            persson_name.as_str(),
        ),
    ];
    for ((ys, colour, stroke, name), hidden) in curves.into_iter().zip(w.slopes) {
        if hidden {
            withheld_entry(&mut lg, name, colour, stroke);
        } else {
            line(&mut c, &mut lg, xy, (&s.x, ys), colour, stroke, name)?;
        }
    }
    lg.draw(area, &c, room.is_some())
}

pub(super) fn indices(
    area: &Area,
    state: &State,
    opts: &FigureOptions,
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let s = IndexSeries::compute(state, opts.points)?;
    let asy: Vec<f64> = s
        .psi_star_asymptotic
        .iter()
        .map(|v| v.unwrap_or(f64::NAN))
        .collect();
    let x = x_scale(state);
    let (lo, hi) = positive_span(s.psi_gw.iter().chain(&s.psi_p).chain(&s.psi_star));
    let y = Scale::around(true, lo.min(0.5).max(hi * 1e-8), hi.max(2.0), "Ψ".into());
    let mut c = chart(area, &title(state, "plasticity indices"), (&x, &y), room)?;
    let mut lg = Legend::default();
    marker(&mut c, &mut lg, state, (&x, &y))?;
    let r = x.range();
    // Dashed and darker than the marker's grey: two guides, two looks.
    guide(
        &mut c,
        &mut lg,
        (r.start, 0.0),
        (r.end, 0.0),
        THRESHOLD,
        Some("Ψ = 1: plastic above"),
    )?;
    let xy = (&x, &y);
    let solid = Stroke::Solid;
    let curves = [
        (&s.psi_gw, PSI_GW, solid, "Ψ_GW (Greenwood–Williamson)"),
        (&s.psi_p, PLASTIC, solid, "Ψ_P (Persson, H0)"),
        (&s.psi_star, TOTAL, solid, "Ψ* (size-dependent H_y)"),
        (&asy, PSI_ASY, Stroke::Dashed, "Ψ*asy (eq. 13)"),
    ];
    // Eq. 13 is a power law's: no line on a measured surface.
    let n = if state.is_measured() { 3 } else { 4 };
    let hidden = opts.withheld.indices;
    for ((ys, colour, stroke, name), hidden) in curves.into_iter().zip(hidden).take(n) {
        if hidden {
            withheld_entry(&mut lg, name, colour, stroke);
        } else {
            line(&mut c, &mut lg, xy, (&s.x, ys), colour, stroke, name)?;
        }
    }
    lg.draw(area, &c, room.is_some())
}

pub(super) fn load(
    area: &Area,
    state: &State,
    opts: &FigureOptions,
    room: Option<u32>,
) -> anyhow::Result<Placed> {
    let l = LoadCurve::compute(state, opts.points)?;
    // The hardness by its own name (H alone is the Hurst exponent).
    let h = state.hardness_name();
    let x = Scale {
        log: false,
        lo: 0.0,
        hi: 1.0,
        desc: format!("load p̄/{h}"),
    };
    let y = Scale {
        log: false,
        lo: 0.0,
        hi: 1.0,
        desc: "contact area A/A0".into(),
    };
    let psi = state.index_name();
    if opts.withheld.marks {
        // At the marker: the areas (and the index) would answer the poll.
        let c = chart(area, &title(state, "areas against load"), (&x, &y), room)?;
        super::waits(area, &c, "the areas at the marker")?;
        return Ok(Placed::Inside);
    }
    let what = format!("areas against load at {psi} = {}", short_number(l.psi));
    let mut c = chart(area, &title(state, &what), (&x, &y), room)?;
    let mut lg = Legend::default();
    let (tx, ty) = l.tangent_end();
    let tangent = TOTAL.mix(0.5).stroke_width(1);
    c.draw_series(std::iter::once(PathElement::new(
        vec![(0.0, 0.0), (tx, ty)],
        tangent,
    )))
    .map_err(plot_err)?;
    lg.paths.push(vec![(0.0, 0.0), (tx, ty)]);
    lg.add(
        format!("initial slope S_tot = {}", short_number(l.slopes.total)),
        RGBColor(255, 128, 128),
        Sample::Solid(1),
    );
    let xy = (&x, &y);
    let solid = Stroke::Solid;
    line(
        &mut c,
        &mut lg,
        xy,
        (&l.load, &l.elastic),
        ELASTIC,
        solid,
        "elastic",
    )?;
    line(
        &mut c,
        &mut lg,
        xy,
        (&l.load, &l.plastic),
        PLASTIC,
        solid,
        "plastic",
    )?;
    line(
        &mut c,
        &mut lg,
        xy,
        (&l.load, &l.total),
        TOTAL,
        solid,
        "total",
    )?;
    lg.draw(area, &c, room.is_some())
}
