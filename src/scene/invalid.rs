//! Why a scene is not acceptable: a value that parsed but is out of its
//! domain, a view the scene cannot show, a name or caption that cannot be
//! printed.

use std::fmt;

use rough_model::{ParamError, RoughnessError, SweepError};

/// A value that parsed but is not acceptable.
#[derive(Debug, Clone, PartialEq)]
pub enum Invalid {
    /// A parameter outside its domain (the model's validation).
    Params(ParamError),
    /// Moments that cannot be computed at these parameters (H = 1 with
    /// asymptotic moments).
    Moments(ParamError),
    /// An empty sweep or one outside its axis' domain.
    Sweep(SweepError),
    /// A sweep or value a measured surface does not have (h_rms or H, ζ
    /// beyond the data).
    Surface(RoughnessError),
    /// A view, map axis or ghost the scene cannot show (`shown.rs`).
    Shown(String),
    /// `name` or `caption` is too long or not printable.
    Text {
        field: &'static str,
        problem: TextProblem,
    },
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TextProblem {
    TooLong { chars: usize, max: usize },
    Control(char),
}

impl fmt::Display for Invalid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Invalid::Params(e) => write!(f, "params: {e}"),
            Invalid::Moments(e) => write!(f, "{e}"),
            Invalid::Sweep(e) => write!(f, "{e}"),
            Invalid::Surface(e) => write!(f, "{e}"),
            Invalid::Shown(e) => write!(f, "{e}"),
            Invalid::Text {
                field,
                problem: TextProblem::TooLong { chars, max },
            } => write!(
                f,
                "{field} is {chars} characters long: it must be at most {max}"
            ),
            Invalid::Text {
                field,
                problem: TextProblem::Control(c),
            } => write!(
                f,
                "{field} contains the control character U+{:04X}: it must be printable text",
                u32::from(*c)
            ),
        }
    }
}

impl std::error::Error for Invalid {}
