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
}

/// A lesson and the step on screen.
#[derive(Clone, Debug, PartialEq)]
pub struct LessonAt {
    pub lesson: Arc<Lesson>,
    pub at: usize,
}

impl LessonAt {
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
}

impl StepLine {
    pub fn text(&self) -> String {
        format!("step {}/{} · {}", self.at, self.of, self.title)
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
        let at = LessonAt {
            lesson: Arc::new(l),
            at: 1,
        };
        assert_eq!(at.line().text(), "step 2/3 · two");
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
    }
}
