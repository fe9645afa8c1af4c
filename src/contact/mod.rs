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
mod csv;
pub mod engine;
pub mod ensemble;
pub mod local;
pub mod measured;
mod progress;
mod rows;
pub mod sampling;
pub mod scene;
pub mod slopes;

use rough_contact::{Boundary, Contact, LoadResult, Options};
use rough_model::{areas, Areas};
use scene::SceneKey;

pub(crate) use csv::push_row;
pub use csv::{
    theory_split, write_contact, write_contact_sweep, CONTACT_HEADER, PERSSON_KAPPA, SWEEP_HEADER,
};
pub use ensemble::{Seeds, Stat};
pub use rows::{load_rows, sweep_rows, LoadRow, SweepRow};
pub use sampling::{Grid, Hardness, LoadScale, Sampling, MAX_GRID, MIN_GRID};

use crate::scene::State;

/// What the contact view's chart shows (the explorer draws it; the class
/// carries it to the students who follow).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Plot {
    /// The areas against the load.
    #[default]
    Load,
    /// `b`: the plastic share against ζ at the chosen load.
    Share,
    /// `i`: the initial slopes against ζ.
    Slopes,
}

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
/// A grid finer than this is started from its surface's answer on this
/// grid (sampled at every second, fourth … node), prolonged: 10–16 % fewer
/// iterations on the fine grid for a sixteenth of the work a coarse
/// iteration costs (docs/accuracy-speed.md).
pub const COARSE_GRID: usize = 256;

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
    /// The caps per node of the last solve with a hardness per node.
    pub last_caps: Option<Vec<f64>>,
    /// The same surface on a coarse grid, whose answer at each load the
    /// fine grid starts from (a power law's grid finer than
    /// [`COARSE_GRID`], a hardness per asperity aside: its solve starts
    /// from the elastic one).
    coarse: Option<Box<Simulation>>,
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
        let mut sim = Simulation::of_key(state, seed, &key, key.build()?)?;
        let asperity = key.local.is_some_and(|l| l.0 == local::Radius::Asperity);
        if let (Some(c), false) = (key.coarser(COARSE_GRID), asperity) {
            // The fine grid's heights at every second, fourth … node.
            let (mut h, mut side) = (sim.contact.heights().to_vec(), key.n);
            while side > c.side() {
                h = rough_contact::restrict(&h, side);
                side /= 2;
            }
            let contact = Contact::new(h, side, key.length(), 1.0, Boundary::Periodic)?;
            sim.coarse = Some(Box::new(Simulation::of_key(state, seed, &c, contact)?));
        }
        Ok(sim)
    }

    /// The simulation of `key` (a scene of `state`) on `contact`, without
    /// a coarse start.
    fn of_key(
        state: &State,
        seed: u64,
        key: &SceneKey,
        contact: Contact,
    ) -> anyhow::Result<Simulation> {
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
            contact,
            hardness: key.hardness(),
            psi: ix.psi_in_use(state.size_effect),
            model: state.model,
            zeta: key.zeta(),
            seed,
            cell: key.cell,
            rms_slope: key.rms_slope(),
            local: key.local(),
            last_local: None,
            last_caps: None,
            coarse: None,
        })
    }

    /// Solve at p̄/H = `p_over_h`; the theory's areas at the same load.
    pub fn solve(
        &mut self,
        p_over_h: f64,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> anyhow::Result<(LoadResult, Areas)> {
        let p_mean = p_over_h * self.hardness;
        if let Some(c) = &mut self.coarse {
            // The same load on the coarse grid first, its pressure the fine
            // grid's start (a failure there leaves the usual start).
            if c.solve(p_over_h, &mut |_, _| true).is_ok() {
                let mut p = c.contact.pressure().to_vec();
                let mut side = c.contact.n();
                while side < self.contact.n() {
                    p = rough_contact::prolong(&p, side);
                    side *= 2;
                }
                self.contact.start_from(&p)?;
            }
        }
        let r = match &self.local {
            Some(law) => {
                let (r, caps, info) = local::solve(
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
                self.last_caps = Some(caps);
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
