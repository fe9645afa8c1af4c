//! The contact view: the boundary-element simulation of the scene's
//! surface beside the theory. A title with the grid, seed and the solver's
//! progress; a readout at the chosen load; left the contact map at that
//! load (out of contact, elastic, at the hardness), right A/A0 against
//! p̄/H_use (log–log) with the simulation's points on the theory's curves,
//! or (`b`) the plastic share against ζ with and without the size effect.
//! Drawing only reads what [`crate::tui::contact`] holds.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Dataset, GraphType, Paragraph, Widget, Wrap};

use super::chart::{self, Scale};
use crate::contact::engine::Progress;
use crate::contact::Stat;
use crate::physical::print::{fmt_num, load_text};
use crate::tui::app::App;
use crate::tui::contact::{load_value, ContactPane, LOADS};
use crate::tui::glyphs::Glyphs;
use crate::tui::layout::Y_LABEL_W;
use crate::tui::theme::{CurveStyle, Theme};

mod convergence;
mod map;
mod title;

pub use map::{dithered, map_scale};
use map::{draw_map, map_legend};
use title::seeds_words;

/// The map's colours: elastic light grey, at the hardness blue (the
/// paper's plastic colour); out of contact the terminal's background.
const ELASTIC: Color = Color::Gray;
const PLASTIC: Color = Color::Blue;

/// `v` (a fraction) in per cent with three significant digits.
pub fn pct(v: f64) -> String {
    let p = v * 100.0;
    if !p.is_finite() {
        "—".into()
    } else if p == 0.0 {
        "0".into()
    } else if p >= 10.0 {
        format!("{p:.1}")
    } else if p >= 1.0 {
        format!("{p:.2}")
    } else {
        fmt_num(p)
    }
}

/// A mean and its spread in per cent, the spread to the mean's last
/// digit ("2.10 ± 0.10"; "0.0312 ± 0.0040").
pub fn pct_pm(mean: f64, sd: f64) -> String {
    let m = pct(mean);
    let decimals = m.split_once('.').map_or(0, |(_, d)| d.len());
    if !sd.is_finite() {
        return m;
    }
    format!("{m} ± {:.*}", decimals, 100.0 * sd)
}

/// A plastic share in per cent: whole from 10 %, one decimal below ("0"
/// exactly none, "<0.1" a trace).
pub fn share_pct(plastic: f64, total: f64) -> String {
    if total <= 0.0 {
        return "—".into();
    }
    let s = 100.0 * plastic / total;
    if s == 0.0 {
        "0".into()
    } else if s < 0.05 {
        "<0.1".into()
    } else if s >= 9.95 {
        format!("{s:.0}")
    } else {
        format!("{s:.1}")
    }
}

/// The readout at the chosen load: one line, the longest form that fits
/// `width`, or where none does (an 80-column screen leaves the panel 46)
/// two, the simulation's and the theory's, so that nothing is cut. `h`
/// names the hardness in use (H0, or H_y with the size effect: H alone is
/// the Hurst exponent). The flag: the line is an error.
pub fn readout(pane: &ContactPane, width: usize, g: Glyphs, h: &str) -> (Vec<String>, bool) {
    let at = load_text(load_value(pane.load));
    let theory = pane
        .theory
        .at_load
        .map(|a| (pct(a.total), share_pct(a.plastic, a.total)));
    let sim = match pane.chosen() {
        _ if pane.why_not.is_some() => Err("-".into()),
        // Over the seeds solved so far: mean ± sample standard deviation.
        Some(Ok(_)) => match pane.at_load(pane.load) {
            Some([a, _, p]) if a.n > 1 => Ok((pct_pm(a.mean, a.sd), share_pct(p.mean, a.mean))),
            Some([a, _, p]) => Ok((pct(a.mean), share_pct(p.mean, a.mean))),
            None => Err(String::new()),
        },
        Some(Err(e)) => Err(e.clone()),
        None => Err(String::new()),
    };
    let th_full = match &theory {
        Some((a, s)) => format!("theory: {a} %, {s} % plastic"),
        None => "theory: —".into(),
    };
    let th_short = match &theory {
        Some((a, s)) => format!("th. {a}% {s}%pl"),
        None => "th. —".into(),
    };
    let (forms, split): (Vec<String>, Vec<String>) = match &sim {
        Ok((a, s)) => (
            vec![
                format!("simulation at p̄ = {at} {h}: contact {a} %, {s} % plastic · {th_full}"),
                format!("p̄ = {at} {h}: sim {a} %, {s} % plastic · {th_full}"),
                format!("{at} {h}: sim {a}% {s}%pl · {th_short}"),
            ],
            vec![
                format!("p̄ = {at} {h} · sim {a} %, {s} % plastic"),
                format!("p̄ = {at} {h} · sim {}%, {s}% pl", a.replace(" ± ", "±")),
                format!("{at} {h} · sim {}%, {s}% pl", a.replace(" ± ", "±")),
            ],
        ),
        Err(e) if e.is_empty() => (
            vec![
                format!("simulation at p̄ = {at} {h}: solving… · {th_full}"),
                format!("{at} {h}: sim … · {th_short}"),
            ],
            vec![format!("p̄ = {at} {h} · sim solving…")],
        ),
        Err(e) if e == "-" => (
            vec![
                format!("at p̄ = {at} {h}: no simulation · {th_full}"),
                format!("{at} {h}: no sim. · {th_short}"),
            ],
            vec![format!("p̄ = {at} {h} · no simulation")],
        ),
        Err(e) => (vec![format!("at p̄ = {at} {h}: {e}")], vec![]),
    };
    let text = |f: &String| g.text(f).into_owned();
    let fits = |s: &String| Span::raw(s.as_str()).width() <= width;
    let error = matches!(sim, Err(ref e) if !e.is_empty() && e != "-");
    let first = |forms: &[String]| forms.iter().map(text).find(|s| fits(s));
    if let Some(line) = first(&forms) {
        return (vec![line], error);
    }
    if let (Some(a), Some(b)) = (first(&split), first(&[th_full.clone(), th_short.clone()])) {
        return (vec![a, b], error);
    }
    // Nothing fits (a very narrow panel): the shortest, cut by the screen.
    let last = forms.last().map(text).unwrap_or_default();
    (vec![last], error)
}

/// A job's progress in at most `room` columns, the longest form that fits
/// ("solving 3/13 [███░░░] 25 %, 4 s left" … "25 %, 4 s left"; the time
/// left is kept longest), or that it waits for a core.
pub(super) fn progress_fit(p: &Progress, gl: Glyphs, room: usize) -> String {
    let full = progress_bar(p, gl, 12);
    if p.queued {
        return full;
    }
    let short = progress_bar(p, gl, 4);
    let tail = short.split_once("] ").map_or("", |(_, t)| t).to_string();
    let no_verb = short.trim_start_matches("solving ").to_string();
    [full, short, no_verb, tail]
        .into_iter()
        .find(|f| Span::raw(f.as_str()).width() <= room)
        .unwrap_or_default()
}

/// A job's progress: "solving 3/13 [███░░░] 25 %, 4 s left" (a bar of
/// `width` cells, 4 to 12), or that it waits for a core.
pub(super) fn progress_bar(p: &Progress, gl: Glyphs, width: usize) -> String {
    if p.queued {
        return "waiting for a free core".into();
    }
    let cells = width.clamp(4, 12);
    let full = (p.fraction() * cells as f64).round() as usize;
    let (on, off) = if gl.ascii_only() {
        ("#", "-")
    } else {
        ("█", "░")
    };
    let left = match p.left() {
        Some(d) if d.as_secs_f64() >= 90.0 => {
            format!(", {:.0} min left", d.as_secs_f64() / 60.0)
        }
        Some(d) => format!(", {:.0} s left", d.as_secs_f64().max(1.0)),
        None => String::new(),
    };
    format!(
        "solving {}/{} [{}{}] {:.0} %{left}",
        p.done,
        p.total,
        on.repeat(full.min(cells)),
        off.repeat(cells - full.min(cells)),
        100.0 * p.fraction()
    )
}

/// The title's right part: the progress bar while solving, else what was
/// solved.
fn progress_text(app: &App, width: usize) -> String {
    let pane = &app.contact;
    let gl = app.theme.glyphs;
    let p = &pane.progress;
    if pane.why_not.is_some() || pane.tasks.is_empty() {
        return String::new();
    }
    if pane.busy() {
        return progress_fit(p, gl, width);
    }
    let all = || {
        pane.results
            .iter()
            .chain(pane.seed_results.iter().flatten())
    };
    let secs: f64 = all()
        .flatten()
        .filter_map(|r| r.as_ref().ok())
        .map(|s| s.took.as_secs_f64())
        .sum();
    let failed = all().flatten().filter(|r| r.is_err()).count();
    let mut text = format!("{} solved, {:.1} s", all().count() - failed, secs);
    if failed > 0 {
        text.push_str(&format!(", {failed} failed"));
    }
    text
}

/// The panel's first row: the title `head`, and right of it `right` (the
/// progress) where it fits.
pub(super) fn title_line(t: &Theme, (head, right): (&str, &str), area: Rect, buf: &mut Buffer) {
    let width = |s: &str| Span::raw(s).width();
    let mut spans = vec![Span::styled(head.to_string(), t.title)];
    if !right.is_empty() && width(head) + 2 + width(right) <= usize::from(area.width) {
        spans.push(Span::raw("  "));
        spans.push(Span::styled(t.glyphs.text(right).into_owned(), t.dim));
    }
    Line::from(spans).render(Rect { height: 1, ..area }, buf);
}

/// The chart panel `area` (its graph `_g` is not used: the panel is split).
pub fn render(app: &App, (area, _g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let gl = t.glyphs;
    let pane = &app.contact;
    if pane.table {
        convergence::render(app, area, buf);
        return;
    }
    let w = usize::from(area.width);
    let (n, coarse) = pane.grids();
    // The grid of the answer shown: the coarse one until the scene's own
    // grid has solved the chosen load.
    let shown = if pane.chosen_is_coarse() { coarse } else { n };
    // The hardness in use by its own name (H alone is the Hurst exponent).
    let h = app.state.hardness_name();
    let head = if pane.sweep {
        format!(
            "plastic share vs ζ at p̄ = {} {h} · {}",
            load_text(load_value(pane.load)),
            seeds_words(pane)
        )
    } else {
        let measured = pane
            .tasks
            .first()
            .is_some_and(|t| t.scene.surface.is_some());
        match n {
            Some(n) if measured => format!("simulation {n}² · measured map"),
            Some(n) if shown != Some(n) => format!(
                "simulation {}² coarse, {n}² to come · {}",
                shown.unwrap_or(0),
                seeds_words(pane)
            ),
            Some(n) => format!("simulation {n}² · {}", seeds_words(pane)),
            None => "simulation".into(),
        }
    };
    let head = title::with_sampling(pane, gl, head, (n, w));
    let head = gl.text(&head).into_owned();
    let used = Span::raw(head.as_str()).width();
    let right = progress_text(app, w.saturating_sub(used + 2));
    title_line(t, (&head, &right), area, buf);
    if area.height < 8 {
        return;
    }
    // The simulation and the theory beside it are at the marker (and the
    // sweep's chart is the share itself): while a claim's poll is open
    // they wait, as the readout's values do.
    let rest = Rect::new(area.x, area.y + 1, area.width, area.height - 1);
    if chart::withheld(app, "the simulation and the theory's areas", rest, buf) {
        return;
    }
    let row1 = Rect::new(area.x, area.y + 1, area.width, 1);
    let mut top = 2;
    if pane.sweep {
        let n = pane.seeds_asked();
        let text = if n > 1 {
            format!("simulation: mean ± sd of {n} seeds · theory S_pl/S_tot lines · b: vs load")
        } else {
            "simulation points · theory S_pl/S_tot lines · b: areas vs load".into()
        };
        Line::styled(gl.text(&text).into_owned(), t.dim).render(row1, buf);
    } else {
        let (lines, error) = readout(pane, w, gl, h);
        let style = if error { t.error } else { Style::new() };
        for (k, line) in lines.into_iter().enumerate() {
            let row = Rect::new(area.x, area.y + 1 + k as u16, area.width, 1);
            Line::styled(line, style).render(row, buf);
            top = 2 + k as u16;
        }
    }
    let body = Rect::new(area.x, area.y + top, area.width, area.height - top);
    if pane.sweep {
        sweep_chart(app, body, buf);
        return;
    }
    // The map: a square of points, two per cell up where half blocks are
    // drawn, at most 45 % of the panel's width.
    let rows = body.height.saturating_sub(1);
    let side = (rows * 2).min(body.width * 45 / 100);
    let map = Rect::new(body.x, body.y + 1, side, side / 2);
    let chart = Rect::new(
        body.x + side + 1,
        body.y,
        body.width.saturating_sub(side + 1),
        body.height,
    );
    let half = t.color && !t.glyphs.ascii_only();
    let scale = map_scale(shown.unwrap_or(0), usize::from(side));
    // Without half blocks a character is one point across and two up.
    let scale = if half {
        scale
    } else {
        format!("{scale} across")
    };
    map_legend(t, h, &scale, Rect::new(body.x, body.y, side, 1), buf);
    if let Some(why) = &pane.why_not {
        let text = gl.text(why).into_owned();
        Paragraph::new(text)
            .style(t.dim)
            .wrap(Wrap { trim: true })
            .render(Rect::new(body.x, body.y + 1, side.max(1), rows), buf);
    } else if let Some(Ok(s)) = pane.chosen() {
        let nn = (s.map.len() as f64).sqrt().round() as usize;
        draw_map(t, &s.map, nn, map, buf);
    }
    load_chart(app, chart, buf);
}

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

fn scatter<'a>(style: (Style, Marker), data: &'a [(f64, f64)]) -> Dataset<'a> {
    Dataset::default()
        .graph_type(GraphType::Scatter)
        .marker(style.1)
        .style(style.0)
        .data(data)
}

/// The graph inside a chart region: a legend row on top, y labels left,
/// x axis and labels below.
fn graph_of(area: Rect) -> Option<Rect> {
    let w = area.width.checked_sub(Y_LABEL_W + 1 + 2)?;
    let h = area.height.checked_sub(1 + 2)?;
    (w >= 4 && h >= 3).then(|| Rect::new(area.x + Y_LABEL_W + 1, area.y + 1, w, h))
}

fn load_chart(app: &App, area: Rect, buf: &mut Buffer) {
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
    let label = |s: &str| Span::raw(t.glyphs.text(s).into_owned());
    let legend = Line::from(vec![
        Span::styled(t.total.sample, t.total.style),
        label(" theory  "),
        Span::styled(
            match point(t, &t.total, 'T').1 {
                Marker::Custom(c) => c.to_string(),
                _ => "●".into(),
            },
            point(t, &t.total, 'T').0,
        ),
        label(" simulation (T E P)"),
    ]);
    legend.render(Rect { height: 1, ..area }, buf);
    let h = if app.state.size_effect {
        "p̄/H_y"
    } else {
        "p̄/H0"
    };
    chart::axes(
        t,
        (&Scale::decades(xb), &Scale::decades(yb)),
        h,
        (area, g),
        buf,
    );
    let theory = &pane.theory.curves;
    let at = load_value(pane.load).log10();
    let marker = [(at, yb[0]), (at, yb[1])];
    let mut sets = vec![chart::dataset(&t.marker_line, &marker)];
    for (c, data) in [&t.total, &t.elastic, &t.plastic].into_iter().zip(theory) {
        sets.push(chart::dataset(c, data));
    }
    // The total last: on top where it equals the elastic part.
    for (k, (c, ch)) in [(&t.total, 'T'), (&t.elastic, 'E'), (&t.plastic, 'P')]
        .into_iter()
        .enumerate()
        .rev()
    {
        sets.extend(bars[k].iter().map(|b| chart::dataset(c, b)));
        sets.push(scatter(point(t, c, ch), &sims[k]));
    }
    chart::plot(sets, (xb, yb), g, buf);
}

fn sweep_chart(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let pane = &app.contact;
    let Some(g) = graph_of(area) else {
        return;
    };
    if let Some(why) = &pane.why_not {
        Paragraph::new(t.glyphs.text(why).into_owned())
            .style(t.dim)
            .wrap(Wrap { trim: true })
            .render(g, buf);
        return;
    }
    let zs = &pane.zetas;
    let hi = zs.last().copied().unwrap_or(2.0).log10();
    // The means over the seeds solved so far, ± one sd (the two sets'
    // bars a little apart, so that neither hides the other).
    let mut sims: [Vec<(f64, f64)>; 2] = Default::default();
    let mut spread: [Vec<(f64, Stat)>; 2] = Default::default();
    for (set, (out, sd)) in sims.iter_mut().zip(spread.iter_mut()).enumerate() {
        for (k, z) in zs.iter().enumerate() {
            if let Some(st) = pane.share_at(set, k) {
                out.push((z.log10(), st.mean));
                sd.push((z.log10(), st));
            }
        }
    }
    let (xb, yb) = ([0.0, hi], [0.0, 1.0]);
    let nudge = 0.006 * hi.max(0.3);
    let bars: Vec<Vec<Vec<(f64, f64)>>> = spread
        .iter()
        .zip([-nudge, nudge])
        .map(|(set, dx)| sd_bars(set, dx, |m, sd| ((m - sd).max(0.0), (m + sd).min(1.0))))
        .collect();
    let (off, on) = (&t.psi_p, &t.psi_star);
    let name = |s: &str| Span::raw(t.glyphs.text(s).into_owned());
    let p_off = point(t, off, 'o');
    let p_on = point(t, on, 'x');
    let ch = |m: Marker| match m {
        Marker::Custom(c) => c.to_string(),
        _ => "●".into(),
    };
    Line::from(vec![
        Span::styled(off.sample, off.style),
        Span::styled(ch(p_off.1), p_off.0),
        name(" H0  "),
        Span::styled(on.sample, on.style),
        Span::styled(ch(p_on.1), p_on.0),
        name(
            if pane.sampling.hardness == crate::contact::Hardness::Asperity {
                " H_y per asperity (points), H_y(R_s) (line)"
            } else {
                " H_y (size effect)"
            },
        ),
    ])
    .render(Rect { height: 1, ..area }, buf);
    let x = Scale::of_axis(rough_model::Axis::Zeta, xb);
    chart::axes(t, (&x, &Scale::linear(yb, 5.0)), "ζ", (area, g), buf);
    let theory = &pane.theory.curves;
    let mut sets = vec![];
    for (c, data) in [off, on].into_iter().zip(theory) {
        sets.push(chart::dataset(c, data));
    }
    for (c, b) in [off, on].into_iter().zip(&bars) {
        sets.extend(b.iter().map(|b| chart::dataset(c, b)));
    }
    sets.push(scatter(p_off, &sims[0]));
    sets.push(scatter(p_on, &sims[1]));
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
