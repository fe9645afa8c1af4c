//! `contact-slopes`: the paper's own quantity simulated — the initial
//! slopes H_use·dA/dp̄/A0 (elastic, plastic, total) against ζ, beside the
//! theory's.
//!
//! The light-load limit of a grid is not p̄ → 0: there the contact is one
//! node, at the hardness however soft the surface. The slope is taken where
//! the contact is light but resolved: at each ζ the scene is solved at
//! [`LIGHT`] loads p̄/(E* h′) = 0.5, 1, 2, 4 and 8 × 10⁻³ (the same band of
//! contact areas, about 0.1 … 2 % of A0, at every ζ and hardness), and
//! each area A(x), x = p̄/H_use, is fitted by least squares with
//! A = s·x + c·x² through the origin over the four lightest loads: s is the
//! initial slope, the secant's curvature (c) taken off, s ≥ 0 (a plastic
//! area that starts at a threshold load has none). The same fit over
//! the four heaviest loads gives another s; their difference is the fit's
//! error (`*_fit_err`): what moving the window by a factor of two changes.
//! Each seed is fitted alone; the columns are the seeds' means and sample
//! standard deviations.

use std::io::Write;

use anyhow::Context;
use rough_contact::LoadResult;
use rough_model::{slopes, Axis, Slopes};

use super::rows::{check_seeds, hardness_ratio, sweep_states};
use super::{push_row, Grid, Sampling, Simulation, Spec, Stat};
use crate::physical::csv_number;
use crate::scene::State;

/// The light loads p̄/(E* h′) of the fit.
pub const LIGHT: [f64; 5] = [0.5e-3, 1e-3, 2e-3, 4e-3, 8e-3];
/// Loads each fit takes: the lightest, and (for its error) the heaviest.
const FIT: usize = 4;
/// The least grid side of a slope's solves (a power-law scene solved on
/// nodes per wavelength): light contacts need nodes.
pub const MIN_GRID: usize = 256;

/// The CSV header.
pub const HEADER: &str = "zeta,sim_elastic_slope,sim_elastic_slope_sd,sim_plastic_slope,\
sim_plastic_slope_sd,sim_total_slope,sim_total_slope_sd,theory_elastic_slope,\
theory_plastic_slope,theory_total_slope,seeds,sim_elastic_slope_fit_err,\
sim_plastic_slope_fit_err,sim_total_slope_fit_err,grid,p_over_h_lightest,p_over_h_heaviest";

/// One seed's solves at a ζ: the loads x = p̄/H_use and the results.
pub struct Run {
    pub seed: u64,
    pub x: Vec<f64>,
    pub results: Vec<LoadResult>,
}

impl Run {
    /// The initial slopes fitted over the lightest loads (elastic,
    /// plastic, total).
    pub fn slopes(&self) -> [f64; 3] {
        self.fit(0..FIT.min(self.x.len()))
    }

    /// The same fit over the heaviest loads.
    pub fn slopes_heavy(&self) -> [f64; 3] {
        self.fit(self.x.len().saturating_sub(FIT)..self.x.len())
    }

    fn fit(&self, range: std::ops::Range<usize>) -> [f64; 3] {
        let x = &self.x[range.clone()];
        let r = &self.results[range];
        let part = |f: fn(&LoadResult) -> f64| {
            let y: Vec<f64> = r.iter().map(f).collect();
            initial_slope(x, &y)
        };
        [
            part(|r| r.elastic_area),
            part(|r| r.plastic_area),
            part(|r| r.area),
        ]
    }
}

/// s of the least-squares fit y = s·x + c·x² through the origin with
/// s ≥ 0 (x scaled to its largest for the normal equations; one point:
/// y/x). A part that grows faster than linearly from nothing — a plastic
/// area that starts at a threshold load — has no initial slope: where the
/// unconstrained fit's s is negative the constrained one's is 0 (the least
/// squares are convex in (s, c): their least over s ≥ 0 lies on s = 0).
pub fn initial_slope(x: &[f64], y: &[f64]) -> f64 {
    unconstrained_slope(x, y).max(0.0)
}

fn unconstrained_slope(x: &[f64], y: &[f64]) -> f64 {
    let m = x.iter().cloned().fold(0.0, f64::max);
    if x.len() < 2 || m <= 0.0 {
        return x.first().zip(y.first()).map_or(f64::NAN, |(x, y)| y / x);
    }
    let (mut a, mut b, mut c, mut d, mut e) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (&xi, &yi) in x.iter().zip(y) {
        let t = xi / m;
        a += t * t;
        b += t * t * t;
        c += t * t * t * t;
        d += t * yi;
        e += t * t * yi;
    }
    let det = a * c - b * b;
    if det.abs() <= 1e-14 * a * c {
        return d / a / m;
    }
    (d * c - e * b) / det / m
}

/// One ζ of the slopes, over the seeds.
pub struct Row {
    pub zeta: f64,
    pub grid: usize,
    /// H_use/H0 at this ζ (the slopes' normalisation).
    pub ratio: f64,
    pub runs: Vec<Run>,
    pub theory: Slopes,
}

impl Row {
    /// The seeds' slopes (elastic, plastic, total): mean and sd.
    pub fn stats(&self) -> [Stat; 3] {
        let s: Vec<[f64; 3]> = self.runs.iter().map(Run::slopes).collect();
        [0, 1, 2].map(|k| Stat::of(s.iter().map(|v| v[k])))
    }

    /// The fit's error: |mean slope over the lightest loads − over the
    /// heaviest|.
    pub fn fit_error(&self) -> [f64; 3] {
        let (light, heavy) = (self.stats(), self.heavy_stats());
        [0, 1, 2].map(|k| (light[k].mean - heavy[k].mean).abs())
    }

    /// The seeds' slopes over the heaviest loads: mean and sd.
    pub fn heavy_stats(&self) -> [Stat; 3] {
        let s: Vec<[f64; 3]> = self.runs.iter().map(Run::slopes_heavy).collect();
        [0, 1, 2].map(|k| Stat::of(s.iter().map(|v| v[k])))
    }
}

/// The sampling a slope is solved on: at least [`MIN_GRID`] a side when
/// the grid follows the nodes per wavelength.
fn slope_sampling(sampling: &Sampling, zeta: f64) -> anyhow::Result<Sampling> {
    let n = sampling.side(zeta)?;
    Ok(match sampling.grid {
        Grid::PerWavelength(_) if n < MIN_GRID => Sampling {
            grid: Grid::Side(MIN_GRID),
            ..*sampling
        },
        _ => *sampling,
    })
}

/// The scene's initial slopes at ζ = 1, 2, …, 128 for each seed of `spec`;
/// the first ζ's simulation (for the parameter lines).
pub fn rows(state: &State, spec: &Spec) -> anyhow::Result<(Simulation, Vec<Row>)> {
    check_seeds(state, spec)?;
    let mut out = vec![];
    let mut first = None;
    for (zeta, s) in sweep_states(state)? {
        let ratio = hardness_ratio(&s);
        let sampling = if s.is_measured() {
            spec.sampling
        } else {
            slope_sampling(&spec.sampling, zeta)?
        };
        let psi = s
            .roughness()
            .surface(&s.params, s.moments)
            .indices
            .psi_in_use(s.size_effect);
        let mut runs = vec![];
        let mut grid = 0;
        for seed in spec.seeds.iter() {
            let mut sim = Simulation::with(&s, seed, &sampling)?;
            // p̄/H_use of p̄/(E* h′) = q.
            let x: Vec<f64> = LIGHT
                .iter()
                .map(|q| q * sim.rms_slope / sim.hardness)
                .collect();
            let mut results = vec![];
            for &xi in &x {
                let (r, _) = sim
                    .solve(xi, &mut |_, _| true)
                    .with_context(|| format!("contact at ζ = {zeta}, p̄/H = {xi}, seed {seed}"))?;
                results.push(r);
            }
            grid = sim.contact.n();
            runs.push(Run { seed, x, results });
            first.get_or_insert(sim);
        }
        out.push(Row {
            zeta,
            grid,
            ratio,
            runs,
            theory: slopes(s.model, psi),
        });
    }
    let first = first.ok_or_else(|| anyhow::anyhow!("no ζ to sweep"))?;
    Ok((first, out))
}

/// The slopes as CSV, `scene` its first `#` lines. A `part` (one seed of
/// a `--shard`) writes the heavy window's slopes, `*_heavy`, in place of
/// `*_fit_err`, which `roughtui merge` forms from them over the seeds.
pub fn write(
    out: &mut impl Write,
    state: &State,
    spec: &Spec,
    scene: &[String],
    part: bool,
) -> anyhow::Result<()> {
    let (sim, rows) = rows(state, spec)?;
    let mut buf = String::new();
    for r in &rows {
        let [el, pl, tot] = r.stats();
        let err = if part {
            r.heavy_stats().map(|s| s.mean)
        } else {
            r.fit_error()
        };
        let x = &r.runs[0].x;
        push_row(
            &mut buf,
            &[
                r.zeta,
                el.mean,
                el.sd,
                pl.mean,
                pl.sd,
                tot.mean,
                tot.sd,
                r.theory.elastic,
                r.theory.plastic,
                r.theory.total,
                r.runs.len() as f64,
                err[0],
                err[1],
                err[2],
                r.grid as f64,
                x[0],
                x[x.len() - 1],
            ],
        );
    }
    for l in scene {
        writeln!(out, "# {l}")?;
    }
    let s = &spec.sampling;
    let p = state
        .params
        .with(Axis::Zeta, sim.zeta)
        .unwrap_or(state.params);
    if let Some(m) = &sim.measured {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), {m}; each zeta its own \
             low-pass (the first zeta's here: q ≤ {} 1/m)",
            csv_number::format(p.zeta() * p.q0())
        )?;
    } else {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), periodic grid of side \
             {} × 2π/q0 (cell: {}), {}, at least {MIN_GRID} × {MIN_GRID} (column grid), \
             power-law Gaussian surface rescaled to each zeta's sqrt(2 m2), {} (columns: means \
             over the seeds, each seed fitted alone; *_sd: their sample standard deviation)",
            s.cell,
            s.cell_words(),
            match s.grid {
                Grid::PerWavelength(k) => format!("{k} nodes per shortest wavelength"),
                Grid::Side(n) => format!("{n} nodes a side"),
            },
            spec.seeds.words()
        )?;
    }
    writeln!(
        out,
        "# hardness = {}",
        super::csv::hardness_words(&sim, state)
    )?;
    writeln!(
        out,
        "# slopes = initial slopes {h}·dA/dp̄/A0 (normalised by the theory's hardness in use \
         {h}, H0 or H_y(R_s), at each zeta, as the slopes view's): the simulation's from its \
         light-load limit, each seed's areas at pbar/(E* h') = {} (p_over_h_lightest … \
         p_over_h_heaviest, pbar/{h}) fitted by A = s x + c x^2 through the origin over the {FIT} \
         lightest loads, s the slope; *_fit_err: |s over the {FIT} lightest − s over the {FIT} \
         heaviest| (the mean's change when the window moves by a factor of two)",
        LIGHT.map(csv_number::format).join(", "),
        h = state.hardness_name()
    )?;
    writeln!(
        out,
        "# theory = the {} model's initial slopes at the index in use ({}), the slopes view's \
         elastic, plastic and total at the same zeta; its split: {}",
        state.model.label(),
        if state.size_effect {
            "psi_star"
        } else {
            "psi_p"
        },
        super::csv::theory_split(state.model)
    )?;
    if part {
        writeln!(out, "{}", HEADER.replace("_fit_err", "_heavy"))?;
    } else {
        writeln!(out, "{HEADER}")?;
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fit_takes_the_curvature_off_and_keeps_the_slope_non_negative() {
        let x = [1.0, 2.0, 4.0, 8.0];
        // y = 3x − 0.1x²: s = 3 exactly.
        let y: Vec<f64> = x.iter().map(|x| 3.0 * x - 0.1 * x * x).collect();
        assert!((initial_slope(&x, &y) - 3.0).abs() < 1e-12);
        // y = 0.2x² (a threshold's curvature): no initial slope.
        let y: Vec<f64> = x.iter().map(|x| 0.2 * x * x - 0.05 * x).collect();
        assert_eq!(initial_slope(&x, &y), 0.0);
        assert_eq!(initial_slope(&[2.0], &[3.0]), 1.5);
    }
}
