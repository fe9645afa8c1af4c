//! `contact-convergence`: the scene's surface at one load on grids of 4, 8
//! and 16 nodes per shortest wavelength and cells of 1, 2 and 4 longest
//! wavelengths, over the seeds, so that a reader sees how the areas move
//! with the discretisation and with the cell.

use std::io::Write;

use anyhow::Context;

use super::{push_row, Grid, Sampling, Simulation, Spec, Stat};
use crate::physical::csv_number;
use crate::scene::State;

/// Nodes per shortest wavelength compared.
pub const PER_WAVELENGTH: [u32; 3] = [4, 8, 16];
/// Cells compared, in longest wavelengths.
pub const CELLS: [u32; 3] = [1, 2, 4];

/// The CSV header.
pub const HEADER: &str = "per_wavelength,cell,grid,area,area_sd,elastic_area,plastic_area,\
plastic_area_sd,plastic_share,plastic_share_sd,iterations,seeds,area_corrected,\
area_corrected_sd";

/// One (nodes per wavelength, cell) pair over the seeds; `None` where the
/// grid is beyond what the machine or the solver takes (the reason).
pub struct Point {
    pub per_wavelength: u32,
    pub cell: u32,
    pub result: Result<Solved, String>,
}

/// The areas of one pair.
pub struct Solved {
    pub grid: usize,
    pub area: Stat,
    /// The area with the grid's edge corrected (Yastrebov et al. 2017).
    pub corrected: Stat,
    pub elastic: Stat,
    pub plastic: Stat,
    pub share: Stat,
    pub iterations: Stat,
}

/// A solve's plastic share S_pl/S_tot; NaN without contact (left out of
/// a [`Stat`]).
pub fn share(r: &rough_contact::LoadResult) -> f64 {
    if r.area > 0.0 {
        r.plastic_area / r.area
    } else {
        f64::NAN
    }
}

/// The pairs of [`PER_WAVELENGTH`] × [`CELLS`] at p̄/H = `p_over_h`,
/// smallest grids first; `on_point` is told each as it is solved.
pub fn points(
    state: &State,
    spec: &Spec,
    p_over_h: f64,
    on_point: &mut dyn FnMut(&Point),
) -> anyhow::Result<Vec<Point>> {
    let mut pairs: Vec<(u32, u32)> = PER_WAVELENGTH
        .iter()
        .flat_map(|&k| CELLS.iter().map(move |&c| (k, c)))
        .collect();
    pairs.sort_by_key(|&(k, c)| k * c);
    let mut out = vec![];
    for (k, cell) in pairs {
        let sampling = Sampling {
            cell,
            grid: Grid::PerWavelength(k),
            ..spec.sampling
        };
        let result = match sampling.side(state.params.zeta()) {
            Err(e) => Err(format!("{e:#}")),
            Ok(grid) => {
                let mut runs = vec![];
                for seed in spec.seeds.iter() {
                    let mut sim = Simulation::with(state, seed, &sampling)?;
                    let (r, _) = sim.solve(p_over_h, &mut |_, _| true).with_context(|| {
                        format!("{k} nodes per wavelength, cell {cell}, seed {seed}")
                    })?;
                    runs.push(r);
                }
                Ok(Solved {
                    grid,
                    area: Stat::of(runs.iter().map(|r| r.area)),
                    corrected: Stat::of(runs.iter().map(|r| r.corrected_area())),
                    elastic: Stat::of(runs.iter().map(|r| r.elastic_area)),
                    plastic: Stat::of(runs.iter().map(|r| r.plastic_area)),
                    share: Stat::of(runs.iter().map(share)),
                    iterations: Stat::of(runs.iter().map(|r| r.iterations as f64)),
                })
            }
        };
        let p = Point {
            per_wavelength: k,
            cell,
            result,
        };
        on_point(&p);
        out.push(p);
    }
    Ok(out)
}

/// The convergence view as CSV.
pub fn write(
    out: &mut impl Write,
    state: &State,
    spec: &Spec,
    p_over_h: f64,
) -> anyhow::Result<()> {
    if state.is_measured() {
        anyhow::bail!(
            "--view contact-convergence compares synthesised surfaces on other grids and cells: \
             a measured map has its own"
        );
    }
    let points = points(state, spec, p_over_h, &mut |_| {})?;
    let mut buf = String::new();
    let mut skipped = vec![];
    for p in &points {
        match &p.result {
            Ok(s) => push_row(
                &mut buf,
                &[
                    p.per_wavelength as f64,
                    p.cell as f64,
                    s.grid as f64,
                    s.area.mean,
                    s.area.sd,
                    s.elastic.mean,
                    s.plastic.mean,
                    s.plastic.sd,
                    s.share.mean,
                    s.share.sd,
                    s.iterations.mean,
                    s.area.n as f64,
                    s.corrected.mean,
                    s.corrected.sd,
                ],
            ),
            Err(why) => skipped.push(format!(
                "{} per wavelength, cell {}: {why}",
                p.per_wavelength, p.cell
            )),
        }
    }
    writeln!(out, "# scene: {}", state.name)?;
    writeln!(
        out,
        "# convergence: the scene's surface at p_over_h = {} on {} nodes per shortest \
         wavelength and cells of {} longest wavelengths, {} (means and sample standard \
         deviations over the realisations), each grid the power of two giving as many nodes",
        csv_number::format(p_over_h),
        PER_WAVELENGTH.map(|k| k.to_string()).join(", "),
        CELLS.map(|k| k.to_string()).join(", "),
        spec.seeds.words()
    )?;
    for s in &skipped {
        writeln!(out, "# not solved: {s}")?;
    }
    writeln!(
        out,
        "# zeta = {}, hardness_in_use_over_e = {}; areas as fractions of A0; area_corrected: the \
         area less (pi - 1 + ln 2)/24 of a node per side of the contact's perimeter (Yastrebov, \
         Anciaux & Molinari 2017)",
        csv_number::format(state.params.zeta()),
        csv_number::format(
            state.params.h0_over_e()
                * state
                    .roughness()
                    .surface(&state.params, state.moments)
                    .indices
                    .hardness_in_use(state.size_effect)
        )
    )?;
    writeln!(out, "{HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}
