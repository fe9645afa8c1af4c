//! Where a contact job stands.

use std::time::{Duration, Instant};

use rough_contact::Options;

/// Where a job stands.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Progress {
    /// Tasks ended (solved, failed or found in the cache).
    pub done: usize,
    pub total: usize,
    /// Whether the job waits for a free core.
    pub queued: bool,
    /// The task being solved: its iterations and residual so far.
    pub iteration: usize,
    pub residual: f64,
    /// The first residual of the task being solved (for the bar).
    pub first_residual: f64,
    pub finished: bool,
    /// Work of the tasks ended and of all, in nodes solved (a coarse
    /// grid's task counts for its few nodes).
    pub work_done: f64,
    pub work_total: f64,
    /// When the job got its core.
    pub started: Option<Instant>,
}

impl Progress {
    /// The fraction done, the current task counted by how far its residual
    /// has fallen (in decades) from the first towards the tolerance.
    pub fn fraction(&self) -> f64 {
        if self.total == 0 || self.finished {
            return 1.0;
        }
        let tol = Options::default().tolerance;
        let part = if self.residual > 0.0 && self.first_residual > tol {
            ((self.first_residual / self.residual).ln() / (self.first_residual / tol).ln())
                .clamp(0.0, 0.99)
        } else {
            0.0
        };
        if self.work_total > 0.0 && self.done < self.total {
            // The task under way weighs as the tasks left do on average.
            let each = (self.work_total - self.work_done) / (self.total - self.done) as f64;
            return ((self.work_done + part * each) / self.work_total).clamp(0.0, 1.0);
        }
        ((self.done as f64 + part) / self.total as f64).clamp(0.0, 1.0)
    }

    /// The time left, from the time taken so far and the work done (none
    /// before a twentieth is done: too early to say).
    pub fn left(&self) -> Option<Duration> {
        let f = self.fraction();
        let took = self.started?.elapsed().as_secs_f64();
        if self.finished || self.queued || f < 0.05 {
            return None;
        }
        Some(Duration::from_secs_f64(took * (1.0 - f) / f))
    }
}
