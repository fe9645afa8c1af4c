//! The regime map as SVG: cells coloured by plastic share, merged into
//! runs of equal colour along each row, the Ψ = 1 contour, the current
//! point, and a legend panel with the colour bar and the thresholds.

use plotters::prelude::*;

use super::{axis_desc, chart, plot_err, title, Area, Scale};
use crate::figure::{
    share_colour, FigureOptions, MapSpec, RegimeMap, ELASTIC_BELOW, PLASTIC_ABOVE,
};
use crate::scene::State;

/// Width of the legend panel right of the map (on a phone's picture).
const LEGEND_W: u32 = 230;
const NARROW_W: u32 = 110;

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
    // A phone's picture: a narrow panel, the bar's ends and thresholds only.
    let narrow = super::phone::size().is_some();
    let legend_w = if narrow { NARROW_W } else { LEGEND_W };
    let (plot, side) = area.split_horizontally(area.dim_in_pixel().0 - legend_w);
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
    if opts.withheld.marks {
        // Along the marker's row the colours show where the share passes
        // ½: the axes and the point only.
        super::waits(&plot, &c, "the colours and the Ψ = 1 contour")?;
        point(&mut c, &spec, (xa, xb), (ya, yb))?;
        return Ok(());
    }
    let m = RegimeMap::compute(&spec);

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

    // The Ψ = 1 contour, interpolated between the cell centres.
    let centres = |a: f64, b: f64, n: usize| -> Vec<f64> {
        (0..n)
            .map(|k| a + (b - a) * k as f64 / (n - 1).max(1) as f64)
            .collect()
    };
    let segs = contour(&m, &centres(xa, xb, spec.cols), &centres(ya, yb, spec.rows));
    let contour_style = CONTOUR.stroke_width(2);
    for [a, b] in segs {
        super::fine::path(&mut c, vec![a, b], contour_style)?;
    }

    let on_map = point(&mut c, &spec, (xa, xb), (ya, yb))?;
    side_legend(&side, &m, on_map, narrow)
}

/// The current point, where it lies on the map (drawn from `xa` to `xb`
/// across, `ya` to `yb` up); whether it does.
fn point(
    c: &mut super::Chart,
    spec: &MapSpec,
    (xa, xb): (f64, f64),
    (ya, yb): (f64, f64),
) -> anyhow::Result<bool> {
    let (fx, fy) = spec.position();
    let on_map = (0.0..=1.0).contains(&fx) && (0.0..=1.0).contains(&fy);
    if on_map {
        let p = (xa + (xb - xa) * fx, ya + (yb - ya) * fy);
        c.draw_series(std::iter::once(Circle::new(p, 7, POINT.stroke_width(3))))
            .map_err(plot_err)?;
    }
    Ok(on_map)
}

/// The Ψ = 1 line by marching squares over the cell centres `xc` × `yc`
/// (drawn coordinates): ln ψ of the index in use at each centre, its zero
/// interpolated linearly along each edge of each square of four centres; a
/// saddle (opposite corners alike) is split as the mean of the four says.
/// A smooth line, not the cells' stair steps.
pub(crate) fn contour(m: &RegimeMap, xc: &[f64], yc: &[f64]) -> Vec<[(f64, f64); 2]> {
    // ψ = 0 (no roughness left) is far below 1, not -∞.
    let f = |col: usize, row: usize| m.psi_at(col, row).ln().max(-50.0);
    let mut segs = Vec::new();
    for row in 0..yc.len().saturating_sub(1) {
        for col in 0..xc.len().saturating_sub(1) {
            // Corners counter-clockwise from the lower left.
            let p = [
                (xc[col], yc[row]),
                (xc[col + 1], yc[row]),
                (xc[col + 1], yc[row + 1]),
                (xc[col], yc[row + 1]),
            ];
            let v = [
                f(col, row),
                f(col + 1, row),
                f(col + 1, row + 1),
                f(col, row + 1),
            ];
            if v.iter().any(|x| x.is_nan()) {
                continue;
            }
            // Where edge k (corner k to k + 1) crosses zero, if it does.
            let cut = |k: usize| -> Option<(f64, f64)> {
                let (a, b) = (v[k], v[(k + 1) % 4]);
                if (a >= 0.0) == (b >= 0.0) {
                    return None;
                }
                let t = a / (a - b);
                let (pa, pb) = (p[k], p[(k + 1) % 4]);
                Some((pa.0 + (pb.0 - pa.0) * t, pa.1 + (pb.1 - pa.1) * t))
            };
            let cuts: Vec<(usize, (f64, f64))> =
                (0..4).filter_map(|k| cut(k).map(|q| (k, q))).collect();
            match cuts.len() {
                2 => segs.push([cuts[0].1, cuts[1].1]),
                4 => {
                    // A saddle: the mean decides which corners connect.
                    let above = v.iter().sum::<f64>() / 4.0 >= 0.0;
                    let corner0_above = v[0] >= 0.0;
                    let q: Vec<(f64, f64)> = cuts.iter().map(|c| c.1).collect();
                    if above == corner0_above {
                        segs.push([q[0], q[1]]);
                        segs.push([q[2], q[3]]);
                    } else {
                        segs.push([q[3], q[0]]);
                        segs.push([q[1], q[2]]);
                    }
                }
                _ => {}
            }
        }
    }
    segs
}

/// The colour bar with the thresholds, the contour and, where it is on the
/// map, the current point.
fn side_legend(area: &Area, m: &RegimeMap, point: bool, narrow: bool) -> anyhow::Result<()> {
    let font = ("sans-serif", 14).into_font();
    let text = |s: String, x: i32, y: i32| Text::new(s, (x, y), font.clone());
    let (x0, top, bar_h) = if narrow {
        (5, 70, area.dim_in_pixel().1 as i32 - 200)
    } else {
        (15, 60, 260)
    };
    let head: &[&str] = if narrow {
        &["plastic", "share"]
    } else {
        &["plastic share S_pl/S_tot"]
    };
    for (i, h) in head.iter().enumerate() {
        let y = top - 30 - 18 * (head.len() - 1 - i) as i32;
        area.draw(&text((*h).into(), x0, y)).map_err(plot_err)?;
    }
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
    let marks = if narrow {
        [
            (1.0, "1".to_string()),
            (PLASTIC_ABOVE, format!("{PLASTIC_ABOVE}")),
            (0.5, "0.5".to_string()),
            (ELASTIC_BELOW, format!("{ELASTIC_BELOW}")),
            (0.0, "0".to_string()),
        ]
    } else {
        [
            (1.0, "1 plastic".to_string()),
            (PLASTIC_ABOVE, format!("{PLASTIC_ABOVE} plastic above")),
            (0.5, "0.5".to_string()),
            (ELASTIC_BELOW, format!("{ELASTIC_BELOW} elastic below")),
            (0.0, "0 elastic".to_string()),
        ]
    };
    for (share, label) in marks {
        let y = at(share);
        area.draw(&PathElement::new(vec![(x0 + 28, y), (x0 + 36, y)], BLACK))
            .map_err(plot_err)?;
        area.draw(&text(label, x0 + 40, y - 7)).map_err(plot_err)?;
    }
    let mut y = top + bar_h + 25;
    let notes: &[&str] = if narrow {
        &[]
    } else {
        &[
            "thresholds 10 % and 90 %:",
            "this program's own",
            "(the paper sets none)",
        ]
    };
    for line in notes {
        area.draw(&text((*line).into(), x0, y)).map_err(plot_err)?;
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
    let contour = if narrow { " = 1" } else { " = 1 contour" };
    area.draw(&text(format!("{psi}{contour}"), x0 + 40, y - 7))
        .map_err(plot_err)?;
    if point {
        y += 26;
        area.draw(&Circle::new((x0 + 14, y), 7, POINT.stroke_width(3)))
            .map_err(plot_err)?;
        let what = if narrow { "marker" } else { "current point" };
        area.draw(&text(what.into(), x0 + 40, y - 7))
            .map_err(plot_err)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::contour;
    use crate::figure::{MapSpec, RegimeMap};
    use rough_model::{psi_in_use, Axis};

    /// fig2's map: ψ ∝ E/H0 at fixed ζ, so ln ψ is linear in log10(H0/E)
    /// and a crossing on a vertical edge of the squares is exact: ψ = 1
    /// there to rounding. Crossings on horizontal edges lie between two
    /// centres where ψ straddles 1.
    #[test]
    fn the_contour_is_interpolated_where_psi_is_one() {
        let state = crate::presets::load("fig2").unwrap();
        let spec = MapSpec::of(&state, (40, 24), None).unwrap();
        assert_eq!(spec.y.axis(), Axis::H0OverE);
        let m = RegimeMap::compute(&spec);
        let t = |s: &rough_model::Sweep, n: usize| -> Vec<f64> {
            let (a, b) = (s.from().log10(), s.to().log10());
            (0..n)
                .map(|k| a + (b - a) * k as f64 / (n - 1) as f64)
                .collect()
        };
        let (xc, yc) = (t(&spec.x, spec.cols), t(&spec.y, spec.rows));
        let segs = contour(&m, &xc, &yc);
        assert!(segs.len() >= spec.cols / 2, "{} segments", segs.len());
        let mut exact = 0;
        for p in segs.iter().flatten() {
            if xc.iter().any(|x| (x - p.0).abs() < 1e-12) {
                let params = state
                    .params
                    .with(Axis::Zeta, 10f64.powf(p.0))
                    .and_then(|q| q.with(Axis::H0OverE, 10f64.powf(p.1)))
                    .unwrap();
                let psi = psi_in_use(&params, state.size_effect, state.moments)
                    .0
                    .to_f64();
                assert!((psi - 1.0).abs() < 1e-9, "ψ = {psi} at {p:?}");
                exact += 1;
            }
            // Inside the map, not on a cell's edge grid only.
            assert!(p.0 >= xc[0] && p.0 <= xc[xc.len() - 1]);
        }
        assert!(exact > 0);
    }
}
