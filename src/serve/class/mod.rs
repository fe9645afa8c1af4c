//! The class: state the server owns, beside the follow channel. A roster
//! of the students (name, address, following or not, terminal size, marker
//! set, last key) and the poll (question, scene, answers, revealed).
//!
//! Sessions tell it what changed ([`Note`]) and send their answers; they
//! read it through latest-value channels: the lecturer through a version
//! number that moves with every change the class list shows (its session
//! then takes a fresh [`ClassView`]), students through the poll alone,
//! which changes only when a poll opens, is revealed or is cancelled. So one
//! student's key never wakes another student, and a student who sits still
//! is sent nothing.

use std::collections::BTreeMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use tokio::sync::watch;

mod names;
mod poll;

pub use super::csv::CSV_HEADER;
pub use crate::tui::class::duration;
use crate::tui::class::{ClassGlyphs, ClassView, Seat, SeatState, Tally};
pub use names::{clean_name, NAME_CHARS};
use poll::Open;
pub use poll::{Poll, Refused};

/// What a student's session tells the class.
#[derive(Clone, Debug, PartialEq)]
pub enum Note {
    /// Following the lecturer, or not.
    Following(bool),
    Size(u16, u16),
    Marker(String),
    /// A key: the idle time starts again (nobody is woken).
    Key,
}

#[derive(Debug)]
struct Student {
    name: String,
    addr: IpAddr,
    following: bool,
    size: (u16, u16),
    marker: String,
    last_key: Instant,
}

#[derive(Debug, Default)]
struct Inner {
    next_seat: u64,
    next_poll: u64,
    seats: BTreeMap<u64, Student>,
    poll: Option<Open>,
}

/// A place in the class, from [`Class::join`].
pub type SeatId = u64;

#[derive(Debug)]
pub struct Class {
    inner: Mutex<Inner>,
    /// The seats the lecturer removed; their sessions end with a line.
    removed: watch::Sender<std::collections::BTreeSet<SeatId>>,
    roster: watch::Sender<u64>,
    poll: watch::Sender<Option<Arc<Poll>>>,
}

impl Default for Class {
    fn default() -> Class {
        Class {
            inner: Mutex::default(),
            removed: watch::Sender::new(Default::default()),
            roster: watch::Sender::new(0),
            poll: watch::Sender::new(None),
        }
    }
}

impl Class {
    fn lock(&self) -> MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn changed(&self) {
        self.roster.send_modify(|v| *v += 1);
    }

    /// What the lecturer watches: it moves whenever the class list changes.
    pub fn watch_roster(&self) -> watch::Receiver<u64> {
        self.roster.subscribe()
    }

    /// What students watch: the poll.
    pub fn watch_poll(&self) -> watch::Receiver<Option<Arc<Poll>>> {
        self.poll.subscribe()
    }

    /// A student comes in.
    pub fn join(
        &self,
        name: &str,
        addr: IpAddr,
        size: (u16, u16),
        marker: &str,
        following: bool,
    ) -> SeatId {
        let mut c = self.lock();
        c.next_seat += 1;
        let id = c.next_seat;
        c.seats.insert(
            id,
            Student {
                name: name.to_string(),
                addr,
                following,
                size,
                marker: marker.to_string(),
                last_key: Instant::now(),
            },
        );
        drop(c);
        self.changed();
        id
    }

    /// The lecturer removes a student: their session ends, told why;
    /// whether they were here.
    pub fn remove(&self, id: SeatId) -> Option<String> {
        let name = self.lock().seats.get(&id).map(|s| s.name.clone())?;
        self.removed.send_modify(|r| {
            r.insert(id);
        });
        Some(name)
    }

    /// What students watch to learn they were removed.
    pub fn watch_removed(&self) -> watch::Receiver<std::collections::BTreeSet<SeatId>> {
        self.removed.subscribe()
    }

    /// A student goes; an answer they gave stays in the poll.
    pub fn leave(&self, id: SeatId) {
        if self.lock().seats.remove(&id).is_some() {
            self.changed();
        }
    }

    pub fn note(&self, id: SeatId, note: Note) {
        let mut c = self.lock();
        let Some(s) = c.seats.get_mut(&id) else {
            return;
        };
        let changed = match note {
            Note::Following(f) => std::mem::replace(&mut s.following, f) != f,
            Note::Size(w, h) => std::mem::replace(&mut s.size, (w, h)) != (w, h),
            Note::Marker(m) => std::mem::replace(&mut s.marker, m.clone()) != m,
            Note::Key => {
                s.last_key = Instant::now();
                false
            }
        };
        drop(c);
        if changed {
            self.changed();
        }
    }

    /// How many students came, in all.
    pub fn seen(&self) -> u64 {
        self.lock().next_seat
    }

    /// The class as the lecturer's explorer shows it, idle times as of now.
    pub fn view(&self) -> ClassView {
        let c = self.lock();
        let now = Instant::now();
        let open = c.poll.as_ref().filter(|o| !o.poll.revealed);
        let seats = c
            .seats
            .iter()
            .map(|(id, s)| Seat {
                id: *id,
                name: s.name.clone(),
                state: match open {
                    Some(o) if o.answers.contains_key(id) => SeatState::Answered,
                    Some(_) => SeatState::Answering,
                    None if s.following => SeatState::Following,
                    None => SeatState::Own,
                },
                size: s.size,
                marker: s.marker.clone(),
                idle: now.saturating_duration_since(s.last_key),
            })
            .collect();
        let poll = c.poll.as_ref().map(|o| {
            let gone = o.answers.keys().filter(|k| !c.seats.contains_key(k));
            Tally {
                question: o.poll.question,
                answers: o.answers.values().map(|a| a.1).collect(),
                asked: c.seats.len() + gone.count(),
                revealed: o.poll.revealed,
                sweep: o.poll.scene.state.sweep,
            }
        });
        ClassView { seats, poll }
    }

    /// How many students are here.
    pub fn students(&self) -> usize {
        self.lock().seats.len()
    }

    /// The console's summary line; `None` while no student is here.
    pub fn summary(&self) -> Option<String> {
        const CONSOLE: ClassGlyphs = ClassGlyphs {
            sep: ", ",
            ..crate::tui::class::ASCII
        };
        (self.students() > 0).then(|| format!("class: {}", self.view().line(&CONSOLE)))
    }

    /// The address a seat came from.
    pub fn addr(&self, id: SeatId) -> Option<IpAddr> {
        self.lock().seats.get(&id).map(|s| s.addr)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::serve::follow::Shown;
    use crate::tui::class::{Ask, Question, UNICODE};
    use rough_model::Axis;

    fn shown() -> Shown {
        let app = crate::tui::app::App::new(
            crate::presets::load("fig2").unwrap(),
            crate::tui::theme::Theme::plain(),
            (80, 24),
        );
        Shown::of(&app)
    }

    fn question() -> Question {
        Question {
            axis: Axis::Zeta,
            ask: Ask::Share { rising: true },
            truth: 321.5,
        }
    }

    const HOME: IpAddr = IpAddr::V4(std::net::Ipv4Addr::LOCALHOST);

    #[test]
    fn names_are_escaped_and_cut() {
        assert_eq!(clean_name("alice"), "alice");
        assert_eq!(clean_name(""), "(no name)");
        assert_eq!(clean_name("a\x1b[31mb"), "a\\x1b[31mb");
        assert_eq!(clean_name("x\u{202e}y\u{85}"), "x\\u{202e}y\\x85");
        assert_eq!(clean_name("a\\b"), "a\\\\b");
        let long = clean_name(&"é".repeat(10_000));
        assert_eq!(long.chars().count(), NAME_CHARS);
        assert!(long.ends_with("é…"), "{long}");
        let ctl = clean_name(&"\x07".repeat(100));
        assert_eq!(ctl.chars().count(), NAME_CHARS);
        assert!(ctl.starts_with("\\x07\\x07"), "{ctl}");
        assert!(!ctl.chars().any(char::is_control));
        assert_eq!(clean_name(&"b".repeat(32)), "b".repeat(32));
    }

    #[test]
    fn the_roster_counts_and_wakes_only_the_lecturer() {
        let class = Class::default();
        let mut roster = class.watch_roster();
        let mut poll = class.watch_poll();
        let a = class.join("alice", HOME, (100, 30), "braille", true);
        let b = class.join("bob", HOME, (60, 20), "ascii", true);
        assert!(roster.has_changed().unwrap());
        roster.mark_unchanged();
        class.note(a, Note::Key);
        assert!(!roster.has_changed().unwrap(), "a key woke the lecturer");
        class.note(b, Note::Following(false));
        class.note(b, Note::Size(80, 24));
        assert!(roster.has_changed().unwrap());
        assert!(
            !poll.has_changed().unwrap(),
            "a roster change woke students"
        );
        let v = class.view();
        assert_eq!(
            v.line(&UNICODE),
            "2 students · 1 following · 1 on their own"
        );
        assert_eq!(v.seats[1].marker, "ascii");
        assert_eq!(
            class.summary().unwrap(),
            "class: 2 students, 1 following, 1 on their own"
        );
        class.leave(a);
        class.leave(b);
        assert_eq!(class.summary(), None);
        poll.mark_unchanged();
    }

    #[test]
    fn a_poll_is_answered_revealed_and_refuses_late_answers() {
        let class = Class::default();
        let a = class.join("alice", HOME, (100, 30), "braille", true);
        let b = class.join("b,\"ob\"", HOME, (100, 30), "braille", true);
        let c = class.join("carol", HOME, (100, 30), "braille", true);
        let mut poll = class.watch_poll();
        assert_eq!(class.answer(a, 1, 100.0), Err(Refused::NoPoll));
        let id = class.open(question(), shown());
        assert!(poll.has_changed().unwrap());
        assert!(!poll.borrow_and_update().as_ref().unwrap().revealed);
        class.answer(a, id, 100.0).unwrap();
        class.answer(b, id, 1000.0).unwrap();
        // A second Enter replaces the first answer.
        class.answer(a, id, 200.0).unwrap();
        assert!(!poll.has_changed().unwrap(), "an answer woke students");
        let v = class.view();
        assert_eq!(v.line(&UNICODE), "3 students · 2/3 answered");
        assert_eq!(v.seats[2].state, SeatState::Answering);
        assert_eq!(v.seats[0].state, SeatState::Answered);
        // Bob leaves: his answer stays and still counts.
        class.leave(b);
        assert_eq!(class.view().line(&UNICODE), "2 students · 2/3 answered");
        assert!(class.reveal());
        assert!(!class.reveal());
        assert!(poll.borrow_and_update().as_ref().unwrap().revealed);
        let state = |v: ClassView| {
            (
                v.poll,
                v.seats.into_iter().map(|s| s.state).collect::<Vec<_>>(),
            )
        };
        let before = (state(class.view()), class.csv());
        let mut roster = class.watch_roster();
        roster.mark_unchanged();
        assert_eq!(class.answer(c, id, 5.0), Err(Refused::Closed));
        assert_eq!(class.answer(a, id, 5.0), Err(Refused::Closed));
        // What the student reads in their status line.
        assert_eq!(
            Refused::Closed.text(),
            "too late: the answers were already revealed"
        );
        // An answer to a poll that is gone is refused the same way.
        assert_eq!(class.answer(a, id + 1, 5.0), Err(Refused::Closed));
        assert_eq!(
            (state(class.view()), class.csv()),
            before,
            "a late answer changed the class"
        );
        assert!(
            !roster.has_changed().unwrap(),
            "a late answer woke the lecturer"
        );
        assert_eq!(
            class.csv().unwrap(),
            "question,quantity,unit,truth,name,answer,offset\n\
             where does the plastic share pass 1/2?,zeta,,321.5,alice,200,-121.5\n\
             where does the plastic share pass 1/2?,zeta,,321.5,\"b,\"\"ob\"\"\",1000,678.5\n\
             where does the plastic share pass 1/2?,zeta,,321.5,carol,no answer,\n"
        );
        assert_eq!(
            class.view().line(&UNICODE),
            "2 students · 2 following · 0 on their own · revealed ζ = 321.5 (2 answers)"
        );
        // A revealed poll is not cancelled: it stays for S.
        assert!(!class.cancel());
        assert!(class.csv().is_some());
        // An answer to an older poll is refused once another opened; the
        // new poll replaces the last one's answers.
        let id2 = class.open(question(), shown());
        assert_eq!(class.answer(c, id, 5.0), Err(Refused::Closed));
        class.answer(c, id2, 5.0).unwrap();
        // While open, everyone here without an answer is a no-answer row.
        assert_eq!(
            class.csv().unwrap().lines().skip(1).collect::<Vec<_>>(),
            [
                "where does the plastic share pass 1/2?,zeta,,321.5,carol,5,-316.5",
                "where does the plastic share pass 1/2?,zeta,,321.5,alice,no answer,"
            ]
        );
        assert!(class.cancel());
        assert_eq!(class.poll(), None);
        assert_eq!(class.csv(), None);
        assert_eq!(class.answer(c, id2, 5.0), Err(Refused::NoPoll));
        assert_eq!((class.polls(), class.seen()), (2, 3));
    }
}
