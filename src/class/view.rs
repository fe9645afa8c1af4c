//! The class as a screen shows it: the lecturer's view of the roster and
//! the poll's answers ([`ClassView`], [`Seat`], [`Tally`]), and a
//! student's poll ([`Asked`]), each with the line it reads as.

use std::time::Duration;

use super::glyphs::ClassGlyphs;
use super::question::{fmt_value, Question, NOWHERE};

/// One student as the lecturer's class list shows them.
#[derive(Clone, Debug, PartialEq)]
pub struct Seat {
    /// The student's place in the class (the server's number).
    pub id: u64,
    /// Escaped and cut (see [`super::clean_name`]).
    pub name: String,
    pub state: SeatState,
    /// Columns × rows.
    pub size: (u16, u16),
    /// The student's marker set.
    pub marker: String,
    /// Since their last key.
    pub idle: Duration,
    /// How they reach the class: `ssh`, `web` or `phone`.
    pub via: &'static str,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SeatState {
    Following,
    /// Exploring on their own (or no lecturer to follow).
    Own,
    /// A poll is open and they have not answered.
    Answering,
    Answered,
}

impl SeatState {
    pub fn label(self) -> &'static str {
        match self {
            SeatState::Following => "following",
            SeatState::Own => "on their own",
            SeatState::Answering => "answering",
            SeatState::Answered => "answered",
        }
    }
}

/// The poll as the lecturer sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct Tally {
    pub question: Question,
    /// Every answer given (also by students who left since).
    pub answers: Vec<f64>,
    /// Students asked: those here and those who left after answering.
    pub asked: usize,
    pub revealed: bool,
    /// The poll scene's sweep: the histogram shows on a chart along it.
    pub sweep: rough_model::Sweep,
}

impl Tally {
    /// "23/31 answered", or "ζ = 321.5 · 23 answers (2 nowhere)" after
    /// the reveal: what the histogram of the answers says.
    pub fn count(&self, g: &ClassGlyphs) -> String {
        if !self.revealed {
            return format!("{}/{} answered", self.answers.len(), self.asked);
        }
        let q = &self.question;
        let n = self.answers.len();
        let nowhere = self.answers.iter().filter(|a| **a == NOWHERE).count();
        let nowhere = if nowhere > 0 {
            format!(" ({nowhere} nowhere)")
        } else {
            String::new()
        };
        format!(
            "{}{}{n} {}{nowhere}",
            q.value(q.truth),
            g.sep,
            if n == 1 { "answer" } else { "answers" }
        )
    }
}

/// How close answers must come to the truth to count as right on the
/// projector: within 10 % of it.
pub const WITHIN: f64 = 0.1;

impl Tally {
    /// The median of the answers that name a value (the middle one, or
    /// the mean of the two middle ones); `None` without any. "Nowhere"
    /// answers are counted apart ([`Tally::nowhere`]).
    pub fn median(&self) -> Option<f64> {
        let mut v: Vec<f64> = self
            .answers
            .iter()
            .copied()
            .filter(|a| a.is_finite())
            .collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let n = v.len();
        Some(if n % 2 == 1 {
            v[n / 2]
        } else {
            // On a log axis the middle of two answers is their geometric
            // mean (the point halfway between them on the chart).
            let (a, b) = (v[n / 2 - 1], v[n / 2]);
            if self.question.axis.is_log() && a > 0.0 && b > 0.0 {
                (a * b).sqrt()
            } else {
                (a + b) / 2.0
            }
        })
    }

    /// The "nowhere in the sweep" answers.
    pub fn nowhere(&self) -> usize {
        self.answers.iter().filter(|a| **a == NOWHERE).count()
    }

    /// How many answers are within [`WITHIN`] of the truth (|answer −
    /// truth| ≤ 10 % of the truth; a "nowhere" answer is right when the
    /// truth is nowhere).
    pub fn within(&self) -> usize {
        let t = self.question.truth;
        self.answers
            .iter()
            .filter(|&&a| {
                if t == NOWHERE || a == NOWHERE {
                    a == t
                } else {
                    (a - t).abs() <= WITHIN * t.abs()
                }
            })
            .count()
    }
}

/// What the lecturer's explorer shows about the class.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClassView {
    /// The students, in the order they came.
    pub seats: Vec<Seat>,
    pub poll: Option<Tally>,
}

/// The smallest terminal the explorer draws in (its layout's minimum;
/// below it, a short message): the class line counts the students at a
/// smaller one.
pub const MIN_SIZE: (u16, u16) = (80, 24);

impl ClassView {
    /// "31 students · 28 following · 3 on their own · 2 terminals < 80×24",
    /// with the poll's count while one is open ("23/31 answered") instead
    /// of who follows, or its answer once revealed (until the next poll).
    pub fn line(&self, g: &ClassGlyphs) -> String {
        let n = self.seats.len();
        let count = |s: SeatState| self.seats.iter().filter(|x| x.state == s).count();
        let plural =
            |k: usize, one: &str, many: &str| format!("{k} {}", if k == 1 { one } else { many });
        let mut parts = vec![plural(n, "student", "students")];
        match &self.poll {
            Some(t) if !t.revealed => {
                parts.push(format!("{}/{} answered", t.answers.len(), t.asked));
            }
            _ => {
                parts.push(format!("{} following", count(SeatState::Following)));
                parts.push(format!("{} on their own", count(SeatState::Own)));
            }
        }
        if let Some(t) = self.poll.as_ref().filter(|t| t.revealed) {
            parts.push(format!(
                "revealed {} ({})",
                t.question.value(t.question.truth),
                plural(t.answers.len(), "answer", "answers")
            ));
        }
        // (A phone draws no cells: its size is not a terminal's.)
        let small = self
            .seats
            .iter()
            .filter(|s| s.via != "phone" && (s.size.0 < MIN_SIZE.0 || s.size.1 < MIN_SIZE.1))
            .count();
        if small > 0 {
            parts.push(format!(
                "{} < {}{}{}",
                plural(small, "terminal", "terminals"),
                MIN_SIZE.0,
                g.times,
                MIN_SIZE.1
            ));
        }
        parts.join(g.sep)
    }
}

/// A student's poll.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Asked {
    pub question: Question,
    /// Their answer, once sent.
    pub answer: Option<f64>,
    pub revealed: bool,
    /// Revealed after the lecturer changed the scene asked about.
    pub changed: bool,
}

impl Asked {
    /// The line that stands in for the claims while the poll is on.
    pub fn line(&self, g: &ClassGlyphs, width: usize) -> String {
        let q = &self.question;
        let sep = g.sep;
        if self.revealed {
            // The lecturer changed the scene after asking: the truth is
            // the scene's as asked.
            let asked = if self.changed { ", as asked" } else { "" };
            let truth = format!("the model{asked}: {}", q.value(q.truth));
            let line = match self.answer {
                Some(a) => format!(
                    "{truth}{sep}you: {}{sep}{}",
                    fmt_value(q.axis, a),
                    q.off(a, g)
                ),
                None => format!("{truth}{sep}you did not answer"),
            };
            let how = format!("{line}{sep}Enter dismisses");
            return if how.chars().count() <= width {
                how
            } else {
                line
            };
        }
        match self.answer {
            None => {
                let ask = format!("Predict: {}", q.text(g));
                let hows: &[&str] = if q.nowhere_ok() {
                    &[
                        " Marker and Enter, or 0: nowhere",
                        " Enter, or 0: nowhere",
                        "",
                    ]
                } else {
                    &[
                        " Move the marker and press Enter",
                        " Marker, then Enter",
                        "",
                    ]
                };
                hows.iter()
                    .map(|how| format!("{ask}{how}"))
                    .find(|s| s.chars().count() <= width)
                    .unwrap_or(ask)
            }
            Some(a) => format!(
                "you answered {}{sep}Enter again changes it{sep}waiting for the reveal",
                q.value(a)
            ),
        }
    }
}

/// How long, in words: `45s`, `2m03s`, `1h02m`.
pub fn duration(d: Duration) -> String {
    let s = d.as_secs();
    match s {
        0..60 => format!("{s}s"),
        60..3600 => format!("{}m{:02}s", s / 60, s % 60),
        _ => format!("{}h{:02}m", s / 3600, s / 60 % 60),
    }
}
