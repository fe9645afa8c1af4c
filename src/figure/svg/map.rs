//! The regime map as SVG: cells coloured by plastic share, merged into
//! runs of equal colour along each row, the Ψ = 1 contour, the current
//! point, and a legend panel with the colour bar and the thresholds.

use plotters::prelude::*;

use super::{axis_desc, chart, plot_err, title, Area, Scale};
use crate::figure::{
    share_colour, FigureOptions, MapSpec, RegimeMap, ELASTIC_BELOW, PLASTIC_ABOVE,
};
use crate::snapshot::State;

/// Width of the legend panel right of the map.
const LEGEND_W: u32 = 230;

const CONTOUR: RGBColor = RGBColor(255, 255, 255);
const POINT: RGBColor = RGBColor(255, 0, 0);

fn rgb(share: f64) -> RGBColor {
    let (r, g, b) = share_colour(share);
    RGBColor(r, g, b)
}

/// Drawn coordinates of the cell edges of `n` cells centred on an even
/// grid from `a` to `b` (drawn units): n + 1 edges.
fn edges(a: f64, b: f64, n: usize) -> Vec<f64> {
    let step = (b - a) / (n - 1) as f64;
    (0..=n).map(|k| a + step * (k as f64 - 0.5)).collect()
}

/// A scale whose drawn range runs from `e0` to `e1` (drawn units).
fn scale(log: bool, e0: f64, e1: f64, desc: String) -> Scale {
    let back = |u: f64| if log { 10f64.powf(u) } else { u };
    Scale {
        log,
        lo: back(e0),
        hi: back(e1),
        desc,
    }
}

pub(super) fn draw(area: &Area, state: &State, opts: &FigureOptions) -> anyhow::Result<()> {
    let spec = MapSpec::of(state, opts.grid, opts.map_y)?;
    let m = RegimeMap::compute(&spec);
    let (plot, side) = area.split_horizontally(area.dim_in_pixel().0 - LEGEND_W);
    let drawn = |s: &rough_model::Sweep| {
        let log = s.axis().is_log();
        let t = |v: f64| if log { v.log10() } else { v };
        (log, t(s.from()), t(s.to()))
    };
    let (xlog, xa, xb) = drawn(&spec.x);
    let (ylog, ya, yb) = drawn(&spec.y);
    let xe = edges(xa, xb, spec.cols);
    let ye = edges(ya, yb, spec.rows);
    let x = scale(xlog, xe[0], xe[spec.cols], axis_desc(spec.x.axis()));
    let y = scale(ylog, ye[0], ye[spec.rows], axis_desc(spec.y.axis()));
    let mut c = chart(&plot, &title(state, "regime map"), (&x, &y), None)?;

    // Cells, as runs of equal colour along each row.
    let mut rects = Vec::new();
    for row in 0..spec.rows {
        let mut start = 0;
        for col in 1..=spec.cols {
            let here = rgb(m.share_at(start, row));
            if col == spec.cols || rgb(m.share_at(col, row)) != here {
                rects.push(Rectangle::new(
                    [(xe[start], ye[row]), (xe[col], ye[row + 1])],
                    here.filled(),
                ));
                start = col;
            }
        }
    }
    c.draw_series(rects).map_err(plot_err)?;

    // The Ψ = 1 contour along the cell edges where ψ crosses 1.
    let mut segs = Vec::new();
    for row in 0..spec.rows {
        for col in 0..spec.cols {
            let (right, up) = m.contour_edges(col, row);
            if right {
                segs.push(vec![(xe[col + 1], ye[row]), (xe[col + 1], ye[row + 1])]);
            }
            if up {
                segs.push(vec![(xe[col], ye[row + 1]), (xe[col + 1], ye[row + 1])]);
            }
        }
    }
    let contour = CONTOUR.stroke_width(2);
    c.draw_series(segs.into_iter().map(|s| PathElement::new(s, contour)))
        .map_err(plot_err)?;

    // The current point, where it lies on the map.
    let (fx, fy) = spec.position();
    let on_map = (0.0..=1.0).contains(&fx) && (0.0..=1.0).contains(&fy);
    if on_map {
        let p = (xa + (xb - xa) * fx, ya + (yb - ya) * fy);
        c.draw_series(std::iter::once(Circle::new(p, 7, POINT.stroke_width(3))))
            .map_err(plot_err)?;
    }
    side_legend(&side, &m, on_map)
}

/// The colour bar with the thresholds, the contour and, where it is on the
/// map, the current point.
fn side_legend(area: &Area, m: &RegimeMap, point: bool) -> anyhow::Result<()> {
    let font = ("sans-serif", 14).into_font();
    let text = |s: String, x: i32, y: i32| Text::new(s, (x, y), font.clone());
    let (x0, top, bar_h) = (15, 60, 260);
    area.draw(&text("plastic share S_pl/S_tot".into(), x0, top - 30))
        .map_err(plot_err)?;
    let steps = 52;
    for k in 0..steps {
        let share = 1.0 - (k as f64 + 0.5) / steps as f64;
        let y = top + bar_h * k / steps;
        area.draw(&Rectangle::new(
            [(x0, y), (x0 + 28, top + bar_h * (k + 1) / steps)],
            rgb(share).filled(),
        ))
        .map_err(plot_err)?;
    }
    let at = |share: f64| top + ((1.0 - share) * f64::from(bar_h)) as i32;
    for (share, label) in [
        (1.0, "1 plastic".to_string()),
        (PLASTIC_ABOVE, format!("{PLASTIC_ABOVE} plastic above")),
        (0.5, "0.5".to_string()),
        (ELASTIC_BELOW, format!("{ELASTIC_BELOW} elastic below")),
        (0.0, "0 elastic".to_string()),
    ] {
        let y = at(share);
        area.draw(&PathElement::new(vec![(x0 + 28, y), (x0 + 36, y)], BLACK))
            .map_err(plot_err)?;
        area.draw(&text(label, x0 + 40, y - 7)).map_err(plot_err)?;
    }
    let mut y = top + bar_h + 25;
    for line in [
        "thresholds 10 % and 90 %:",
        "this program's own",
        "(the paper sets none)",
    ] {
        area.draw(&text(line.into(), x0, y)).map_err(plot_err)?;
        y += 18;
    }
    y += 12;
    let psi = if m.spec.size_effect { "Ψ*" } else { "Ψ_P" };
    area.draw(&Rectangle::new(
        [(x0, y - 5), (x0 + 28, y + 5)],
        BLACK.filled(),
    ))
    .map_err(plot_err)?;
    area.draw(&PathElement::new(
        vec![(x0 + 2, y), (x0 + 26, y)],
        CONTOUR.stroke_width(2),
    ))
    .map_err(plot_err)?;
    area.draw(&text(format!("{psi} = 1 contour"), x0 + 40, y - 7))
        .map_err(plot_err)?;
    if point {
        y += 26;
        area.draw(&Circle::new((x0 + 14, y), 7, POINT.stroke_width(3)))
            .map_err(plot_err)?;
        area.draw(&text("current point".into(), x0 + 40, y - 7))
            .map_err(plot_err)?;
    }
    Ok(())
}
