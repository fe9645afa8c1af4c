//! Why a snapshot was refused, kept typed until it is displayed.
//!
//! Parse errors come from ron's typed errors ([`ron::error::SpannedError`]:
//! an [`ron::Error`] and its position) and the field path that
//! `serde_path_to_error` records (`params.zeta`). The lists in messages
//! (fields, axes, models, moments) are the ones serde's derive hands to ron,
//! so they follow the types.

use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

use ron::error::SpannedError;
use rough_model::{Axis, Model, Moments, ParamValues};
use serde::de::DeserializeOwned;
use serde_path_to_error::Segment;

use crate::scene::Invalid;

use super::{SnapshotFile, SurfaceFile, SurfaceProblem, SweepFile, MAX_BYTES, MAX_DEPTH, VERSION};

/// Why a snapshot text was rejected (without the file name; [`LoadError`]
/// adds it).
#[derive(Debug, Clone, PartialEq)]
pub enum SnapshotError {
    /// More than [`MAX_BYTES`]; `bytes` is the size when known.
    TooLarge { bytes: Option<u64> },
    /// The first invalid byte is at this line and column.
    NotUtf8 { line: usize, column: usize },
    /// Nothing but blanks (or a byte-order mark).
    Empty,
    /// A RON syntax, field, type, version, variant or nesting error.
    Parse {
        line: usize,
        column: usize,
        problem: Box<ParseProblem>,
    },
    /// A version other than [`VERSION`] (from [`super::State::from_file`]).
    Version(u32),
    /// Values that parse but are out of their domain.
    Invalid(Invalid),
    /// The measured surface it names cannot be shown.
    Surface(SurfaceProblem),
}

/// What is wrong at a position in the text. `within` and `field` are dotted
/// field paths ("" for the snapshot as a whole).
#[derive(Debug, Clone, PartialEq)]
pub enum ParseProblem {
    UnknownField {
        within: String,
        found: String,
        expected: &'static [&'static str],
    },
    MissingField {
        within: String,
        field: &'static str,
    },
    DuplicateField {
        within: String,
        field: &'static str,
    },
    UnknownVariant {
        field: String,
        found: String,
        expected: &'static [&'static str],
    },
    WrongType {
        field: String,
        expected: Expected,
    },
    /// A version other than [`VERSION`]; `None` when it does not fit an i64.
    Version(Option<i64>),
    /// Deeper than [`MAX_DEPTH`].
    TooDeep,
    /// The text ends inside the snapshot.
    Eof,
    /// Text after the closing bracket.
    Trailing,
    /// A field name was expected here.
    FieldName {
        within: String,
    },
    /// Any other RON error, in ron's words.
    Syntax {
        within: String,
        error: ron::Error,
    },
}

/// What a field's value should have been.
#[derive(Debug, Clone, PartialEq)]
pub enum Expected {
    Number,
    WholeNumber,
    Bool,
    Text,
    /// A group `(…)` with these fields.
    Group(&'static [&'static str]),
    /// One of these names.
    OneOf(&'static [&'static str]),
}

impl From<Invalid> for SnapshotError {
    fn from(e: Invalid) -> Self {
        SnapshotError::Invalid(e)
    }
}

/// A ron error at the field `path` (dotted, "" for the whole text),
/// classified.
pub(super) fn parse_error(path: &str, e: SpannedError) -> SnapshotError {
    SnapshotError::Parse {
        line: e.span.start.line,
        column: e.span.start.col,
        problem: Box::new(classify(path, e.code)),
    }
}

/// `params.zeta` for the path through fields (enum variants and keys that
/// could not be read add nothing).
pub(super) fn dotted(path: &serde_path_to_error::Path) -> String {
    let keys: Vec<&str> = path
        .iter()
        .filter_map(|s| match s {
            Segment::Map { key } => Some(key.as_str()),
            _ => None,
        })
        .collect();
    keys.join(".")
}

fn classify(path: &str, code: ron::Error) -> ParseProblem {
    use ron::Error as E;
    let at = path.to_string();
    match code {
        E::ExceededRecursionLimit => ParseProblem::TooDeep,
        E::Eof => ParseProblem::Eof,
        E::TrailingCharacters => ParseProblem::Trailing,
        E::NoSuchStructField {
            expected, found, ..
        } => {
            // The path ends with the unknown key itself.
            let parent = match path.rsplit_once('.') {
                Some((p, last)) if last == found => p,
                None if path == found => "",
                _ => path,
            };
            ParseProblem::UnknownField {
                within: parent.to_string(),
                found,
                expected,
            }
        }
        E::MissingStructField { field, .. } => ParseProblem::MissingField { within: at, field },
        E::DuplicateStructField { field, .. } => ParseProblem::DuplicateField { within: at, field },
        E::NoSuchEnumVariant {
            expected, found, ..
        } => ParseProblem::UnknownVariant {
            field: at,
            found,
            expected,
        },
        // de_version's refusal carries the number it read.
        E::Message(m) if path == "version" => ParseProblem::Version(m.parse().ok()),
        E::IntegerOutOfBounds if path == "version" => ParseProblem::Version(None),
        code => {
            let expected = match (code, shape_at(path)) {
                (_, Some(Expected::OneOf(v))) => Expected::OneOf(v),
                (E::ExpectedFloat, _) => Expected::Number,
                (E::ExpectedInteger, _) => Expected::WholeNumber,
                (E::ExpectedBoolean, _) => Expected::Bool,
                (E::ExpectedString, _) => Expected::Text,
                (
                    E::ExpectedStructLike
                    | E::ExpectedNamedStructLike(_)
                    | E::ExpectedDifferentStructName { .. },
                    Some(g),
                ) => g,
                (E::ExpectedIdentifier, Some(Expected::Group(_))) => {
                    return ParseProblem::FieldName { within: at }
                }
                (error, _) => return ParseProblem::Syntax { within: at, error },
            };
            ParseProblem::WrongType {
                field: at,
                expected,
            }
        }
    }
}

/// The shape of the value at `path`: a group with its fields, or a choice of
/// names.
fn shape_at(path: &str) -> Option<Expected> {
    Some(match path {
        "" => Expected::Group(fields::<SnapshotFile>()),
        "params" => Expected::Group(fields::<ParamValues>()),
        "sweep" => Expected::Group(fields::<SweepFile>()),
        "surface" => Expected::Group(fields::<SurfaceFile>()),
        "sweep.axis" => Expected::OneOf(variants::<Axis>()),
        "model" => Expected::OneOf(variants::<Model>()),
        "moments" | "ghost.moments" => Expected::OneOf(variants::<Moments>()),
        "view" => Expected::OneOf(variants::<crate::scene::View>()),
        "map_y" => Expected::OneOf(variants::<Axis>()),
        "ghost" => Expected::Group(fields::<super::GhostFile>()),
        "ghost.params" => Expected::Group(fields::<ParamValues>()),
        "ghost.kind" => Expected::OneOf(variants::<crate::scene::GhostOf>()),
        "ghost.model" => Expected::OneOf(variants::<Model>()),
        _ => return None,
    })
}

// serde's derive hands ron the list of names whenever it meets one it does not
// know: asking for a name no type has reads the list off the type itself.
fn fields<T: DeserializeOwned>() -> &'static [&'static str] {
    match ron::from_str::<T>("(not_a_field_: 0)") {
        Err(SpannedError {
            code: ron::Error::NoSuchStructField { expected, .. },
            ..
        }) => expected,
        _ => &[],
    }
}

fn variants<T: DeserializeOwned>() -> &'static [&'static str] {
    match ron::from_str::<T>("NotAVariant_") {
        Err(SpannedError {
            code: ron::Error::NoSuchEnumVariant { expected, .. },
            ..
        }) => expected,
        _ => &[],
    }
}

/// `path: ` before a message about a field, nothing at the top level.
struct At<'a>(&'a str);

impl fmt::Display for At<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_empty() {
            Ok(())
        } else {
            write!(f, "{}: ", self.0)
        }
    }
}

/// " in the snapshot" after a message about the top level's fields.
fn in_snapshot(within: &str) -> &'static str {
    if within.is_empty() {
        " in the snapshot"
    } else {
        ""
    }
}

impl fmt::Display for Expected {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Expected::Number => f.write_str("a number such as 0.01 or 2e-8"),
            Expected::WholeNumber => f.write_str("a whole number"),
            Expected::Bool => f.write_str("true or false"),
            Expected::Text => f.write_str("text in double quotes"),
            Expected::Group(fields) => {
                write!(f, "a group `(…)` with the fields {}", fields.join(", "))
            }
            Expected::OneOf(names) => write!(f, "one of {}", names.join(", ")),
        }
    }
}

impl fmt::Display for ParseProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParseProblem::UnknownField {
                within,
                found,
                expected,
            } => write!(
                f,
                "{}unknown field `{found}`{}: expected one of {}",
                At(within),
                in_snapshot(within),
                expected.join(", ")
            ),
            ParseProblem::MissingField { within, field } => write!(
                f,
                "{}missing field `{field}`{}",
                At(within),
                in_snapshot(within)
            ),
            ParseProblem::DuplicateField { within, field } => write!(
                f,
                "{}field `{field}` appears twice{}",
                At(within),
                in_snapshot(within)
            ),
            ParseProblem::UnknownVariant {
                field,
                found,
                expected,
            } => {
                // "unknown axis `Eta`" for sweep.axis.
                let kind = field.rsplit('.').next().unwrap_or(field);
                write!(
                    f,
                    "{}unknown {kind} `{found}`: expected one of {}",
                    At(field),
                    expected.join(", ")
                )
            }
            ParseProblem::WrongType { field, expected } if field.is_empty() => {
                write!(f, "a snapshot is {expected}")
            }
            ParseProblem::WrongType { field, expected } => {
                write!(f, "{field}: wrong type, expected {expected}")
            }
            ParseProblem::Version(Some(v)) => write!(
                f,
                "unknown snapshot version {v}: this build reads version {VERSION}"
            ),
            ParseProblem::Version(None) => write!(
                f,
                "unknown snapshot version: this build reads version {VERSION}"
            ),
            ParseProblem::TooDeep => write!(f, "brackets nested more than {MAX_DEPTH} deep"),
            ParseProblem::Eof => f.write_str("the file ends in the middle of the snapshot"),
            ParseProblem::Trailing => {
                f.write_str("unexpected text after the snapshot's closing `)`")
            }
            ParseProblem::FieldName { within } => {
                write!(f, "{}expected a field name", At(within))
            }
            ParseProblem::Syntax { within, error } => {
                // ron's sentences start with a capital; ours continue after "line …:".
                let m = error.to_string();
                let mut c = m.chars();
                let first = c.next().map(|c| c.to_lowercase().collect::<String>());
                write!(
                    f,
                    "{}{}{}",
                    At(within),
                    first.unwrap_or_default(),
                    c.as_str()
                )
            }
        }
    }
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::TooLarge { bytes } => {
                write!(
                    f,
                    "the file is larger than the 1 MiB ({MAX_BYTES} bytes) limit for a snapshot"
                )?;
                match bytes {
                    Some(b) => write!(f, " ({b} bytes)"),
                    None => Ok(()),
                }
            }
            SnapshotError::NotUtf8 { line, column } => write!(
                f,
                "not UTF-8 text: invalid byte at line {line}, column {column}"
            ),
            SnapshotError::Empty => {
                f.write_str("the file is empty: a snapshot starts with `(version: 1, …`")
            }
            SnapshotError::Parse {
                line,
                column,
                problem,
            } => write!(f, "line {line}, column {column}: {problem}"),
            SnapshotError::Version(v) => ParseProblem::Version(Some(i64::from(*v))).fmt(f),
            SnapshotError::Invalid(e) => write!(f, "{e}"),
            SnapshotError::Surface(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SnapshotError {}

/// Line and column (1-based, in characters) just past the end of `text`.
pub(super) fn line_col(text: &str) -> (usize, usize) {
    let line = text.bytes().filter(|&b| b == b'\n').count() + 1;
    let line_start = text.rfind('\n').map_or(0, |i| i + 1);
    (line, text[line_start..].chars().count() + 1)
}

/// A path for messages: control characters escaped, "." for the empty path.
pub(super) fn shown(p: &Path) -> String {
    let s = p.display().to_string();
    if s.is_empty() {
        return ".".into();
    }
    s.chars()
        .flat_map(|c| {
            let esc: Vec<char> = if c.is_control() {
                c.escape_default().collect()
            } else {
                vec![c]
            };
            esc
        })
        .collect()
}

/// Why [`super::load_file`] failed: the file and the problem.
#[derive(Debug)]
pub struct LoadError {
    pub path: PathBuf,
    pub problem: LoadProblem,
}

#[derive(Debug)]
pub enum LoadProblem {
    /// The file could not be opened or read.
    Read(io::Error),
    /// The path names a directory.
    IsDir,
    /// The contents are not a valid snapshot.
    Snapshot(SnapshotError),
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let p = shown(&self.path);
        match &self.problem {
            LoadProblem::Read(e) => {
                let why = match e.kind() {
                    io::ErrorKind::NotFound => "no such file".to_string(),
                    io::ErrorKind::PermissionDenied => "permission denied".to_string(),
                    _ => e.to_string(),
                };
                write!(f, "cannot read snapshot {p}: {why}")
            }
            LoadProblem::IsDir => {
                write!(f, "cannot read snapshot {p}: it is a directory, not a file")
            }
            LoadProblem::Snapshot(e) => write!(f, "bad snapshot {p}: {e}"),
        }
    }
}

impl std::error::Error for LoadError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recursion_limit_reads_as_nesting() {
        // The schema refuses brackets before the limit; a deeper schema would not.
        assert_eq!(
            classify("params", ron::Error::ExceededRecursionLimit).to_string(),
            "brackets nested more than 16 deep"
        );
    }

    #[test]
    fn lists_come_from_the_types() {
        assert_eq!(fields::<SweepFile>(), ["axis", "from", "to"]);
        assert_eq!(variants::<Moments>(), ["Truncated", "Asymptotic"]);
        assert_eq!(variants::<Model>(), ["Exact", "ClosedForm"]);
    }

    #[test]
    fn unknown_fields_are_placed_in_their_group() {
        let e = |path| {
            let code = ron::Error::NoSuchStructField {
                expected: &["a"],
                found: "e".into(),
                outer: None,
            };
            classify(path, code).to_string()
        };
        assert_eq!(
            e("e"),
            "unknown field `e` in the snapshot: expected one of a"
        );
        assert_eq!(
            e("params.e"),
            "params: unknown field `e`: expected one of a"
        );
    }
}
