//! Theory against simulation: the scene's surface solved by the boundary-
//! element contact of `rough-contact` (elastic–perfectly-plastic by pressure
//! saturation at the hardness in use) beside the theory's finite-load areas.
//!
//! The power-law scene becomes a periodic Gaussian surface on one period
//! L = 2π/q0, wavevectors q0…ζq0, random phases from a seed, rescaled to
//! the scene's rms slope √(2 m2) (the quantity the index is made of), on
//! N × N nodes with N the power of two ≥ 8ζ (at least eight nodes per
//! shortest wavelength), N ≤ [`MAX_GRID`]. Pressures are in units of E*,
//! so the cap is H_use/E*.

pub mod engine;
pub mod measured;
pub mod scene;

use std::io::Write;

use anyhow::{bail, Context};
use rough_contact::{Contact, LoadResult, Options};
use rough_model::{areas, Areas};
use scene::SceneKey;

use crate::physical::csv_number;
use crate::scene::State;

/// Largest grid side the scene solves (ζ ≤ 128).
pub const MAX_GRID: usize = 1024;
/// Smallest grid side (a ζ = 1 surface still gets a real grid).
pub const MIN_GRID: usize = 32;
/// The seed of the random phases when none is given.
pub const DEFAULT_SEED: u64 = 1;
/// Loads of the contact view: p̄/H from 1e-3 to 1, four per decade.
pub const DEFAULT_LOADS: usize = 13;
/// The load of the ζ sweep, p̄/H.
pub const SWEEP_LOAD: f64 = 0.01;

/// The contact view's CSV header.
pub const CONTACT_HEADER: &str = "p_over_h,area,elastic_area,plastic_area,mean_gap,iterations,\
residual,theory_area,theory_elastic_area,theory_plastic_area";
/// The ζ sweep's CSV header.
pub const SWEEP_HEADER: &str = "zeta,p_over_h,plastic_share,theory_plastic_share,area,\
theory_area,grid,iterations,residual";

/// The grid side for magnification `zeta`: 8 nodes per shortest wavelength.
pub fn grid_for(zeta: f64) -> anyhow::Result<usize> {
    let need = (8.0 * zeta).ceil();
    if !need.is_finite() || need > MAX_GRID as f64 {
        bail!(
            "ζ = {zeta} needs a grid of at least {need} nodes a side (8 per shortest \
             wavelength); the contact simulation solves up to {MAX_GRID} (ζ ≤ {})",
            MAX_GRID / 8
        );
    }
    Ok((need as usize).next_power_of_two().max(MIN_GRID))
}

/// One scene ready to be loaded.
pub struct Simulation {
    pub contact: Contact,
    /// H_use/E*, the pressure cap.
    pub hardness: f64,
    /// The index in use (Ψ* or Ψ_P), for the theory.
    pub psi: rough_model::Dd,
    pub model: rough_model::Model,
    pub zeta: f64,
    pub seed: u64,
    /// rms slope of the solved surface (the scene's √(2 m2)).
    pub rms_slope: f64,
    /// A measured map: how it is cropped, sampled and bounded.
    pub measured: Option<String>,
}

impl Simulation {
    /// The power-law scene of `state` with phases from `seed`.
    pub fn of(state: &State, seed: u64) -> anyhow::Result<Simulation> {
        let key = SceneKey::of(state, seed)?;
        let ix = state
            .roughness()
            .surface(&state.params, state.moments)
            .indices;
        let measured = match measured::heights_of(state)? {
            Some((_, h)) => {
                let p = &state.params;
                Some(measured::describe(
                    &h,
                    &measured::plan(&h, p.zeta() * p.q0())?,
                ))
            }
            None => None,
        };
        Ok(Simulation {
            measured,
            contact: key.build()?,
            hardness: key.hardness(),
            psi: ix.psi_in_use(state.size_effect),
            model: state.model,
            zeta: key.zeta(),
            seed,
            rms_slope: key.rms_slope(),
        })
    }

    /// Solve at p̄/H = `p_over_h`; the theory's areas at the same load.
    pub fn solve(
        &mut self,
        p_over_h: f64,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> anyhow::Result<(LoadResult, Areas)> {
        let r = self.contact.solve_with_progress(
            p_over_h * self.hardness,
            self.hardness,
            &Options::default(),
            progress,
        )?;
        let t = areas(self.model, self.psi, p_over_h)
            .map_err(|e| anyhow::anyhow!("theory at p̄/H = {p_over_h}: {e}"))?;
        Ok((r, t))
    }
}

/// The side of the square the scene's simulation solves (m): the periodic
/// cell 2π/q0 of a power law, a measured map's solved square.
pub fn solved_side(state: &State) -> anyhow::Result<f64> {
    let p = &state.params;
    Ok(match measured::heights_of(state)? {
        Some((_, h)) => measured::plan(&h, p.zeta() * p.q0())?.length,
        None => std::f64::consts::TAU / p.q0(),
    })
}

/// `points` loads p̄/H, log-spaced from 1e-3 to 1.
pub fn loads(points: usize) -> Vec<f64> {
    let k = points.max(2) - 1;
    (0..=k)
        .map(|i| {
            if i == k {
                1.0
            } else {
                10f64.powf(-3.0 + 3.0 * i as f64 / k as f64)
            }
        })
        .collect()
}

/// ζ values of the sweep: powers of two from 1 to what the grid allows.
pub fn sweep_zetas() -> Vec<f64> {
    (0..=7).map(|k| 2f64.powi(k)).collect()
}

/// The `#` lines of a contact CSV: `scene` (the scene as every view's CSV
/// has it, made by export), then what the simulation adds.
fn comments(
    out: &mut impl Write,
    scene: &[String],
    state: &State,
    sim: &Simulation,
) -> anyhow::Result<()> {
    for l in scene {
        writeln!(out, "# {l}")?;
    }
    let p = &state.params;
    // A sweep's first point solves another ζ than the scene's.
    let p = &p.with(rough_model::Axis::Zeta, sim.zeta).unwrap_or(*p);
    if let Some(m) = &sim.measured {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), {m}, wavevectors \
             q ≤ zeta q0 = {} 1/m kept",
            csv_number::format(p.zeta() * p.q0())
        )?;
    } else {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), periodic {n} × {n} grid \
             of side 2π/q0, power-law Gaussian surface, seed {}",
            sim.seed,
            n = sim.contact.n()
        )?;
    }
    writeln!(
        out,
        "# hardness_in_use_over_e = {} ({}/E*, the pressure cap); rms_slope = {} (the \
         surface rescaled to the scene's sqrt(2 m2))",
        csv_number::format(sim.hardness),
        state.hardness_name(),
        csv_number::format(sim.rms_slope)
    )?;
    writeln!(
        out,
        "# theory = the {} model's finite-load areas at the index in use {} = {}",
        state.model.label(),
        if state.size_effect {
            "psi_star"
        } else {
            "psi_p"
        },
        csv_number::format(sim.psi.to_f64())
    )?;
    writeln!(
        out,
        "# units: areas as fractions of A0, mean_gap in m; residual: rms violation of the \
         contact conditions over h_rms"
    )?;
    Ok(())
}

fn push_row(buf: &mut String, fields: &[f64]) {
    for (k, v) in fields.iter().enumerate() {
        if k > 0 {
            buf.push(',');
        }
        csv_number::push(buf, *v);
    }
    buf.push('\n');
}

/// One load of the contact view.
pub struct LoadRow {
    pub p_over_h: f64,
    pub sim: LoadResult,
    pub theory: Areas,
}

/// The scene at `points` loads from 1e-3 H to H.
pub fn load_rows(
    state: &State,
    points: usize,
    seed: u64,
) -> anyhow::Result<(Simulation, Vec<LoadRow>)> {
    let mut sim = Simulation::of(state, seed)?;
    let mut rows = vec![];
    for p_over_h in loads(points) {
        let (r, t) = sim
            .solve(p_over_h, &mut |_, _| true)
            .with_context(|| format!("contact at p̄/H = {p_over_h}"))?;
        rows.push(LoadRow {
            p_over_h,
            sim: r,
            theory: t,
        });
    }
    Ok((sim, rows))
}

/// One magnification of the ζ sweep.
pub struct SweepRow {
    pub zeta: f64,
    pub grid: usize,
    pub sim: LoadResult,
    pub theory: Areas,
}

impl SweepRow {
    /// Plastic share of the simulated contact area (NaN without contact).
    pub fn share(&self) -> f64 {
        share(self.sim.plastic_area, self.sim.area)
    }
    /// The theory's plastic share at the same load.
    pub fn theory_share(&self) -> f64 {
        share(self.theory.plastic, self.theory.total)
    }
}

fn share(plastic: f64, total: f64) -> f64 {
    if total > 0.0 {
        plastic / total
    } else {
        f64::NAN
    }
}

/// The scene at ζ = 1, 2, …, 128 and p̄/H = [`SWEEP_LOAD`]; the first
/// point's simulation (for the parameter lines).
pub fn sweep_rows(state: &State, seed: u64) -> anyhow::Result<(Simulation, Vec<SweepRow>)> {
    let mut rows = vec![];
    let mut first = None;
    // A measured map's ζ runs from the first that keeps a mode of its
    // solved square to its data's largest.
    let zeta_max = state.roughness().zeta_max() * (1.0 + 1e-12);
    let zeta_min = match measured::heights_of(state)? {
        Some((_, h)) => measured::lowest_zeta(&h) * (1.0 - 1e-9),
        None => 0.0,
    };
    let zetas = sweep_zetas().into_iter();
    for zeta in zetas.filter(|z| (zeta_min..=zeta_max).contains(z)) {
        let mut s = state.clone();
        s.params = s
            .params
            .with(rough_model::Axis::Zeta, zeta)
            .map_err(|e| anyhow::anyhow!("ζ = {zeta}: {e}"))?;
        let mut sim = Simulation::of(&s, seed)?;
        let (r, t) = sim
            .solve(SWEEP_LOAD, &mut |_, _| true)
            .with_context(|| format!("contact at ζ = {zeta}"))?;
        rows.push(SweepRow {
            zeta,
            grid: sim.contact.n(),
            sim: r,
            theory: t,
        });
        first.get_or_insert(sim);
    }
    let first = first.ok_or_else(|| anyhow::anyhow!("no ζ to sweep"))?;
    Ok((first, rows))
}

/// The contact view as CSV, `scene` its first `#` lines.
pub fn write_contact(
    out: &mut impl Write,
    state: &State,
    points: usize,
    seed: u64,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows) = load_rows(state, points, seed)?;
    let mut buf = String::new();
    for r in &rows {
        push_row(
            &mut buf,
            &[
                r.p_over_h,
                r.sim.area,
                r.sim.elastic_area,
                r.sim.plastic_area,
                r.sim.mean_gap,
                r.sim.iterations as f64,
                r.sim.residual,
                r.theory.total,
                r.theory.elastic,
                r.theory.plastic,
            ],
        );
    }
    comments(out, scene, state, &sim)?;
    writeln!(out, "{CONTACT_HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The ζ sweep as CSV, `scene` its first `#` lines.
pub fn write_contact_sweep(
    out: &mut impl Write,
    state: &State,
    seed: u64,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows) = sweep_rows(state, seed)?;
    let mut buf = String::new();
    for r in &rows {
        push_row(
            &mut buf,
            &[
                r.zeta,
                SWEEP_LOAD,
                r.share(),
                r.theory_share(),
                r.sim.area,
                r.theory.total,
                r.grid as f64,
                r.sim.iterations as f64,
                r.sim.residual,
            ],
        );
    }
    comments(out, scene, state, &sim)?;
    writeln!(
        out,
        "# the simulation and theory lines above are the first zeta's; each zeta solves its own \
         grid (column grid) and hardness"
    )?;
    writeln!(out, "{SWEEP_HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// Most loads the contact view solves in one export.
pub const MAX_LOADS: usize = 64;
