//! The contact view's state: which load and which plot (`b`, `i`), the ticket
//! on the engine's job for the scene on screen, the results read from the
//! engine's cache and the theory's curves beside them. Only
//! [`ContactPane::refresh`] (from `update`) changes it; the worker thread
//! never touches an [`super::app::App`], it wakes the session, which sends
//! [`super::app::Message::Tick`].

use std::sync::Arc;

use rough_model::Model;

use crate::contact::engine::{Engine, Outcome, Progress, Task, Ticket, Waker};
use crate::contact::measured::{self, Fetch};
use crate::contact::slopes::{Run, LIGHT};
pub use crate::contact::Plot;
use crate::contact::{Sampling, Stat, DEFAULT_SEED, MAX_GRID};
use crate::scene::State;

pub mod convergence;
mod keys;
mod request;
pub use keys::{on_key, picture, save};
pub use request::{share_sets, Set};

/// Loads of the contact view, p̄/H_use: 1e-3 to 1, four per decade.
pub const LOADS: usize = 13;
/// The load shown first: p̄ = 0.01 H.
pub const DEFAULT_LOAD: usize = 4;
/// Points along a theory curve.
pub(crate) const THEORY_POINTS: usize = 96;
/// The coarse answer's grid side at most: a finer scene is first solved on
/// its surface sampled at every second, fourth … node (256²: a load in
/// tenths of a second), then on its own grid.
pub use crate::contact::COARSE_GRID;
/// Surfaces (seeds) the load plot averages over when the view opens; `R`
/// steps through [`SEED_CHOICES`].
pub const DEFAULT_SEEDS: u32 = 4;
pub const SEED_CHOICES: [u32; 3] = [4, 16, 1];

/// p̄/H of load `k` (0 … [`LOADS`] − 1).
pub fn load_value(k: usize) -> f64 {
    if k + 1 >= LOADS {
        1.0
    } else {
        10f64.powf(-3.0 + k as f64 / 4.0)
    }
}

/// ζ of the `b` plot: 1, 2, 4, … up to what the grid resolves (and 128).
pub fn sweep_zetas(sampling: &Sampling) -> Vec<f64> {
    (0..=7)
        .map(|k| 2f64.powi(k))
        .take_while(|z| sampling.side(*z).is_ok())
        .collect()
}

/// What the chart shows beside the simulation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Theory {
    /// Load plot: (log10 p̄/H, log10 A/A0) of total, elastic, plastic.
    /// `b` plot: (log10 ζ, A_pl/A at the load) with the size effect off,
    /// on. `i` plot: (log10 ζ, log10 S) of total, elastic, plastic.
    pub curves: Vec<Vec<(f64, f64)>>,
    /// The theory's areas at the chosen load (load plot).
    pub at_load: Option<rough_model::Areas>,
}

/// What the requested tasks are for.
#[derive(Clone, Debug, PartialEq)]
struct Request {
    tasks: Vec<Task>,
    /// The theory's inputs: model, moments, the scene's parameters, the load.
    theory: (
        Model,
        rough_model::Moments,
        rough_model::Params,
        bool,
        usize,
    ),
}

pub struct ContactPane {
    pub engine: Arc<Engine>,
    /// Called from the worker when there is something new to draw.
    pub waker: Waker,
    /// The chosen load, index into [`LOADS`].
    pub load: usize,
    /// The plot: areas against the load, `b` the plastic share against ζ,
    /// `i` the initial slopes against ζ.
    pub plot: Plot,
    /// `b`'s sets of caps, in the order of their tasks.
    pub sets: Vec<Set>,
    /// The scene's seed (the snapshot's, 1 by default).
    pub seed: u64,
    /// The cell and grid of the simulation.
    pub sampling: Sampling,
    /// The ζ of the `b` plot: [`sweep_zetas`], a measured map's those it
    /// resolves.
    pub zetas: Vec<f64>,
    /// Why the scene cannot be simulated (then nothing is requested).
    pub why_not: Option<String>,
    /// The tasks on screen and what is shown for each: the cache's result,
    /// or while it is not in, the coarse grid's ([`ContactPane::coarse`]).
    pub tasks: Vec<Task>,
    pub results: Vec<Option<Outcome>>,
    /// The same loads on a coarse grid (empty when the grid is coarse
    /// enough), solved first; which of `results` are theirs.
    pub coarse_tasks: Vec<Task>,
    pub coarse: Vec<bool>,
    /// Surfaces averaged over (a power law's load plot and `b` plot):
    /// seeds `seed` … `seed + seeds − 1`; the further seeds' tasks and
    /// results, each as long as `tasks`.
    pub seeds: u32,
    pub seed_tasks: Vec<Vec<Task>>,
    pub seed_results: Vec<Vec<Option<Outcome>>>,
    /// The further seeds' loads on the coarse grid, each fine load's start
    /// (not shown: only the drawn seed's coarse answer is).
    pub seed_coarse: Vec<Vec<Task>>,
    pub progress: Progress,
    pub theory: Theory,
    /// `t`: the convergence table at the chosen load in place of the plot
    /// (the plot's job waits meanwhile).
    pub table: bool,
    pub convergence: convergence::Convergence,
    request: Option<Request>,
    ticket: Option<Ticket>,
    /// The scene [`ContactPane::request`] was worked out for.
    scene: Option<State>,
    /// A measured map's heights are being read (the view says so).
    reading: bool,
}

impl Default for ContactPane {
    fn default() -> Self {
        ContactPane {
            engine: Engine::global(),
            waker: Arc::new(|| {}),
            load: DEFAULT_LOAD,
            plot: Plot::Load,
            sets: vec![],
            seed: DEFAULT_SEED,
            // One longest wavelength: the explorer's first answer must come
            // quickly (export's default is two).
            sampling: Sampling {
                cell: 1,
                ..Sampling::default()
            },
            zetas: vec![],
            why_not: None,
            tasks: vec![],
            results: vec![],
            coarse_tasks: vec![],
            coarse: vec![],
            seeds: DEFAULT_SEEDS,
            seed_tasks: vec![],
            seed_results: vec![],
            seed_coarse: vec![],
            progress: Progress::default(),
            theory: Theory::default(),
            table: false,
            convergence: convergence::Convergence::default(),
            request: None,
            ticket: None,
            scene: None,
            reading: false,
        }
    }
}

impl ContactPane {
    /// Whether a job is under way for the scene on screen (the session
    /// then wakes for its progress).
    pub fn busy(&self) -> bool {
        self.reading
            || (self.ticket.is_some() && !self.progress.finished)
            || self.convergence.busy()
    }

    /// The result for the chosen load (load plot), if solved.
    pub fn chosen(&self) -> Option<&Outcome> {
        if self.plot != Plot::Load {
            return None;
        }
        self.results.get(self.load).and_then(Option::as_ref)
    }

    /// The results at load `k` of the seeds solved so far, the first
    /// seed's first (the coarse grid's answer alone while the first seed's
    /// is not in); none before the first seed's.
    fn runs_at_load(&self, k: usize) -> Option<Vec<rough_contact::LoadResult>> {
        let first = match self.results.get(k)? {
            Some(Ok(s)) => s,
            _ => return None,
        };
        let mut runs = vec![first.result];
        if !self.coarse.get(k).copied().unwrap_or(false) {
            runs.extend(self.seed_results.iter().filter_map(|r| match r.get(k) {
                Some(Some(Ok(s))) => Some(s.result),
                _ => None,
            }));
        }
        Some(runs)
    }

    /// The areas at load `k` over the seeds solved so far (total, elastic,
    /// plastic; the coarse grid's answer alone while the first seed's is
    /// not in).
    pub fn at_load(&self, k: usize) -> Option<[Stat; 3]> {
        let runs = self.runs_at_load(k)?;
        Some([
            Stat::of(runs.iter().map(|r| r.area)),
            Stat::of(runs.iter().map(|r| r.elastic_area)),
            Stat::of(runs.iter().map(|r| r.plastic_area)),
        ])
    }

    /// The plastic share A_pl/A at load `k` over the seeds solved so far
    /// (each seed's own share; a seed without contact left out).
    pub fn share_at_load(&self, k: usize) -> Option<Stat> {
        let runs = self.runs_at_load(k)?;
        let st = Stat::of(runs.iter().map(|r| {
            if r.area > 0.0 {
                r.plastic_area / r.area
            } else {
                f64::NAN
            }
        }));
        (st.n > 0).then_some(st)
    }

    /// κ at the lightest load, A/A0 over p̄/(E* h′), over the seeds solved
    /// so far (the coarse answer while the scene's grid has not solved it).
    pub fn kappa(&self) -> Option<Stat> {
        let task = self.tasks.first()?;
        let x = task.p_over_h() * task.scene.hardness() / task.scene.rms_slope();
        let [a, _, _] = self.at_load(0)?;
        (x > 0.0 && a.n > 0).then(|| Stat {
            mean: a.mean / x,
            sd: a.sd / x,
            n: a.n,
        })
    }

    /// The initial slopes (elastic, plastic, total) at ζ number `k` of the
    /// `i` plot, each seed's fitted alone, over the seeds whose light loads
    /// there are all in.
    pub fn slopes_at(&self, k: usize) -> Option<[Stat; 3]> {
        let m = LIGHT.len();
        let runs: Vec<[f64; 3]> = std::iter::once((&self.tasks, &self.results))
            .chain(self.seed_tasks.iter().zip(&self.seed_results))
            .filter_map(|(ts, rs)| {
                let ts = ts.get(k * m..(k + 1) * m)?;
                let rs = rs.get(k * m..(k + 1) * m)?;
                let results = rs
                    .iter()
                    .map(|r| match r {
                        Some(Ok(s)) => Some(s.result),
                        _ => None,
                    })
                    .collect::<Option<Vec<_>>>()?;
                let run = Run {
                    seed: ts[0].scene.seed,
                    x: ts.iter().map(Task::p_over_h).collect(),
                    results,
                };
                Some(run.slopes())
            })
            .collect();
        let st = [0, 1, 2].map(|i| Stat::of(runs.iter().map(|r| r[i])));
        (st[2].n > 0).then_some(st)
    }

    /// Seeds of the plot: those asked for (1 for a measured map).
    pub fn seeds_asked(&self) -> usize {
        1 + self.seed_tasks.len()
    }

    /// Seeds whose every task is in (the `b` plot's seeds landed).
    pub fn seeds_in(&self) -> usize {
        let done = |rs: &[Option<Outcome>]| !rs.is_empty() && rs.iter().all(Option::is_some);
        usize::from(done(&self.results)) + self.seed_results.iter().filter(|r| done(r)).count()
    }

    /// The `b` plot's plastic share S_pl/S_tot at ζ number `k`, size effect
    /// off (`set` 0) or on (1), over the seeds solved so far (a seed
    /// without contact there left out).
    pub fn share_at(&self, set: usize, k: usize) -> Option<Stat> {
        if self.plot != Plot::Share {
            return None;
        }
        // A seed's tasks: at each ζ, its sets in turn.
        let i = k * self.sets.len() + set;
        let runs = std::iter::once(&self.results)
            .chain(&self.seed_results)
            .filter_map(|rs| match rs.get(i) {
                Some(Some(Ok(s))) if s.result.area > 0.0 => {
                    Some(s.result.plastic_area / s.result.area)
                }
                _ => None,
            });
        let st = Stat::of(runs);
        (st.n > 0).then_some(st)
    }

    /// Whether the chosen load shows the coarse grid's answer.
    pub fn chosen_is_coarse(&self) -> bool {
        self.plot == Plot::Load && self.coarse.get(self.load).copied().unwrap_or(false)
    }

    /// The grid side of the scene, and of its coarse answer if any.
    pub fn grids(&self) -> (Option<usize>, Option<usize>) {
        (
            self.tasks.first().map(|t| t.scene.side()),
            self.coarse_tasks.first().map(|t| t.scene.side()),
        )
    }

    /// Reads what the cache holds: each task's result, or the coarse
    /// grid's while it is not in.
    fn read_results(&mut self) {
        let fine: Vec<Option<Outcome>> = self.tasks.iter().map(|t| self.engine.get(t)).collect();
        self.coarse = vec![false; fine.len()];
        self.results = fine;
        self.seed_results = self
            .seed_tasks
            .iter()
            .map(|ts| ts.iter().map(|t| self.engine.get(t)).collect())
            .collect();
        for (i, t) in self.coarse_tasks.iter().enumerate() {
            if self.results.get(i).is_some_and(Option::is_none) {
                if let Some(Ok(c)) = self.engine.get(t) {
                    self.results[i] = Some(Ok(c));
                    self.coarse[i] = true;
                }
            }
        }
    }

    /// The job's tasks: the coarse grid's, then the scene's own.
    fn job_tasks(&self) -> Vec<Task> {
        let mut all: Vec<Task> = self
            .coarse_tasks
            .iter()
            .chain(&self.tasks)
            .copied()
            .collect();
        for (j, ts) in self.seed_tasks.iter().enumerate() {
            all.extend(self.seed_coarse.get(j).into_iter().flatten());
            all.extend(ts);
        }
        all
    }

    /// The order the job solves in: the chosen load on the coarse grid,
    /// the coarse grid's other loads, then the chosen load on the scene's
    /// grid (then its other loads in turn, each from the last answer).
    fn job_order(&self) -> Vec<usize> {
        let c = self.coarse_tasks.len();
        if self.plot != Plot::Load {
            return vec![0];
        }
        let mut order = vec![];
        if c > 0 {
            order.push(self.load.min(c - 1));
            order.extend(0..c);
        }
        order.push(c + self.load);
        // Each further seed's chosen load (on the coarse grid first, its
        // start), so that the spread comes soon.
        let mut at = c + self.tasks.len();
        for (j, ts) in self.seed_tasks.iter().enumerate() {
            let sc = self.seed_coarse.get(j).map_or(0, Vec::len);
            if sc > 0 {
                order.push(at + self.load.min(sc - 1));
            }
            order.push(at + sc + self.load.min(ts.len().saturating_sub(1)));
            at += sc + ts.len();
        }
        order
    }

    /// Brings the pane up to `state`: a changed scene cancels the job on
    /// the old one (by dropping its ticket) and, if `shown`, requests the
    /// new one; the results are read from the cache.
    pub fn refresh(&mut self, state: &State, shown: bool) {
        self.seed = state.seed.unwrap_or(DEFAULT_SEED);
        if !shown {
            // Off screen nothing is worked out (a measured map's scene
            // would read its heights from the file) and the job stops at
            // its next iteration (what it solved stays in the cache; back
            // in the view it goes on from there). A read of heights goes
            // on, but nobody waits on it here.
            self.reading = false;
            self.ticket = None;
            self.progress = Progress::default();
            self.convergence.stop();
            if !self.scene.as_ref().is_some_and(|s| same_scene(s, state)) {
                self.ticket = None;
                self.progress = Progress::default();
                self.request = None;
                self.scene = None;
            }
            return;
        }
        // The convergence table on screen: its job alone (the plot's
        // waits, going on from the cache when the table is closed).
        if self.table {
            self.reading = false;
            self.ticket = None;
            self.progress = Progress::default();
            let seeds = (self.seed, self.seeds);
            let p = load_value(self.load);
            let c = &mut self.convergence;
            c.refresh(&self.engine, &self.waker, state, seeds, &self.sampling, p);
            return;
        }
        self.convergence.stop();
        // A measured map's heights are read off this thread first.
        let fetched = measured::fetch(state, &self.waker);
        self.reading = fetched == Fetch::Reading;
        let wait = match fetched {
            Fetch::Ready => None,
            Fetch::Reading => Some(format!(
                "reading the heights of {} for the simulation …",
                state.surface.as_ref().map_or_else(String::new, |s| {
                    s.path
                        .file_name()
                        .unwrap_or(s.path.as_os_str())
                        .to_string_lossy()
                        .into_owned()
                })
            )),
            Fetch::Failed(why) => Some(why),
        };
        if let Some(why) = wait {
            self.why_not = Some(why);
            self.ticket = None;
            self.progress = Progress::default();
            self.request = None;
            self.scene = None;
            self.tasks.clear();
            self.results.clear();
            self.coarse_tasks.clear();
            self.coarse.clear();
            self.seed_tasks.clear();
            self.seed_coarse.clear();
            self.seed_results.clear();
            self.theory = Theory::default();
            return;
        }
        self.scene = Some(state.clone());
        let request = self.request_for(state);
        if request.as_ref().map(|r| &r.tasks) != self.request.as_ref().map(|r| &r.tasks) {
            self.ticket = None;
            self.progress = Progress::default();
        }
        if request != self.request {
            self.theory = request
                .as_ref()
                .map(|_| self.theory_of(state))
                .unwrap_or_default();
            self.tasks = request
                .as_ref()
                .map(|r| r.tasks.clone())
                .unwrap_or_default();
            self.seed_tasks = vec![];
            // A seed's tasks: the loads, b's ζ for each set of caps, or
            // i's light loads at each ζ.
            let per = self.per_seed();
            if per > 0 && self.tasks.len() > per {
                self.seed_tasks = self.tasks[per..]
                    .chunks(per)
                    .map(<[Task]>::to_vec)
                    .collect();
                self.tasks.truncate(per);
            }
            let coarse = |ts: &[Task]| -> Vec<Task> {
                ts.iter()
                    .map_while(|t| Some(Task::new(t.scene.coarser(COARSE_GRID)?, t.p_over_h())))
                    .collect()
            };
            (self.coarse_tasks, self.seed_coarse) = if self.plot != Plot::Load {
                (vec![], vec![])
            } else {
                (
                    coarse(&self.tasks),
                    self.seed_tasks.iter().map(|ts| coarse(ts)).collect(),
                )
            };
            self.request = request;
        }
        self.read_results();
        let all_in = self
            .tasks
            .iter()
            .chain(self.seed_tasks.iter().flatten())
            .all(|t| self.engine.has(t, t.scene.seed == self.seed));
        if self.ticket.is_none() && !all_in {
            let order = self.job_order();
            let t = self
                .engine
                .request(self.job_tasks(), order[0], Arc::clone(&self.waker));
            self.ticket = Some(t);
        }
        if let Some(t) = &self.ticket {
            t.prefer_in_order(&self.job_order());
            self.progress = t.progress();
            if self.progress.finished {
                // Read once more: the last result came with the end.
                self.read_results();
            }
        } else {
            self.progress = Progress {
                done: self.tasks.len(),
                total: self.tasks.len(),
                finished: true,
                ..Progress::default()
            };
        }
    }
}

/// The grid cap in words, for the view's messages.
pub fn grid_cap() -> String {
    format!("{MAX_GRID}² (ζ ≤ {})", MAX_GRID / 8)
}

/// Whether `a` and `b` are the same scene for the simulation (their names,
/// captions and views aside). A measured surface compares by file, reading
/// and SHA-256, and its moment table by fingerprint: nothing is read.
fn same_scene(a: &State, b: &State) -> bool {
    a.surface == b.surface
        && a.params == b.params
        && a.size_effect == b.size_effect
        && a.model == b.model
        && a.moments == b.moments
        && a.seed == b.seed
        && a.sweep == b.sweep
}
