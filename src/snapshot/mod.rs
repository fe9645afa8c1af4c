//! Snapshots: a parameter set and a view, saved as RON (schema version 1).
//!
//! ```text
//! (
//!     version: 1,
//!     name: "fig2",
//!     params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, hurst: 0.8, r_star: 0.001, q0: 100000.0),
//!     size_effect: false,
//!     sweep: (axis: Zeta, from: 1.0, to: 10000.0),
//!     model: Exact,
//! )
//! ```
//!
//! The schema is fixed: later fields may only be added as optional with
//! defaults. The swept parameter's value in `params` is where the marker stands.

//!
//! # Reading
//!
//! [`load_file`] refuses, with one message that names the file and the
//! problem: a missing, unreadable or non-regular file; more than
//! [`MAX_BYTES`] (checked before parsing); text that is not UTF-8; brackets
//! nested deeper than [`MAX_DEPTH`] (checked before parsing); RON syntax
//! errors, unknown, missing or duplicated fields and values of the wrong type
//! (with line and column, and the field's name); an unknown version, axis or
//! model; NaN, infinities and out-of-range values (the model's own validation
//! names the field and its valid range); an empty or out-of-domain sweep; a
//! `name` longer than [`MAX_NAME_CHARS`] characters or holding control
//! characters (the TUI prints the name, so escape sequences are refused).
//!
//! Accepted leniently: comments, a leading UTF-8 byte-order mark, integers
//! where a float is expected (`zeta: 128`), and fields in any order.
//!
//! # Writing
//!
//! [`save_new`] never replaces a file: it writes a temporary file in the
//! target folder, then hard-links it under the first free name
//! (`stem.ron`, `stem-2.ron`, …; a link fails rather than replace a file that
//! appeared meanwhile) and removes the temporary file, also on failure.

use std::fmt;
use std::fs::{File, OpenOptions};
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{SystemTime, UNIX_EPOCH};

use rough_model::{Axis, Model, ParamValues, Params, Sweep};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize};

/// The only schema version this build reads and writes.
pub const VERSION: u32 = 1;
/// Larger files are refused before they are parsed (1 MiB).
pub const MAX_BYTES: u64 = 1 << 20;
/// Brackets nested deeper than this are refused before parsing (a valid
/// snapshot nests 2 deep).
pub const MAX_DEPTH: usize = 16;
/// Longest accepted `name`, in characters.
pub const MAX_NAME_CHARS: usize = 64;
/// Longest accepted file stem for [`save_new`], in bytes.
pub const MAX_STEM_BYTES: usize = 200;

const TOP_FIELDS: &str = "version, name, params, size_effect, sweep, model";
const PARAM_FIELDS: &str = "h0_over_e, h_rms, zeta, hurst, r_star, q0";
const SWEEP_FIELDS: &str = "axis, from, to";
const AXES: &str = "H0OverE, HRms, Zeta, Hurst, RStar";
const MODELS: &str = "Exact, ClosedForm";

/// The file form, field for field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SnapshotFile {
    #[serde(deserialize_with = "de_version")]
    pub version: u32,
    #[serde(deserialize_with = "de_name")]
    pub name: String,
    #[serde(deserialize_with = "de_params")]
    pub params: ParamsFile,
    #[serde(deserialize_with = "de_size_effect")]
    pub size_effect: bool,
    #[serde(deserialize_with = "de_sweep")]
    pub sweep: SweepFile,
    #[serde(deserialize_with = "de_model")]
    pub model: Model,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParamsFile {
    #[serde(deserialize_with = "de_h0_over_e")]
    pub h0_over_e: f64,
    #[serde(deserialize_with = "de_h_rms")]
    pub h_rms: f64,
    #[serde(deserialize_with = "de_zeta")]
    pub zeta: f64,
    #[serde(deserialize_with = "de_hurst")]
    pub hurst: f64,
    #[serde(deserialize_with = "de_r_star")]
    pub r_star: f64,
    #[serde(deserialize_with = "de_q0")]
    pub q0: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    #[serde(deserialize_with = "de_axis")]
    pub axis: Axis,
    #[serde(deserialize_with = "de_from")]
    pub from: f64,
    #[serde(deserialize_with = "de_to")]
    pub to: f64,
}

// Each field deserializes through a wrapper that names it in any error, so a
// type error reads "params.zeta: wrong type, …" rather than "Expected float".
macro_rules! labelled_field {
    ($($fn:ident: $ty:ty = $path:literal;)*) => {$(
        fn $fn<'de, D: Deserializer<'de>>(d: D) -> Result<$ty, D::Error> {
            <$ty>::deserialize(d).map_err(|e| D::Error::custom(label($path, &e.to_string())))
        }
    )*};
}

labelled_field! {
    de_name: String = "name";
    de_params: ParamsFile = "params";
    de_size_effect: bool = "size_effect";
    de_sweep: SweepFile = "sweep";
    de_model: Model = "model";
    de_h0_over_e: f64 = "params.h0_over_e";
    de_h_rms: f64 = "params.h_rms";
    de_zeta: f64 = "params.zeta";
    de_hurst: f64 = "params.hurst";
    de_r_star: f64 = "params.r_star";
    de_q0: f64 = "params.q0";
    de_axis: Axis = "sweep.axis";
    de_from: f64 = "sweep.from";
    de_to: f64 = "sweep.to";
}

/// Reads any integer, so that `version: 2` or `version: -1` is reported as an
/// unknown version rather than a type or range error.
fn de_version<'de, D: Deserializer<'de>>(d: D) -> Result<u32, D::Error> {
    match i64::deserialize(d) {
        Ok(v) if v == i64::from(VERSION) => Ok(VERSION),
        Ok(v) => Err(D::Error::custom(format!(
            "unknown snapshot version {v}: this build reads version {VERSION}"
        ))),
        Err(e) if e.to_string().contains("out of bounds") => Err(D::Error::custom(format!(
            "unknown snapshot version: this build reads version {VERSION}"
        ))),
        Err(e) => Err(D::Error::custom(label("version", &e.to_string()))),
    }
}

/// `path: problem`, with ron's wording made specific to the schema. Errors
/// already labelled by an inner field pass through unchanged.
fn label(path: &str, msg: &str) -> String {
    if msg.starts_with(&format!("{path}.")) {
        return msg.to_string();
    }
    if path.is_empty() {
        reword(path, msg)
    } else {
        format!("{path}: {}", reword(path, msg))
    }
}

/// The text between the first pair of backticks after `marker` in `msg`.
fn quoted_after<'a>(msg: &'a str, marker: &str) -> Option<&'a str> {
    let rest = &msg[msg.find(marker)? + marker.len()..];
    let start = rest.find('`')? + 1;
    let len = rest[start..].find('`')?;
    Some(&rest[start..start + len])
}

/// Schema-specific wording for a ron error message about the field `path`
/// ("" for the snapshot as a whole).
fn reword(path: &str, msg: &str) -> String {
    let fields = match path {
        "params" => PARAM_FIELDS,
        "sweep" => SWEEP_FIELDS,
        _ => TOP_FIELDS,
    };
    // A field's errors are already prefixed with its path.
    let group = |p: &str| -> &'static str {
        if p.is_empty() {
            " in the snapshot"
        } else {
            ""
        }
    };
    if let Some(found) = quoted_after(msg, "Unexpected variant named") {
        let (kind, list) = if path.ends_with("axis") {
            ("axis", AXES)
        } else {
            ("model", MODELS)
        };
        return format!("unknown {kind} `{found}`: expected one of {list}");
    }
    if path == "model" {
        return format!("wrong type, expected one of {MODELS}");
    }
    if path == "sweep.axis" {
        return format!("wrong type, expected one of {AXES}");
    }
    if let Some(found) = quoted_after(msg, "Unexpected field named") {
        return format!(
            "unknown field `{found}`{}: expected one of {fields}",
            group(path)
        );
    }
    if let Some(field) = quoted_after(msg, "Unexpected missing field named") {
        return format!("missing field `{field}`{}", group(path));
    }
    if let Some(field) = quoted_after(msg, "Unexpected duplicate field named") {
        return format!("field `{field}` appears twice{}", group(path));
    }
    match msg {
        "Expected float" => "wrong type, expected a number such as 0.01 or 2e-8".into(),
        "Expected integer" => "wrong type, expected a whole number".into(),
        "Expected boolean" => "wrong type, expected true or false".into(),
        "Expected string" => "wrong type, expected text in double quotes".into(),
        "Unexpected end of RON" => "the file ends in the middle of the snapshot".into(),
        "Non-whitespace trailing characters" => {
            "unexpected text after the snapshot's closing `)`".into()
        }
        "Exceeded recursion limit, try increasing `ron::Options::recursion_limit` \
         and using `serde_stacker` to protect against a stack overflow"
        | "Exceeded recursion limit" => "nested too deeply".into(),
        _ if msg.starts_with("Expected opening `(`")
            || msg.starts_with("Expected struct")
            || msg.contains("for struct") =>
        {
            format!("wrong type, expected a group `(…)` with the fields {fields}")
        }
        _ => {
            let m = msg
                .replace("`SnapshotFile`", "the snapshot")
                .replace("`ParamsFile`", "params")
                .replace("`SweepFile`", "sweep");
            let mut c = m.chars();
            match c.next() {
                Some(first) => first.to_lowercase().chain(c).collect(),
                None => m,
            }
        }
    }
}

/// A validated snapshot: what the TUI and the export work from.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    pub name: String,
    pub params: Params,
    pub size_effect: bool,
    pub sweep: Sweep,
    pub model: Model,
}

/// Why a snapshot text was rejected (without the file name; [`LoadError`]
/// adds it).
#[derive(Debug, Clone, PartialEq)]
pub enum SnapshotError {
    /// More than [`MAX_BYTES`]; `bytes` is the size when known.
    TooLarge { bytes: Option<u64> },
    /// The first invalid byte is at this line and column.
    NotUtf8 { line: usize, column: usize },
    /// Brackets nested deeper than [`MAX_DEPTH`] at this line and column.
    TooDeep { line: usize, column: usize },
    /// A RON syntax, field, type, version or variant error.
    Parse {
        line: usize,
        column: usize,
        message: String,
    },
    /// A version other than [`VERSION`] (from [`State::from_file`]).
    Version(u32),
    /// A value out of its domain, an empty sweep, or a bad name.
    Invalid(String),
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
            SnapshotError::TooDeep { line, column } => write!(
                f,
                "line {line}, column {column}: brackets nested more than {MAX_DEPTH} deep"
            ),
            SnapshotError::Parse {
                line,
                column,
                message,
            } => write!(f, "line {line}, column {column}: {message}"),
            SnapshotError::Version(v) => write!(
                f,
                "unknown snapshot version {v}: this build reads version {VERSION}"
            ),
            SnapshotError::Invalid(m) => write!(f, "{m}"),
        }
    }
}

impl std::error::Error for SnapshotError {}

/// Line and column (1-based, in characters) of byte offset `at` in `text`.
fn line_col(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at];
    let line = before.bytes().filter(|&b| b == b'\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
}

/// Byte offset of the first bracket nested deeper than [`MAX_DEPTH`], if any.
/// Skips strings, raw strings, character literals and comments. A cheap guard
/// run before the parser; it may over-count only in text that is not a valid
/// snapshot anyway.
fn too_deep_at(text: &str) -> Option<usize> {
    let b = text.as_bytes();
    let n = b.len();
    let mut depth = 0usize;
    let mut i = 0;
    while i < n {
        match b[i] {
            b'(' | b'[' | b'{' => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return Some(i);
                }
            }
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            b'"' => {
                i += 1;
                while i < n && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
            }
            b'\'' => {
                // 'x' or '\x…': skip to the closing quote if it is close by.
                if let Some(k) = b[i + 1..n.min(i + 12)]
                    .iter()
                    .skip(1)
                    .position(|&c| c == b'\'')
                {
                    i += k + 2;
                }
            }
            b'r' if (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
                && matches!(b.get(i + 1), Some(b'"' | b'#')) =>
            {
                let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                if b.get(i + 1 + hashes) == Some(&b'"') {
                    let mut close = vec![b'#'; hashes + 1];
                    close[0] = b'"';
                    let body = i + 2 + hashes;
                    i = b[body..]
                        .windows(close.len())
                        .position(|w| w == close.as_slice())
                        .map_or(n, |k| body + k + close.len() - 1);
                }
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < n && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let mut level = 1;
                i += 2;
                while i < n && level > 0 {
                    if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                        level += 1;
                        i += 2;
                    } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                        level -= 1;
                        i += 2;
                    } else {
                        i += 1;
                    }
                }
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// Whether `name` is acceptable as a snapshot's display name.
pub fn check_name(name: &str) -> Result<(), String> {
    let chars = name.chars().count();
    if chars > MAX_NAME_CHARS {
        return Err(format!(
            "name is {chars} characters long: it must be at most {MAX_NAME_CHARS}"
        ));
    }
    if let Some(c) = name.chars().find(|c| c.is_control()) {
        return Err(format!(
            "name contains the control character U+{:04X}: it must be printable text",
            u32::from(c)
        ));
    }
    Ok(())
}

impl State {
    /// Checks the size, encoding and nesting of raw file contents, then parses
    /// and validates them. A leading UTF-8 byte-order mark is skipped.
    pub fn from_bytes(bytes: &[u8]) -> Result<State, SnapshotError> {
        if bytes.len() as u64 > MAX_BYTES {
            return Err(SnapshotError::TooLarge {
                bytes: Some(bytes.len() as u64),
            });
        }
        let text = match std::str::from_utf8(bytes) {
            Ok(t) => t,
            Err(e) => {
                // The valid prefix is UTF-8 by definition.
                let valid = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or("");
                let (line, column) = line_col(valid, valid.len());
                return Err(SnapshotError::NotUtf8 { line, column });
            }
        };
        State::from_ron(text)
    }

    /// Parses and validates a snapshot text.
    pub fn from_ron(text: &str) -> Result<State, SnapshotError> {
        if text.len() as u64 > MAX_BYTES {
            return Err(SnapshotError::TooLarge {
                bytes: Some(text.len() as u64),
            });
        }
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        if text.trim().is_empty() {
            return Err(SnapshotError::Invalid(
                "the file is empty: a snapshot starts with `(version: 1, …`".into(),
            ));
        }
        if let Some(at) = too_deep_at(text) {
            let (line, column) = line_col(text, at);
            return Err(SnapshotError::TooDeep { line, column });
        }
        let file: SnapshotFile = ron::Options::default()
            .with_recursion_limit(MAX_DEPTH)
            .from_str(text)
            .map_err(|e| SnapshotError::Parse {
                line: e.span.start.line,
                column: e.span.start.col,
                message: label("", &e.code.to_string()),
            })?;
        State::from_file(file)
    }

    /// Validates a parsed file: version, name, parameters and sweep.
    pub fn from_file(f: SnapshotFile) -> Result<State, SnapshotError> {
        if f.version != VERSION {
            return Err(SnapshotError::Version(f.version));
        }
        check_name(&f.name).map_err(SnapshotError::Invalid)?;
        let p = f.params;
        let params = Params::new(ParamValues {
            h0_over_e: p.h0_over_e,
            h_rms: p.h_rms,
            zeta: p.zeta,
            hurst: p.hurst,
            r_star: p.r_star,
            q0: p.q0,
        })
        .map_err(|e| SnapshotError::Invalid(format!("params: {e}")))?;
        let sweep = Sweep::new(f.sweep.axis, f.sweep.from, f.sweep.to)
            .map_err(|e| SnapshotError::Invalid(e.to_string()))?;
        Ok(State {
            name: f.name,
            params,
            size_effect: f.size_effect,
            sweep,
            model: f.model,
        })
    }

    pub fn to_file(&self) -> SnapshotFile {
        let v = self.params.values();
        SnapshotFile {
            version: VERSION,
            name: self.name.clone(),
            params: ParamsFile {
                h0_over_e: v.h0_over_e,
                h_rms: v.h_rms,
                zeta: v.zeta,
                hurst: v.hurst,
                r_star: v.r_star,
                q0: v.q0,
            },
            size_effect: self.size_effect,
            sweep: SweepFile {
                axis: self.sweep.axis(),
                from: self.sweep.from(),
                to: self.sweep.to(),
            },
            model: self.model,
        }
    }

    /// The snapshot as RON text (floats round-trip exactly).
    pub fn to_ron(&self) -> String {
        let cfg = ron::ser::PrettyConfig::new().depth_limit(1);
        let mut s = ron::ser::to_string_pretty(&self.to_file(), cfg)
            .expect("a snapshot of plain numbers always serializes");
        s.push('\n');
        s
    }
}

/// A path for messages: control characters escaped, "." for the empty path.
fn shown(p: &Path) -> String {
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

/// Why [`load_file`] failed: the file and the problem.
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

/// Reads and validates the snapshot at `path`; the error names the file.
/// Files over [`MAX_BYTES`] are refused before they are read in full.
pub fn read_file(path: &Path) -> Result<State, LoadError> {
    let fail = |problem| LoadError {
        path: path.to_path_buf(),
        problem,
    };
    let meta = std::fs::metadata(path).map_err(|e| fail(LoadProblem::Read(e)))?;
    if meta.is_dir() {
        return Err(fail(LoadProblem::IsDir));
    }
    if meta.is_file() && meta.len() > MAX_BYTES {
        return Err(fail(LoadProblem::Snapshot(SnapshotError::TooLarge {
            bytes: Some(meta.len()),
        })));
    }
    let file = File::open(path).map_err(|e| fail(LoadProblem::Read(e)))?;
    let mut bytes = Vec::new();
    // Devices and pipes have no size up front: read one byte past the limit.
    file.take(MAX_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(LoadProblem::Read(e)))?;
    if bytes.len() as u64 > MAX_BYTES {
        return Err(fail(LoadProblem::Snapshot(SnapshotError::TooLarge {
            bytes: None,
        })));
    }
    State::from_bytes(&bytes).map_err(|e| fail(LoadProblem::Snapshot(e)))
}

/// Reads and validates the snapshot at `path`; errors name the file (a
/// [`LoadError`] inside).
pub fn load_file(path: &Path) -> anyhow::Result<State> {
    Ok(read_file(path)?)
}

/// `{name}-{YYYYMMDD-HHMMSS}` (UTC) for a save at `time`. Characters of
/// `name` other than letters, digits, `-`, `_` and `.` become `_`, a leading
/// `.` is dropped, and an empty name becomes `snapshot`.
pub fn default_stem(name: &str, time: SystemTime) -> String {
    let mut base: String = name
        .chars()
        .take(MAX_NAME_CHARS)
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect::<String>()
        .trim_start_matches('.')
        .to_string();
    if base.is_empty() {
        base = "snapshot".into();
    }
    let secs = time.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rem) = (secs / 86_400, secs % 86_400);
    // Civil date from days since 1970-01-01 (Howard Hinnant's algorithm).
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{base}-{y:04}{m:02}{d:02}-{:02}{:02}{:02}",
        rem / 3600,
        rem / 60 % 60,
        rem % 60
    )
}

/// The stem a user typed, checked: surrounding blanks and a trailing `.ron`
/// are dropped; empty names, paths, control characters, a leading `.` and
/// over-long names are refused.
pub fn check_stem(stem: &str) -> Result<&str, String> {
    let s = stem.trim();
    let s = s.strip_suffix(".ron").unwrap_or(s);
    let why = if s.is_empty() {
        "it is empty".to_string()
    } else if s.contains('/') || s.contains('\\') {
        "it must be a file name, not a path (no '/' or '\\')".to_string()
    } else if s.chars().any(char::is_control) {
        "it contains a control character".to_string()
    } else if s.starts_with('.') {
        "it must not start with '.'".to_string()
    } else if s.len() > MAX_STEM_BYTES {
        format!("it is {} bytes long: at most {MAX_STEM_BYTES}", s.len())
    } else {
        return Ok(s);
    };
    Err(format!("bad file name {:?}: {why}", stem))
}

static SAVE_SEQ: AtomicU64 = AtomicU64::new(0);

/// Writes `state` to `dir/{stem}.ron`, never overwriting: if that name is
/// taken, `{stem}-2.ron`, `{stem}-3.ron`, …. The text goes to a temporary
/// file in `dir` first and is linked into place without replacing anything;
/// the temporary file is removed whatever happens. `stem` is checked by
/// [`check_stem`], and the state's name by [`check_name`] (so that whatever
/// is saved loads back). Returns the path written.
pub fn save_new(dir: &Path, stem: &str, state: &State) -> anyhow::Result<PathBuf> {
    // What could not be loaded back is not written.
    check_name(&state.name).map_err(|e| anyhow::anyhow!("cannot save snapshot: {e}"))?;
    save_with(dir, stem, state.to_ron().as_bytes(), |f, b| f.write_all(b))
}

/// [`save_new`] with the write step given, so that tests can make it fail.
fn save_with(
    dir: &Path,
    stem: &str,
    bytes: &[u8],
    write: impl Fn(&mut File, &[u8]) -> io::Result<()>,
) -> anyhow::Result<PathBuf> {
    let stem = check_stem(stem).map_err(|e| anyhow::anyhow!("cannot save snapshot: {e}"))?;
    let d = shown(dir);
    let in_dir = |e: io::Error| anyhow::anyhow!("cannot save snapshot in {d}: {e}");

    // 1. A fresh temporary file of our own.
    let (tmp, mut file) = {
        let mut tries = 0;
        loop {
            let seq = SAVE_SEQ.fetch_add(1, Ordering::Relaxed);
            let tmp = dir.join(format!(".roughtui-{}-{seq}.tmp", std::process::id()));
            match OpenOptions::new().write(true).create_new(true).open(&tmp) {
                Ok(f) => break (tmp, f),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 100 => tries += 1,
                Err(e) => return Err(in_dir(e)),
            }
        }
    };
    if let Err(e) = write(&mut file, bytes).and_then(|()| file.sync_all()) {
        drop(file);
        let _ = std::fs::remove_file(&tmp);
        return Err(in_dir(e));
    }
    drop(file);

    // 2. Linked under the first free name: a link never replaces a file, also
    //    one that appeared since we looked.
    let result = (|| {
        for n in 1..10_000u32 {
            let target = dir.join(if n == 1 {
                format!("{stem}.ron")
            } else {
                format!("{stem}-{n}.ron")
            });
            match std::fs::hard_link(&tmp, &target) {
                Ok(()) => return Ok(target),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::Unsupported | io::ErrorKind::PermissionDenied
                    ) =>
                {
                    // No hard links here (e.g. FAT): create the target
                    // exclusively and write it directly.
                    match write_exclusive(&target, bytes, &write) {
                        Ok(true) => return Ok(target),
                        Ok(false) => continue,
                        Err(e) => return Err(in_dir(e)),
                    }
                }
                Err(e) => return Err(in_dir(e)),
            }
        }
        anyhow::bail!("cannot save snapshot in {d}: too many snapshots named {stem}")
    })();
    let _ = std::fs::remove_file(&tmp);
    if result.is_ok() {
        // Make the new directory entry durable; not all systems allow it.
        let _ = File::open(dir).and_then(|f| f.sync_all());
    }
    result
}

/// Creates `target` (only if absent) and writes `bytes`; `Ok(false)` if it
/// exists. A partly written target is removed.
fn write_exclusive(
    target: &Path,
    bytes: &[u8],
    write: &impl Fn(&mut File, &[u8]) -> io::Result<()>,
) -> io::Result<bool> {
    let mut f = match OpenOptions::new().write(true).create_new(true).open(target) {
        Ok(f) => f,
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => return Ok(false),
        Err(e) => return Err(e),
    };
    if let Err(e) = write(&mut f, bytes).and_then(|()| f.sync_all()) {
        drop(f);
        let _ = std::fs::remove_file(target);
        return Err(e);
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let s = crate::presets::load("fig4").unwrap();
        let back = State::from_ron(&s.to_ron()).unwrap();
        assert_eq!(back, s);
    }

    fn files_in(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn failed_write_leaves_no_file_behind() {
        let dir = tempfile::tempdir().unwrap();
        let err = save_with(dir.path(), "full", b"(version: 1)", |f, b| {
            f.write_all(&b[..4])?;
            Err(io::Error::from_raw_os_error(28)) // ENOSPC
        })
        .unwrap_err()
        .to_string();
        assert!(err.contains("cannot save snapshot in"), "{err}");
        assert!(err.contains(&dir.path().display().to_string()), "{err}");
        assert!(err.contains("No space left on device"), "{err}");
        assert_eq!(files_in(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn a_file_created_during_the_save_is_not_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let theirs = dir.path().join("race.ron");
        let path = save_with(dir.path(), "race", b"ours\n", |f, b| {
            // Someone else takes the name after any check we could have made.
            std::fs::write(&theirs, "theirs\n")?;
            f.write_all(b)
        })
        .unwrap();
        assert_eq!(path, dir.path().join("race-2.ron"));
        assert_eq!(std::fs::read_to_string(&theirs).unwrap(), "theirs\n");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "ours\n");
        assert_eq!(files_in(dir.path()), ["race-2.ron", "race.ron"]);
    }

    #[test]
    fn exclusive_fallback_writes_once_and_cleans_up_on_failure() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("x.ron");
        let ok = |f: &mut File, b: &[u8]| f.write_all(b);
        assert!(write_exclusive(&target, b"one", &ok).unwrap());
        assert!(!write_exclusive(&target, b"two", &ok).unwrap());
        assert_eq!(std::fs::read(&target).unwrap(), b"one");
        let fail = |_: &mut File, _: &[u8]| Err(io::Error::from_raw_os_error(28));
        let other = dir.path().join("y.ron");
        assert!(write_exclusive(&other, b"three", &fail).is_err());
        assert!(!other.exists());
    }

    #[test]
    fn nesting_guard_skips_strings_and_comments() {
        let deep = "(".repeat(MAX_DEPTH + 1);
        assert_eq!(too_deep_at(&deep), Some(MAX_DEPTH));
        for hidden in [
            format!("\"{deep}\""),
            format!("r#\"{deep}\"#"),
            format!("// {deep}\n"),
            format!("/* /* {deep} */ */"),
            format!("'(' {}", "()".repeat(100)),
        ] {
            assert_eq!(too_deep_at(&hidden), None, "{hidden}");
        }
        assert_eq!(
            too_deep_at(&format!("\"\\\"\" {deep}")),
            Some(5 + MAX_DEPTH)
        );
    }

    #[test]
    fn stems_carry_utc_date_and_time() {
        let t = UNIX_EPOCH + std::time::Duration::from_secs(1_795_275_012);
        assert_eq!(default_stem("fig2", t), "fig2-20261121-153012");
    }
}
