//! What a poll asks: where along the swept parameter a claim of the
//! scene holds, or a value the lecturer typed; its truth, and how far an
//! answer is from it, in words.

use rough_model::Axis;

use super::glyphs::ClassGlyphs;
use crate::figure::{Claim, ClaimKind, View, Withheld};
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

/// What a poll asks: where along its swept parameter a claim of the scene
/// holds, or a value the lecturer typed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Question {
    /// The parameter the answer is a value of (the sweep's, at the poll).
    pub axis: Axis,
    pub ask: Ask,
    /// The model's answer: the claim's bisection, or the typed value.
    pub truth: f64,
    /// The scene asked about uses the size-dependent hardness (its index
    /// is Ψ*, else Ψ_P).
    pub size_effect: bool,
    /// A reading question (a lesson's `read: true`): the answer is read
    /// off the chart, whose curves then stay while it is open.
    pub read: bool,
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
    pub fn of_claims(view: View, claims: &[Claim], size_effect: bool) -> Option<Question> {
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
            size_effect,
            read: false,
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

    /// A value the lecturer typed for a poll on `axis`.
    pub fn typed(axis: Axis, truth: f64) -> Question {
        Question {
            axis,
            ask: Ask::Typed,
            truth,
            size_effect: false,
            read: false,
        }
    }

    /// What a view of a scene (using the size-dependent hardness when
    /// `size_effect`) leaves out while this question's answer waits: the
    /// marks, readouts and remarks (not for a typed value), and, unless
    /// it is a reading question, the curves whose drawing answers it —
    /// the plastic and total slopes for the share and the index (each
    /// brackets the other), every slope for the total's minimum, on a
    /// scene of the question's hardness; and the index of the question's
    /// hardness (Ψ* with eq. 13, or Ψ_P), wherever it is drawn.
    pub fn withheld(&self, size_effect: bool) -> Withheld {
        if self.ask == Ask::Typed {
            return Withheld::NONE;
        }
        let mut w = Withheld {
            marks: true,
            ..Withheld::NONE
        };
        if self.read {
            return w;
        }
        let same = size_effect == self.size_effect;
        match self.ask {
            Ask::Minimum => w.slopes = [same; 4],
            _ => w.slopes = [false, same, same, false],
        }
        w.indices = if self.size_effect {
            [false, false, true, true]
        } else {
            [false, true, false, false]
        };
        w
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
