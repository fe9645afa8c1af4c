//! The contact views as SVG: the simulation's points beside the theory's
//! curves, in the paper's colours (elastic black, plastic blue, total red).

use std::io::Write;

use plotters::prelude::*;
use rough_model::areas;

use super::{load_rows, sweep_rows, SWEEP_LOAD};
use crate::scene::State;

const SIZE: (u32, u32) = (900, 600);
const ELASTIC: RGBColor = RGBColor(0, 0, 0);
const PLASTIC: RGBColor = RGBColor(0, 0, 255);
const TOTAL: RGBColor = RGBColor(255, 0, 0);

fn err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::anyhow!("cannot draw the picture: {e}")
}

fn log_points(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from * (to / from).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// A/A0 against p̄/H (both log): simulation points, theory curves.
pub fn contact(
    out: &mut impl Write,
    state: &State,
    points: usize,
    seed: u64,
) -> anyhow::Result<()> {
    let (sim, rows) = load_rows(state, points, seed)?;
    let theory: Vec<(f64, rough_model::Areas)> = log_points(1e-3, 1.0, 120)
        .into_iter()
        .filter_map(|x| areas(sim.model, sim.psi, x).ok().map(|a| (x, a)))
        .collect();
    let floor = rows
        .iter()
        .flat_map(|r| [r.sim.area, r.sim.elastic_area, r.sim.plastic_area])
        .chain(theory.iter().map(|(_, a)| a.total))
        .filter(|&v| v > 0.0)
        .fold(1.0, f64::min)
        .max(1e-8)
        / 2.0;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let what = match sim.measured {
            Some(_) => "measured map".to_string(),
            None => format!("seed {}", sim.seed),
        };
        let title = format!(
            "{}: simulation (points, {n}×{n}, {what}) and theory (lines)",
            state.name,
            n = sim.contact.n()
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(70)
            .build_cartesian_2d((1e-3f64..1.0).log_scale(), (floor..1.0f64).log_scale())
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("p̄/H (H = hardness in use)")
            .y_desc("A/A0")
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .map_err(err)?;
        type Pick = fn(&rough_model::Areas) -> f64;
        type PickSim = fn(&rough_contact::LoadResult) -> f64;
        let series: [(&str, RGBColor, Pick, PickSim); 3] = [
            ("total", TOTAL, |a| a.total, |r| r.area),
            ("elastic", ELASTIC, |a| a.elastic, |r| r.elastic_area),
            ("plastic", PLASTIC, |a| a.plastic, |r| r.plastic_area),
        ];
        // What is drawn, in pixels: the legend goes where none of it is.
        let mut drawn: Vec<Vec<(i32, i32)>> = Vec::new();
        for (name, colour, pick, pick_sim) in series {
            let line: Vec<(f64, f64)> = theory
                .iter()
                .map(|(x, a)| (*x, pick(a)))
                .filter(|&(_, y)| y > floor)
                .collect();
            drawn.push(line.iter().map(|p| chart.backend_coord(p)).collect());
            chart
                .draw_series(LineSeries::new(line, colour.stroke_width(2)))
                .map_err(err)?
                .label(format!("{name}: theory"))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], colour));
            let pts: Vec<(f64, f64)> = rows
                .iter()
                .map(|r| (r.p_over_h, pick_sim(&r.sim)))
                .filter(|&(_, y)| y > floor)
                .collect();
            drawn.extend(pts.iter().map(|p| vec![chart.backend_coord(p)]));
            chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, 4, colour.filled())))
                .map_err(err)?
                .label(format!("{name}: simulation"))
                .legend(move |(x, y)| Circle::new((x + 9, y), 4, colour.filled()));
        }
        let corner = free_corner(&chart, &drawn, (170, 110));
        chart
            .configure_series_labels()
            .position(corner)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// Where a legend of `size` pixels goes: the first corner of the plot (upper
/// left, upper right, lower right, lower left) where no line or point of
/// `drawn` (pixels) comes within 6 px of it, else the one with the fewest.
fn free_corner<DB: DrawingBackend, CT: CoordTranslate>(
    chart: &ChartContext<DB, CT>,
    drawn: &[Vec<(i32, i32)>],
    (w, h): (i32, i32),
) -> SeriesLabelPosition {
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let (aw, ah) = (xr.end - xr.start, yr.end - yr.start);
    let corners = [
        (5, 5),
        (aw - w - 5, 5),
        (aw - w - 5, ah - h - 5),
        (5, ah - h - 5),
    ];
    // Pixels each line passes (its segments sampled every pixel).
    let pixels: Vec<(i32, i32)> = drawn
        .iter()
        .flat_map(|l| {
            let one = (l.len() == 1).then(|| l[0]);
            let segs = l.windows(2).flat_map(|s| {
                let ((x0, y0), (x1, y1)) = (s[0], s[1]);
                let n = (x1 - x0).abs().max((y1 - y0).abs()).clamp(1, 10_000);
                (0..=n).map(move |k| (x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n))
            });
            one.into_iter().chain(segs)
        })
        .collect();
    let hits = |(x, y): (i32, i32)| {
        let (x0, y0) = (xr.start + x - 6, yr.start + y - 6);
        let (x1, y1) = (xr.start + x + w + 6, yr.start + y + h + 6);
        pixels
            .iter()
            .filter(|&&(px, py)| px >= x0 && px <= x1 && py >= y0 && py <= y1)
            .count()
    };
    let best = corners
        .into_iter()
        .min_by_key(|&c| hits(c))
        .unwrap_or((5, 5));
    SeriesLabelPosition::Coordinate(best.0, best.1)
}

/// Plastic share of the contact area against ζ at p̄/H = [`SWEEP_LOAD`].
pub fn sweep(out: &mut impl Write, state: &State, seed: u64) -> anyhow::Result<()> {
    let (_, rows) = sweep_rows(state, seed)?;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let what = match state.is_measured() {
            true => "measured map".to_string(),
            false => format!("seed {seed}"),
        };
        let title = format!(
            "{}: plastic share of the contact area at p̄/H = {SWEEP_LOAD}, {what}",
            state.name
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(60)
            .build_cartesian_2d((1f64..128.0).log_scale(), 0f64..1.0)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("ζ = q1/q0")
            .y_desc("A_pl/A")
            .draw()
            .map_err(err)?;
        let line: Vec<(f64, f64)> = rows
            .iter()
            .map(|r| (r.zeta, r.theory_share()))
            .filter(|p| p.1.is_finite())
            .collect();
        chart
            .draw_series(LineSeries::new(line, PLASTIC.stroke_width(2)))
            .map_err(err)?
            .label("theory")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], PLASTIC));
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .map(|r| (r.zeta, r.share()))
            .filter(|p| p.1.is_finite())
            .collect();
        chart
            .draw_series(pts.into_iter().map(|p| Circle::new(p, 5, PLASTIC.filled())))
            .map_err(err)?
            .label("simulation")
            .legend(|(x, y)| Circle::new((x + 9, y), 5, PLASTIC.filled()));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}
