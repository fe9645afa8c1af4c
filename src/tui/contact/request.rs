//! What the contact view asks the engine for, plot by plot, and the
//! theory's curves beside it: the thirteen loads (the load plot), the ζ
//! sweep at the chosen load for each set of caps (`b`), the light loads of
//! the initial slopes at each ζ (`i`).

use rough_model::{areas, psi_in_use, slopes, Axis};

use super::{load_value, sweep_zetas, ContactPane, Plot, Request, Theory, LOADS, THEORY_POINTS};
use crate::contact::engine::Task;
use crate::contact::scene::SceneKey;
use crate::contact::slopes::{LIGHT, MIN_GRID};
use crate::contact::{Grid, Hardness, Sampling};
use crate::scene::State;

/// One set of points of `b`'s plot: the size effect off (H0) or on, and
/// where its hardness applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Set {
    pub size_effect: bool,
    pub hardness: Hardness,
}

/// `b`'s sets: the bulk's one cap H0 (size effect off), the theory's one
/// cap H_y(R_s), and with `A` a per-node hardness beside them.
pub fn share_sets(hardness: Hardness) -> Vec<Set> {
    let mut sets = vec![
        Set {
            size_effect: false,
            hardness: Hardness::Global,
        },
        Set {
            size_effect: true,
            hardness: Hardness::Global,
        },
    ];
    if hardness != Hardness::Global {
        sets.push(Set {
            size_effect: true,
            hardness,
        });
    }
    sets
}

/// The sampling of an initial slope's solves at `zeta`: at least
/// [`MIN_GRID`] a side where the grid follows the nodes per wavelength (as
/// `export --view contact-slopes`).
pub fn slope_sampling(sampling: &Sampling, zeta: f64) -> Option<Sampling> {
    let n = sampling.side(zeta).ok()?;
    Some(match sampling.grid {
        Grid::PerWavelength(_) if n < MIN_GRID => Sampling {
            grid: Grid::Side(MIN_GRID),
            ..*sampling
        },
        _ => *sampling,
    })
}

/// H_use/H0 of `state` with or without the size effect.
fn ratio(state: &State, size_effect: bool) -> f64 {
    state
        .roughness()
        .surface(&state.params, state.moments)
        .indices
        .hardness_in_use(size_effect)
}

impl ContactPane {
    /// The ζ of the sweeps the scene can solve (a measured map: those it
    /// resolves); the reason where there is none.
    fn solvable_zetas(&mut self, state: &State, sampling: &Sampling) -> Vec<f64> {
        let zeta_max = state.roughness().zeta_max() * (1.0 + 1e-12);
        let mut keys = vec![];
        self.why_not = None;
        for z in sweep_zetas(&self.sampling)
            .into_iter()
            .filter(|z| *z <= zeta_max)
        {
            let mut s = state.clone();
            let Ok(p) = s.params.with(Axis::Zeta, z) else {
                continue;
            };
            s.params = p;
            match SceneKey::with(&s, self.seed, sampling) {
                Ok(_) => keys.push(z),
                Err(e) => self.why_not = Some(format!("{e:#}")),
            }
        }
        if !keys.is_empty() {
            self.why_not = None;
        }
        keys
    }

    pub(super) fn request_for(&mut self, state: &State) -> Option<Request> {
        self.why_not = crate::contact::scene::unsolvable(state, &self.sampling);
        let theory = (
            state.model,
            state.moments,
            state.params,
            state.size_effect,
            self.load,
        );
        let mut tasks = vec![];
        // A measured map has one surface.
        let seeds = if state.is_measured() { 1 } else { self.seeds };
        match self.plot {
            Plot::Share => {
                // b's sets give each its own hardness and size effect: the
                // ζ are those the grid holds.
                let global = Sampling {
                    hardness: Hardness::Global,
                    ..self.sampling
                };
                self.zetas = self.solvable_zetas(state, &global);
                self.sets = share_sets(self.sampling.hardness);
                // Each seed's sweep in turn, at each ζ its sets together:
                // one surface, each set's solve from the last's answer at
                // the same absolute load.
                for j in 0..u64::from(seeds) {
                    let seed = self.seed.wrapping_add(j);
                    for &z in &self.zetas {
                        for set in &self.sets {
                            let sampling = Sampling {
                                hardness: set.hardness,
                                ..self.sampling
                            };
                            let mut s = state.clone();
                            s.size_effect = set.size_effect;
                            s.params = s.params.with(Axis::Zeta, z).ok()?;
                            let key = SceneKey::with(&s, seed, &sampling).ok()?;
                            let p = self
                                .sampling
                                .loads
                                .over_in_use(load_value(self.load), ratio(&s, set.size_effect));
                            tasks.push(Task::new(key, p));
                        }
                    }
                }
            }
            Plot::Slopes => {
                let sampling = self.sampling;
                self.zetas = self.solvable_zetas(state, &sampling);
                // Each seed's ζ in turn, its light loads together (each
                // from the last).
                for j in 0..u64::from(seeds) {
                    let seed = self.seed.wrapping_add(j);
                    for &z in &self.zetas {
                        let mut s = state.clone();
                        s.params = s.params.with(Axis::Zeta, z).ok()?;
                        let sampling = if s.is_measured() {
                            self.sampling
                        } else {
                            slope_sampling(&self.sampling, z)?
                        };
                        let key = match SceneKey::with(&s, seed, &sampling) {
                            Ok(k) => k,
                            Err(e) => {
                                self.why_not = Some(format!("{e:#}"));
                                return Some(Request {
                                    tasks: vec![],
                                    theory,
                                });
                            }
                        };
                        for q in LIGHT {
                            tasks.push(Task::new(key, q * key.rms_slope() / key.hardness()));
                        }
                    }
                }
            }
            Plot::Load if self.why_not.is_none() => {
                match SceneKey::with(state, self.seed, &self.sampling) {
                    Ok(key) => tasks = (0..LOADS).map(|k| Task::new(key, load_value(k))).collect(),
                    Err(e) => self.why_not = Some(format!("{e:#}")),
                }
                if !tasks.is_empty() {
                    for j in 1..u64::from(seeds) {
                        let seed = self.seed.wrapping_add(j);
                        let key = SceneKey::with(state, seed, &self.sampling).ok()?;
                        tasks.extend((0..LOADS).map(|k| Task::new(key, load_value(k))));
                    }
                }
            }
            Plot::Load => {}
        }
        Some(Request { tasks, theory })
    }

    /// Tasks of one seed in the plot's list.
    pub(super) fn per_seed(&self) -> usize {
        match self.plot {
            Plot::Load => LOADS,
            Plot::Share => self.sets.len() * self.zetas.len(),
            Plot::Slopes => LIGHT.len() * self.zetas.len(),
        }
    }

    pub(super) fn theory_of(&self, state: &State) -> Theory {
        let p = state.params;
        let hi = self.zetas.last().copied().unwrap_or(1.0).log10();
        let along = |f: &dyn Fn(f64) -> Option<f64>| -> Vec<(f64, f64)> {
            (0..THEORY_POINTS)
                .filter_map(|i| {
                    let x = hi * i as f64 / (THEORY_POINTS - 1) as f64;
                    f(10f64.powf(x)).filter(|v| v.is_finite()).map(|v| (x, v))
                })
                .collect()
        };
        match self.plot {
            Plot::Share => {
                // The theory's share at the same finite load: its areas at
                // p̄/H_use, not its initial slopes.
                let load = load_value(self.load);
                let scale = self.sampling.loads;
                let curves = [false, true]
                    .into_iter()
                    .map(|se| {
                        along(&|z| {
                            let pz = p.with(Axis::Zeta, z).ok()?;
                            let (psi, r) = psi_in_use(&pz, se, state.moments);
                            let a = areas(state.model, psi, scale.over_in_use(load, r)).ok()?;
                            (a.total > 0.0).then(|| a.plastic / a.total)
                        })
                    })
                    .collect();
                Theory {
                    curves,
                    at_load: None,
                }
            }
            Plot::Slopes => {
                let curves = [0, 1, 2]
                    .into_iter()
                    .map(|k| {
                        along(&|z| {
                            let pz = p.with(Axis::Zeta, z).ok()?;
                            let (psi, _) = psi_in_use(&pz, state.size_effect, state.moments);
                            let s = slopes(state.model, psi);
                            let v = [s.total, s.elastic, s.plastic][k];
                            (v > 0.0).then(|| v.log10())
                        })
                    })
                    .collect();
                Theory {
                    curves,
                    at_load: None,
                }
            }
            Plot::Load => {
                let ix = state.roughness().surface(&p, state.moments).indices;
                let psi = ix.psi_in_use(state.size_effect);
                let mut curves = vec![vec![]; 3];
                for i in 0..THEORY_POINTS {
                    let x = -3.0 + 3.0 * i as f64 / (THEORY_POINTS - 1) as f64;
                    let Ok(a) = areas(state.model, psi, 10f64.powf(x).min(1.0)) else {
                        continue;
                    };
                    for (c, v) in curves.iter_mut().zip([a.total, a.elastic, a.plastic]) {
                        if v > 0.0 && v.is_finite() {
                            c.push((x, v.log10()));
                        }
                    }
                }
                Theory {
                    curves,
                    at_load: areas(state.model, psi, load_value(self.load)).ok(),
                }
            }
        }
    }
}
