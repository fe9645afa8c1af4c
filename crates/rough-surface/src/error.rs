//! Why a surface file was refused: one message naming the file, the line
//! and the problem, the same on the command line and in the explorer.

use std::fmt;
use std::path::PathBuf;

/// What is wrong with a surface file.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Problem {
    /// The file could not be read (the system's reason).
    Read(String),
    IsDir,
    /// Larger than [`crate::MAX_BYTES`].
    TooLarge(u64),
    /// Not UTF-8 text.
    NotText,
    /// No data rows.
    Empty,
    /// A field that is not a number.
    NotNumber(String),
    /// NaN or an infinity.
    NotFinite(String),
    /// A row with another number of columns than the first.
    Ragged {
        got: usize,
        want: usize,
    },
    /// A PSD table or spectrum the model refuses (non-increasing q, C ≤ 0 …).
    Table(rough_model::TableError),
    /// Content that is none of the formats read.
    Unknown(String),
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Problem::Read(e) => write!(f, "cannot read: {e}"),
            Problem::IsDir => write!(f, "is a folder, not a file"),
            Problem::TooLarge(n) => write!(
                f,
                "{n} bytes is too large: surface files are read up to {} MB",
                crate::MAX_BYTES >> 20
            ),
            Problem::NotText => write!(f, "not UTF-8 text"),
            Problem::Empty => write!(f, "no data rows"),
            Problem::NotNumber(s) => write!(f, "'{s}' is not a number"),
            Problem::NotFinite(s) => write!(f, "{s} is not a finite number"),
            Problem::Ragged { got, want } => {
                write!(f, "{got} columns where the first row has {want}")
            }
            Problem::Table(e) => e.fmt(f),
            Problem::Unknown(s) => write!(f, "{s}"),
        }
    }
}

/// A refused surface file: `FILE:LINE: problem`.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceError {
    pub path: PathBuf,
    /// 1-based, where the problem has a line.
    pub line: Option<usize>,
    pub problem: Problem,
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "bad surface {}", self.path.display())?;
        if let Some(l) = self.line {
            write!(f, ", line {l}")?;
        }
        write!(f, ": {}", self.problem)
    }
}

impl std::error::Error for SurfaceError {}
