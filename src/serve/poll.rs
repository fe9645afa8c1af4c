//! Predict, then reveal, as sessions play it. The lecturer's `v` opens a
//! poll on the claim the view and scene make (or, with none, or with `V`,
//! on a value the lecturer types); every student is put on the poll's scene
//! with the marker theirs to move, Enter sends their answer, and the
//! lecturer's `v` again reveals the model's answer to all, who then follow
//! again. `S` saves the answers as CSV. The poll ends when the lecturer
//! moves on from the revealed scene, opens another, or leaves.

use std::sync::Arc;
use std::time::SystemTime;

use rough_model::Axis;

use super::class::Poll;
use super::session::Seat;
use crate::snapshot;
use crate::tui::app::Message;
use crate::tui::class::{Ask, Asked, Question, UNICODE};

/// A student's status when a poll opens.
pub const PREDICT: &str = "predict: ←→ move the marker (⇧ fine), Enter answers";

/// What a student's session does when the poll changes; whether the
/// screen changed.
pub(super) fn on_poll(s: &mut Seat, poll: Option<Arc<Poll>>) -> bool {
    let app = &mut s.ex.app;
    let Some(p) = poll else {
        // Closed: the result line goes; an unanswered student follows again.
        let had = app.class.asked.take().is_some();
        s.poll = None;
        let lecturer = s.lecturer.borrow().is_some();
        let e = s.follow.on_poll_end(lecturer);
        s.effect(e);
        return had;
    };
    if !p.revealed {
        if s.poll == Some(p.id) {
            return false;
        }
        // A new poll: on its scene, the marker's slider selected.
        s.poll = Some(p.id);
        p.scene.apply(app);
        if let Some(i) = Axis::ALL.iter().position(|a| *a == p.question.axis) {
            app.selected = i;
        }
        app.mode = crate::tui::app::Mode::Main;
        app.class.asked = Some(Asked {
            question: p.question,
            answer: None,
            revealed: false,
        });
        app.set_status(PREDICT, false);
        s.follow.on_poll();
        s.note(super::class::Note::Following(false));
        return true;
    }
    // Revealed: only those who were asked see the result.
    if s.poll != Some(p.id) {
        return false;
    }
    if let Some(a) = app.class.asked.as_mut() {
        a.revealed = true;
    }
    let lecturer = s.lecturer.borrow().is_some();
    let e = s.follow.on_poll_end(lecturer);
    s.effect(e);
    true
}

/// The poll keys: the lecturer's `v` and `S`, a student's Enter.
pub(super) fn on_key(s: &mut Seat, msg: Message) {
    match msg {
        Message::Answer => answer(s),
        Message::Poll if s.is_lecturer() => {
            let class = &s.shared.class;
            let app = &mut s.ex.app;
            match class.poll() {
                Some(p) if !p.revealed => {
                    class.reveal();
                    let q = &p.question;
                    app.set_status(
                        format!(
                            "revealed: {} · S saves the answers · v asks again",
                            q.value(q.truth)
                        ),
                        false,
                    );
                }
                _ => match Question::of_claims(app.view, &app.claims) {
                    Some(q) => open(s, q),
                    // No claim here: the lecturer types the value.
                    None => {
                        let _ = s.ex.update(Message::PollTyped);
                    }
                },
            }
        }
        Message::SavePoll if s.is_lecturer() => save(s),
        _ => {}
    }
}

/// After the lecturer's keys: a typed value opens a poll; a move away from
/// a revealed poll's scene ends it.
pub(super) fn after_lecturer_keys(s: &mut Seat) {
    if let Some((axis, truth)) = s.ex.app.class.typed.take() {
        let ask = Ask::Typed;
        open(s, Question { axis, ask, truth });
        return;
    }
    let class = &s.shared.class;
    if class
        .poll()
        .is_some_and(|p| p.revealed && p.scene.state != s.ex.app.state)
    {
        class.close();
    }
}

fn open(s: &mut Seat, q: Question) {
    let shown = super::follow::Shown::of(&s.ex.app);
    let class = &s.shared.class;
    class.open(q, shown);
    let n = class.students();
    s.ex.app.set_status(
        format!(
            "asked {n} {}: {} · v reveals",
            if n == 1 { "student" } else { "students" },
            q.text(&UNICODE)
        ),
        false,
    );
}

/// A student's Enter: their marker's value as their answer.
fn answer(s: &mut Seat) {
    let (Some(id), Some(poll)) = (s.seat, s.poll) else {
        return;
    };
    let app = &mut s.ex.app;
    let Some(asked) = app.class.asked.filter(|a| !a.revealed) else {
        return;
    };
    let q = asked.question;
    let v = app.state.params.get(q.axis);
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
        Ok(path) => app.set_status(format!("saved {}", path.display()), false),
        Err(e) => app.set_status(format!("{e:#}"), true),
    }
}
