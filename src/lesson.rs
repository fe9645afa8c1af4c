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

use std::path::{Path, PathBuf};
use std::sync::Arc;

use anyhow::{anyhow, bail, Context};
use rough_model::Axis;
use serde::Deserialize;

use crate::figure::{claims, View};
use crate::scene::State;
use crate::tui::app::App;
use crate::tui::class::{Ask, Question};

/// The most steps a lesson has.
pub const MAX_STEPS: usize = 100;

/// The most bytes a lesson file has.
pub const MAX_BYTES: u64 = 1 << 20;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LessonFile {
    title: String,
    steps: Vec<StepFile>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StepFile {
    title: String,
    scene: SceneFile,
    #[serde(default)]
    view: Option<String>,
    #[serde(default)]
    caption: Option<String>,
    #[serde(default)]
    poll: Option<PollFile>,
    /// `Hidden`: the claims line and the chart's regime marks wait (a
    /// step before a poll whose answer they would give).
    #[serde(default)]
    claims: Option<ClaimsFile>,
}

#[derive(Debug, Deserialize)]
enum ClaimsFile {
    Shown,
    Hidden,
}

#[derive(Debug, Deserialize)]
enum SceneFile {
    Preset(String),
    /// A snapshot file, relative to the lesson file.
    Snapshot(PathBuf),
}

#[derive(Debug, Deserialize)]
enum PollFile {
    /// Where the view's claim holds (as the lecturer's `v`).
    Claim,
    /// A value of the swept parameter, in the model's units (metres).
    Value(f64),
    /// Where the plastic share passes ½, if anywhere: "nowhere in the
    /// sweep" (a student's `0`) may be the answer.
    Share,
}

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

    /// Whether the step's claims wait: it hides them (`claims: Hidden`)
    /// and the lesson's next poll (its own, or a later step's) has not
    /// been revealed.
    fn claims_wait(&self) -> bool {
        let steps = &self.lesson.steps;
        let next = (self.at..steps.len()).find(|i| steps[*i].poll.is_some());
        self.step().claims_hidden && next.is_none_or(|i| !self.revealed[i])
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

/// Reads and checks the lesson at `path`.
pub fn read(path: &Path) -> anyhow::Result<Lesson> {
    let name = path.display();
    let meta = std::fs::metadata(path).with_context(|| format!("cannot read the lesson {name}"))?;
    if meta.is_dir() {
        bail!("the lesson {name} is a folder, not a file");
    }
    if meta.len() > MAX_BYTES {
        bail!("the lesson {name} is larger than {MAX_BYTES} bytes");
    }
    let bytes = std::fs::read(path).with_context(|| format!("cannot read the lesson {name}"))?;
    let text = std::str::from_utf8(&bytes)
        .map_err(|_| anyhow!("the lesson {name} is not valid UTF-8 text"))?;
    parse(text, path)
}

/// Parses and checks a lesson's `text`, snapshots relative to `path`'s
/// folder.
pub fn parse(text: &str, path: &Path) -> anyhow::Result<Lesson> {
    let name = path.display();
    let opts =
        ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let file: LessonFile = opts.from_str(text).map_err(|e| {
        anyhow!(
            "the lesson {name}, line {} column {}: {}",
            e.span.start.line,
            e.span.start.col,
            e.code
        )
    })?;
    if file.steps.is_empty() {
        bail!("the lesson {name} has no steps");
    }
    if file.steps.len() > MAX_STEPS {
        bail!("the lesson {name} has more than {MAX_STEPS} steps");
    }
    let base = path.parent().unwrap_or(Path::new("."));
    let steps = file
        .steps
        .into_iter()
        .enumerate()
        .map(|(i, s)| {
            read_step(s, base).with_context(|| format!("the lesson {name}, step {}", i + 1))
        })
        .collect::<anyhow::Result<Vec<Step>>>()?;
    let stem = path
        .file_stem()
        .map_or("lesson".into(), |s| s.to_string_lossy().into_owned());
    Ok(Lesson {
        title: file.title,
        stem,
        steps,
    })
}

fn read_step(s: StepFile, base: &Path) -> anyhow::Result<Step> {
    if s.title.trim().is_empty() || s.title.chars().any(char::is_control) {
        bail!("the title must be a line of text");
    }
    let mut state = match &s.scene {
        SceneFile::Preset(p) => crate::presets::load(p)?,
        SceneFile::Snapshot(f) => crate::snapshot::load_file(&base.join(f))?,
    };
    match s.caption {
        Some(c) => {
            crate::scene::check_caption(&c).map_err(|e| anyhow!("caption: {e}"))?;
            state.caption = Some(c);
        }
        // A poll's step shows only a caption of its own: a preset's may
        // name the answer.
        None if s.poll.is_some() => state.caption = None,
        None => {}
    }
    let view = match s.view.as_deref() {
        None => View::Slopes,
        Some(v) => View::parse(v).ok_or_else(|| {
            let names: Vec<&str> = View::ALL.iter().map(|v| v.name()).collect();
            anyhow!("view \"{v}\" is not one of {}", names.join(", "))
        })?,
    };
    if !view.exists(state.is_measured()) {
        bail!("the {} view needs a measured surface", view.name());
    }
    let poll = match s.poll {
        None => None,
        Some(PollFile::Claim) => Some(
            Question::of_claims(view, &claims(&state))
                .ok_or_else(|| anyhow!("poll: Claim, but this scene makes no claim"))?,
        ),
        Some(PollFile::Share) => {
            let share = claims(&state)
                .into_iter()
                .find(|c| c.kind == crate::figure::ClaimKind::ShareHalf);
            Some(Question {
                axis: state.sweep.axis(),
                ask: Ask::ShareEver,
                truth: share.map_or(crate::tui::class::NOWHERE, |c| c.at),
            })
        }
        Some(PollFile::Value(truth)) => {
            let sw = &state.sweep;
            let axis: Axis = sw.axis();
            if !(truth >= sw.from() && truth <= sw.to()) {
                bail!(
                    "poll: Value({truth}) is outside the sweep of {}, {}…{}",
                    axis.symbol(),
                    sw.from(),
                    sw.to()
                );
            }
            Some(Question {
                axis,
                ask: Ask::Typed,
                truth,
            })
        }
    };
    Ok(Step {
        title: s.title,
        state,
        view,
        poll,
        claims_hidden: matches!(s.claims, Some(ClaimsFile::Hidden)),
    })
}

/// Shows the lesson's current step in `app`: its scene, view and caption.
pub fn show(app: &mut App) {
    let Some(at) = app.class.lesson.clone() else {
        return;
    };
    let s = at.step();
    app.load_state(s.state.clone());
    app.view = s.view;
    app.class.step = Some(at.line());
    let text = if s.poll.is_some() {
        "v opens this step's poll · n next step · N back"
    } else {
        "n next step · N back"
    };
    app.set_status(text, false);
}

/// `n` / `N`: the next or previous step (at either end, a line says so).
pub fn step(app: &mut App, next: bool) {
    // Back from a scene loaded with `o`: `n` returns to the step left.
    if next && app.class.step.as_ref().is_some_and(|s| s.left.is_some()) {
        show(app);
        return;
    }
    let Some(at) = app.class.lesson.as_mut() else {
        return;
    };
    let n = at.lesson.steps.len();
    let to = if next {
        at.at.checked_add(1).filter(|t| *t < n)
    } else {
        at.at.checked_sub(1)
    };
    match to {
        Some(t) => {
            at.at = t;
            show(app);
        }
        None if next => app.set_status("the lesson's last step: N goes back", false),
        None => app.set_status("the lesson's first step: n goes on", false),
    }
}

/// The lecturer loaded `scene` with `o`: the step line says the class
/// left the lesson (`n` returns).
pub fn leave(app: &mut App, scene: &str) {
    if let Some(step) = app.class.step.as_mut() {
        step.left = Some(scene.to_string());
        step.pending = None;
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
        format!("{}\n", crate::serve::class::CSV_HEADER).as_bytes(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_here(text: &str) -> anyhow::Result<Lesson> {
        parse(text, Path::new("lessons/test.ron"))
    }

    #[test]
    fn a_lesson_reads_its_steps_views_and_polls() {
        let l = parse_here(
            r#"(title: "t", steps: [
                (title: "one", scene: Preset("fig1")),
                (title: "two", scene: Preset("fig2"), view: "indices", poll: Claim,
                 caption: "mine"),
                (title: "three", scene: Preset("fig2"), poll: Value(100.0)),
            ])"#,
        )
        .unwrap();
        assert_eq!(l.stem, "test");
        assert_eq!(l.steps.len(), 3);
        assert_eq!(l.steps[0].view, View::Slopes);
        assert_eq!(l.steps[0].poll, None);
        let q = l.steps[1].poll.unwrap();
        assert_eq!(
            q.text(&crate::tui::class::UNICODE),
            "where does Ψ_P reach 1?"
        );
        assert_eq!(l.steps[1].state.caption.as_deref(), Some("mine"));
        assert_eq!(l.steps[2].poll.unwrap().truth, 100.0);
        let at = LessonAt::new(Arc::new(l), 1);
        assert_eq!(at.line().text(), "step 2/3 · two");
    }

    #[test]
    fn hidden_claims_wait_for_the_lessons_next_poll() {
        let l = parse_here(
            r#"(title: "t", steps: [
                (title: "one", scene: Preset("fig1"), claims: Hidden),
                (title: "two", scene: Preset("fig1"), poll: Claim, claims: Hidden),
                (title: "three", scene: Preset("fig2")),
                (title: "four", scene: Preset("fig2"), claims: Hidden),
            ])"#,
        )
        .unwrap();
        let mut at = LessonAt::new(Arc::new(l), 0);
        let hides = |at: &mut LessonAt, i: usize| {
            at.at = i;
            at.line().hides_claims()
        };
        assert!(hides(&mut at, 0) && hides(&mut at, 1));
        assert!(!hides(&mut at, 2));
        // Step two's poll revealed: one's and two's claims show (two's
        // question is asked again if the lecturer comes back to it).
        at.at = 1;
        at.mark_revealed();
        assert!(!hides(&mut at, 0));
        at.at = 1;
        assert!(!at.line().claims_hidden && at.line().pending.is_some());
        // No poll after step four: its claims wait for good.
        assert!(hides(&mut at, 3));
    }

    #[test]
    fn bad_lessons_say_where_and_what() {
        let err = |t: &str| format!("{:#}", parse_here(t).unwrap_err());
        let e = err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig9"))])"#);
        assert!(
            e.starts_with("the lesson lessons/test.ron, step 1: "),
            "{e}"
        );
        assert!(e.contains("fig9"), "{e}");
        let e = err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig1"), view: "pie")])"#);
        assert!(
            e.contains("view \"pie\" is not one of slopes, indices"),
            "{e}"
        );
        let e =
            err(r#"(title: "t", steps: [(title: "a", scene: Preset("fig2"), poll: Value(1e9))])"#);
        assert!(e.contains("outside the sweep"), "{e}");
        let e = err(r#"(title: "t", steps: [])"#);
        assert_eq!(e, "the lesson lessons/test.ron has no steps");
        let e = err("(title: \"t\",\n steps: [(titel: \"a\")])");
        assert!(
            e.starts_with("the lesson lessons/test.ron, line 2 column"),
            "{e}"
        );
        assert!(e.contains("titel"), "{e}");
        let e = err(r#"(title: "t", steps: [(title: "a", scene: Snapshot("none.ron"))])"#);
        assert!(e.contains("step 1") && e.contains("none.ron"), "{e}");
    }

    #[test]
    fn the_shipped_lesson_walks_the_paper_with_three_polls() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
        let l = read(&path).unwrap();
        assert!((6..=8).contains(&l.steps.len()), "{}", l.steps.len());
        let polls: Vec<&Step> = l.steps.iter().filter(|s| s.poll.is_some()).collect();
        assert_eq!(polls.len(), 3);
        // From fig1 to fig4, in the paper's order.
        let names: Vec<&str> = l.steps.iter().map(|s| s.state.name.as_str()).collect();
        assert_eq!(names.first(), Some(&"fig1"));
        assert_eq!(names.last(), Some(&"fig4"));
        // Step 1 keeps the paper's qualifier and hides the claims that
        // would answer step 2's poll.
        let one = &l.steps[0];
        let cap = one.state.caption.as_deref().unwrap();
        assert!(
            cap.contains(
                "only because the surface is very smooth and the magnification is quite low"
            ),
            "{cap}"
        );
        assert!(one.claims_hidden && l.steps[1].poll.is_some());
        // fig3's poll asks what the paper asks: is there plastic area at
        // all? Nowhere: the plastic area is zero over the whole range.
        let fig3 = polls.iter().find(|s| s.state.name == "fig3").unwrap();
        let q = fig3.poll.unwrap();
        assert_eq!(
            (q.ask, q.truth),
            (Ask::ShareEver, crate::tui::class::NOWHERE)
        );
        let message = l
            .steps
            .iter()
            .find(|s| s.title.contains("message"))
            .unwrap();
        assert!(message
            .state
            .caption
            .as_deref()
            .unwrap()
            .contains("the plastic area is zero over the whole range"));
    }
}
