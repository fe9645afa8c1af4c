//! The class's poll: the question as students read it, their answers, the
//! reveal, and the answers as CSV.

use std::collections::BTreeMap;
use std::sync::Arc;
use std::time::SystemTime;

use super::{Class, Inner, SeatId};
use crate::class::csv::{csv_field, csv_value, utc, CSV_HEADER};
use crate::class::glyphs::ASCII;
use crate::class::question::{Question, NOWHERE};
use crate::class::shown::Shown;
use crate::physical::{ascii::to_ascii, csv_number};

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

/// The last poll: open, or revealed (kept until the next opens, for `S`).
#[derive(Debug)]
pub(super) struct Open {
    pub(super) poll: Arc<Poll>,
    /// By seat: the name then, the answer and when it came.
    pub(super) answers: BTreeMap<u64, (String, f64, SystemTime)>,
    /// The students who were here at the reveal without an answer.
    pub(super) silent: Vec<String>,
}

impl Class {
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
            .filter(|(id, s)| s.here && !open.answers.contains_key(id))
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

    /// Whether the last poll is open (asked, not revealed).
    pub fn poll_open(&self) -> bool {
        self.lock().poll.as_ref().is_some_and(|o| !o.poll.revealed)
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
        let nowhere = value == NOWHERE && open.poll.question.nowhere_ok();
        if open.poll.id != poll || open.poll.revealed || !(value.is_finite() || nowhere) {
            return Err(Refused::Closed);
        }
        open.answers.insert(id, (name, value, SystemTime::now()));
        drop(c);
        self.changed();
        Ok(())
    }

    /// The last poll's answers as CSV: [`CSV_HEADER`], then a row per
    /// answer in the order students came, then a `no answer` row for each
    /// student here (at the reveal, or now while the poll is open) who
    /// did not answer. Values in the model's units (metres for lengths);
    /// `offset` is the answer minus the truth; `step` the lesson's step
    /// the poll was asked on (empty outside a lesson), `time` when the
    /// answer came (UTC), `poll` the class's count of polls asked (1 for
    /// the first), `revealed` `yes`, or `no` for a poll saved open (the
    /// server stopped before its reveal).
    pub fn csv(&self) -> Option<String> {
        self.csv_rows().map(|rows| format!("{CSV_HEADER}\n{rows}"))
    }

    /// The same without the header (a lesson's polls go to one file).
    pub fn csv_rows(&self) -> Option<String> {
        let c = self.lock();
        let o = c.poll.as_ref()?;
        let q = &o.poll.question;
        let head = [
            csv_field(&to_ascii(&q.text(&ASCII))),
            csv_field(&to_ascii(q.axis.symbol())),
            q.unit().to_string(),
            csv_value(q.truth),
        ]
        .join(",");
        let step = (o.poll.scene.step.as_ref())
            .filter(|s| s.left.is_none())
            .map_or(String::new(), |s| s.at.to_string());
        let tail = format!(
            "{},{}",
            o.poll.id,
            if o.poll.revealed { "yes" } else { "no" }
        );
        let mut s = String::new();
        for (name, v, at) in o.answers.values() {
            let offset = if v.is_finite() && q.truth.is_finite() {
                csv_number::format(*v - q.truth)
            } else {
                String::new()
            };
            s.push_str(&format!(
                "{head},{},{},{offset},{step},{},{tail}\n",
                csv_field(name),
                csv_value(*v),
                utc(*at)
            ));
        }
        let silent: Vec<String> = if o.poll.revealed {
            o.silent.clone()
        } else {
            c.seats
                .iter()
                .filter(|(id, st)| st.here && !o.answers.contains_key(id))
                .map(|(_, st)| st.name.clone())
                .collect()
        };
        for name in silent {
            s.push_str(&format!(
                "{head},{},no answer,,{step},,{tail}\n",
                csv_field(&name)
            ));
        }
        Some(s)
    }
}
