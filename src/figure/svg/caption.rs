//! What goes under a picture's chart: the scene in short, the view's own
//! caption and, along the sweep, the claims, each line in its colour.

use plotters::prelude::*;

use super::wrap::wrap;
use super::{plot_err, Area, CAPTION_W, CLAIMS, LINE_H};
use crate::figure::{scene_text, ClaimKind, FigureOptions, View};
use crate::scene::State;

/// The scene's colour under the chart: dark grey, so that the caption and
/// the claims stand out.
pub(super) const SCENE: RGBColor = RGBColor(70, 70, 70);

/// What goes under the chart, each line with its colour: the scene's
/// parameters, the view's caption and, on the views along the sweep
/// (slopes, indices, map), the claims (as on the explorer's caption row,
/// in full).
pub(super) fn caption_lines(
    view: View,
    state: &State,
    opts: &FigureOptions,
) -> Vec<(String, RGBColor)> {
    let mut lines: Vec<_> = scene_text::short_lines(state, view, opts)
        .iter()
        .flat_map(|l| wrap(l, CAPTION_W))
        .map(|l| (l, SCENE))
        .collect();
    let text = view_caption(view, state);
    lines.extend(wrap(&text, CAPTION_W).into_iter().map(|l| (l, BLACK)));
    // The spectrum's fit in full, on lines of its own.
    if let Some(fit) = (view == View::Spectrum)
        .then(|| super::spectrum::fit_line(state))
        .flatten()
    {
        lines.extend(wrap(&fit, CAPTION_W).into_iter().map(|l| (l, BLACK)));
    }
    // Each picture its own claims: the slopes' share and minimum, the
    // indices' crossing of 1, the map's share and crossing along the
    // row of the current parameters.
    let own = |k: ClaimKind| match view {
        View::Slopes => matches!(k, ClaimKind::ShareHalf | ClaimKind::TotalMinimum),
        View::Indices => k == ClaimKind::IndexOne,
        View::Map => matches!(k, ClaimKind::ShareHalf | ClaimKind::IndexOne),
        _ => false,
    };
    let mut claims: Vec<String> = crate::figure::shown_claims(state)
        .into_iter()
        .filter(|c| own(c.kind))
        .map(|c| c.text())
        .collect();
    if view == View::Map && !claims.is_empty() {
        if let Ok(m) = crate::figure::MapSpec::of(state, opts.grid, opts.map_y) {
            let a = m.y.axis();
            let v = scene_text::short_value(a, state.params.get(a));
            claims[0] = format!("along {} = {v}: {}", a.symbol(), claims[0]);
        }
    }
    // Claims are packed whole, never broken inside one.
    let mut row = String::new();
    for c in claims {
        if !row.is_empty() && row.chars().count() + 3 + c.chars().count() > CAPTION_W {
            lines.push((std::mem::take(&mut row), CLAIMS));
        }
        row = if row.is_empty() {
            c
        } else {
            format!("{row} · {c}")
        };
    }
    if !row.is_empty() {
        lines.push((row, CLAIMS));
    }
    lines
}

/// The view's own caption: a scene's caption describes its slopes (the
/// paper's figures are slope plots), so the slopes view carries it; every
/// other view says what it shows.
pub(crate) fn view_caption(view: View, state: &State) -> String {
    let swept = state.sweep.axis().symbol();
    let psi = if state.size_effect {
        "Ψ* (with the size-dependent hardness H_y)"
    } else {
        "Ψ_P (with the bulk hardness H0)"
    };
    match view {
        View::Slopes => state.caption.clone().unwrap_or_else(|| {
            format!(
                "Initial slopes of the elastic, plastic and total contact area against {swept}, \
                 with Persson's elastic line; the grey line is the marker."
            )
        }),
        View::Indices => format!(
            "Plasticity indices against {swept}: Greenwood–Williamson's, Persson's with the \
             bulk hardness and Ψ* with the size-dependent hardness. The contact turns plastic \
             where the index in use, {psi}, passes 1."
        ),
        View::Map => format!(
            "Regime map: the plastic share S_pl/S_tot of the initial slope, computed with \
             {psi}; the white line is where that index is 1."
        ),
        View::Load => "Contact areas against the load at the parameters above, with the \
                       initial slope drawn from the origin."
            .to_string(),
        View::Spectrum => "The surface's power spectrum, the power law fitted over its fit \
                           band (the grey lines: the spectrum's self-affine stretch unless set) \
                           and the cutoff q1 = ζ q0."
            .to_string(),
        View::Contact => "The boundary-element simulation of the scene's surface beside the \
                          theory's areas."
            .to_string(),
    }
}

/// `lines` under the chart.
pub(super) fn caption(area: &Area, lines: &[(String, RGBColor)]) -> anyhow::Result<()> {
    let mut y = 8;
    for (l, colour) in lines {
        let font = ("sans-serif", 14).into_font().color(colour);
        area.draw(&Text::new(l.as_str(), (20, y), font))
            .map_err(plot_err)?;
        y += LINE_H as i32;
    }
    Ok(())
}
