//! The class as one explorer holds it: the lecturer's view of the class,
//! a student's poll, the answers shown to everyone, the lesson led and
//! its step, and what the lecturer picked (a student to remove, a scene
//! to load). The explorer draws it; the server fills it in.

use std::sync::Arc;

use rough_model::Axis;

use super::lesson::{Lesson, LessonAt, StepLine, StepScene};
use super::question::{Ask, Question};
use super::scenes::SceneList;
use super::view::{Asked, ClassView, Tally};
use crate::figure::Withheld;

/// The class as one explorer sees it: the lecturer's view, or a student's
/// poll, and the value a lecturer typed for a poll (taken by the server).
/// With the scene the explorer shows, this is all a screen draws of its
/// class: plain data, for the terminal or any other renderer.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Classroom {
    /// Set for the lecturer of a served class.
    pub view: Option<ClassView>,
    /// Set for a student while a poll is on.
    pub asked: Option<Asked>,
    /// The true value the lecturer typed for a new poll, until the server
    /// takes it.
    pub typed: Option<(Axis, f64)>,
    /// The lesson led from this explorer (the lecturer's, or alone to
    /// rehearse) and its step.
    pub lesson: Option<LessonAt>,
    /// The lesson's step as every screen shows it (a student's from the
    /// lecturer).
    pub step: Option<StepLine>,
    /// The row chosen in the lecturer's class list (`x` removes it).
    pub chosen: usize,
    /// The student the lecturer chose to remove, until the server acts.
    pub remove: Option<u64>,
    /// The lecturer's scene list, while open.
    pub scenes: Option<SceneList>,
    /// The revealed poll's answers, when the lecturer shows them to
    /// everyone (`d`): a student's chart draws their histogram.
    pub tally: Option<Tally>,
    /// The class's web page with its code (`serve --web`), for the
    /// lecturer's `Q`.
    pub join_url: Option<String>,
    /// `Q`'s full-screen QR code is up (any key closes it).
    pub join_shown: bool,
    /// The lecturer's projector view (`P`) is up.
    pub projector: bool,
    /// The poll's countdown on the projector (`t`): when it ends, and how
    /// long it was.
    pub countdown: Option<(std::time::Instant, std::time::Duration)>,
}

impl Classroom {
    /// The question of a poll that is open (asked, not yet revealed), for
    /// the lecturer or a student: while it is, no screen shows its answer.
    pub fn open_question(&self) -> Option<Question> {
        let asked = self.asked.filter(|a| !a.revealed).map(|a| a.question);
        let tally = self.view.as_ref().and_then(|v| v.poll.as_ref());
        asked.or_else(|| tally.filter(|t| !t.revealed).map(|t| t.question))
    }

    /// The question whose answer no screen shows: an open poll's, or the
    /// poll a lesson's step is about to ask (until its reveal).
    pub fn hidden_question(&self) -> Option<Question> {
        let step = self.step.as_ref().filter(|s| s.left.is_none());
        self.open_question()
            .or_else(|| step.and_then(|s| s.pending))
    }

    /// Whether what gives or brackets a claim's answer waits: the chart's
    /// regime marks (the share's 10 % and 90 % marks bracket its ½, Ψ = 1
    /// sits near it), the readout's values at the marker, the map's
    /// colours and its Ψ = 1 contour, the load and contact views (both
    /// at the marker); a typed value's poll hides none. The curves stay:
    /// they are what a student reads the answer from.
    pub fn marks_hidden(&self) -> bool {
        match self.hidden_question() {
            Some(q) => q.ask != Ask::Typed,
            None => self.claims_hidden(),
        }
    }

    /// What a view of a scene (with the size-dependent hardness when
    /// `size_effect`) leaves out: while a poll's answer waits, the marks
    /// ([`Classroom::marks_hidden`]) and the curves whose drawing answers
    /// it ([`Question::withheld`]): the open or pending poll's, or on a
    /// lesson's step that hides its claims, the lesson's next poll's.
    pub fn withheld(&self, size_effect: bool) -> Withheld {
        let step = self.step.as_ref().filter(|s| s.left.is_none());
        let q = self
            .hidden_question()
            .or_else(|| step.filter(|s| s.claims_hidden).and_then(|s| s.next));
        let mut w = q.map_or(Withheld::NONE, |q| q.withheld(size_effect));
        w.marks = self.marks_hidden();
        w
    }

    /// Until when the marks wait, in words ("the reveal", "the lesson's
    /// next poll"); `None` when they show.
    pub fn marks_wait(&self) -> Option<&'static str> {
        if !self.marks_hidden() {
            return None;
        }
        Some(if self.hidden_question().is_some() {
            "the reveal"
        } else {
            "the lesson's next poll"
        })
    }

    /// Whether the claims line and the chart's regime marks wait: a poll
    /// open or about to be asked, or a lesson's step that hides them.
    pub fn claims_hidden(&self) -> bool {
        self.hidden_question().is_some() || self.step.as_ref().is_some_and(|s| s.hides_claims())
    }

    /// Whether the scene's caption (which may name the answer) waits for
    /// the reveal: while a poll is open outside a lesson (a lesson's
    /// captions are written for its polls).
    pub fn caption_waits(&self) -> bool {
        self.open_question().is_some() && self.step.is_none()
    }

    /// What the claims' row shows: the claims, or what the class puts in
    /// their place.
    pub fn claims_row(&self) -> ClaimsRow<'_> {
        if let Some(a) = &self.asked {
            return ClaimsRow::Asked(a);
        }
        let tally = self.view.as_ref().and_then(|v| v.poll.as_ref());
        if let Some(t) = tally.filter(|t| !t.revealed) {
            return ClaimsRow::Open(t);
        }
        if let Some(q) = self.hidden_question() {
            return ClaimsRow::Asks(q);
        }
        if self.claims_hidden() {
            ClaimsRow::Waiting
        } else {
            ClaimsRow::Claims
        }
    }

    /// Leads `lesson` from its first step: the step to show.
    pub fn start_lesson(&mut self, lesson: Arc<Lesson>) -> Option<StepScene> {
        self.lesson = Some(LessonAt::new(lesson, 0));
        self.show_step()
    }

    /// The lesson's current step, to show: every screen's step line says
    /// it from now on.
    pub fn show_step(&mut self) -> Option<StepScene> {
        let at = self.lesson.as_ref()?;
        let scene = at.step().scene();
        self.step = Some(at.line());
        Some(scene)
    }

    /// The next (`next`) or previous step: the step to show, or the end
    /// the lesson stands at; `None` without a lesson. Away from the
    /// lesson (the lecturer loaded a scene), the next step is the one left.
    pub fn lesson_step(&mut self, next: bool) -> Option<Result<StepScene, LessonEnd>> {
        if next && self.step.as_ref().is_some_and(|s| s.left.is_some()) {
            return self.show_step().map(Ok);
        }
        let at = self.lesson.as_mut()?;
        let n = at.lesson.steps.len();
        let to = if next {
            at.at.checked_add(1).filter(|t| *t < n)
        } else {
            at.at.checked_sub(1)
        };
        match to {
            Some(t) => {
                at.at = t;
                self.show_step().map(Ok)
            }
            None if next => Some(Err(LessonEnd::Last)),
            None => Some(Err(LessonEnd::First)),
        }
    }

    /// The lecturer loaded `scene` away from the lesson's step: the step
    /// line says the class left the lesson (its next step returns).
    pub fn leave_lesson(&mut self, scene: &str) {
        if let Some(step) = self.step.as_mut() {
            step.left = Some(scene.to_string());
            step.pending = None;
            step.next = None;
        }
    }

    /// The step's poll was revealed: its answer and its claims show (and,
    /// from now on, those of the steps before it that hid theirs for
    /// this poll).
    pub fn step_revealed(&mut self) {
        if let Some(step) = self.step.as_mut() {
            step.pending = None;
            step.claims_hidden = false;
            step.next = None;
            if step.left.is_none() {
                if let Some(at) = self.lesson.as_mut() {
                    at.mark_revealed();
                }
            }
        }
    }

    /// The poll of the lesson's step on a value of `axis` (a typed value,
    /// or whether the share passes ½ at all), while the lecturer is at it.
    pub fn step_poll(&self, axis: Axis) -> Option<Question> {
        if self.step.as_ref().is_some_and(|s| s.left.is_some()) {
            return None;
        }
        let q = self.lesson.as_ref()?.step().poll?;
        let own = matches!(q.ask, Ask::Typed | Ask::ShareEver);
        (own && q.axis == axis).then_some(q)
    }
}

/// What stands in the row of the scene's claims, in a class.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ClaimsRow<'a> {
    /// A student's poll: the question, their answer, the reveal
    /// ([`Asked::line`]).
    Asked(&'a Asked),
    /// The lecturer's open poll: how many of those asked answered.
    Open(&'a Tally),
    /// A lesson's step about to poll: its question, not its answer.
    Asks(Question),
    /// A lesson's step before a poll: the claims would answer it.
    Waiting,
    /// The scene's claims.
    Claims,
}

/// The end of the lesson a step would go past.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LessonEnd {
    /// Its last step: there is no next.
    Last,
    /// Its first step: there is none before.
    First,
}
