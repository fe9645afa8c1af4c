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
    /// Of `work_done`, the work this job solved itself (not found in the
    /// cache): the rate the time left is measured by.
    pub work_solved: f64,
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

    /// The time left: the work left at the rate this job has solved so
    /// far. Work found in the cache (a job resumed after the view was
    /// left) took no time and does not count towards the rate; none before
    /// a twentieth of the work left has been solved (too early to say).
    pub fn left(&self) -> Option<Duration> {
        let took = self.started?.elapsed().as_secs_f64();
        if self.finished || self.queued || self.work_total <= 0.0 {
            return None;
        }
        let f = self.fraction();
        let done = f * self.work_total;
        let cached = self.work_done - self.work_solved;
        let solved = done - cached;
        let left = self.work_total - done;
        if solved <= 0.05 * (self.work_total - cached) || solved <= 0.0 {
            return None;
        }
        Some(Duration::from_secs_f64(took * left / solved))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A job resumed with most of its work in the cache: the time left
    /// goes by the rate of the work solved since, not by the fraction done
    /// (which would say "1 s left" of minutes).
    #[test]
    fn the_time_left_after_a_resume_goes_by_the_work_solved() {
        let p = Progress {
            done: 9,
            total: 10,
            work_done: 90.0,
            work_total: 100.0,
            work_solved: 10.0,
            started: Some(Instant::now() - Duration::from_secs(10)),
            ..Progress::default()
        };
        // 10 units solved in 10 s, 10 left: 10 s, not 10 × 10/90 = 1.1 s.
        let left = p.left().unwrap().as_secs_f64();
        assert!((left - 10.0).abs() < 0.1, "{left}");
        // All of it in the cache so far: too early to say.
        let resumed = Progress {
            work_solved: 0.0,
            ..p.clone()
        };
        assert_eq!(resumed.left(), None);
    }
}
