//! The contact view's charts: the areas against the load (the simulation's
//! points on the theory's curves), the plastic share against ζ at the
//! chosen load for each set of caps (`b`), and the initial slopes against
//! ζ (`i`), each point a mean over the seeds with ± one sd.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Dataset, GraphType, Paragraph, Widget, Wrap};

use super::super::chart::{self, Scale};
use crate::contact::{Hardness, Stat};
use crate::tui::app::App;
use crate::tui::contact::{load_value, LOADS};
use crate::tui::layout::Y_LABEL_W;
use crate::tui::theme::{CurveStyle, Theme};

/// A point style of the simulation: the curve's colour, a dot; without
/// colour the letter `plain`.
fn point(t: &Theme, c: &CurveStyle, plain: char) -> (Style, Marker) {
    if t.color && !t.glyphs.ascii_only() {
        (c.style, Marker::Custom('●'))
    } else if t.color {
        (c.style, Marker::Custom(plain))
    } else {
        (Style::new(), Marker::Custom(plain))
    }
}

fn mark(m: Marker) -> String {
    match m {
        Marker::Custom(c) => c.to_string(),
        _ => "●".into(),
    }
}

fn scatter<'a>(style: (Style, Marker), data: &'a [(f64, f64)]) -> Dataset<'a> {
    Dataset::default()
        .graph_type(GraphType::Scatter)
        .marker(style.1)
        .style(style.0)
        .data(data)
}

/// The legend row over a chart of the theory's curves and the
/// simulation's points: the first of `forms` that fits, the total's line
/// sample before it and the point's mark (`p_total`) in its colour.
fn legend_row(t: &Theme, forms: &[String], p_total: (Style, Marker), area: Rect, buf: &mut Buffer) {
    let text = fitting(t, forms, area.width.saturating_sub(2));
    let (theory, rest) = text.split_once(&mark(p_total.1)).unwrap_or((&text, ""));
    Line::from(vec![
        Span::styled(t.total.sample, t.total.style),
        Span::raw(theory.to_string()),
        Span::styled(mark(p_total.1), p_total.0),
        Span::raw(rest.to_string()),
    ])
    .render(Rect { height: 1, ..area }, buf);
}

/// The theory's curves (total, elastic, plastic, as `theory` holds them),
/// then each part's ± sd `bars` and mean points `sims` (same order), the
/// total's last: on top where it equals the elastic part.
fn theory_and_points<'a>(
    t: &Theme,
    theory: &'a [Vec<(f64, f64)>],
    bars: &'a [Vec<Vec<(f64, f64)>>],
    sims: &'a [Vec<(f64, f64)>],
) -> Vec<Dataset<'a>> {
    let mut sets = vec![];
    for (c, data) in [&t.total, &t.elastic, &t.plastic].into_iter().zip(theory) {
        sets.push(chart::dataset(c, data));
    }
    for (k, (c, ch)) in [(&t.total, 'T'), (&t.elastic, 'E'), (&t.plastic, 'P')]
        .into_iter()
        .enumerate()
        .rev()
    {
        sets.extend(bars[k].iter().map(|b| chart::dataset(c, b)));
        sets.push(scatter(point(t, c, ch), &sims[k]));
    }
    sets
}

/// The graph inside a chart region: a legend row on top, y labels left,
/// x axis and labels below.
fn graph_of(area: Rect) -> Option<Rect> {
    let w = area.width.checked_sub(Y_LABEL_W + 1 + 2)?;
    let h = area.height.checked_sub(1 + 2)?;
    (w >= 4 && h >= 3).then(|| Rect::new(area.x + Y_LABEL_W + 1, area.y + 1, w, h))
}

/// The first of `forms` that fits `width` columns (the last, cut, if none).
fn fitting(t: &Theme, forms: &[String], width: u16) -> String {
    let text = |f: &String| t.glyphs.text(f).into_owned();
    forms
        .iter()
        .map(text)
        .find(|s| Span::raw(s.as_str()).width() <= usize::from(width))
        .unwrap_or_else(|| forms.last().map(text).unwrap_or_default())
}

/// The theory's split in a few words.
fn split_words(model: rough_model::Model) -> &'static str {
    match model {
        rough_model::Model::ClosedForm => "split: App. A image",
        rough_model::Model::Exact => "split: exact",
    }
}

pub(super) fn load_chart(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let pane = &app.contact;
    let Some(g) = graph_of(area) else {
        return;
    };
    let mut sims: [Vec<(f64, f64)>; 3] = Default::default();
    // Each load's means over the seeds solved so far, and their spread.
    let mut spread: [Vec<(f64, Stat)>; 3] = Default::default();
    for k in 0..pane.results.len().min(LOADS) {
        if let Some(stats) = pane.at_load(k) {
            let x = load_value(k).log10();
            for ((st, out), sd) in stats.iter().zip(sims.iter_mut()).zip(spread.iter_mut()) {
                if st.mean > 0.0 {
                    out.push((x, st.mean.log10()));
                    sd.push((x, *st));
                }
            }
        }
    }
    let lowest = pane
        .theory
        .curves
        .iter()
        .flatten()
        .map(|p| p.1)
        .chain(sims.iter().flatten().map(|p| p.1))
        .fold(0.0, f64::min);
    let y0 = lowest.floor().clamp(-6.0, -1.0);
    let (xb, yb) = ([-3.0, 0.0], [y0, 0.0]);
    // ± one sd on the log axis: a mean − sd at or below zero runs to the
    // axis.
    let log = |v: f64| if v > 0.0 { v.log10().max(y0) } else { y0 };
    let bars: Vec<Vec<Vec<(f64, f64)>>> = spread
        .iter()
        .map(|set| sd_bars(set, 0.0, |m, sd| (log(m - sd), log(m + sd).min(0.0))))
        .collect();
    // The legend: the theory (and which split it reads), the simulation
    // (κ and the split in words in the row over the map where there is
    // room).
    let p_total = point(t, &t.total, 'T');
    let split = split_words(app.state.model);
    let forms = [
        format!(" theory ({split})  {} simulation (T E P)", mark(p_total.1)),
        format!(" theory  {} simulation (T E P)", mark(p_total.1)),
        format!(" theory  {} simulation", mark(p_total.1)),
        format!(" theory  {} sim", mark(p_total.1)),
    ];
    legend_row(t, &forms, p_total, area, buf);
    let h = format!("p̄/{}", super::load_unit(app));
    chart::axes(
        t,
        (&Scale::decades(xb), &Scale::decades(yb)),
        &h,
        (area, g),
        buf,
    );
    let theory = &pane.theory.curves;
    let at = load_value(pane.load).log10();
    let marker = [(at, yb[0]), (at, yb[1])];
    let mut sets = vec![chart::dataset(&t.marker_line, &marker)];
    sets.extend(theory_and_points(t, theory, &bars, &sims));
    chart::plot(sets, (xb, yb), g, buf);
}

/// The graph of a chart over ζ and the largest ζ's log10, or none where
/// the region is too small or there is nothing to draw (then said in the
/// graph).
fn zeta_graph(app: &App, area: Rect, buf: &mut Buffer) -> Option<(Rect, f64)> {
    let g = graph_of(area)?;
    if why_not(app, g, buf) {
        return None;
    }
    let hi = app.contact.zetas.last().copied().unwrap_or(2.0).log10();
    Some((g, hi))
}

/// Why a chart over ζ has nothing to draw, in its graph.
fn why_not(app: &App, g: Rect, buf: &mut Buffer) -> bool {
    let t = &app.theme;
    match &app.contact.why_not {
        Some(why) => {
            Paragraph::new(t.glyphs.text(why).into_owned())
                .style(t.dim)
                .wrap(Wrap { trim: true })
                .render(g, buf);
            true
        }
        None => false,
    }
}

/// The name of a set of `b`'s plot.
pub(super) fn set_name(set: &crate::tui::contact::Set) -> &'static str {
    match (set.size_effect, set.hardness) {
        (false, _) => "H0",
        (true, Hardness::Global) => "H_y(R_s)",
        (true, Hardness::Asperity) => "per asperity",
        (true, Hardness::Summit) => "per summit",
    }
}

/// `b`: the plastic share at the chosen load against ζ, one set of points
/// per set of caps, on a log axis so that shares of a tenth of a per cent
/// show beside tens of per cent (a share of 0 sits on the axis's floor).
pub(super) fn share_chart(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let pane = &app.contact;
    let Some((g, hi)) = zeta_graph(app, area, buf) else {
        return;
    };
    let zs = &pane.zetas;
    let styles = [&t.psi_p, &t.psi_star, &t.psi_asy];
    let chars = ['o', 'x', '+'];
    // The means over the seeds solved so far, ± one sd, the sets' bars a
    // little apart so that none hides another.
    let mut stats: Vec<Vec<(f64, Stat)>> = vec![vec![]; pane.sets.len()];
    for (set, out) in stats.iter_mut().enumerate() {
        for (k, z) in zs.iter().enumerate() {
            if let Some(st) = pane.share_at(set, k) {
                out.push((z.log10(), st));
            }
        }
    }
    let positive = stats
        .iter()
        .flatten()
        .map(|(_, s)| s.mean)
        .chain(pane.theory.curves.iter().flatten().map(|p| p.1))
        .filter(|v| *v > 0.0)
        .fold(1.0, f64::min);
    let floor = positive.log10().floor().clamp(-4.0, -1.0);
    let log = |v: f64| if v > 0.0 { v.log10().max(floor) } else { floor };
    let sims: Vec<Vec<(f64, f64)>> = stats
        .iter()
        .map(|s| s.iter().map(|(x, st)| (*x, log(st.mean))).collect())
        .collect();
    let (xb, yb) = ([0.0, hi], [floor, 0.0]);
    let nudge = 0.006 * hi.max(0.3);
    let bars: Vec<Vec<Vec<(f64, f64)>>> = stats
        .iter()
        .enumerate()
        .map(|(i, set)| {
            let dx = (i as f64 - 1.0) * nudge;
            sd_bars(set, dx, |m, sd| (log(m - sd), log(m + sd).min(0.0)))
        })
        .collect();
    let mut spans = vec![];
    for (i, set) in pane.sets.iter().enumerate() {
        let c = styles[i.min(2)];
        let p = point(t, c, chars[i.min(2)]);
        if i < 2 {
            spans.push(Span::styled(c.sample, c.style));
        }
        spans.push(Span::styled(mark(p.1), p.0));
        spans.push(Span::raw(format!(" {}  ", set_name(set))));
    }
    spans.push(Span::styled(
        t.glyphs
            .text("lines: theory at the load · a share of 0 on the floor")
            .into_owned(),
        t.dim,
    ));
    Line::from(spans).render(Rect { height: 1, ..area }, buf);
    let x = Scale::of_axis(rough_model::Axis::Zeta, xb);
    let y = Scale::decades(yb);
    chart::axes(t, (&x, &y), "ζ", (area, g), buf);
    let theory: Vec<Vec<(f64, f64)>> = pane
        .theory
        .curves
        .iter()
        .map(|c| c.iter().map(|p| (p.0, log(p.1))).collect())
        .collect();
    let mut sets = vec![];
    for (c, data) in styles.iter().zip(&theory) {
        sets.push(chart::dataset(c, data));
    }
    for (c, b) in styles.iter().zip(&bars) {
        sets.extend(b.iter().map(|b| chart::dataset(c, b)));
    }
    for (i, data) in sims.iter().enumerate() {
        sets.push(scatter(point(t, styles[i.min(2)], chars[i.min(2)]), data));
    }
    chart::plot(sets, (xb, yb), g, buf);
}

/// `i`: the initial slopes against ζ, log–log, the simulation's points
/// (total, elastic, plastic) on the theory's curves.
pub(super) fn slopes_chart(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let pane = &app.contact;
    let Some((g, hi)) = zeta_graph(app, area, buf) else {
        return;
    };
    let zs = &pane.zetas;
    // total, elastic, plastic as the theory's curves are.
    let mut stats: [Vec<(f64, Stat)>; 3] = Default::default();
    for (k, z) in zs.iter().enumerate() {
        if let Some([el, pl, tot]) = pane.slopes_at(k) {
            let x = z.log10();
            for (out, st) in stats.iter_mut().zip([tot, el, pl]) {
                if st.mean > 0.0 {
                    out.push((x, st));
                }
            }
        }
    }
    let ys: Vec<f64> = pane
        .theory
        .curves
        .iter()
        .flatten()
        .map(|p| p.1)
        .chain(stats.iter().flatten().map(|(_, s)| s.mean.log10()))
        .collect();
    let top = ys.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let top = if top.is_finite() {
        top.ceil().max(1.0)
    } else {
        1.0
    };
    let low = ys.iter().cloned().fold(f64::INFINITY, f64::min);
    let low = if low.is_finite() { low.floor() } else { -2.0 };
    let yb = [low.max(top - 4.0).min(top - 1.0), top];
    let xb = [0.0, hi];
    let log = |v: f64| {
        if v > 0.0 {
            v.log10().clamp(yb[0], yb[1])
        } else {
            yb[0]
        }
    };
    let sims: Vec<Vec<(f64, f64)>> = stats
        .iter()
        .map(|s| s.iter().map(|(x, st)| (*x, st.mean.log10())).collect())
        .collect();
    let bars: Vec<Vec<Vec<(f64, f64)>>> = stats
        .iter()
        .map(|s| sd_bars(s, 0.0, |m, sd| (log(m - sd), log(m + sd))))
        .collect();
    let p_total = point(t, &t.total, 'T');
    let n = pane.seeds_asked();
    let forms = [
        format!(
            " theory ({})  {} simulation (T E P){}, fit over p̄/(E*h′) = 0.5…8e-3",
            split_words(app.state.model),
            mark(p_total.1),
            if n > 1 {
                format!(", mean ± sd of {n} seeds")
            } else {
                String::new()
            }
        ),
        format!(
            " theory  {} simulation (T E P), light-load fit",
            mark(p_total.1)
        ),
        format!(" theory  {} sim (T E P)", mark(p_total.1)),
    ];
    legend_row(t, &forms, p_total, area, buf);
    let x = Scale::of_axis(rough_model::Axis::Zeta, xb);
    chart::axes(t, (&x, &Scale::decades(yb)), "ζ", (area, g), buf);
    let sets = theory_and_points(t, &pane.theory.curves, &bars, &sims);
    chart::plot(sets, (xb, yb), g, buf);
}

/// One vertical bar of ± one standard deviation for each point of more
/// than one seed, at x + `dx`, from `ends(mean, sd)` (the axis's
/// coordinates).
fn sd_bars(
    points: &[(f64, Stat)],
    dx: f64,
    ends: impl Fn(f64, f64) -> (f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    points
        .iter()
        .filter(|(_, st)| st.n > 1 && st.sd.is_finite() && st.sd > 0.0)
        .map(|&(x, st)| {
            let (lo, hi) = ends(st.mean, st.sd);
            vec![(x + dx, lo), (x + dx, hi)]
        })
        .collect()
}
