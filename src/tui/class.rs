//! The explorer's side of a class it is part of: the class list's keys
//! (`↑` `↓` `x`) and a lesson's step brought on screen. What the class
//! is (the roster, the polls, the lessons, the answers' CSV) is
//! [`crate::class`]; the explorer draws it (`views::class`) and shows a
//! step's scene as it shows any scene loaded.

use std::sync::Arc;

use crate::class::{Lesson, LessonEnd, StepScene};
use crate::tui::app::App;

/// The lecturer's `P` (the projector view, open or closed) and, in it,
/// `t` (the countdown: 30 s, 1 min, 2 min, off, each from the start).
pub fn projector(app: &mut App, msg: crate::tui::app::Message) {
    use crate::tui::app::Message;
    use std::time::{Duration, Instant};
    if app.class.view.is_none() {
        return;
    }
    match msg {
        Message::Projector => app.class.projector = !app.class.projector,
        Message::Countdown => {
            let next = match app.class.countdown.map(|c| c.1.as_secs()) {
                None => Some(30),
                Some(30) => Some(60),
                Some(60) => Some(120),
                _ => None,
            };
            app.class.countdown = next.map(|s| {
                let d = Duration::from_secs(s);
                (Instant::now() + d, d)
            });
        }
        _ => {}
    }
}

/// The class list's `↑` / `↓`: the previous / next student.
pub fn choose(app: &mut App, down: bool) {
    let n = app.class.view.as_ref().map_or(0, |v| v.seats.len());
    if n == 0 {
        return;
    }
    let c = app.class.chosen.min(n - 1);
    app.class.chosen = if down { (c + 1) % n } else { (c + n - 1) % n };
}

/// The class list's `x`: the chosen student is to be removed.
pub fn remove(app: &mut App) {
    let v = app.class.view.as_ref();
    app.class.remove = v.and_then(|v| v.seats.get(app.class.chosen)).map(|s| s.id);
}

/// Leads `lesson` from its first step (the lecturer's, or alone to
/// rehearse).
pub fn start_lesson(app: &mut App, lesson: Arc<Lesson>) {
    if let Some(step) = app.class.start_lesson(lesson) {
        show(app, step);
    }
}

/// `n` / `N`: the next or previous step (at either end, a line says so).
pub fn step(app: &mut App, next: bool) {
    match app.class.lesson_step(next) {
        Some(Ok(step)) => show(app, step),
        Some(Err(LessonEnd::Last)) => app.set_status("the lesson's last step: N goes back", false),
        Some(Err(LessonEnd::First)) => app.set_status("the lesson's first step: n goes on", false),
        None => {}
    }
}

/// A step's scene, view and caption on screen, with its keys.
fn show(app: &mut App, step: StepScene) {
    app.load_state(step.state);
    app.view = step.view;
    let text = if step.poll {
        "v opens this step's poll · n next step · N back"
    } else {
        "n next step · N back"
    };
    app.set_status(text, false);
}
