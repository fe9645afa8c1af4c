//! One explorer and its place in the class: what a session's parts (its
//! run loop, the poll's keys, the shared frames) all act on.

use std::sync::Arc;

use tokio::sync::watch;

use super::auth::Role;
use super::follow::{Effect, Follow, Scene, FOLLOWING};
use super::output::FrameBuf;
use super::Shared;
use crate::class::{Note, SeatId, Shown};
use crate::tui::app::Message;
use crate::tui::glyphs::Glyphs;
use crate::tui::session::Session;

/// One explorer and its place in the class.
pub(super) struct Seat {
    pub ex: Session<FrameBuf>,
    /// What `ex` writes its frames into.
    pub out: FrameBuf,
    pub shared: Arc<Shared>,
    pub role: Role,
    pub follow: Follow,
    /// A student's place in the roster, and this session's turn on it.
    pub seat: Option<SeatId>,
    pub turn: u64,
    /// The results of the polls revealed to this student, as their line
    /// read ("the model: ζ = 321.5 · you: 316.2 · 1.6 % low"): their
    /// terminal keeps them when the session ends.
    pub results: Vec<String>,
    /// The poll a student is in (its id).
    pub poll: Option<u64>,
    pub lecturer: watch::Receiver<Option<Arc<Shown>>>,
    /// The scene the explorer shows, or is to show (`pending`), while it
    /// is the lecturer's or the poll's as it came (none of the student's
    /// own moves on it): then its frame may be shared (see `frames`).
    pub scene: Option<Scene>,
    /// `scene` is not applied yet: the explorer catches up when it needs
    /// to (a key, a frame no one else drew).
    pub pending: bool,
}

impl Seat {
    pub fn is_lecturer(&self) -> bool {
        self.role == Role::Lecturer
    }

    /// Is to show the lecturer's latest state (see `pending`).
    pub fn follow_lecturer(&mut self) {
        let shown = self.lecturer.borrow().clone();
        if let Some(s) = shown {
            self.show(Scene::Lecturer(s));
        }
    }

    /// The explorer is to show `scene`, when it next needs to (see
    /// `pending`).
    pub fn show(&mut self, scene: Scene) {
        self.scene = Some(scene);
        self.pending = true;
        if self.ex.app.ghost.is_some() {
            // A ghost that no longer fits goes, and says so, now: before
            // what the caller says next (such a screen is never shared).
            self.sync();
        }
    }

    /// Brings the explorer up to its scene, if it is behind.
    pub fn sync(&mut self) {
        if std::mem::take(&mut self.pending) {
            if let Some(scene) = &self.scene {
                scene.apply(&mut self.ex.app);
            }
        }
    }

    /// Applies `msg` to the explorer, brought up to its scene first.
    pub fn update(&mut self, msg: Message) -> std::io::Result<()> {
        self.own_move(&msg);
        self.sync();
        self.ex.update(msg)
    }

    /// The explorer changed on its own: what it shows is its own now
    /// (until it follows again), unless `msg` changed only its look.
    fn own_move(&mut self, msg: &Message) {
        use Message as M;
        let look_only = matches!(
            msg,
            M::ToggleHelp
                | M::CloseHelp
                | M::HelpPage { .. }
                | M::Resize(..)
                | M::Redraw
                | M::CycleGlyphs
                | M::ToggleColor
                | M::Answer
                | M::AnswerNowhere
                | M::Follow
                | M::Tick
                | M::Quit
        );
        if !look_only {
            self.sync();
            self.scene = None;
        }
    }

    /// Acts on a change of following: the status, the scene, the roster.
    pub fn effect(&mut self, e: Effect) {
        match e {
            Effect::Say(s) => self.ex.app.set_status(s, false),
            Effect::Catch => {
                self.follow_lecturer();
                self.ex.app.set_status(FOLLOWING, false);
            }
            Effect::None => {}
        }
        self.note(Note::Following(self.follow.following()));
    }

    pub fn note(&self, note: Note) {
        if let Some(id) = self.seat {
            self.shared.class.note(id, note);
        }
    }

    /// The marker set the class list shows.
    pub fn marker(&self) -> Glyphs {
        self.ex.app.theme.glyphs
    }
}
