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
    /// Larger than [`crate::limits::MAX_BYTES`].
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
    /// A height matrix or line with neither a size header nor a pixel size.
    NoSize {
        /// A line scan (needs `# Width:`) rather than a map.
        line: bool,
    },
    /// A unit that is not one of the length units read.
    UnknownUnit(String),
    /// Fewer than 4 samples along an axis.
    TooFew {
        axis: &'static str,
        got: usize,
    },
    /// Zero variance: all heights equal, or nothing left after removing
    /// the plane (line).
    Flat {
        /// The heights were a tilted plane (line), not a constant.
        plane: bool,
    },
    /// Nothing left after removing the least-squares quadratic
    /// (`--detrend curvature`).
    Quadratic,
    /// A line scan whose x is not uniformly spaced (or does not increase).
    NonUniform {
        x: f64,
        expected: f64,
        spacing: f64,
    },
    /// Two columns that could be a line scan or a PSD table.
    Ambiguous,
    /// Numbers written with decimal commas.
    DecimalComma(String),
    /// A file holding several channels or blocks where one is read.
    Several(String),
    /// A header whose value cannot be read (e.g. `# Width: wide`).
    BadHeader(String),
    /// A command-line option that does not apply to this file.
    Option(String),
    /// More undefined points (NaN, empty cells, masked) than are filled
    /// ([`crate::MAX_UNDEFINED`]).
    Undefined {
        count: usize,
        total: usize,
        /// The share filled at most (0–1): [`crate::MAX_UNDEFINED`] or
        /// `--max-undefined`'s.
        allowed: f64,
    },
    /// An undefined value (NaN, an empty cell) where only heights may be
    /// undefined: a position, a wavevector, a PSD value.
    UndefinedValue(&'static str),
    /// A binary file (x3p, .gwy) that is damaged or holds what is not
    /// read, or a file in a format not read (with what to do about it).
    Format(String),
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Problem::Read(e) => write!(f, "cannot read: {e}"),
            Problem::IsDir => write!(f, "is a folder, not a file"),
            Problem::TooLarge(n) => write!(
                f,
                "{n} bytes is too large: surface files are read up to {} MB",
                crate::limits::MAX_BYTES >> 20
            ),
            Problem::NotText => write!(f, "not UTF-8 text"),
            Problem::Empty => write!(f, "no data rows (the file is empty or all comments)"),
            Problem::NotNumber(s) => write!(f, "'{s}' is not a number"),
            Problem::NotFinite(s) => write!(f, "{s} is not a finite number"),
            Problem::Ragged { got, want } => {
                write!(f, "{got} columns where the first row has {want}")
            }
            Problem::Table(e) => e.fmt(f),
            Problem::Unknown(s) => write!(f, "{s}"),
            Problem::NoSize { line: true } => write!(
                f,
                "no size: add a header line '# Width: 10 µm' (the scan's length) \
                 or give the sample spacing with --pixel-size"
            ),
            Problem::NoSize { line: false } => write!(
                f,
                "no size: add header lines '# Width: 10 µm' and '# Height: 10 µm' \
                 or give the sample spacing with --pixel-size"
            ),
            Problem::UnknownUnit(u) => write!(
                f,
                "unknown unit '{u}': lengths are read in m, mm, µm (um), nm, pm or Å"
            ),
            Problem::TooFew { axis, got } => write!(
                f,
                "{got} point{} along {axis}: at least 4 are needed",
                if *got == 1 { "" } else { "s" }
            ),
            Problem::Flat { plane: false } => {
                write!(f, "the surface is flat: every height is the same")
            }
            Problem::Flat { plane: true } => write!(
                f,
                "the surface is flat: nothing is left after removing its tilt \
                 (the heights lie on a plane)"
            ),
            Problem::Quadratic => write!(
                f,
                "the surface is flat: nothing is left after removing its curvature \
                 (--detrend curvature; the heights lie on a quadratic)"
            ),
            Problem::NonUniform {
                x,
                expected,
                spacing,
            } => {
                // Computed numbers to 6 significant digits, the file's x as written.
                let g = |v: &f64| format!("{v:.5e}").parse::<f64>().unwrap_or(*v);
                let (expected, spacing) = (g(expected), g(spacing));
                write!(
                    f,
                    "x is not uniformly spaced: x = {x} where the least-squares spacing \
                 {spacing} puts {expected} (a line scan needs \
                 uniform x, to 1% of the spacing beyond the rounding of the \
                 printed digits)"
                )
            }
            Problem::Ambiguous => write!(
                f,
                "two columns that could be a line scan (x z) or a PSD table \
                 (q C): add a header line '# x z' for a line scan or '# q C' \
                 for a PSD table"
            ),
            Problem::DecimalComma(s) => write!(
                f,
                "'{s}' has a decimal comma: write numbers with a decimal point"
            ),
            Problem::Several(s) => write!(f, "{s}"),
            Problem::BadHeader(s) => write!(f, "{s}"),
            Problem::Option(s) => write!(f, "{s}"),
            Problem::UndefinedValue(what) => write!(
                f,
                "an undefined {what} (nan or an empty cell): only heights may be undefined"
            ),
            Problem::Undefined {
                count,
                total,
                allowed,
            } => write!(
                f,
                "{count} of {total} points ({}) are undefined (NaN, empty or masked): \
                 up to {} are filled, more is refused; crop the data to the part \
                 that was measured, or allow more with --max-undefined PERCENT",
                share(*count, *total),
                percent(*allowed)
            ),
            Problem::Format(s) => write!(f, "{s}"),
        }
    }
}

/// A refused surface file: `bad surface FILE, line N: problem`.
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

/// A problem and the 1-based line it is about, if any.
pub(crate) type Failure = (Option<usize>, Problem);

/// A share 0–1 as a percentage for people: "35 %", "0.5 %".
pub(crate) fn percent(share: f64) -> String {
    let s = format!("{:.4}", share * 100.0);
    format!("{} %", s.trim_end_matches('0').trim_end_matches('.'))
}

/// A share of points as a percentage for people: "0.4 %", "0.12 %",
/// "2.5 %", "12.5 %", "< 0.01 %".
pub(crate) fn share(count: usize, total: usize) -> String {
    let p = 100.0 * count as f64 / total as f64;
    if p < 0.01 {
        return "< 0.01 %".to_string();
    }
    let digits = if p < 1.0 { 2 } else { 1 };
    let s = format!("{p:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    format!("{s} %")
}
