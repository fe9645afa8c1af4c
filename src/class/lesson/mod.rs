//! Lessons: an ordered list of steps a lecturer walks through (`n` next,
//! `N` back), each a scene (a preset or a snapshot file) with its view, an
//! optional caption of its own and an optional poll (the claim the view
//! makes, or a value of the swept parameter). A lesson file is RON:
//!
//! ```ron
//! (
//!     title: "The paper's argument",
//!     steps: [
//!         (title: "Bulk hardness", scene: Preset("fig1"), view: "slopes"),
//!         (title: "Finer scales", scene: Snapshot("mine.ron"), poll: Claim),
//!         (title: "Guess ζ", scene: Preset("fig2"), poll: Value(100.0)),
//!         (title: "Plastic at all?", scene: Preset("fig3"), poll: Share),
//!         (title: "Before a poll", scene: Preset("fig1"), claims: Hidden),
//!     ],
//! )
//! ```
//!
//! `roughtui serve --lesson FILE` leads a class through it (every screen
//! shows "step 3/8 · title", `v` opens the step's poll, all the lesson's
//! polls go to one CSV); `roughtui --lesson FILE` rehearses alone. The
//! whole file is checked when it is read: a bad step is an error naming
//! the file, the step and the problem.

mod read;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::question::Question;
use crate::figure::View;
use crate::scene::State;
pub use read::{parse, read};

/// The most steps a lesson has.
pub const MAX_STEPS: usize = 100;

/// The most bytes a lesson file has.
pub const MAX_BYTES: u64 = 1 << 20;

/// A lesson, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Lesson {
    pub title: String,
    /// The file's name without its extension (the CSV is named after it).
    pub stem: String,
    pub steps: Vec<Step>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    pub title: String,
    /// The scene, its caption the step's own where it has one.
    pub state: State,
    pub view: View,
    /// The step's poll: its question and true value.
    pub poll: Option<Question>,
    /// The claims and regime marks wait (`claims: Hidden`).
    pub claims_hidden: bool,
}

/// A lesson and the step on screen.
#[derive(Clone, Debug, PartialEq)]
pub struct LessonAt {
    pub lesson: Arc<Lesson>,
    pub at: usize,
    /// Which steps' polls were revealed (in this run of the lesson).
    revealed: Vec<bool>,
}

impl LessonAt {
    /// `lesson` at step `at` (from 0), no poll revealed yet.
    pub fn new(lesson: Arc<Lesson>, at: usize) -> LessonAt {
        let revealed = vec![false; lesson.steps.len()];
        LessonAt {
            lesson,
            at,
            revealed,
        }
    }

    /// The step's poll was revealed: the claims a step hid for it show
    /// from now on.
    pub fn mark_revealed(&mut self) {
        if let Some(r) = self.revealed.get_mut(self.at) {
            *r = true;
        }
    }

    /// The lesson's next poll (its own, or a later step's), if any.
    fn next_poll(&self) -> Option<usize> {
        let steps = &self.lesson.steps;
        (self.at..steps.len()).find(|i| steps[*i].poll.is_some())
    }

    /// Whether the step's claims wait: it hides them (`claims: Hidden`)
    /// and the lesson's next poll (its own, or a later step's) has not
    /// been revealed.
    fn claims_wait(&self) -> bool {
        self.step().claims_hidden && self.next_poll().is_none_or(|i| !self.revealed[i])
    }

    pub fn step(&self) -> &Step {
        &self.lesson.steps[self.at.min(self.lesson.steps.len() - 1)]
    }

    /// "step 3/8 · Finer scales"
    pub fn line(&self) -> StepLine {
        StepLine {
            at: self.at + 1,
            of: self.lesson.steps.len(),
            title: self.step().title.clone(),
            pending: self.step().poll,
            claims_hidden: self.claims_wait(),
            next: self
                .next_poll()
                .filter(|_| self.claims_wait())
                .and_then(|i| self.lesson.steps[i].poll),
            left: None,
        }
    }
}

/// Where a lesson stands, as every screen shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct StepLine {
    /// From 1.
    pub at: usize,
    pub of: usize,
    pub title: String,
    /// The step's poll, until it is revealed: what would answer it stays
    /// off every screen.
    pub pending: Option<Question>,
    /// The step hides its claims (`claims: Hidden`), until the lesson's
    /// next poll is revealed.
    pub claims_hidden: bool,
    /// That next poll's question while the step hides its claims: what
    /// would answer it stays off every screen too.
    pub next: Option<Question>,
    /// The scene the lecturer loaded with `o`, away from the lesson's
    /// step (`n` returns to it).
    pub left: Option<String>,
}

impl StepLine {
    pub fn text(&self) -> String {
        match &self.left {
            Some(scene) => format!(
                "left the lesson at step {}/{} for {scene} · n returns",
                self.at, self.of
            ),
            None => format!("step {}/{} · {}", self.at, self.of, self.title),
        }
    }

    /// Whether what the claims say stays off the screen: before a poll,
    /// or on a step that hides them (not once the class left the lesson).
    pub fn hides_claims(&self) -> bool {
        self.left.is_none() && (self.pending.is_some() || self.claims_hidden)
    }
}

/// What a step puts on screen: its scene (a fresh state, with the step's
/// caption), the view it is shown in, and whether it has a poll to open.
#[derive(Clone, Debug, PartialEq)]
pub struct StepScene {
    pub state: State,
    pub view: View,
    pub poll: bool,
}

impl Step {
    /// The step's scene, to show.
    pub fn scene(&self) -> StepScene {
        StepScene {
            state: self.state.clone(),
            view: self.view,
            poll: self.poll.is_some(),
        }
    }
}

/// The lesson's CSV of all its polls, in `dir`, named once per run.
pub fn csv_path(dir: &Path, lesson: &Lesson) -> anyhow::Result<PathBuf> {
    let stem = crate::snapshot::default_stem(
        &format!("{}-polls", lesson.stem),
        std::time::SystemTime::now(),
    );
    crate::snapshot::save_file_new(
        dir,
        &stem,
        "csv",
        "lesson poll answers",
        format!("{}\n", super::csv::CSV_HEADER).as_bytes(),
    )
}

#[cfg(test)]
mod tests;
