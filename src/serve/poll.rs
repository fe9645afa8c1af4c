//! Predict, then reveal, as sessions play it. The lecturer's `v` opens a
//! poll on the claim the view and scene make (or, with none, or with `V`,
//! on a value the lecturer types); every student is put on the poll's scene
//! with the marker theirs to move, Enter sends their answer. The poll is a
//! state of the class: it holds, whatever else the lecturer does (moves,
//! views, snapshots, pictures, help, even leaving and coming back), until
//! the lecturer reveals it (`v` again) or cancels it (`C`). At the reveal
//! every student follows again, the model's answer and their miss staying
//! on their screen until the next poll or their Enter. `S` saves the last
//! poll's answers as CSV until a new poll opens.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;

use super::follow::{Scene, FOLLOWING};
use super::seat::Seat;
use crate::class::{Asked, Lesson, Poll, Question, Tally, NOWHERE, UNICODE};
use crate::snapshot;
use crate::tui::app::Message;

/// A student's status when a poll opens.
pub const PREDICT: &str = "predict: ←→ move the marker (⇧ fine), Enter answers";

/// A student's status when the lecturer cancels the poll.
pub const CANCELLED: &str = "the lecturer cancelled the poll";

/// What a student's session does when the poll changes; whether the
/// screen changed.
pub(super) fn on_poll(s: &mut Seat, poll: Option<Arc<Poll>>) -> bool {
    let app = &mut s.ex.app;
    let Some(p) = poll else {
        // Cancelled: an unanswered question goes, a reveal stays.
        if s.poll.take().is_none() || app.class.asked.is_some_and(|a| a.revealed) {
            return false;
        }
        app.class.asked = None;
        let lecturer = s.lecturer.borrow().is_some();
        let e = s.follow.on_poll_end(lecturer);
        s.effect(e);
        s.ex.app.set_status(CANCELLED, false);
        return true;
    };
    if !p.revealed {
        if s.poll == Some(p.id) {
            return false;
        }
        // A new poll: on its scene, the marker's slider selected (when
        // the explorer next needs it: every student's first frame of the
        // question is one render).
        s.poll = Some(p.id);
        app.class.tally = None;
        let question = p.question;
        s.show(Scene::Poll(p));
        let app = &mut s.ex.app;
        app.mode = crate::tui::app::Mode::Main;
        app.class.asked = Some(Asked {
            question,
            answer: None,
            revealed: false,
            changed: false,
        });
        app.set_status(PREDICT, false);
        s.follow.on_poll();
        s.note(crate::class::Note::Following(false));
        return true;
    }
    // The lecturer showed the answers to everyone (`d`).
    let mut shown = false;
    if let (Some(answers), None) = (&p.answers, &app.class.tally) {
        app.class.tally = Some(Tally {
            question: p.question,
            answers: answers.to_vec(),
            asked: answers.len(),
            revealed: true,
            sweep: p.scene.state.sweep,
        });
        shown = true;
    }
    // Revealed: only those who were asked see the result.
    if s.poll != Some(p.id) {
        return shown;
    }
    match app.class.asked.as_mut() {
        Some(a) if !a.revealed => {
            a.revealed = true;
            a.changed = p.changed;
            let line = a.line(&UNICODE, usize::MAX);
            let line = line.trim_end_matches(" · Enter dismisses").to_string();
            s.results
                .push(format!("poll {}: {}", s.results.len() + 1, line));
        }
        _ => return shown,
    }
    let lecturer = s.lecturer.borrow().is_some();
    let e = s.follow.on_poll_end(lecturer);
    s.effect(e);
    true
}

/// The poll keys: the lecturer's `v`, `C` and `S`, a student's Enter.
pub(super) fn on_key(s: &mut Seat, msg: Message) {
    match msg {
        Message::Answer => answer(s, false),
        Message::AnswerNowhere => answer(s, true),
        Message::ShareAnswers if s.is_lecturer() => {
            let text = if s.shared.class.share_answers() {
                "every screen shows the answers' histogram now"
            } else {
                "no revealed poll: d shows its answers after v reveals"
            };
            s.ex.app.set_status(text, false);
        }
        Message::Poll if s.is_lecturer() => {
            let class = &s.shared.class;
            let app = &mut s.ex.app;
            match class.poll() {
                Some(p) if !p.revealed => {
                    // The lecturer may have moved on since asking: the
                    // truth is the scene's as asked, and says so.
                    let changed = !crate::scene::same_scene(&app.state, &p.scene.state);
                    class.reveal(changed);
                    // The lesson's step has had its poll: its answer and
                    // its claims show.
                    app.class.step_revealed();
                    let q = &p.question;
                    let saved = match to_lesson_csv(s) {
                        Some(Ok(path)) => format!("answers added to {}", path.display()),
                        Some(Err(e)) => format!("{e:#}"),
                        None => "S saves the answers".into(),
                    };
                    let asked = if changed {
                        " (for the scene as asked: it has changed since)"
                    } else {
                        ""
                    };
                    s.ex.app.set_status(
                        format!(
                            "revealed: {}{asked} · {saved} · v asks again",
                            q.value(q.truth)
                        ),
                        false,
                    );
                }
                // A lesson's step with a value to poll: that value.
                _ if step_value(app).is_some() => {
                    if let Some(q) = step_value(app) {
                        open(s, q);
                    }
                }
                _ => match Question::of_claims(app.view, &app.claims, app.state.size_effect) {
                    Some(q) => {
                        // A lesson's reading question keeps its chart.
                        let read = step_read(app);
                        open(s, Question { read, ..q })
                    }
                    // No claim here: the lecturer types the value.
                    None => {
                        let _ = s.ex.update(Message::PollTyped);
                    }
                },
            }
        }
        Message::CancelPoll if s.is_lecturer() => {
            let text = if s.shared.class.cancel() {
                "poll cancelled: its answers are dropped"
            } else {
                "no open poll to cancel"
            };
            s.ex.app.set_status(text, false);
        }
        Message::SavePoll if s.is_lecturer() => save(s),
        _ => {}
    }
}

/// Whether the lesson's step the lecturer is at asks a reading question.
fn step_read(app: &crate::tui::app::App) -> bool {
    let at_step = app.class.step.as_ref().is_some_and(|s| s.left.is_none());
    at_step
        && (app.class.lesson.as_ref())
            .and_then(|l| l.step().poll)
            .is_some_and(|q| q.read)
}

/// The poll of a lesson's step on a value, if the lecturer is at one.
fn step_value(app: &crate::tui::app::App) -> Option<Question> {
    app.class.step_poll(app.state.sweep.axis())
}

/// A lesson's CSV: all its polls' rows in one file, made when the first
/// is revealed (or saved open, the server stopping).
#[derive(Debug, Default)]
pub struct LessonCsv {
    pub path: Option<PathBuf>,
    /// The open poll's lesson, if it was asked at a lesson's step, and the
    /// lecturer's save folder.
    asking: Option<(Arc<Lesson>, PathBuf)>,
}

impl LessonCsv {
    /// Appends `rows` to the CSV of `lesson` (made in `dir` the first
    /// time); the file.
    fn append(&mut self, dir: &Path, lesson: &Lesson, rows: &str) -> anyhow::Result<PathBuf> {
        use std::io::Write;
        let path = match &self.path {
            Some(p) => p.clone(),
            None => {
                let p = crate::class::lesson::csv_path(dir, lesson)?;
                self.path = Some(p.clone());
                p
            }
        };
        std::fs::OpenOptions::new()
            .append(true)
            .open(&path)
            .and_then(|mut f| f.write_all(rows.as_bytes()))
            .map_err(|e| anyhow::anyhow!("cannot add the answers to {}: {e}", path.display()))?;
        Ok(path)
    }
}

/// In a lesson, the revealed poll's rows appended to the lesson's one CSV
/// (made at the first reveal, in the lecturer's save folder); `None`
/// outside a lesson.
fn to_lesson_csv(s: &Seat) -> Option<anyhow::Result<PathBuf>> {
    let lesson = &s.ex.app.class.lesson.as_ref()?.lesson;
    let rows = s.shared.class.csv_rows()?;
    let mut slot = s.shared.lesson_csv.lock().ok()?;
    let new = slot.path.is_none();
    let r = slot.append(&s.ex.app.save_dir, lesson, &rows);
    if let (true, Ok(p)) = (new, &r) {
        s.shared.saved(p.clone());
    }
    Some(r)
}

/// After the lecturer's keys: a value typed at `V` opens a poll.
pub(super) fn after_lecturer_keys(s: &mut Seat) {
    if let Some((axis, truth)) = s.ex.app.class.typed.take() {
        open(s, Question::typed(axis, truth));
    }
}

fn open(s: &mut Seat, q: Question) {
    // Asked at a lesson's step: saved open, its rows go to the lesson's CSV.
    let app = &s.ex.app;
    let at_step = app.class.step.as_ref().is_some_and(|st| st.left.is_none());
    let asking = (app.class.lesson.as_ref())
        .filter(|_| at_step)
        .map(|l| (Arc::clone(&l.lesson), app.save_dir.clone()));
    if let Ok(mut slot) = s.shared.lesson_csv.lock() {
        slot.asking = asking;
    }
    // A new poll's countdown starts at the lecturer's `t`.
    s.ex.app.class.countdown = None;
    let shown = s.ex.app.shown();
    let class = &s.shared.class;
    class.open(q, shown);
    let n = class.students();
    s.ex.app.set_status(
        format!(
            "asked {n} {}: {} · v reveals · C cancels",
            if n == 1 { "student" } else { "students" },
            q.text(&UNICODE)
        ),
        false,
    );
}

/// A student's Enter: their marker's value as their answer; after the
/// reveal, it dismisses the result (the student keeps following).
fn answer(s: &mut Seat, nowhere: bool) {
    let app = &mut s.ex.app;
    if app.class.asked.is_some_and(|a| a.revealed) {
        app.class.asked = None;
        s.poll = None;
        let text = if s.follow.following() {
            FOLLOWING
        } else {
            "result dismissed"
        };
        s.ex.app.set_status(text, false);
        return;
    }
    let (Some(id), Some(poll)) = (s.seat, s.poll) else {
        return;
    };
    let Some(asked) = app.class.asked.filter(|a| !a.revealed) else {
        return;
    };
    let q = asked.question;
    if nowhere && !q.nowhere_ok() {
        return;
    }
    let v = if nowhere {
        NOWHERE
    } else {
        app.state.params.get(q.axis)
    };
    match s.shared.class.answer(id, poll, v) {
        Ok(()) => {
            if let Some(a) = app.class.asked.as_mut() {
                a.answer = Some(v);
            }
            app.set_status(format!("answer sent: {}", q.value(v)), false);
        }
        Err(r) => app.set_status(r.text(), true),
    }
}

/// `S`: the answers as CSV in the lecturer's save folder, never over a file.
fn save(s: &mut Seat) {
    let app = &mut s.ex.app;
    let Some(csv) = s.shared.class.csv() else {
        app.set_status("no poll to save: v starts one", true);
        return;
    };
    let name = format!("{}-poll", app.state.name);
    let stem = snapshot::default_stem(&name, SystemTime::now());
    match snapshot::save_file_new(&app.save_dir, &stem, "csv", "poll answers", csv.as_bytes()) {
        Ok(path) => {
            app.set_status(format!("saved {}", path.display()), false);
            s.shared.saved(path);
        }
        Err(e) => app.set_status(format!("{e:#}"), true),
    }
}

/// The server stops with a poll open: its answers so far (and a `no
/// answer` row for each student here) go to the lesson's CSV, or to a
/// CSV of their own in the folder the server runs in; the console's line
/// that says so.
pub(super) fn save_open(shared: &super::Shared) -> Option<String> {
    if !shared.class.poll_open() {
        return None;
    }
    let rows = shared.class.csv_rows()?;
    let answers = shared.class.view().poll.map_or(0, |t| t.answers.len());
    let dir = std::env::current_dir().unwrap_or_else(|_| ".".into());
    let mut slot = shared.lesson_csv.lock().unwrap_or_else(|p| p.into_inner());
    let written = match slot.asking.clone() {
        Some((lesson, folder)) => {
            let new = slot.path.is_none();
            let r = slot.append(&folder, &lesson, &rows);
            if let (true, Ok(p)) = (new, &r) {
                shared.saved(p.clone());
            }
            r
        }
        None => {
            let name = shared
                .class
                .poll()
                .map_or("class".into(), |p| p.scene.state.name.clone());
            let stem = snapshot::default_stem(&format!("{name}-poll"), SystemTime::now());
            let csv = format!("{}\n{rows}", crate::class::CSV_HEADER);
            let path = snapshot::save_file_new(&dir, &stem, "csv", "poll answers", csv.as_bytes());
            if let Ok(p) = &path {
                shared.saved(p.clone());
            }
            path
        }
    };
    Some(match written {
        Ok(path) => format!(
            "the poll was still open: its {answers} {} saved unrevealed in {}",
            if answers == 1 { "answer" } else { "answers" },
            path.display()
        ),
        Err(e) => format!("the poll was still open and its answers were not saved: {e:#}"),
    })
}
