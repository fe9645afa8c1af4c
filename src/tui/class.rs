//! What an explorer shows about a class it is part of: the lecturer's view
//! of the class (who is there, who follows, the poll's answers) and a
//! student's poll (the question, their answer, the reveal). The explorer
//! only draws these; who fills them in, and how, is the server's business
//! (`serve::class`).

use std::time::Duration;

use rough_model::Axis;

use crate::figure::{Claim, ClaimKind, View};
use crate::physical::short_number;

/// A value of `axis` to four digits, lengths in a readable unit: `321.5`,
/// `20 nm`, `0.85`.
pub fn fmt_value(axis: Axis, v: f64) -> String {
    if v == NOWHERE {
        return "nowhere".into();
    }
    if !matches!(axis, Axis::HRms | Axis::RStar) {
        return short_number(v);
    }
    crate::physical::short_length(v)
}

/// The answer, or the truth, of a poll that allows "nowhere in the
/// sweep" ([`Ask::ShareEver`]): the student's `0`, the model's when the
/// plastic share never passes ½.
pub const NOWHERE: f64 = f64::INFINITY;

/// The characters the class panels draw that are not plain ASCII, in one
/// place, with their ASCII stand-ins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClassGlyphs {
    /// Between the parts of a line, with its spaces.
    pub sep: &'static str,
    /// In a terminal size, 80×24.
    pub times: &'static str,
    pub half: &'static str,
    /// The end of a cut name.
    pub cut: &'static str,
    /// A histogram bar's cells, one to eight eighths full.
    pub bars: [&'static str; 8],
    /// The true value's column on the histogram.
    pub truth: &'static str,
}

pub const UNICODE: ClassGlyphs = ClassGlyphs {
    sep: " · ",
    times: "×",
    half: "½",
    cut: "…",
    bars: ["▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"],
    truth: "┃",
};

pub const ASCII: ClassGlyphs = ClassGlyphs {
    sep: " - ",
    times: "x",
    half: "1/2",
    cut: "~",
    bars: ["_", "_", ".", ".", ":", ":", "#", "#"],
    truth: "|",
};

/// What a poll asks: where along its swept parameter a claim of the scene
/// holds, or a value the lecturer typed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Question {
    /// The parameter the answer is a value of (the sweep's, at the poll).
    pub axis: Axis,
    pub ask: Ask,
    /// The model's answer: the claim's bisection, or the typed value.
    pub truth: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ask {
    /// Where the plastic share passes ½ (rising) or falls below it.
    Share { rising: bool },
    /// Where the index in use (Ψ* with the size effect, else Ψ_P) reaches 1
    /// (rising) or falls below it.
    Index { rising: bool, size_effect: bool },
    /// Where the total slope has its minimum inside the sweep.
    Minimum,
    /// Where the plastic share passes ½, if anywhere in the sweep (the
    /// truth may be [`NOWHERE`], and so may an answer: a student's `0`).
    ShareEver,
    /// A value the lecturer typed.
    Typed,
}

impl Question {
    /// The question the view and the scene's claims make: on the index
    /// view the index reaching 1, elsewhere the plastic share passing ½
    /// (each falling back on the other, then on the total slope's minimum,
    /// fig3's claim); `None` when the scene makes no claim (the lecturer
    /// then types the value).
    pub fn of_claims(view: View, claims: &[Claim]) -> Option<Question> {
        let first = |kind| claims.iter().find(|c| c.kind == kind);
        let (a, b) = match view {
            View::Indices => (ClaimKind::IndexOne, ClaimKind::ShareHalf),
            _ => (ClaimKind::ShareHalf, ClaimKind::IndexOne),
        };
        let c = first(a)
            .or_else(|| first(b))
            .or_else(|| first(ClaimKind::TotalMinimum))?;
        let ask = match c.kind {
            ClaimKind::ShareHalf => Ask::Share { rising: c.rising },
            ClaimKind::IndexOne => Ask::Index {
                rising: c.rising,
                size_effect: c.size_effect,
            },
            ClaimKind::TotalMinimum => Ask::Minimum,
        };
        Some(Question {
            axis: c.axis,
            ask,
            truth: c.at,
        })
    }

    /// "where does the plastic share pass ½?"
    pub fn text(&self, g: &ClassGlyphs) -> String {
        let half = g.half;
        match self.ask {
            Ask::Share { rising: true } => format!("where does the plastic share pass {half}?"),
            Ask::Share { rising: false } => {
                format!("where does the plastic share fall below {half}?")
            }
            Ask::Index {
                rising,
                size_effect,
            } => {
                let psi = if size_effect { "Ψ*" } else { "Ψ_P" };
                let verb = if rising { "reach" } else { "fall below" };
                format!("where does {psi} {verb} 1?")
            }
            Ask::Minimum => "where is the total slope smallest?".to_string(),
            Ask::ShareEver => {
                format!("where does the plastic share pass {half} now (if anywhere)?")
            }
            Ask::Typed => format!("which {} is it?", self.axis.symbol()),
        }
    }

    /// `ζ = 321.5`
    pub fn value(&self, v: f64) -> String {
        if v == NOWHERE {
            return "nowhere in the sweep".into();
        }
        format!("{} = {}", self.axis.symbol(), fmt_value(self.axis, v))
    }

    /// Whether a student may answer "nowhere" (`0`).
    pub fn nowhere_ok(&self) -> bool {
        self.ask == Ask::ShareEver
    }

    /// How far `answer` is from the truth, said plainly: on log axes a
    /// percentage of the truth below a factor of two ("1.6 % low"), a factor from two
    /// on ("13× high"); on the Hurst exponent's linear axis the difference
    /// ("0.1 low").
    pub fn off(&self, answer: f64, g: &ClassGlyphs) -> String {
        let t = self.truth;
        match (answer == NOWHERE, t == NOWHERE) {
            (true, true) => return "right".into(),
            (false, true) => return "it never passes".into(),
            (true, false) => return "it does pass".into(),
            (false, false) => {}
        }
        if self.axis.is_log() {
            if !(answer > 0.0 && t > 0.0) {
                return "off the scale".into();
            }
            let f = (answer / t).max(t / answer);
            let dir = if answer > t { "high" } else { "low" };
            if f < 1.0005 {
                return "spot on".into();
            }
            if f < 2.0 {
                // Two digits: 1.6 %, 24 %; 0.8 % under one per cent. Of
                // the truth: low is (1 − answer/truth), high (answer/truth − 1).
                let pc = (answer / t - 1.0).abs() * 100.0;
                let pc = if pc < 10.0 {
                    format!("{pc:.1}")
                } else {
                    format!("{pc:.0}")
                };
                return format!("{pc} % {dir}");
            }
            // Two digits say how far off well enough: 2.4×, 13×, 1.2e3×.
            let f = if f < 10.0 {
                format!("{f:.1}").trim_end_matches(".0").to_string()
            } else {
                short_number(f.round())
            };
            format!("{f}{} {dir}", g.times)
        } else {
            let d = answer - t;
            if d.abs() < 0.005 {
                return "spot on".into();
            }
            let dir = if d > 0.0 { "high" } else { "low" };
            format!("{} {dir}", fmt_value(self.axis, d.abs()))
        }
    }

    /// The unit of the answers as the CSV writes them: `m` for lengths,
    /// empty for pure numbers.
    pub fn unit(&self) -> &'static str {
        if matches!(self.axis, Axis::HRms | Axis::RStar) {
            "m"
        } else {
            ""
        }
    }
}

/// One student as the lecturer's class list shows them.
#[derive(Clone, Debug, PartialEq)]
pub struct Seat {
    /// The student's place in the class (the server's number).
    pub id: u64,
    /// Escaped and cut (see `serve::class::clean_name`).
    pub name: String,
    pub state: SeatState,
    /// Columns × rows.
    pub size: (u16, u16),
    /// The student's marker set.
    pub marker: String,
    /// Since their last key.
    pub idle: Duration,
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

/// What the lecturer's explorer shows about the class.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClassView {
    /// The students, in the order they came.
    pub seats: Vec<Seat>,
    pub poll: Option<Tally>,
}

/// The smallest terminal the explorer draws in (the layout's minimum).
const FULL: (u16, u16) = super::layout::MIN_SIZE;

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
        let small = self
            .seats
            .iter()
            .filter(|s| s.size.0 < FULL.0 || s.size.1 < FULL.1)
            .count();
        if small > 0 {
            parts.push(format!(
                "{} < {}{}{}",
                plural(small, "terminal", "terminals"),
                FULL.0,
                g.times,
                FULL.1
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

/// The class as one explorer sees it: the lecturer's view, or a student's
/// poll, and the value a lecturer typed for a poll (taken by the server).
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
    pub lesson: Option<crate::lesson::LessonAt>,
    /// The lesson's step as every screen shows it (a student's from the
    /// lecturer).
    pub step: Option<crate::lesson::StepLine>,
    /// The row chosen in the lecturer's class list (`x` removes it).
    pub chosen: usize,
    /// The student the lecturer chose to remove, until the server acts.
    pub remove: Option<u64>,
    /// The lecturer's scene list, while open.
    pub scenes: Option<crate::tui::scenes::SceneList>,
    /// The revealed poll's answers, when the lecturer shows them to
    /// everyone (`d`): a student's chart draws their histogram.
    pub tally: Option<Tally>,
    /// The class's web page with its code (`serve --web`), for the
    /// lecturer's `Q`.
    pub join_url: Option<String>,
    /// `Q`'s full-screen QR code is up (any key closes it).
    pub join_shown: bool,
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
}

/// The class list's `↑` / `↓`: the previous / next student.
pub fn choose(app: &mut crate::tui::app::App, down: bool) {
    let n = app.class.view.as_ref().map_or(0, |v| v.seats.len());
    if n == 0 {
        return;
    }
    let c = app.class.chosen.min(n - 1);
    app.class.chosen = if down { (c + 1) % n } else { (c + n - 1) % n };
}

/// The class list's `x`: the chosen student is to be removed.
pub fn remove(app: &mut crate::tui::app::App) {
    let v = app.class.view.as_ref();
    app.class.remove = v.and_then(|v| v.seats.get(app.class.chosen)).map(|s| s.id);
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

#[cfg(test)]
#[path = "class_tests.rs"]
mod tests;
