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

/// How a student reaches the class: the class list says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Transport {
    /// An SSH client's terminal.
    Ssh,
    /// The web page's terminal (xterm.js).
    Web,
    /// The web page's phone layout: a picture and buttons.
    Phone,
}

impl Transport {
    pub fn label(self) -> &'static str {
        match self {
            Transport::Ssh => "ssh",
            Transport::Web => "web",
            Transport::Phone => "phone",
        }
    }
}

/// A student arriving: who, from where, on what, and the seat they held
/// before (a web page's seat token, kept over a reload).
#[derive(Clone, Debug)]
pub struct Arrival<'a> {
    pub name: &'a str,
    pub addr: IpAddr,
    pub size: (u16, u16),
    pub marker: &'a str,
    pub following: bool,
    pub via: Transport,
    pub token: Option<&'a str>,
}

/// A seat taken: its place, the session's turn on it (a later session on
/// the same seat takes it over), the name the class gives the student and
/// the token that takes the seat again.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Taken {
    pub id: SeatId,
    pub turn: u64,
    pub name: String,
    pub token: String,
    /// The seat was held before (a reload, a connection dropped).
    pub again: bool,
}

#[derive(Debug)]
struct Student {
    name: String,
    /// The name as the student gave it (before `-2`): an SSH student
    /// who comes back from the same address under it takes the seat again.
    asked: String,
    addr: IpAddr,
    following: bool,
    size: (u16, u16),
    marker: String,
    last_key: Instant,
    via: Transport,
    token: String,
    /// Whether a session holds the seat now (else the student is away:
    /// the seat waits, its row and its answers kept).
    here: bool,
    /// The session's turn on the seat.
    turn: u64,
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
    /// Moves when a seat is taken over (see [`Class::turn`]).
    turns: watch::Sender<u64>,
}

impl Default for Class {
    fn default() -> Class {
        Class {
            inner: Mutex::default(),
            removed: watch::Sender::new(Default::default()),
            roster: watch::Sender::new(0),
            poll: watch::Sender::new(None),
            turns: watch::Sender::new(0),
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

    /// A student comes in over SSH (see [`Class::take_seat`]).
    pub fn join(
        &self,
        name: &str,
        addr: IpAddr,
        size: (u16, u16),
        marker: &str,
        following: bool,
    ) -> SeatId {
        self.take_seat(&Arrival {
            name,
            addr,
            size,
            marker,
            following,
            via: Transport::Ssh,
            token: None,
        })
        .id
    }

    /// A student takes a seat: the one their token names (a page
    /// reloaded, a tab that lost its connection: the same row in the
    /// class list, the same name, the same answers), or, over SSH, the
    /// seat an SSH student of the same name from the same address left;
    /// else a new seat, under a name no other student has. A session
    /// still on the seat is taken over ([`Class::turn`] says so).
    pub fn take_seat(&self, a: &Arrival) -> Taken {
        let mut c = self.lock();
        let again = match a.token {
            Some(t) => c
                .seats
                .iter()
                .find(|(_, s)| s.token == t)
                .map(|(id, _)| *id),
            None if a.via == Transport::Ssh => c
                .seats
                .iter()
                .find(|(_, s)| {
                    !s.here && s.via == Transport::Ssh && s.asked == a.name && s.addr == a.addr
                })
                .map(|(id, _)| *id),
            None => None,
        };
        let taken = if let Some(id) = again {
            let s = c.seats.get_mut(&id).expect("found");
            s.here = true;
            s.turn += 1;
            s.addr = a.addr;
            s.following = a.following;
            s.size = a.size;
            s.marker = a.marker.to_string();
            s.last_key = Instant::now();
            s.via = a.via;
            Taken {
                id,
                turn: s.turn,
                name: s.name.clone(),
                token: s.token.clone(),
                again: true,
            }
        } else {
            c.next_seat += 1;
            let id = c.next_seat;
            let name = c.distinct(a.name);
            let token = names::token();
            c.seats.insert(
                id,
                Student {
                    name: name.clone(),
                    asked: a.name.to_string(),
                    addr: a.addr,
                    following: a.following,
                    size: a.size,
                    marker: a.marker.to_string(),
                    last_key: Instant::now(),
                    via: a.via,
                    token: token.clone(),
                    here: true,
                    turn: 1,
                },
            );
            Taken {
                id,
                turn: 1,
                name,
                token,
                again: false,
            }
        };
        drop(c);
        if taken.again {
            self.turns.send_modify(|n| *n += 1);
        }
        self.changed();
        taken
    }

    /// The session's turn on a seat now: a session whose turn it is not
    /// was taken over by a later one (the page reloaded).
    pub fn turn(&self, id: SeatId) -> Option<u64> {
        self.lock().seats.get(&id).map(|s| s.turn)
    }

    /// What sessions watch to learn their seat was taken over.
    pub fn watch_turns(&self) -> watch::Receiver<u64> {
        self.turns.subscribe()
    }

    /// The name a seat has in the class (made distinct when it was taken).
    pub fn name(&self, id: SeatId) -> Option<String> {
        self.lock().seats.get(&id).map(|s| s.name.clone())
    }

    /// The lecturer removes a student: their session ends, told why, and
    /// their seat goes (a token no longer takes it); their name, if they
    /// were here.
    pub fn remove(&self, id: SeatId) -> Option<String> {
        let name = {
            let mut c = self.lock();
            let s = c.seats.get_mut(&id)?;
            // A fresh token: the old one takes no seat.
            s.token = names::token();
            s.name.clone()
        };
        self.removed.send_modify(|r| {
            r.insert(id);
        });
        Some(name)
    }

    /// What students watch to learn they were removed.
    pub fn watch_removed(&self) -> watch::Receiver<std::collections::BTreeSet<SeatId>> {
        self.removed.subscribe()
    }

    /// A student's session on its `turn` goes: the seat waits for them
    /// (out of the class list, its answers staying in the poll); a
    /// removed student's seat goes. A session taken over leaves nothing.
    pub fn leave(&self, id: SeatId, turn: u64) {
        let gone = self.removed.borrow().contains(&id);
        let mut c = self.lock();
        let Some(s) = c.seats.get_mut(&id).filter(|s| s.turn == turn) else {
            return;
        };
        if gone {
            c.seats.remove(&id);
        } else {
            s.here = false;
        }
        drop(c);
        self.changed();
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

    /// How many students came, in all: seats taken (a student who
    /// reloaded, or came back, counts once).
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
            .filter(|(_, s)| s.here)
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
                via: s.via.label(),
            })
            .collect();
        let poll = c.poll.as_ref().map(|o| {
            let here = |k: &u64| c.seats.get(k).is_some_and(|s| s.here);
            let gone = o.answers.keys().filter(|k| !here(k));
            Tally {
                question: o.poll.question,
                answers: o.answers.values().map(|a| a.1).collect(),
                asked: c.seats.values().filter(|s| s.here).count() + gone.count(),
                revealed: o.poll.revealed,
                sweep: o.poll.scene.state.sweep,
            }
        });
        ClassView { seats, poll }
    }

    /// How many students are here.
    pub fn students(&self) -> usize {
        self.lock().seats.values().filter(|s| s.here).count()
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
