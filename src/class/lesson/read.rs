//! A lesson's file: RON read, checked step by step, each refusal naming
//! the file, the step and the problem.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context};
use rough_model::Axis;
use serde::Deserialize;

use super::{Lesson, Step, MAX_BYTES, MAX_STEPS};
use crate::class::question::{Ask, Question, NOWHERE};
use crate::figure::{claims, View};

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
    /// `true`: the poll is a reading question (its answer is read off the
    /// chart, whose curves stay while it is open); else a prediction,
    /// whose curves wait for the reveal.
    #[serde(default)]
    read: Option<bool>,
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
            Question::of_claims(view, &claims(&state), state.size_effect)
                .ok_or_else(|| anyhow!("poll: Claim, but this scene makes no claim"))?,
        ),
        Some(PollFile::Share) => {
            let share = claims(&state)
                .into_iter()
                .find(|c| c.kind == crate::figure::ClaimKind::ShareHalf);
            Some(Question {
                axis: state.sweep.axis(),
                ask: Ask::ShareEver,
                truth: share.map_or(NOWHERE, |c| c.at),
                size_effect: state.size_effect,
                read: false,
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
            Some(Question::typed(axis, truth))
        }
    };
    let poll = match (poll, s.read) {
        (Some(q), read) => Some(Question {
            read: read.unwrap_or(false),
            ..q
        }),
        (None, Some(_)) => bail!("read: applies to a step's poll, and this step has none"),
        (None, None) => None,
    };
    Ok(Step {
        title: s.title,
        state,
        view,
        poll,
        claims_hidden: matches!(s.claims, Some(ClaimsFile::Hidden)),
    })
}
