//! The contact views as SVG: the simulation's points beside the theory's
//! curves, in the paper's colours (elastic black, plastic blue, total red).

use std::io::Write;

use plotters::prelude::*;
use rough_model::areas;

use super::{load_rows, sweep_rows, Spec, Stat, SWEEP_LOAD};
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

/// Vertical bars from mean − sd to mean + sd (clipped at `floor`), where
/// there is a spread.
fn bars(points: &[(f64, Stat)], floor: f64) -> Vec<Vec<(f64, f64)>> {
    points
        .iter()
        .filter(|(_, s)| s.sd.is_finite() && s.sd > 0.0 && s.mean > floor)
        .map(|(x, s)| vec![(*x, (s.mean - s.sd).max(floor)), (*x, s.mean + s.sd)])
        .collect()
}

/// A/A0 against p̄/H (both log): the simulation's means over the seeds as
/// points with bars of ± one standard deviation, the theory as curves.
pub fn contact(
    out: &mut impl Write,
    state: &State,
    points: usize,
    spec: &Spec,
) -> anyhow::Result<()> {
    let (sim, rows, _) = load_rows(state, points, spec)?;
    let theory: Vec<(f64, rough_model::Areas)> = log_points(1e-3, 1.0, 120)
        .into_iter()
        .filter_map(|x| areas(sim.model, sim.psi, x).ok().map(|a| (x, a)))
        .collect();
    let floor = rows
        .iter()
        .flat_map(|r| [r.area.mean, r.elastic.mean, r.plastic.mean])
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
            None if spec.seeds.count > 1 => {
                format!("mean ± sd over {}", spec.seeds.words())
            }
            None => spec.seeds.words(),
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
        type PickSim = fn(&super::LoadRow) -> Stat;
        let series: [(&str, RGBColor, Pick, PickSim); 3] = [
            ("total", TOTAL, |a| a.total, |r| r.area),
            ("elastic", ELASTIC, |a| a.elastic, |r| r.elastic),
            ("plastic", PLASTIC, |a| a.plastic, |r| r.plastic),
        ];
        for (name, colour, pick, pick_sim) in series {
            let line: Vec<(f64, f64)> = theory
                .iter()
                .map(|(x, a)| (*x, pick(a)))
                .filter(|&(_, y)| y > floor)
                .collect();
            chart
                .draw_series(LineSeries::new(line, colour.stroke_width(2)))
                .map_err(err)?
                .label(format!("{name}: theory"))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], colour));
            let stats: Vec<(f64, Stat)> = rows.iter().map(|r| (r.p_over_h, pick_sim(r))).collect();
            for bar in bars(&stats, floor) {
                chart
                    .draw_series(LineSeries::new(bar, colour.stroke_width(1)))
                    .map_err(err)?;
            }
            let pts: Vec<(f64, f64)> = stats
                .iter()
                .map(|(x, s)| (*x, s.mean))
                .filter(|&(_, y)| y > floor)
                .collect();
            chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, 4, colour.filled())))
                .map_err(err)?
                .label(format!("{name}: simulation"))
                .legend(move |(x, y)| Circle::new((x + 9, y), 4, colour.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
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

/// Plastic share of the contact area against ζ at p̄/H = [`SWEEP_LOAD`]:
/// the mean over the seeds with bars of ± one standard deviation.
pub fn sweep(out: &mut impl Write, state: &State, spec: &Spec) -> anyhow::Result<()> {
    let (_, rows, _) = sweep_rows(state, spec)?;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let what = match state.is_measured() {
            true => "measured map".to_string(),
            false if spec.seeds.count > 1 => format!("mean ± sd over {}", spec.seeds.words()),
            false => spec.seeds.words(),
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
        let stats: Vec<(f64, Stat)> = rows.iter().map(|r| (r.zeta, r.share())).collect();
        for bar in bars(&stats, 0.0) {
            chart
                .draw_series(LineSeries::new(bar, PLASTIC.stroke_width(1)))
                .map_err(err)?;
        }
        let pts: Vec<(f64, f64)> = stats
            .iter()
            .map(|(z, s)| (*z, s.mean))
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
