//! Theory against simulation: the scene's surface solved by the boundary-
//! element contact of `rough-contact` (elastic–perfectly-plastic by pressure
//! saturation at the hardness in use) beside the theory's finite-load areas.
//!
//! The power-law scene becomes a periodic Gaussian surface on a cell of K
//! longest wavelengths, L = K·2π/q0 ([`Sampling`]; the spectrum flat below
//! q0 when K > 1), wavevectors up to ζq0, random phases and amplitudes from
//! a seed, rescaled to the scene's rms slope √(2 m2) (the quantity the
//! index is made of, under the scene's moments), on N × N nodes with N the
//! power of two giving at least eight nodes per shortest wavelength (or a
//! side given outright), N ≤ [`MAX_GRID`] and the machine's memory. Over
//! several seeds the views give means and sample standard deviations
//! ([`Seeds`], [`Stat`]). Pressures are in units of E*, so the cap is
//! H_use/E*.

pub mod convergence;
pub mod engine;
pub mod ensemble;
pub mod local;
pub mod measured;
mod progress;
mod rows;
pub mod sampling;
pub mod scene;

use std::io::Write;

use rough_contact::{Contact, LoadResult, Options};
use rough_model::{areas, Areas};
use scene::SceneKey;

pub use ensemble::{Seeds, Stat};
pub use rows::{load_rows, sweep_rows, LoadRow, SweepRow};
pub use sampling::{Grid, Hardness, Sampling, MAX_GRID, MIN_GRID};

use crate::physical::csv_number;
use crate::scene::State;

/// The seed of the random phases when none is given.
pub const DEFAULT_SEED: u64 = 1;
/// Loads of the contact view: p̄/H from 1e-3 to 1, four per decade.
pub const DEFAULT_LOADS: usize = 13;
/// The load of the ζ sweep, p̄/H.
pub const SWEEP_LOAD: f64 = 0.01;
/// Most seeds one export averages over.
pub const MAX_SEEDS: u32 = 1000;
/// Most loads the contact view solves in one export.
pub const MAX_LOADS: usize = 64;

/// The contact view's CSV header: means over the seeds, then the spread.
pub const CONTACT_HEADER: &str = "p_over_h,area,elastic_area,plastic_area,mean_gap,iterations,\
residual,theory_area,theory_elastic_area,theory_plastic_area,area_sd,elastic_area_sd,\
plastic_area_sd,seeds";
/// The ζ sweep's CSV header.
pub const SWEEP_HEADER: &str = "zeta,p_over_h,plastic_share,theory_plastic_share,area,\
theory_area,grid,iterations,residual,plastic_share_sd,area_sd,seeds,hardness_over_e,\
theory_hardness_over_e,patches,patch_radius";

/// What is simulated of a scene: how its surface is sampled and over which
/// seeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Spec {
    pub sampling: Sampling,
    pub seeds: Seeds,
}

impl Spec {
    /// The default sampling, one seed.
    pub fn one(seed: u64) -> Spec {
        Spec {
            sampling: Sampling::default(),
            seeds: Seeds::one(seed),
        }
    }
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
    /// The cell in longest wavelengths (1 for a measured map).
    pub cell: u32,
    /// rms slope of the solved surface (the scene's √(2 m2)).
    pub rms_slope: f64,
    /// A measured map: how it is cropped, sampled and bounded.
    pub measured: Option<String>,
    /// A hardness per asperity: its law, and what the last solve found.
    pub local: Option<local::Law>,
    pub last_local: Option<local::Local>,
}

impl Simulation {
    /// The power-law scene of `state` with phases from `seed`, sampled as
    /// by default.
    pub fn of(state: &State, seed: u64) -> anyhow::Result<Simulation> {
        Simulation::with(state, seed, &Sampling::default())
    }

    /// [`Simulation::of`] sampled by `sampling`.
    pub fn with(state: &State, seed: u64, sampling: &Sampling) -> anyhow::Result<Simulation> {
        let key = SceneKey::with(state, seed, sampling)?;
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
            cell: key.cell,
            rms_slope: key.rms_slope(),
            local: key.local(),
            last_local: None,
        })
    }

    /// Solve at p̄/H = `p_over_h`; the theory's areas at the same load.
    pub fn solve(
        &mut self,
        p_over_h: f64,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> anyhow::Result<(LoadResult, Areas)> {
        let p_mean = p_over_h * self.hardness;
        let r = match &self.local {
            Some(law) => {
                let (r, _, info) = local::solve(
                    &mut self.contact,
                    p_mean,
                    law,
                    &Options::default(),
                    progress,
                )
                .map_err(|e| match local::Beyond::of(&e) {
                    Some(b) => anyhow::Error::new(b),
                    None => anyhow::Error::new(e),
                })?;
                self.last_local = Some(info);
                r
            }
            None => self.contact.solve_with_progress(
                p_mean,
                self.hardness,
                &Options::default(),
                progress,
            )?,
        };
        let t = areas(self.model, self.psi, p_over_h)
            .map_err(|e| anyhow::anyhow!("theory at p̄/H = {p_over_h}: {e}"))?;
        Ok((r, t))
    }
}

/// The side of the square `key` solves (m): the periodic cell of K
/// longest wavelengths of a power law, a measured map's solved square.
pub fn solved_side(state: &State, key: &SceneKey) -> anyhow::Result<f64> {
    let p = &state.params;
    Ok(match measured::heights_of(state)? {
        Some((_, h)) => measured::plan(&h, p.zeta() * p.q0())?.length,
        None => key.length(),
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

/// ζ values of the sweep: powers of two from 1 to 128.
pub fn sweep_zetas() -> Vec<f64> {
    (0..=7).map(|k| 2f64.powi(k)).collect()
}

/// The `#` lines of a contact CSV: `scene` (the scene as every view's CSV
/// has it, made by export), then what the simulation adds: how the surface
/// is solved and what it matches, the hardness, the theory and the units.
fn comments(
    out: &mut impl Write,
    scene: &[String],
    state: &State,
    sim: &Simulation,
    spec: &Spec,
    h_rms: &Stat,
) -> anyhow::Result<()> {
    let p = &state.params;
    // A sweep's first point solves another ζ than the scene's.
    let p = &p.with(rough_model::Axis::Zeta, sim.zeta).unwrap_or(*p);
    for l in scene {
        writeln!(out, "# {l}")?;
    }
    if let Some(m) = &sim.measured {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), {m}, wavevectors \
             q ≤ zeta q0 = {} 1/m kept",
            csv_number::format(p.zeta() * p.q0())
        )?;
    } else {
        let n = sim.contact.n();
        let s = &spec.sampling;
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), periodic {n} × {n} grid \
             of side {} × 2π/q0 (cell: {}{}), {} nodes per shortest wavelength, power-law \
             Gaussian surface, {}{}",
            sim.cell,
            s.cell_words(),
            if sim.cell > 1 {
                ", the spectrum flat below q0"
            } else {
                ""
            },
            csv_number::format(s.per_wavelength(n, p.zeta())),
            spec.seeds.words(),
            if spec.seeds.count > 1 {
                format!(
                    " (columns: means over {} realisations; *_sd: their sample standard \
                     deviation)",
                    spec.seeds.count
                )
            } else {
                " (one realisation: the *_sd columns are NaN)".into()
            }
        )?;
        writeln!(
            out,
            "# surface = matched to the scene's rms slope sqrt(2 m2) = {} ({}); its own h_rms \
             {} m{} against the scene's {} m",
            csv_number::format(sim.rms_slope),
            match state.moments {
                rough_model::Moments::Asymptotic => {
                    "the paper's asymptotic moments, eq. 10; --moments truncated matches the \
                     truncated spectrum's"
                }
                rough_model::Moments::Truncated => "the truncated spectrum's moments",
            },
            csv_number::format(h_rms.mean),
            if h_rms.n > 1 {
                format!(
                    " (mean over the seeds, sd {})",
                    csv_number::format(h_rms.sd)
                )
            } else {
                String::new()
            },
            csv_number::format(p.h_rms()),
        )?;
    }
    if let Some(law) = &sim.local {
        writeln!(
            out,
            "# hardness per asperity = each node capped at H0 sqrt(1 + R*/(1.2 R)) with R the \
             curvature radius of its asperity, the paraboloid fitted to the surface under its \
             patch (H0/E* = {}, \
             R* = {} m): the asperities are the patches of the purely elastic contact at the \
             same load, a node outside them takes its nearest patch's, a patch spanning the cell \
             H0; hardness_in_use_over_e, the loads' unit, is the theory's H_y at R_s",
            csv_number::format(law.h0),
            csv_number::format(law.r_star)
        )?;
    }
    writeln!(
        out,
        "# hardness_in_use_over_e = {} ({}/E*, the pressure cap{}); rms_slope = {} (the \
         surface rescaled to the scene's sqrt(2 m2))",
        csv_number::format(sim.hardness),
        state.hardness_name(),
        if sim.local.is_some() {
            ", the loads' unit"
        } else {
            ""
        },
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
         contact conditions over h_rms (the largest over the seeds)"
    )?;
    Ok(())
}

pub(crate) fn push_row(buf: &mut String, fields: &[f64]) {
    for (k, v) in fields.iter().enumerate() {
        if k > 0 {
            buf.push(',');
        }
        csv_number::push(buf, *v);
    }
    buf.push('\n');
}

/// The contact view as CSV, `scene` its first `#` lines.
pub fn write_contact(
    out: &mut impl Write,
    state: &State,
    points: usize,
    spec: &Spec,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows, heights, beyond) = load_rows(state, points, spec)?;
    let mut buf = String::new();
    for r in &rows {
        push_row(
            &mut buf,
            &[
                r.p_over_h,
                r.area.mean,
                r.elastic.mean,
                r.plastic.mean,
                r.mean(|x| x.mean_gap),
                r.mean(|x| x.iterations as f64),
                r.residual(),
                r.theory.total,
                r.theory.elastic,
                r.theory.plastic,
                r.area.sd,
                r.elastic.sd,
                r.plastic.sd,
                r.runs.len() as f64,
            ],
        );
    }
    comments(out, scene, state, &sim, spec, &heights)?;
    for b in &beyond {
        writeln!(out, "# not solved: {b}")?;
    }
    writeln!(out, "{CONTACT_HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The ζ sweep as CSV, `scene` its first `#` lines.
pub fn write_contact_sweep(
    out: &mut impl Write,
    state: &State,
    spec: &Spec,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows, heights) = sweep_rows(state, spec)?;
    let mut buf = String::new();
    for r in &rows {
        let (share, area) = (r.share(), r.area());
        push_row(
            &mut buf,
            &[
                r.zeta,
                SWEEP_LOAD,
                share.mean,
                r.theory_share(),
                area.mean,
                r.theory.total,
                r.grid as f64,
                Stat::of(r.runs.iter().map(|x| x.iterations as f64)).mean,
                r.runs.iter().map(|x| x.residual).fold(0.0, f64::max),
                share.sd,
                area.sd,
                r.runs.len() as f64,
                Stat::of(r.hardness.iter().copied()).mean,
                r.theory_hardness,
                Stat::of(r.asperities.iter().map(|a| a.0 as f64)).mean,
                Stat::of(r.asperities.iter().map(|a| a.1)).mean,
            ],
        );
    }
    comments(out, scene, state, &sim, spec, &heights)?;
    if sim.local.is_some() {
        writeln!(
            out,
            "# hardness_over_e: the load-weighted mean cap of the solution (with a hardness per \
             asperity; theory_hardness_over_e: the theory's H_y at R_s); patches: the elastic \
             contact's, the asperities in contact, with their median curvature radius in m"
        )?;
    }
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
