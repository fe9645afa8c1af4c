//! Contact solutions off the UI thread, shared and cached.
//!
//! An explorer asks the [`Engine`] for a list of [`Task`]s (a scene and a
//! load each) and gets a [`Ticket`]. One worker thread per distinct list
//! solves the tasks not yet cached, the explorer's chosen task first,
//! storing each result in a cache keyed by the task's inputs, and calls
//! every holder's waker as it makes progress (at most every
//! [`WAKE_EVERY`]) and when a task ends. Explorers asking for the same list
//! (the followers of a served class) hold tickets of one job; when the last
//! ticket is dropped (the scene changed) the job is cancelled at its next
//! iteration. At most as many jobs solve at once as the machine has cores;
//! the others wait their turn.
//!
//! A scene solved on its own grid starts each load from the same load's
//! coarse answer if the cache has one (its pressure prolonged to the fine
//! grid: 10–16 % fewer iterations than from a cold start or the last
//! load's answer, fig2 at ζ = 64 and 128), else from the last load's.
//! Only the maps of a job's first seed are kept (the surface the view
//! draws); a further seed's result is kept without its map, so four seeds
//! of thirteen loads at 4096² take 16 maps' room, not 52.

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, OnceLock, Weak};
use std::time::{Duration, Instant};

use rough_contact::{ContactError, LoadResult, Options};

pub use super::progress::Progress;
use super::scene::{classify, classify_capped, Node, SceneKey};

/// What wakes an explorer: called from the worker thread.
pub type Waker = Arc<dyn Fn() + Send + Sync>;

/// Progress is reported at most this often (finished tasks always).
pub const WAKE_EVERY: Duration = Duration::from_millis(100);

/// The cache's bound, in bytes of contact maps (one byte a node).
pub const CACHE_BYTES: usize = 256 << 20;

/// One solution to compute: a scene at a load p̄/H_use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Task {
    pub scene: SceneKey,
    /// p̄/H_use as f64 bits.
    load: u64,
}

impl Task {
    pub fn new(scene: SceneKey, p_over_h: f64) -> Task {
        Task {
            scene,
            load: p_over_h.to_bits(),
        }
    }

    pub fn p_over_h(&self) -> f64 {
        f64::from_bits(self.load)
    }
}

/// A solved task: the areas and the contact map.
#[derive(Debug)]
pub struct Solved {
    pub result: LoadResult,
    /// n × n row-major; empty for a seed whose surface is not drawn.
    pub map: Vec<Node>,
    /// A coarse grid's pressure (n × n, units of E*): where the same load
    /// on the fine grid starts. `None` on a scene's own grid.
    pub pressure: Option<Vec<f64>>,
    /// Wall time of the solve.
    pub took: Duration,
}

/// What a task ended with.
pub type Outcome = Result<Arc<Solved>, String>;

/// The work of a task: the nodes of its grid times the iterations a load
/// takes, which grow with the load (fig2 at 1024²: 44 at p̄ = 1e-3 H to
/// 213 at 0.56 H, about 1 + 4/3 per quarter decade … five times as many);
/// p̄ = H is all at the hardness and takes none.
fn work(task: &Task) -> f64 {
    let nodes = (task.scene.side() as f64).powi(2);
    let p = task.p_over_h();
    if p >= 1.0 {
        return 0.1 * nodes;
    }
    nodes * (1.0 + (p.log10() + 3.0).max(0.0) * 4.0 / 3.0)
}

struct Job {
    tasks: Vec<Task>,
    /// The seed whose maps are kept: the first task's.
    drawn: u64,
    /// Indices into `tasks` of those to solve next, in order, if not yet
    /// done (then the rest in the list's order).
    first: Mutex<Vec<usize>>,
    cancel: AtomicBool,
    state: Mutex<JobState>,
}

struct JobState {
    holders: usize,
    wakers: Vec<(u64, Waker)>,
    progress: Progress,
}

impl Job {
    fn wake(&self) {
        let wakers: Vec<Waker> = match self.state.lock() {
            Ok(s) => s.wakers.iter().map(|(_, w)| Arc::clone(w)).collect(),
            Err(_) => return,
        };
        for w in wakers {
            w();
        }
    }

    fn set(&self, f: impl FnOnce(&mut Progress)) {
        if let Ok(mut s) = self.state.lock() {
            f(&mut s.progress);
        }
    }
}

/// A holder's claim on a job: dropping the last one cancels it.
pub struct Ticket {
    job: Arc<Job>,
    id: u64,
}

impl Ticket {
    pub fn progress(&self) -> Progress {
        self.job
            .state
            .lock()
            .map(|s| s.progress.clone())
            .unwrap_or_default()
    }

    /// Solve task `i` of the list next (the explorer's chosen load).
    pub fn prefer(&self, i: usize) {
        self.prefer_in_order(&[i]);
    }

    /// Solve these tasks of the list next, in this order (a coarse grid's
    /// chosen load, then its other loads, then the fine grid's chosen one).
    pub fn prefer_in_order(&self, order: &[usize]) {
        if let Ok(mut f) = self.job.first.lock() {
            if f.as_slice() != order {
                *f = order.to_vec();
            }
        }
    }

    pub fn tasks(&self) -> &[Task] {
        &self.job.tasks
    }
}

impl Drop for Ticket {
    fn drop(&mut self) {
        if let Ok(mut s) = self.job.state.lock() {
            s.wakers.retain(|(id, _)| *id != self.id);
            s.holders -= 1;
            if s.holders == 0 {
                self.job.cancel.store(true, Ordering::Relaxed);
            }
        }
    }
}

#[derive(Default)]
struct Cache {
    map: HashMap<Task, Outcome>,
    order: VecDeque<(Task, usize)>,
    bytes: usize,
}

impl Cache {
    fn put(&mut self, task: Task, outcome: Outcome) {
        let bytes = outcome.as_ref().map_or(64, |s| {
            s.map.len() + 8 * s.pressure.as_ref().map_or(0, Vec::len) + 64
        });
        if let Some(old) = self.map.remove(&task) {
            // A result solved again with its map: the entry's bytes grow.
            let at = self.order.iter().position(|(t, _)| *t == task);
            if let Some((_, b)) = at.and_then(|i| self.order.remove(i)) {
                self.bytes -= b;
            }
            drop(old);
        }
        if self.map.insert(task, outcome).is_none() {
            self.order.push_back((task, bytes));
            self.bytes += bytes;
        }
        while self.bytes > CACHE_BYTES && self.order.len() > 1 {
            if let Some((old, b)) = self.order.pop_front() {
                self.map.remove(&old);
                self.bytes -= b;
            }
        }
    }
}

/// The cache, the running jobs and the cores they may use.
pub struct Engine {
    cache: Mutex<Cache>,
    running: Mutex<HashMap<Vec<Task>, Weak<Job>>>,
    slots: Mutex<usize>,
    freed: Condvar,
    next_id: AtomicUsize,
    /// Solves started (for tests of the cache and the sharing).
    pub solves: AtomicUsize,
    /// Told a line on each job's end (`serve` logs it).
    report: Mutex<Option<Reporter>>,
}

type Reporter = Arc<dyn Fn(&str) + Send + Sync>;

impl Engine {
    /// An engine solving at most `cores` jobs at once.
    pub fn new(cores: usize) -> Arc<Engine> {
        Arc::new(Engine {
            cache: Mutex::default(),
            running: Mutex::default(),
            slots: Mutex::new(cores.max(1)),
            freed: Condvar::new(),
            next_id: AtomicUsize::new(0),
            solves: AtomicUsize::new(0),
            report: Mutex::new(None),
        })
    }

    /// Calls `f` with a line when a job that solved anything ends: what it
    /// solved, on which grid and seed, in how long, for how many explorers.
    pub fn on_end(&self, f: impl Fn(&str) + Send + Sync + 'static) {
        if let Ok(mut r) = self.report.lock() {
            *r = Some(Arc::new(f));
        }
    }

    /// The process's engine: every explorer of a `serve` shares it.
    pub fn global() -> Arc<Engine> {
        static GLOBAL: OnceLock<Arc<Engine>> = OnceLock::new();
        Arc::clone(GLOBAL.get_or_init(|| {
            let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
            Engine::new(cores)
        }))
    }

    /// Jobs running or waiting for a core.
    pub fn running(&self) -> usize {
        let running = self.running.lock().unwrap_or_else(|e| e.into_inner());
        running.values().filter(|w| w.strong_count() > 0).count()
    }

    /// What the cache holds for `task`.
    pub fn get(&self, task: &Task) -> Option<Outcome> {
        self.cache.lock().ok()?.map.get(task).cloned()
    }

    /// Whether the cache holds `task`'s outcome, with its map if `map`
    /// (a further seed's result is kept without one).
    pub fn has(&self, task: &Task, map: bool) -> bool {
        match self.get(task) {
            Some(Ok(s)) => !map || !s.map.is_empty(),
            Some(Err(_)) => true,
            None => false,
        }
    }

    /// A ticket on the job solving `tasks` (task `first` first), started
    /// unless one is running; `wake` is called as it progresses.
    pub fn request(self: &Arc<Self>, tasks: Vec<Task>, first: usize, wake: Waker) -> Ticket {
        let id = self.next_id.fetch_add(1, Ordering::Relaxed) as u64;
        let mut running = self.running.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(job) = running.get(&tasks).and_then(Weak::upgrade) {
            let joined = match job.state.lock() {
                Ok(mut s) if !job.cancel.load(Ordering::Relaxed) => {
                    s.holders += 1;
                    s.wakers.push((id, Arc::clone(&wake)));
                    true
                }
                _ => false,
            };
            if joined {
                if let Ok(mut f) = job.first.lock() {
                    *f = vec![first];
                }
                return Ticket { job, id };
            }
        }
        let job = Arc::new(Job {
            drawn: tasks.first().map_or(0, |t| t.scene.seed),
            first: Mutex::new(vec![first]),
            cancel: AtomicBool::new(false),
            state: Mutex::new(JobState {
                holders: 1,
                wakers: vec![(id, wake)],
                progress: Progress {
                    total: tasks.len(),
                    work_total: tasks.iter().map(work).sum(),
                    queued: true,
                    ..Progress::default()
                },
            }),
            tasks: tasks.clone(),
        });
        running.insert(tasks, Arc::downgrade(&job));
        drop(running);
        let (engine, worker) = (Arc::clone(self), Arc::clone(&job));
        std::thread::Builder::new()
            .name("contact".into())
            .spawn(move || engine.work(&worker))
            .map(drop)
            .unwrap_or_else(|e| {
                job.set(|p| p.finished = true);
                self.cache_failure(&job.tasks, &format!("cannot start the solver: {e}"));
            });
        Ticket { job, id }
    }

    fn cache_failure(&self, tasks: &[Task], why: &str) {
        if let Ok(mut c) = self.cache.lock() {
            for t in tasks {
                c.put(*t, Err(why.to_string()));
            }
        }
    }

    /// Waits for a core; false if the job was cancelled meanwhile.
    fn acquire(&self, job: &Job) -> bool {
        let mut free = self.slots.lock().unwrap_or_else(|e| e.into_inner());
        loop {
            if job.cancel.load(Ordering::Relaxed) {
                return false;
            }
            if *free > 0 {
                *free -= 1;
                return true;
            }
            free = self
                .freed
                .wait_timeout(free, Duration::from_millis(50))
                .unwrap_or_else(|e| e.into_inner())
                .0;
        }
    }

    fn release(&self) {
        *self.slots.lock().unwrap_or_else(|e| e.into_inner()) += 1;
        self.freed.notify_one();
    }

    fn work(&self, job: &Arc<Job>) {
        if self.acquire(job) {
            job.set(|p| {
                p.queued = false;
                p.started = Some(Instant::now());
            });
            job.wake();
            let (start, before) = (Instant::now(), self.solves.load(Ordering::Relaxed));
            self.solve_all(job);
            self.release();
            let solved = self.solves.load(Ordering::Relaxed) - before;
            let reporter = self.report.lock().ok().and_then(|r| r.clone());
            if let (Some(report), true) = (reporter, solved > 0) {
                report(&job_line(job, solved, start.elapsed()));
            }
        }
        job.set(|p| p.finished = true);
        job.wake();
        let mut running = self.running.lock().unwrap_or_else(|e| e.into_inner());
        if running
            .get(&job.tasks)
            .is_some_and(|w| w.as_ptr() == Arc::as_ptr(job))
        {
            running.remove(&job.tasks);
        }
    }

    fn solve_all(&self, job: &Job) {
        let n = job.tasks.len();
        let mut ended = vec![false; n];
        // The surface of the last scene built, reused by its next loads.
        let mut built: Option<(SceneKey, rough_contact::Contact)> = None;
        loop {
            if job.cancel.load(Ordering::Relaxed) {
                return;
            }
            let preferred = job
                .first
                .lock()
                .map(|f| f.iter().copied().find(|&i| i < n && !ended[i]))
                .unwrap_or(None);
            let next = preferred.or_else(|| ended.iter().position(|e| !e));
            let Some(i) = next else { return };
            ended[i] = true;
            let task = job.tasks[i];
            let solve = !self.has(&task, task.scene.seed == job.drawn);
            if solve {
                let outcome = self.solve_one(job, task, &mut built);
                if outcome.is_err() && job.cancel.load(Ordering::Relaxed) {
                    return;
                }
                if let Ok(mut c) = self.cache.lock() {
                    c.put(task, outcome);
                }
            }
            job.set(|p| {
                p.done += 1;
                p.work_done += work(&task);
                if solve {
                    p.work_solved += work(&task);
                }
                p.iteration = 0;
                p.residual = 0.0;
                p.first_residual = 0.0;
            });
            job.wake();
        }
    }

    fn solve_one(
        &self,
        job: &Job,
        task: Task,
        built: &mut Option<(SceneKey, rough_contact::Contact)>,
    ) -> Outcome {
        self.solves.fetch_add(1, Ordering::Relaxed);
        let began = Instant::now();
        // The same heights capped otherwise (b's sets at one ζ) keep the
        // surface and start from its last answer.
        match built.as_mut() {
            Some(b) if b.0.same_surface(&task.scene) => b.0 = task.scene,
            _ => {
                *built = None;
                let c = task.scene.build().map_err(|e| format!("{e:#}"))?;
                *built = Some((task.scene, c));
            }
        }
        let Some((_, contact)) = built.as_mut() else {
            return Err("no surface".into());
        };
        let start = self.coarse_start(&task);
        if let Some(p) = &start {
            contact.start_from(p).map_err(|e| format!("{e:#}"))?;
        }
        let hardness = task.scene.hardness();
        let mut last_wake = Instant::now();
        let mut progress = |it: usize, r: f64| {
            if job.cancel.load(Ordering::Relaxed) {
                return false;
            }
            if last_wake.elapsed() >= WAKE_EVERY {
                last_wake = Instant::now();
                job.set(|p| {
                    if p.first_residual == 0.0 {
                        p.first_residual = r;
                    }
                    p.iteration = it;
                    p.residual = r;
                });
                job.wake();
            } else if it == 1 {
                job.set(|p| p.first_residual = r);
            }
            true
        };
        let p_mean = task.p_over_h() * hardness;
        let opts = Options::default();
        let r = match task.scene.local() {
            Some(law) => super::local::solve(contact, p_mean, &law, &opts, &mut progress)
                .map(|(r, caps, _)| (r, Some(caps))),
            None => contact
                .solve_with_progress(p_mean, hardness, &opts, &mut progress)
                .map(|r| (r, None)),
        };
        let drawn = task.scene.seed == job.drawn;
        match r {
            Ok((result, caps)) => Ok(Arc::new(Solved {
                result,
                map: match caps {
                    _ if !drawn => vec![],
                    Some(caps) => classify_capped(contact.pressure(), &caps),
                    None => classify(contact.pressure(), hardness),
                },
                pressure: (task.scene.coarse > 0).then(|| contact.pressure().to_vec()),
                took: began.elapsed(),
            })),
            Err(ContactError::Cancelled) => Err("cancelled".into()),
            Err(e) => Err(format!("at p̄/H = {}: {e}", task.p_over_h())),
        }
    }
}

impl Engine {
    /// Where a power-law scene's load on its own grid starts: the finest
    /// coarse answer of the same load in the cache, prolonged (bilinear,
    /// one halving at a time) to the scene's grid. None for a coarse task,
    /// a hardness per asperity (its solve starts from an elastic one) or
    /// a measured map; a hardness per summit starts from the coarse grid's
    /// own summits' answer.
    fn coarse_start(&self, task: &Task) -> Option<Vec<f64>> {
        let scene = task.scene;
        let asperity = scene
            .local
            .is_some_and(|l| l.0 == super::local::Radius::Asperity);
        if scene.coarse > 0 || scene.surface.is_some() || asperity {
            return None;
        }
        (1u8..8).take_while(|c| scene.n >> c >= 2).find_map(|c| {
            let mut key = scene;
            key.coarse = c;
            let coarse = Task {
                scene: key,
                load: task.load,
            };
            let Some(Ok(s)) = self.get(&coarse) else {
                return None;
            };
            let mut p = s.pressure.clone()?;
            let mut side = coarse.scene.side();
            if p.len() != side * side {
                return None;
            }
            while side < scene.n {
                p = rough_contact::prolong(&p, side);
                side *= 2;
            }
            Some(p)
        })
    }
}

/// The line a job's end reports.
fn job_line(job: &Job, solved: usize, took: Duration) -> String {
    let mut grids: Vec<usize> = job.tasks.iter().map(|t| t.scene.n).collect();
    grids.sort_unstable();
    grids.dedup();
    let grid = match (grids.first(), grids.last()) {
        (Some(a), Some(b)) if a != b => format!("{a}²…{b}²"),
        (Some(a), _) => format!("{a}²"),
        _ => "no grid".into(),
    };
    let seed = job.tasks.first().map_or(0, |t| t.scene.seed);
    let holders = job.state.lock().map_or(0, |s| s.holders);
    let s = |n: usize| if n == 1 { "" } else { "s" };
    if job.cancel.load(Ordering::Relaxed) {
        format!(
            "contact: cancelled after {solved} of {} solutions on {grid} (seed {seed})",
            job.tasks.len()
        )
    } else {
        format!(
            "contact: {solved} solution{} on {grid} (seed {seed}) in {:.1} s for {holders} explorer{}",
            s(solved),
            took.as_secs_f64(),
            s(holders)
        )
    }
}
