//! The contact view's convergence table (`t`): the chosen load solved on
//! grids of 4, 8 and 16 nodes per shortest wavelength and in cells of 1, 2
//! and 4 longest wavelengths, over the pane's seeds, as
//! `export --view contact-convergence` does, but through the [`Engine`]:
//! cached, cancelled when the table or the view is left, the smallest
//! grids first so that the table fills in quickly.

use std::sync::Arc;

use crate::contact::convergence::{share, CELLS, PER_WAVELENGTH};
use crate::contact::engine::{Engine, Outcome, Progress, Task, Ticket, Waker};
use crate::contact::sampling::{bytes_words, BYTES_PER_NODE};
use crate::contact::scene::SceneKey;
use crate::contact::{Grid, Sampling, Stat, MAX_GRID};
use crate::scene::State;

/// What the table says in place of a measured map's.
pub const MEASURED: &str = "a measured map is one surface on its own grid: the convergence \
table compares synthesised surfaces on 4, 8 and 16 nodes per shortest wavelength in cells of \
1, 2 and 4 longest wavelengths (a power-law scene: 1–4 loads one)";

/// One (nodes per shortest wavelength, cell) pair of the table.
#[derive(Clone, Debug)]
pub struct Row {
    pub per_wavelength: u32,
    pub cell: u32,
    /// The grid side, or why the pair is not solved.
    pub grid: Result<usize, String>,
    /// One task a seed (none when not solved).
    pub tasks: Vec<Task>,
    pub results: Vec<Option<Outcome>>,
}

/// A row's answers over the seeds solved so far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowStats {
    pub area: Stat,
    /// The area with the grid's edge corrected (Yastrebov et al. 2017).
    pub corrected: Stat,
    /// S_pl/S_tot of each seed (one without contact left out).
    pub share: Stat,
    pub iterations: Stat,
    /// Mean wall time of a solve, in seconds.
    pub seconds: f64,
}

impl Row {
    pub fn stats(&self) -> Option<RowStats> {
        let runs: Vec<_> = self
            .results
            .iter()
            .filter_map(|r| match r {
                Some(Ok(s)) => Some(s),
                _ => None,
            })
            .collect();
        if runs.is_empty() {
            return None;
        }
        Some(RowStats {
            area: Stat::of(runs.iter().map(|s| s.result.area)),
            corrected: Stat::of(runs.iter().map(|s| s.result.corrected_area())),
            share: Stat::of(runs.iter().map(|s| share(&s.result))),
            iterations: Stat::of(runs.iter().map(|s| s.result.iterations as f64)),
            seconds: runs.iter().map(|s| s.took.as_secs_f64()).sum::<f64>() / runs.len() as f64,
        })
    }

    /// The first failure among the seeds' solves, if any.
    pub fn failure(&self) -> Option<&str> {
        self.results.iter().find_map(|r| match r {
            Some(Err(e)) => Some(e.as_str()),
            _ => None,
        })
    }
}

/// The inputs the rows were worked out for.
type Inputs = (State, u64, u32, Sampling, f64);

/// The table's rows and the job solving them.
#[derive(Default)]
pub struct Convergence {
    /// [`PER_WAVELENGTH`] × [`CELLS`], in that order.
    pub rows: Vec<Row>,
    pub progress: Progress,
    /// Why there is no table (a measured map).
    pub why_not: Option<String>,
    inputs: Option<Inputs>,
    ticket: Option<Ticket>,
}

impl Convergence {
    /// Whether its job is under way.
    pub fn busy(&self) -> bool {
        self.ticket.is_some() && !self.progress.finished
    }

    /// Stops the job (at its next iteration; what it solved stays cached).
    pub fn stop(&mut self) {
        self.ticket = None;
        self.progress = Progress::default();
    }

    /// Brings the table up to the scene at p̄/H = `p_over_h` over seeds
    /// `seed` … `seed + seeds − 1`, sampled otherwise as `sampling`, and
    /// requests what the cache lacks.
    pub fn refresh(
        &mut self,
        engine: &Arc<Engine>,
        waker: &Waker,
        state: &State,
        (seed, seeds): (u64, u32),
        sampling: &Sampling,
        p_over_h: f64,
    ) {
        if state.is_measured() {
            self.stop();
            self.rows.clear();
            self.inputs = None;
            self.why_not = Some(MEASURED.into());
            return;
        }
        self.why_not = None;
        let inputs = (state.clone(), seed, seeds, *sampling, p_over_h);
        if self.inputs.as_ref() != Some(&inputs) {
            let rows = rows(state, (seed, seeds), sampling, p_over_h);
            let tasks = |rows: &[Row]| -> Vec<Task> {
                rows.iter().flat_map(|r| r.tasks.iter().copied()).collect()
            };
            if tasks(&rows) != tasks(&self.rows) {
                self.stop();
            }
            self.rows = rows;
            self.inputs = Some(inputs);
        }
        self.read(engine);
        let all_in = self
            .rows
            .iter()
            .all(|r| r.results.iter().all(Option::is_some));
        if self.ticket.is_none() && !all_in {
            self.ticket = Some(engine.request(self.job(), 0, Arc::clone(waker)));
        }
        if let Some(t) = &self.ticket {
            self.progress = t.progress();
            if self.progress.finished {
                self.read(engine);
            }
        } else {
            let n = self.rows.iter().map(|r| r.tasks.len()).sum();
            self.progress = Progress {
                done: n,
                total: n,
                finished: true,
                ..Progress::default()
            };
        }
    }

    fn read(&mut self, engine: &Engine) {
        for r in &mut self.rows {
            r.results = r.tasks.iter().map(|t| engine.get(t)).collect();
        }
    }

    /// The job's tasks, the smallest grids first (a row's seeds together).
    fn job(&self) -> Vec<Task> {
        let mut rows: Vec<&Row> = self.rows.iter().collect();
        rows.sort_by_key(|r| {
            (
                *r.grid.as_ref().unwrap_or(&usize::MAX),
                r.per_wavelength * r.cell,
            )
        });
        rows.iter().flat_map(|r| r.tasks.iter().copied()).collect()
    }
}

/// The table's rows for a power-law scene.
fn rows(state: &State, (seed, seeds): (u64, u32), sampling: &Sampling, p: f64) -> Vec<Row> {
    let mut out = vec![];
    for &k in &PER_WAVELENGTH {
        for &cell in &CELLS {
            let s = Sampling {
                cell,
                grid: Grid::PerWavelength(k),
                ..*sampling
            };
            let grid = side(state, &s, k);
            let mut tasks = vec![];
            let grid = grid.and_then(|n| {
                for j in 0..u64::from(seeds.max(1)) {
                    let key = SceneKey::with(state, seed.wrapping_add(j), &s)
                        .map_err(|e| format!("{e:#}"))?;
                    tasks.push(Task::new(key, p));
                }
                Ok(n)
            });
            if grid.is_err() {
                tasks.clear();
            }
            out.push(Row {
                per_wavelength: k,
                cell,
                grid,
                results: vec![None; tasks.len()],
                tasks,
            });
        }
    }
    out
}

/// A pair's grid side, or in a few words why it is not solved: beyond
/// [`MAX_GRID`], or more memory than the machine has.
fn side(state: &State, s: &Sampling, k: u32) -> Result<usize, String> {
    let zeta = state.params.zeta();
    let need = (f64::from(k) * zeta * f64::from(s.cell)).ceil();
    if !need.is_finite() || need > MAX_GRID as f64 {
        let n = (need.min(1e15) as u64).next_power_of_two();
        return Err(format!("{n}² nodes, beyond the {MAX_GRID}² solved"));
    }
    s.side(zeta).map_err(|e| {
        let n = (need as usize).next_power_of_two();
        let bytes = (n as f64).powi(2) * BYTES_PER_NODE as f64;
        if format!("{e:#}").contains("memory") {
            format!(
                "{n}² needs {} of memory, more than is free",
                bytes_words(bytes)
            )
        } else {
            format!("{e:#}")
        }
    })
}
