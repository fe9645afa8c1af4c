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

use super::glyphs::{ClassGlyphs, ASCII};
use super::view::{ClassView, Seat, SeatState, Tally};
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

impl Inner {
    /// `name`, or `name-2`, `name-3` … when a student here (or one whose
    /// answer the last poll keeps) already has it: the roster and the
    /// CSV tell them apart.
    fn distinct(&self, name: &str) -> String {
        let taken = |n: &str| {
            self.seats.values().any(|s| s.name == n)
                || (self.poll.as_ref()).is_some_and(|o| o.answers.values().any(|a| a.0 == n))
        };
        if !taken(name) {
            return name.to_string();
        }
        (2..)
            .map(|k| {
                // Cut to NAME_CHARS with its number kept.
                let suffix = format!("-{k}");
                let keep = NAME_CHARS.saturating_sub(suffix.chars().count());
                let base: String = name.chars().take(keep).collect();
                format!("{base}{suffix}")
            })
            .find(|n| !taken(n))
            .unwrap_or_else(|| name.to_string())
    }
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
        let name = c.distinct(name);
        c.seats.insert(
            id,
            Student {
                name,
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

    /// The name a seat has in the class (made distinct at [`Class::join`]).
    pub fn name(&self, id: SeatId) -> Option<String> {
        self.lock().seats.get(&id).map(|s| s.name.clone())
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
        const CONSOLE: ClassGlyphs = ClassGlyphs { sep: ", ", ..ASCII };
        (self.students() > 0).then(|| format!("class: {}", self.view().line(&CONSOLE)))
    }

    /// The address a seat came from.
    pub fn addr(&self, id: SeatId) -> Option<IpAddr> {
        self.lock().seats.get(&id).map(|s| s.addr)
    }
}

#[cfg(test)]
mod room_tests;
