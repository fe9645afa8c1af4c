//! The slopes view: the paper's curves, H·dA/dp̄/A0 against the swept
//! parameter for elastic, plastic, total and Persson's elastic slope.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;
use ratatui::widgets::Widget;

use super::chart::{self, Scale};
use super::overlap;
use crate::physical::print::fmt_decade;
use crate::tui::app::App;
use crate::tui::theme::CurveStyle;

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let axis = app.state.sweep.axis();
    if g.width < 2 || g.height < 2 {
        return;
    }
    let p = &app.plot;
    let norm = app.state.hardness_name();
    let title = vec![Span::styled(
        format!("slope {norm}·dA/dp̄/A0 vs {}", axis.symbol()),
        t.title,
    )];
    chart::title(app, title, area, buf);
    // While a poll's answer waits: the curves that would give it are not
    // drawn, the y range fits those drawn, and the legend names curves
    // without saying where they went.
    let withheld = app.class.withheld(app.state.size_effect);
    let all = [&p.elastic, &p.plastic, &p.total, &p.persson];
    let y_bounds = if withheld.slopes.iter().any(|w| *w) {
        let shown: Vec<&Vec<(f64, f64)>> = (0..4)
            .filter(|i| !withheld.slopes[*i])
            .map(|i| all[i])
            .collect();
        crate::tui::plots::slope_bounds(&shown, &[])
    } else {
        p.y_bounds
    };
    let bounds = (p.x_bounds, y_bounds);
    // Draw order, later over earlier: Persson's reference curve last, so
    // that it shows even where it equals the total (fig3) or the elastic
    // curve; a curve left with under a twentieth of its cells visible is
    // named in the legend as lying under the one that hides it.
    // (The order of `overlap::Cover::of`.)
    let curves = [
        (&t.elastic, &p.elastic),
        (&t.plastic, &p.plastic),
        (&t.total, &p.total),
        (&t.persson, &p.persson),
    ];
    // The cover computed with the curves; traced here only if the graph or
    // the glyphs changed since (the app refreshes it on every update).
    let dots = t.glyphs.dots();
    let fresh;
    let cover = match app.plot_cover.as_ref().filter(|c| c.fits(g, dots)) {
        Some(c) => c,
        None => {
            fresh = overlap::Cover::of(p, g, dots);
            &fresh
        }
    };
    let under = &cover.under;
    // A hidden curve joins the entry of the curve on top of it.
    let top = |mut i: usize| {
        while let Some(j) = under[i] {
            i = j;
        }
        i
    };
    let mut names: Vec<(&CurveStyle, String)> = if withheld.marks {
        (0..curves.len())
            .map(|i| {
                let c = curves[i].0;
                let name = if withheld.slopes[i] {
                    format!("{} ?", short_name(c))
                } else {
                    c.name.to_string()
                };
                (c, name)
            })
            .collect()
    } else {
        (0..curves.len())
            .filter(|&i| under[i].is_none())
            .map(|i| {
                let c = curves[i].0;
                let below: Vec<&str> = (0..curves.len())
                    .filter(|&k| k != i && top(k) == i)
                    .map(|k| short_name(curves[k].0))
                    .collect();
                let (data, yb) = (curves[i].1, p.y_bounds);
                if cover.empty[i] {
                    // Nothing on the chart: say where the curve went.
                    let name = if data.is_empty() {
                        format!("{} = 0", c.name)
                    } else if data.iter().all(|q| q.1 < yb[0]) {
                        format!("{} < {}", c.name, fmt_decade(yb[0] as i32))
                    } else if data.iter().all(|q| q.1 > yb[1]) {
                        format!("{} > {}", c.name, fmt_decade(yb[1] as i32))
                    } else {
                        c.name.to_string()
                    };
                    (c, name)
                } else if below.is_empty() {
                    (c, c.name.to_string())
                } else {
                    (c, format!("{} = {} here", short_name(c), below.join(" = ")))
                }
            })
            .collect()
    };
    // " here" goes first when the legend is too long for the panel (each
    // entry takes at least a one-character sample and two spaces).
    let ghost_len = if app.ghost.is_some() {
        "ghost".len() + 3
    } else {
        0
    };
    let len: usize = names.iter().map(|(_, n)| n.chars().count() + 3).sum();
    if len + ghost_len > usize::from(area.width) {
        for (_, n) in &mut names {
            if let Some(cut) = n.strip_suffix(" here") {
                *n = cut.to_string();
            }
        }
    }
    // The ghost's entry: what it shows when that fits, else its name (the
    // status row then says what it shows).
    if let Some(ghost) = &app.ghost {
        let label = ghost.label(&app.state);
        let len: usize = names.iter().map(|(_, n)| n.chars().count() + 3).sum();
        let fits = len + label.chars().count() + 3 <= usize::from(area.width);
        names.push((&t.ghost, if fits { label } else { "ghost".into() }));
    }
    chart::legend_named(t, &names, area, buf);
    reading_line(app, Rect::new(area.x, area.y + 2, area.width, 1), buf);
    let (x, y) = (Scale::of_axis(axis, p.x_bounds), Scale::decades(y_bounds));
    chart::axes(t, (&x, &y), axis.symbol(), (area, g), buf);
    // Where the regime changes along the sweep, on the x axis line; a mark
    // whose cell is taken by another sits in the nearest free one beside it.
    // Not while a poll's answer is hidden: the marks bracket it.
    let mut taken: Vec<u16> = Vec::new();
    let marks = if withheld.marks {
        &[][..]
    } else {
        &p.regime_marks[..]
    };
    for (v, mark) in marks {
        let Some(col) = chart::col_of(g, t.glyphs.dots(), p.x_bounds, *v) else {
            continue;
        };
        let free = [0i32, 1, -1, 2, -2]
            .into_iter()
            .map(|d| i32::from(col) + d)
            .filter(|c| (i32::from(g.x)..i32::from(g.right())).contains(c))
            .map(|c| c as u16)
            .find(|c| !taken.contains(c));
        if let Some(c) = free {
            taken.push(c);
            buf[(c, g.bottom())]
                .set_symbol(t.glyphs.mark(mark.mark()))
                .set_style(t.title);
        }
    }

    // The curves, over the marker line.
    let marker = chart::marker_line(app, y_bounds);
    let mut sets = vec![chart::dataset(&t.marker_line, &marker)];
    // The ghost under everything current.
    if let Some(ghost) = &app.ghost {
        let gp = &ghost.plot;
        for data in [&gp.elastic, &gp.plastic, &gp.total, &gp.persson] {
            sets.push(chart::dataset(&t.ghost, data));
        }
    }
    sets.extend(
        curves
            .iter()
            .zip(withheld.slopes)
            .filter(|(_, w)| !w)
            .map(|((c, data), _)| chart::dataset(c, data)),
    );
    chart::plot(sets, bounds, g, buf);
}

/// Which reading of the elastic/plastic split the shares use (the
/// program's reading of the paper's Appendix A, docs/model.md): the
/// longest form that fits `row`.
fn reading_line(app: &App, row: Rect, buf: &mut Buffer) {
    let h = app.state.hardness_name();
    let forms = [
        format!(
            "shares: elastic area = Appendix A's mass on [0, {h}], plastic the rest \
             (not Persson's erf)"
        ),
        format!("shares: elastic = Appendix A's mass on [0, {h}], not Persson's erf"),
        format!("shares: elastic = App. A's mass on [0, {h}] (? help)"),
        format!("shares: elastic = App. A's mass on [0, {h}]"),
    ];
    let g = app.theme.glyphs;
    let w = usize::from(row.width);
    if let Some(f) = forms
        .iter()
        .map(|f| g.text(f).into_owned())
        .find(|f| Span::raw(f.as_str()).width() <= w)
    {
        ratatui::text::Line::styled(f, app.theme.dim).render(row, buf);
    }
}

/// A curve's name without qualifiers, for "total = Persson here".
fn short_name(c: &CurveStyle) -> &'static str {
    c.name.split_whitespace().next().unwrap_or(c.name)
}
