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
use std::time::{Instant, SystemTime};

use tokio::sync::watch;

pub use super::csv::CSV_HEADER;
use super::csv::{csv_field, csv_value};
use super::follow::Shown;
use crate::csv_number;
pub use crate::tui::class::duration;
use crate::tui::class::{ClassGlyphs, ClassView, Question, Seat, SeatState, Tally};

/// The most characters of a student's name that are shown (after escaping).
pub const NAME_CHARS: usize = 32;

/// A student's SSH user name as the class shows it: control and
/// direction-changing characters escaped (`\x1b`, `\u{202e}`, a backslash
/// doubled), cut to [`NAME_CHARS`] characters with `…` as the last, and
/// `(no name)` for an empty one.
pub fn clean_name(raw: &str) -> String {
    let mut out = String::new();
    let mut n = 0;
    for c in raw.chars() {
        let esc: String = match c {
            '\\' => "\\\\".into(),
            c if (c as u32) < 0x100 && c.is_control() => format!("\\x{:02x}", c as u32),
            c if c.is_control() || invisible(c) => format!("\\u{{{:x}}}", c as u32),
            c => c.to_string(),
        };
        for e in esc.chars() {
            if n == NAME_CHARS {
                out.pop();
                out.push('…');
                return out;
            }
            out.push(e);
            n += 1;
        }
    }
    if out.is_empty() {
        out.push_str("(no name)");
    }
    out
}

/// Characters that draw nothing or reorder what follows: zero-width and
/// bidirectional controls, the byte-order mark.
fn invisible(c: char) -> bool {
    matches!(c as u32, 0x200b..=0x200f | 0x202a..=0x202e | 0x2060..=0x206f | 0xfeff)
}

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

/// The poll as students read it.
#[derive(Clone, Debug, PartialEq)]
pub struct Poll {
    pub id: u64,
    pub question: Question,
    /// The lecturer's scene when the poll opened: every student answers on it.
    pub scene: Shown,
    pub revealed: bool,
    /// Revealed after the lecturer changed the scene asked about (the
    /// truth is the scene's as asked).
    pub changed: bool,
    /// The answers, once the lecturer shows them to everyone (`d`).
    pub answers: Option<Arc<[f64]>>,
}

/// Why an answer was not taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refused {
    /// The answers were revealed (or another poll opened) before it came.
    Closed,
    /// No poll is on.
    NoPoll,
}

impl Refused {
    pub fn text(self) -> &'static str {
        match self {
            Refused::Closed => "too late: the answers were already revealed",
            Refused::NoPoll => "no poll is on",
        }
    }
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

/// The last poll: open, or revealed (kept until the next opens, for `S`).
#[derive(Debug)]
struct Open {
    poll: Arc<Poll>,
    /// By seat: the name then, the answer and when it came.
    answers: BTreeMap<u64, (String, f64, SystemTime)>,
    /// The students who were here at the reveal without an answer.
    silent: Vec<String>,
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

    /// Opens a poll on `scene`, replacing any other (and the last one's
    /// answers); its id.
    pub fn open(&self, question: Question, scene: Shown) -> u64 {
        let mut c = self.lock();
        c.next_poll += 1;
        let poll = Arc::new(Poll {
            id: c.next_poll,
            question,
            scene,
            revealed: false,
            changed: false,
            answers: None,
        });
        c.poll = Some(Open {
            poll: Arc::clone(&poll),
            answers: BTreeMap::new(),
            silent: Vec::new(),
        });
        drop(c);
        self.poll.send_replace(Some(poll.clone()));
        self.changed();
        poll.id
    }

    /// Reveals the open poll's answer (`changed`: the lecturer's scene is
    /// no longer the one asked about); whether there was one to reveal.
    pub fn reveal(&self, changed: bool) -> bool {
        let mut c = self.lock();
        let Inner { seats, poll, .. } = &mut *c;
        let Some(open) = poll.as_mut().filter(|o| !o.poll.revealed) else {
            return false;
        };
        let mut p = (*open.poll).clone();
        p.revealed = true;
        p.changed = changed;
        open.poll = Arc::new(p);
        open.silent = seats
            .iter()
            .filter(|(id, _)| !open.answers.contains_key(id))
            .map(|(_, s)| s.name.clone())
            .collect();
        let poll = Arc::clone(&open.poll);
        drop(c);
        self.poll.send_replace(Some(poll));
        self.changed();
        true
    }

    /// Shows the revealed poll's answers to every student (the lecturer's
    /// `d`); whether there was a revealed poll.
    pub fn share_answers(&self) -> bool {
        let mut c = self.lock();
        let Some(open) = c.poll.as_mut().filter(|o| o.poll.revealed) else {
            return false;
        };
        let mut p = (*open.poll).clone();
        p.answers = Some(open.answers.values().map(|a| a.1).collect());
        open.poll = Arc::new(p);
        let poll = Arc::clone(&open.poll);
        drop(c);
        self.poll.send_replace(Some(poll));
        true
    }

    /// Cancels the open poll (its answers are dropped); whether one was
    /// open. A revealed poll is not cancelled: it stays for `S`.
    pub fn cancel(&self) -> bool {
        let mut c = self.lock();
        if c.poll.as_ref().is_none_or(|o| o.poll.revealed) {
            return false;
        }
        c.poll = None;
        drop(c);
        self.poll.send_replace(None);
        self.changed();
        true
    }

    /// How many polls were opened.
    pub fn polls(&self) -> u64 {
        self.lock().next_poll
    }

    /// How many students came, in all.
    pub fn seen(&self) -> u64 {
        self.lock().next_seat
    }

    /// The poll, if one is on.
    pub fn poll(&self) -> Option<Arc<Poll>> {
        self.lock().poll.as_ref().map(|o| Arc::clone(&o.poll))
    }

    /// A student's answer to poll `poll`: taken (replacing their earlier
    /// one) while that poll is open; refused, changing nothing, after its
    /// reveal.
    pub fn answer(&self, id: SeatId, poll: u64, value: f64) -> Result<(), Refused> {
        let mut c = self.lock();
        let Some(name) = c.seats.get(&id).map(|s| s.name.clone()) else {
            return Err(Refused::Closed);
        };
        let Some(open) = c.poll.as_mut() else {
            return Err(Refused::NoPoll);
        };
        let nowhere = value == crate::tui::class::NOWHERE && open.poll.question.nowhere_ok();
        if open.poll.id != poll || open.poll.revealed || !(value.is_finite() || nowhere) {
            return Err(Refused::Closed);
        }
        open.answers.insert(id, (name, value, SystemTime::now()));
        drop(c);
        self.changed();
        Ok(())
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

    /// The last poll's answers as CSV: [`CSV_HEADER`], then a row per
    /// answer in the order students came, then a `no answer` row for each
    /// student here (at the reveal, or now while the poll is open) who
    /// did not answer. Values in the model's units (metres for lengths);
    /// `offset` is the answer minus the truth; `step` the lesson's step
    /// the poll was asked on (empty outside a lesson), `time` when the
    /// answer came (UTC).
    pub fn csv(&self) -> Option<String> {
        self.csv_rows().map(|rows| format!("{CSV_HEADER}\n{rows}"))
    }

    /// The same without the header (a lesson's polls go to one file).
    pub fn csv_rows(&self) -> Option<String> {
        let c = self.lock();
        let o = c.poll.as_ref()?;
        let q = &o.poll.question;
        let ascii = crate::tui::glyphs::Glyphs::Ascii;
        let head = [
            csv_field(&ascii.text(&q.text(&crate::tui::class::ASCII))),
            csv_field(&ascii.text(q.axis.symbol())),
            q.unit().to_string(),
            csv_value(q.truth),
        ]
        .join(",");
        let step = (o.poll.scene.step.as_ref())
            .filter(|s| s.left.is_none())
            .map_or(String::new(), |s| s.at.to_string());
        let mut s = String::new();
        for (name, v, at) in o.answers.values() {
            let offset = if v.is_finite() && q.truth.is_finite() {
                csv_number::format(*v - q.truth)
            } else {
                String::new()
            };
            s.push_str(&format!(
                "{head},{},{},{offset},{step},{}\n",
                csv_field(name),
                csv_value(*v),
                super::csv::utc(*at)
            ));
        }
        let silent: Vec<String> = if o.poll.revealed {
            o.silent.clone()
        } else {
            c.seats
                .iter()
                .filter(|(id, _)| !o.answers.contains_key(id))
                .map(|(_, st)| st.name.clone())
                .collect()
        };
        for name in silent {
            s.push_str(&format!("{head},{},no answer,,{step},\n", csv_field(&name)));
        }
        Some(s)
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

    /// Whether the last poll is open (asked, not revealed).
    pub fn poll_open(&self) -> bool {
        self.lock().poll.as_ref().is_some_and(|o| !o.poll.revealed)
    }

    /// The address a seat came from.
    pub fn addr(&self, id: SeatId) -> Option<IpAddr> {
        self.lock().seats.get(&id).map(|s| s.addr)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::class::{Ask, UNICODE};
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

    /// The CSV with each answer's time (checked for its form) as `T`.
    fn untimed(csv: &str) -> String {
        let mut out = String::new();
        for line in csv.lines() {
            let (rest, time) = line.rsplit_once(',').unwrap();
            if time.is_empty() || time == "time" {
                out.push_str(line);
            } else {
                assert_eq!((time.len(), &time[10..11], &time[19..]), (20, "T", "Z"));
                out.push_str(&format!("{rest},T"));
            }
            out.push('\n');
        }
        out
    }

    #[test]
    fn two_students_of_one_name_get_distinct_names() {
        let class = Class::default();
        let a = class.join("ada", HOME, (80, 24), "braille", true);
        let b = class.join("ada", HOME, (80, 24), "braille", true);
        let c = class.join("ada", HOME, (80, 24), "braille", true);
        assert_eq!(class.name(a).unwrap(), "ada");
        assert_eq!(class.name(b).unwrap(), "ada-2");
        assert_eq!(class.name(c).unwrap(), "ada-3");
        // A long name keeps its number within NAME_CHARS.
        let long = "b".repeat(NAME_CHARS);
        class.join(&long, HOME, (80, 24), "braille", true);
        let d = class.join(&long, HOME, (80, 24), "braille", true);
        let n = class.name(d).unwrap();
        assert!(n.ends_with("-2") && n.chars().count() == NAME_CHARS, "{n}");
        // One who answered and left keeps the name in the poll's rows.
        let id = class.open(question(), shown());
        class.answer(b, id, 100.0).unwrap();
        class.leave(b);
        let e = class.join("ada", HOME, (80, 24), "braille", true);
        assert_eq!(class.name(e).unwrap(), "ada-4");
        assert!(class.reveal(false));
        let names: Vec<String> = (class.csv().unwrap().lines().skip(1))
            .map(|l| l.split(',').nth(4).unwrap().to_string())
            .collect();
        let mut sorted = names.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), names.len(), "{names:?}");
    }

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
        assert!(class.reveal(false));
        assert!(!class.reveal(false));
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
            untimed(&class.csv().unwrap()),
            "question,quantity,unit,truth,name,answer,offset,step,time\n\
             where does the plastic share pass 1/2?,zeta,,321.5,alice,200,-121.5,,T\n\
             where does the plastic share pass 1/2?,zeta,,321.5,\"b,\"\"ob\"\"\",1000,678.5,,T\n\
             where does the plastic share pass 1/2?,zeta,,321.5,carol,no answer,,,\n"
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
            untimed(&class.csv().unwrap())
                .lines()
                .skip(1)
                .collect::<Vec<_>>(),
            [
                "where does the plastic share pass 1/2?,zeta,,321.5,carol,5,-316.5,,T",
                "where does the plastic share pass 1/2?,zeta,,321.5,alice,no answer,,,"
            ]
        );
        assert!(class.cancel());
        assert_eq!(class.poll(), None);
        assert_eq!(class.csv(), None);
        assert_eq!(class.answer(c, id2, 5.0), Err(Refused::NoPoll));
        assert_eq!((class.polls(), class.seen()), (2, 3));
    }
}
