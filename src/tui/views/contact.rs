//! The contact view: the boundary-element simulation of the scene's
//! surface beside the theory. A title with the grid, seed and the solver's
//! progress; a readout at the chosen load; left the contact map at that
//! load (out of contact, elastic, at the hardness), right A/A0 against
//! p̄/H_use (log–log) with the simulation's points on the theory's curves,
//! or (`b`) the plastic share against ζ at the chosen load for each set of
//! caps, or (`i`) the initial slopes against ζ. Drawing only reads what
//! [`crate::tui::contact`] holds.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::chart;
use crate::contact::engine::Progress;
use crate::contact::{Hardness, LoadScale};
use crate::physical::print::load_text;
use crate::tui::app::App;
use crate::tui::contact::{load_value, Plot};
use crate::tui::glyphs::Glyphs;
use crate::tui::theme::Theme;

mod charts;
mod convergence;
mod map;
mod readout;
mod title;

pub use map::{dithered, map_scale};
use map::{draw_map, map_legend};
pub use readout::{pct, pct_pm, readout, share_pct, share_pm};
use title::seeds_words;

/// The unit the view's loads are given in: H0, the theory's H_y, or under
/// a per-node hardness H_y(R_s) by name (the caps differ from node to
/// node; the load is still over the theory's H_y at R_s).
pub(crate) fn load_unit(app: &App) -> &'static str {
    match (app.state.size_effect, app.contact.sampling.hardness) {
        (false, _) => "H0",
        (true, Hardness::Global) => app.state.hardness_name(),
        (true, _) => "H_y(R_s)",
    }
}

/// The cap a node at the hardness sits at, for the map's legend.
fn cap_name(app: &App) -> &'static str {
    match (app.state.size_effect, app.contact.sampling.hardness) {
        (true, Hardness::Asperity) => "its asperity's H_y",
        (true, Hardness::Summit) => "its summit's H_y",
        _ => app.state.hardness_name(),
    }
}

/// The map's colours: elastic light grey, at the hardness blue (the
/// paper's plastic colour); out of contact the terminal's background.
const ELASTIC: Color = Color::Gray;
const PLASTIC: Color = Color::Blue;

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
    // The load's unit by its own name (H alone is the Hurst exponent).
    let h = load_unit(app);
    let head = if pane.plot == Plot::Share {
        let unit = match pane.sampling.loads {
            LoadScale::H0 => "H0".to_string(),
            LoadScale::InUse => format!("{} at each ζ", app.state.hardness_name()),
        };
        format!(
            "plastic share vs ζ at p̄ = {} {unit} · {}",
            load_text(load_value(pane.load)),
            seeds_words(pane)
        )
    } else if pane.plot == Plot::Slopes {
        format!("initial slopes vs ζ · {}", seeds_words(pane))
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
    if pane.plot == Plot::Share {
        let text = readout::share_row(pane, w, gl);
        Line::styled(text, t.dim).render(row1, buf);
    } else {
        let (lines, error) = readout(pane, w, gl, h);
        let style = if error { t.error } else { Style::new() };
        for (k, line) in lines.into_iter().enumerate() {
            let row = Rect::new(area.x, area.y + 1 + k as u16, area.width, 1);
            Line::styled(line, style).render(row, buf);
            top = 2 + k as u16;
        }
        // Where there is room, a row more: κ at the lightest load beside
        // Persson's, and which split the theory's elastic/plastic reads.
        if pane.plot == Plot::Load && area.height >= 20 {
            if let Some(text) = readout::kappa_row(pane, app.state.model, (w, h), gl) {
                let row = Rect::new(area.x, area.y + top, area.width, 1);
                Line::styled(text, t.dim).render(row, buf);
                top += 1;
            }
        }
    }
    let body = Rect::new(area.x, area.y + top, area.width, area.height - top);
    match pane.plot {
        Plot::Share => return charts::share_chart(app, body, buf),
        Plot::Slopes => return charts::slopes_chart(app, body, buf),
        Plot::Load => {}
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
    map_legend(
        t,
        cap_name(app),
        &scale,
        Rect::new(body.x, body.y, side, 1),
        buf,
    );
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
    charts::load_chart(app, chart, buf);
}
