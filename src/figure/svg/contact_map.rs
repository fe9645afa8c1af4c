//! The contact map as a picture (`export --view contact-map`, the contact
//! view's `p`): the solved cell seen from the half-space, one node a
//! square, out of contact white, elastic grey, at the hardness the paper's
//! plastic blue, with a scale bar, the legend and the numbers beside it,
//! and the scene under it as every picture has. Consecutive nodes of a row
//! in one state are one rectangle (the file grows with the contact's
//! outline, not with N²), written with exact coordinates: on a fine grid a
//! node is smaller than a pixel.

use std::fmt::Write as _;

use plotters::prelude::*;

use super::contact::NODE_ELASTIC;
use super::legend::Placed;
use super::wrap::wrap;
use super::{fine, plot_err, render, under, Area, PLASTIC};
use crate::physical::{short_length, short_number};
use crate::scene::State;

/// The contact map's numbers as its picture draws them.
#[derive(Clone, Debug)]
pub struct ContactMap<'a> {
    /// The seed of the power law's surface; `None`: a measured map.
    pub seed: Option<u64>,
    /// n × n nodes, row-major, row 0 at the top: 0 out of contact, 1
    /// elastic (0 < p < H_use), 2 at the hardness.
    pub nodes: &'a [u8],
    pub n: usize,
    /// The side of the solved square (m).
    pub side: f64,
    /// The load p̄/H_use.
    pub load: f64,
    /// A/A0 and the part of it at the hardness.
    pub area: f64,
    pub plastic: f64,
}

/// Where the map and its legend go in the chart area.
const LEFT: i32 = 40;
const TOP: i32 = 50;
/// Height kept under the map for the scale bar.
const BAR_H: i32 = 45;
const FONT: u32 = 14;

/// The length of a scale bar for a map of side `side`: 1, 2 or 5 times a
/// power of ten, at most a third of the side.
pub(crate) fn bar_length(side: f64) -> f64 {
    let max = side / 3.0;
    let e = max.log10().floor();
    // Parsed, not multiplied: 5e-6 exactly as written.
    let at = |m: u32| -> f64 { format!("{m}e{e}").parse().unwrap_or(f64::NAN) };
    [5, 2, 1]
        .into_iter()
        .map(at)
        .find(|&l| l <= max * (1.0 + 1e-12))
        .unwrap_or_else(|| at(1))
}

/// `nodes` (n × n) as rectangles in a square of `side_px` at `(x0, y0)`.
fn cells(m: &ContactMap, (x0, y0): (f64, f64), side_px: f64) -> String {
    let n = m.n.max(1);
    let cell = side_px / n as f64;
    let mut s = format!(
        r#"<rect x="{x0}" y="{y0}" width="{side_px}" height="{side_px}" fill="white" stroke="none"/>"#
    );
    let colour = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
    let (el, pl) = (colour(NODE_ELASTIC), colour(PLASTIC));
    if m.nodes.len() == n * n {
        for (y, row) in m.nodes.chunks(n).enumerate() {
            let mut x = 0;
            while x < n {
                let k = row[x];
                let run = row[x..].iter().take_while(|v| **v == k).count();
                let fill = match k {
                    1 => Some(&el),
                    2 => Some(&pl),
                    _ => None,
                };
                if let Some(fill) = fill {
                    let _ = write!(
                        s,
                        "\n<rect x=\"{:.3}\" y=\"{:.3}\" width=\"{:.3}\" height=\"{:.3}\" \
                         fill=\"{fill}\"/>",
                        x0 + x as f64 * cell,
                        y0 + y as f64 * cell,
                        run as f64 * cell,
                        cell
                    );
                }
                x += run;
            }
        }
    }
    s.push('\n');
    s
}

fn draw(area: &Area, state: &State, m: &ContactMap, title: &str) -> anyhow::Result<Placed> {
    let (w, h) = area.dim_in_pixel();
    let (w, h) = (w as i32, h as i32);
    super::top_title(area, title)?;
    let side = (h - TOP - BAR_H).min(w / 2);
    let (ox, oy) = area.get_base_pixel();
    fine::raw(
        area,
        [(LEFT, TOP), (LEFT + side, TOP + side)],
        cells(
            m,
            (f64::from(ox + LEFT), f64::from(oy + TOP)),
            f64::from(side),
        ),
    )?;
    area.draw(&Rectangle::new(
        [(LEFT, TOP), (LEFT + side, TOP + side)],
        BLACK.stroke_width(1),
    ))
    .map_err(plot_err)?;

    // The scale bar under the map's left corner.
    let bar = bar_length(m.side);
    let bar_px = (f64::from(side) * bar / m.side).round() as i32;
    let by = TOP + side + 16;
    area.draw(&Rectangle::new(
        [(LEFT, by), (LEFT + bar_px, by + 5)],
        BLACK.filled(),
    ))
    .map_err(plot_err)?;
    let font = ("sans-serif", FONT).into_font();
    area.draw(&Text::new(
        short_length(bar),
        (LEFT + bar_px + 10, by - 4),
        font.clone(),
    ))
    .map_err(plot_err)?;

    // The legend and the numbers right of the map.
    let hy = state.hardness_name();
    let x0 = LEFT + side + 30;
    let mut y = TOP + 4;
    for (fill, label) in [
        (WHITE, "out of contact (p = 0)".to_string()),
        (NODE_ELASTIC, format!("elastic (0 < p < {hy})")),
        (PLASTIC, format!("at the hardness (p = {hy})")),
    ] {
        area.draw(&Rectangle::new([(x0, y), (x0 + 14, y + 14)], fill.filled()))
            .map_err(plot_err)?;
        area.draw(&Rectangle::new([(x0, y), (x0 + 14, y + 14)], BLACK))
            .map_err(plot_err)?;
        area.draw(&Text::new(label, (x0 + 22, y), font.clone()))
            .map_err(plot_err)?;
        y += 24;
    }
    y += 10;
    let share = if m.area > 0.0 {
        m.plastic / m.area
    } else {
        0.0
    };
    let chars = ((w - x0 - 10) as f64 / 7.0) as usize;
    let facts = [
        format!("load p̄ = {} {hy}", short_number(m.load)),
        format!(
            "contact area A/A0 = {} %, {} % of it at the hardness",
            short_number(100.0 * m.area),
            short_number(100.0 * share)
        ),
        format!(
            "{} × {} nodes of {} on a square of side {}",
            m.n,
            m.n,
            short_length(m.side / m.n.max(1) as f64),
            short_length(m.side)
        ),
        match m.seed {
            Some(s) => format!("a periodic Gaussian surface of the scene's spectrum, seed {s}"),
            None => "the measured map's solved square".into(),
        },
    ];
    for f in facts {
        for l in wrap(&f, chars) {
            area.draw(&Text::new(l, (x0, y), font.clone()))
                .map_err(plot_err)?;
            y += 18;
        }
        y += 4;
    }
    Ok(Placed::Inside)
}

/// The contact map of `state` as an SVG document.
pub fn render_contact_map(state: &State, m: &ContactMap, span: String) -> anyhow::Result<String> {
    let hy = state.hardness_name();
    let load = short_number(m.load);
    let what = format!("contact map at p̄ = {load} {hy}");
    let title = super::title(state, &what);
    let n = m.n;
    let short = match m.seed {
        Some(s) => format!("load p̄ = {load} {hy} · {n}×{n} nodes, seed {s}"),
        None => format!("load p̄ = {load} {hy} · {n}×{n} nodes of the measured map"),
    };
    let square = match m.seed {
        Some(_) => {
            // The cell is K longest wavelengths a side (`--cell K`).
            let k = (m.side * state.params.q0() / std::f64::consts::TAU).round();
            if k <= 1.0 {
                format!(
                    "the periodic cell of one longest wavelength, L = 2π/q0 = {}",
                    short_length(m.side)
                )
            } else {
                format!(
                    "the periodic cell of {k} longest wavelengths, {k} · 2π/q0 = {}",
                    short_length(m.side)
                )
            }
        }
        None => format!("the measured map's square of side {}", short_length(m.side)),
    };
    let caption = format!(
        "The contact at p̄ = {load} {hy} seen from the half-space, one node a square: white \
         out of contact, grey elastic (0 < p < {hy}), blue at the hardness (p = {hy}); \
         {square}, as the simulation solves it."
    );
    let lines = under(state, Some(short), &caption);
    let desc = crate::figure::scene_text::full_lines_of(state, "contact-map", span);
    let draw = |area: &Area, _room| draw(area, state, m, &title);
    render(&draw, &lines, &format!("{} — {what}", state.name), &desc)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_bar_is_a_round_length_under_a_third_of_the_side() {
        assert_eq!(bar_length(6.283185307179586e-5), 2e-5);
        assert_eq!(bar_length(3e-5), 1e-5);
        assert_eq!(bar_length(1.0), 0.2);
        assert_eq!(bar_length(3.0), 1.0);
        assert_eq!(bar_length(16e-6), 5e-6);
    }
}
