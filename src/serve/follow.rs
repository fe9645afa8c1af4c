//! Following the lecturer. The lecturer's sessions publish what they show
//! (a [`Shown`]) on a latest-value channel, so a slow student never queues
//! anything; each student's [`Follow`] decides whether to show it.

use std::sync::Arc;

use rough_model::Axis;

use crate::class::Shown;
use crate::figure::View;
use crate::tui::app::{App, Message};

/// The scene a student's explorer shows, by identity: a lecturer's state
/// as published, or a poll's scene with the marker's slider selected.
/// Two explorers that apply one such scene (the same `Arc`, which the
/// token keeps alive, so its address is not reused) show the same scene.
#[derive(Clone, Debug)]
pub enum Scene {
    Lecturer(Arc<Shown>),
    Poll(Arc<crate::class::Poll>),
}

impl PartialEq for Scene {
    fn eq(&self, other: &Scene) -> bool {
        match (self, other) {
            (Scene::Lecturer(a), Scene::Lecturer(b)) => Arc::ptr_eq(a, b),
            (Scene::Poll(a), Scene::Poll(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}

impl Scene {
    /// Makes `app` show this scene.
    pub fn apply(&self, app: &mut App) {
        match self {
            Scene::Lecturer(shown) => app.follow(shown),
            Scene::Poll(p) => {
                app.follow(&p.scene);
                // The marker's slider selected.
                if let Some(i) = Axis::ALL.iter().position(|a| *a == p.question.axis) {
                    app.selected = i;
                }
            }
        }
    }

    /// The view the scene shows.
    pub fn view(&self) -> View {
        match self {
            Scene::Lecturer(shown) => shown.view,
            Scene::Poll(p) => p.scene.view,
        }
    }
}

/// The status line a student sees when leaving the lecturer.
pub const DETACHED: &str = "exploring on your own — f to follow";
pub const FOLLOWING: &str = "following the lecturer — any change explores on your own";
pub const NO_LECTURER: &str = "no lecturer connected: exploring on your own";
pub const LECTURER_BACK: &str = "the lecturer is back — f to follow";
pub const ANSWER_FIRST: &str = "a poll is on: move the marker, then Enter answers";
pub const CALLED_BACK: &str = "the lecturer asked everyone to follow: following again";

/// A student's relation to the lecturer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Follow {
    /// No lecturer is connected.
    Alone,
    /// Showing the lecturer's state.
    Following,
    /// A lecturer is connected, the student explores on their own.
    Detached,
    /// No lecturer is connected, and the student had left the lecturer to
    /// explore: a lecturer who comes (back) does not take their scene.
    Away,
    /// A poll is on: the student answers on the poll's scene, and neither
    /// the lecturer's moves (nor the lecturer leaving: the poll holds)
    /// nor their own keys change that.
    Answering,
}

/// What a change of [`Follow`] asks the session to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effect {
    None,
    /// Show this status line.
    Say(&'static str),
    /// Show the lecturer's latest state (and say so).
    Catch,
}

impl Follow {
    /// The start: following when a lecturer is there.
    pub fn start(lecturer: bool) -> Follow {
        if lecturer {
            Follow::Following
        } else {
            Follow::Alone
        }
    }

    /// Whether lecturer updates are shown.
    pub fn following(self) -> bool {
        self == Follow::Following
    }

    /// Whether the student is with the class: following the lecturer or
    /// answering a poll (such a session never idles out).
    pub fn in_class(self) -> bool {
        matches!(self, Follow::Following | Follow::Answering)
    }

    /// A message the student's keys sent, before it is applied: the first
    /// editing key detaches.
    pub fn on_message(&mut self, msg: &Message) -> Effect {
        if *self == Follow::Following && edits(msg) {
            *self = Follow::Detached;
            return Effect::Say(DETACHED);
        }
        Effect::None
    }

    /// The `f` key.
    pub fn on_follow_key(&mut self) -> Effect {
        match self {
            Follow::Alone | Follow::Away => Effect::Say(NO_LECTURER),
            Follow::Answering => Effect::Say(ANSWER_FIRST),
            _ => {
                *self = Follow::Following;
                Effect::Catch
            }
        }
    }

    /// A lecturer connected (`true`) or the last one left.
    pub fn on_lecturer(&mut self, present: bool) -> Effect {
        match (*self, present) {
            (Follow::Alone, true) => {
                *self = Follow::Following;
                Effect::Catch
            }
            (Follow::Away, true) => {
                *self = Follow::Detached;
                Effect::Say(LECTURER_BACK)
            }
            (Follow::Following, false) => {
                *self = Follow::Alone;
                Effect::Say(NO_LECTURER)
            }
            (Follow::Detached, false) => {
                *self = Follow::Away;
                Effect::Say(NO_LECTURER)
            }
            _ => Effect::None,
        }
    }

    /// The lecturer's `F`: a student exploring on their own follows again
    /// (one answering a poll goes on answering).
    pub fn on_all_follow(&mut self) -> Effect {
        if *self == Follow::Detached {
            *self = Follow::Following;
            return Effect::Catch;
        }
        Effect::None
    }

    /// A poll opened: whatever the student did, they answer it.
    pub fn on_poll(&mut self) {
        *self = Follow::Answering;
    }

    /// The poll was revealed or closed: a student who was answering
    /// follows again (when there is a lecturer).
    pub fn on_poll_end(&mut self, lecturer: bool) -> Effect {
        if *self != Follow::Answering {
            return Effect::None;
        }
        if lecturer {
            *self = Follow::Following;
            Effect::Catch
        } else {
            *self = Follow::Alone;
            Effect::Say(NO_LECTURER)
        }
    }
}

/// Whether a message changes what the lecturer's state decides.
fn edits(msg: &Message) -> bool {
    use Message as M;
    matches!(
        msg,
        M::SelectPrev
            | M::SelectNext
            | M::Step { .. }
            | M::LoadPreset(_)
            | M::CycleSweep
            | M::ToggleModel
            | M::ToggleSizeEffect
            | M::ToggleMoments
            | M::NextView
            | M::PrevView
            | M::NextMapY
            | M::ContactLoad { .. }
            | M::ContactSweep
            | M::ContactSlopes
            | M::ContactSeed
            | M::ContactSeeds
            | M::ContactTable
            | M::ContactHardness
            | M::MoveFitBand { .. }
            | M::AutoFitBand
            // Typing a slider's value: the lecturer's next move would
            // overwrite it.
            | M::StartValue
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets;
    use crate::tui::app::update;
    use crate::tui::theme::Theme;

    fn fig(name: &str) -> App {
        App::new(presets::load(name).unwrap(), Theme::colored(), (80, 24))
    }

    #[test]
    fn catching_up_takes_the_header_marks_too() {
        // A detached student changed fig2; the lecturer loads fig1 afresh.
        let mut student = fig("fig2");
        update(
            &mut student,
            Message::Step {
                up: true,
                fine: false,
            },
        );
        assert!(student.modified);
        let mut lecturer = fig("fig2");
        update(&mut lecturer, Message::LoadPreset(0));
        assert!(!lecturer.modified);
        student.follow(&lecturer.shown());
        assert_eq!(student.state, lecturer.state);
        assert!(!student.modified, "stale modified mark after re-follow");
        // A lecturer's change marks the student's header as well.
        update(&mut lecturer, Message::ToggleModel);
        lecturer.file = Some("class.ron".into());
        student.follow(&lecturer.shown());
        assert!(student.modified);
        assert_eq!(student.file.as_deref(), Some("class.ron"));
    }

    /// A follower's contact view takes the lecturer's load, plot, seed
    /// count and convergence table: the same tasks, so one job for both.
    #[test]
    fn a_follower_takes_the_lecturers_seeds_and_table() {
        let engine = crate::contact::engine::Engine::new(1);
        let mut lecturer = fig("fig2");
        let mut student = fig("fig2");
        lecturer.contact.engine = std::sync::Arc::clone(&engine);
        student.contact.engine = std::sync::Arc::clone(&engine);
        for _ in 0..4 {
            update(&mut lecturer, Message::NextView);
        }
        assert_eq!(lecturer.view, View::Contact);
        update(&mut lecturer, Message::ContactSeeds);
        assert_eq!(lecturer.contact.seeds, 16);
        update(&mut lecturer, Message::ContactLoad { up: true });
        student.follow(&lecturer.shown());
        assert_eq!(student.view, View::Contact);
        assert_eq!((student.contact.seeds, student.contact.load), (16, 5));
        assert_eq!(student.contact.seeds_asked(), 16);
        assert_eq!(student.contact.seed_tasks, lecturer.contact.seed_tasks);
        // The table, and back.
        update(&mut lecturer, Message::ContactTable);
        assert!(lecturer.contact.table);
        student.follow(&lecturer.shown());
        assert!(student.contact.table);
        let tasks = |a: &App| -> Vec<_> {
            a.contact
                .convergence
                .rows
                .iter()
                .flat_map(|r| r.tasks.clone())
                .collect()
        };
        assert_eq!(
            tasks(&student).len(),
            8 * 16,
            "fig2's 16/λ in 4 cells is 8192²"
        );
        assert_eq!(tasks(&student), tasks(&lecturer));
        update(&mut lecturer, Message::ContactSeeds);
        update(&mut lecturer, Message::ContactTable);
        student.follow(&lecturer.shown());
        assert!(!student.contact.table);
        assert_eq!(student.contact.seeds, 1);
        assert!(student.contact.seed_tasks.is_empty());
        // A hardness per asperity (A), with the size effect on (e): the
        // follower solves the lecturer's tasks, each with its law.
        update(&mut lecturer, Message::ToggleSizeEffect);
        update(&mut lecturer, Message::ContactHardness);
        student.follow(&lecturer.shown());
        assert_eq!(
            student.contact.sampling.hardness,
            crate::contact::Hardness::Asperity
        );
        assert!(student
            .contact
            .tasks
            .iter()
            .all(|t| t.scene.local.is_some()));
        assert!(!student.contact.tasks.is_empty());
        assert_eq!(student.contact.tasks, lecturer.contact.tasks);
    }

    #[test]
    fn follow_detach_refollow() {
        let mut f = Follow::start(true);
        assert!(f.following());
        // Looking around does not detach.
        assert_eq!(f.on_message(&Message::ToggleHelp), Effect::None);
        assert_eq!(f.on_message(&Message::Resize(80, 24)), Effect::None);
        assert_eq!(f.on_message(&Message::StartSave), Effect::None);
        assert!(f.following());
        // The first edit detaches, once.
        let step = Message::Step {
            up: true,
            fine: false,
        };
        assert_eq!(f.on_message(&step), Effect::Say(DETACHED));
        assert_eq!(f, Follow::Detached);
        assert_eq!(f.on_message(&step), Effect::None);
        assert!(!f.following());
        // f follows again and catches up.
        assert_eq!(f.on_follow_key(), Effect::Catch);
        assert!(f.following());
        assert_eq!(f.on_message(&Message::SelectNext), Effect::Say(DETACHED));
        f.on_follow_key();
        assert_eq!(f.on_message(&Message::NextView), Effect::Say(DETACHED));
    }

    #[test]
    fn lecturer_comes_and_goes() {
        let mut f = Follow::start(false);
        assert_eq!(f, Follow::Alone);
        assert_eq!(f.on_message(&Message::ToggleModel), Effect::None);
        assert_eq!(f.on_follow_key(), Effect::Say(NO_LECTURER));
        assert_eq!(f.on_lecturer(true), Effect::Catch);
        assert!(f.following());
        assert_eq!(f.on_lecturer(true), Effect::None);
        f.on_message(&Message::CycleSweep);
        // A detached student stays detached while the lecturer stays.
        assert_eq!(f.on_lecturer(true), Effect::None);
        assert_eq!(f, Follow::Detached);
        assert_eq!(f.on_lecturer(false), Effect::Say(NO_LECTURER));
        assert_eq!(f, Follow::Away);
        assert_eq!(f.on_lecturer(false), Effect::None);
        // A following student left alone follows the next lecturer.
        let mut f = Follow::start(true);
        assert_eq!(f.on_lecturer(false), Effect::Say(NO_LECTURER));
        assert_eq!(f, Follow::Alone);
        assert_eq!(f.on_lecturer(true), Effect::Catch);
    }

    #[test]
    fn a_poll_holds_the_student_until_it_ends() {
        for start in [Follow::Following, Follow::Detached] {
            let mut f = start;
            f.on_poll();
            assert!(!f.following(), "a lecturer's move would move the marker");
            let step = Message::Step {
                up: true,
                fine: false,
            };
            assert_eq!(f.on_message(&step), Effect::None);
            assert_eq!(f.on_follow_key(), Effect::Say(ANSWER_FIRST));
            assert_eq!(f.on_lecturer(true), Effect::None);
            assert_eq!(f, Follow::Answering);
            assert_eq!(f.on_poll_end(true), Effect::Catch);
            assert!(f.following());
            assert_eq!(f.on_poll_end(true), Effect::None);
        }
        // The lecturer's connection drops: the poll holds.
        let mut f = Follow::Answering;
        assert_eq!(f.on_lecturer(false), Effect::None);
        assert_eq!(f, Follow::Answering);
        let mut f = Follow::Answering;
        assert_eq!(f.on_poll_end(false), Effect::Say(NO_LECTURER));
    }

    #[test]
    fn everyone_follow_pulls_back_only_the_detached() {
        let mut f = Follow::start(true);
        assert_eq!(f.on_all_follow(), Effect::None);
        f.on_message(&Message::ToggleModel);
        assert_eq!(f.on_all_follow(), Effect::Catch);
        assert!(f.following());
        f.on_poll();
        assert_eq!(f.on_all_follow(), Effect::None);
        assert_eq!(f, Follow::Answering);
    }

    #[test]
    fn typing_a_value_detaches() {
        let mut f = Follow::start(true);
        assert_eq!(f.on_message(&Message::StartValue), Effect::Say(DETACHED));
        assert!(!f.following());
    }

    #[test]
    fn a_detached_student_keeps_their_scene_when_the_lecturer_returns() {
        let mut f = Follow::start(true);
        f.on_message(&Message::ToggleModel);
        assert_eq!(f.on_lecturer(false), Effect::Say(NO_LECTURER));
        assert!(!f.following());
        assert_eq!(f.on_message(&Message::ToggleModel), Effect::None);
        assert_eq!(f.on_follow_key(), Effect::Say(NO_LECTURER));
        assert_eq!(f.on_lecturer(true), Effect::Say(LECTURER_BACK));
        assert_eq!(f, Follow::Detached);
        assert!(!f.following());
        assert_eq!(f.on_follow_key(), Effect::Catch);
        assert!(f.following());
    }
}
