//! Snapshots: a scene ([`crate::scene::State`]) and its view, saved as RON
//! (schema version 1).
//!
//! ```text
//! (
//!     version: 1,
//!     name: "fig2",
//!     caption: "Figure 2: …",           // optional
//!     params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, hurst: 0.8, r_star: 0.001, q0: 100000.0),
//!     size_effect: false,
//!     sweep: (axis: Zeta, from: 1.0, to: 10000.0),
//!     model: Exact,
//!     moments: Asymptotic,              // optional, Truncated when absent
//!     surface: (path: "../data/steel.txt", sha256: "9f86…", periodic: true, pixel_size: 5e-8),
//!                                       // optional: a measured surface
//!     view: Map,                        // optional: the view (Slopes when absent),
//!     map_y: HRms,                      //   the map's y axis and the ghost
//!     ghost: (kind: Curves, params: (…), size_effect: false, model: Exact),
//! )
//! ```
//!
//! A measured surface is recorded by its path relative to the snapshot's
//! folder (absolute where there is no relative way), its SHA-256, and how
//! it was read (`periodic` and `pixel_size` optional, false and none when
//! absent). For such a snapshot `h_rms`, `hurst` and `q0` in `params` are
//! the data's (√m0 over the whole band, a fit's H, the data's q0), written
//! for reference and recomputed from the file on loading. A surface file
//! that is missing or refused makes the snapshot refused, naming both; one
//! whose SHA-256 differs is loaded as it is now and the difference reported
//! ([`State::surface_warning`]).
//!
//! The schema is fixed: later fields may only be added as optional with
//! defaults. The swept parameter's value in `params` is where the marker stands.
//!
//! # Reading
//!
//! [`load_file`] refuses, with one message that names the file and the
//! problem (`error.rs` builds it from ron's typed errors and the field path):
//! a missing, unreadable or non-regular file; more than [`MAX_BYTES`]
//! (checked before parsing); text that is not UTF-8; RON syntax errors,
//! unknown, missing or duplicated fields and values of the wrong type (with
//! line and column, and the field's path); an unknown version, axis, model or
//! moments; brackets nested deeper than [`MAX_DEPTH`] (ron's recursion
//! limit); NaN, infinities and out-of-range values (the model's own
//! validation names the field and its valid range); H = 1 with asymptotic
//! moments; an empty or out-of-domain sweep; a `name` longer than
//! [`MAX_NAME_CHARS`] or a `caption` longer than [`MAX_CAPTION_CHARS`]
//! characters, or either holding control characters (the TUI prints both, so
//! escape sequences are refused).
//!
//! Accepted leniently: comments, a leading UTF-8 byte-order mark, integers
//! where a float is expected (`zeta: 128`), and fields in any order.
//!
//! # Writing
//!
//! [`save_new`] never replaces a file (see `save.rs`). Optional fields at their
//! defaults are not written, so a snapshot without a caption and with
//! truncated moments is byte for byte what earlier builds wrote.

mod error;
mod save;
mod shown;
mod surface;

use std::fs::File;
use std::io::Read;
use std::path::Path;

use rough_model::{Axis, Model, Moments, ParamValues, Params, Sweep};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

pub use error::{Expected, LoadError, LoadProblem, ParseProblem, SnapshotError};
pub use save::{check_stem, default_stem, save_file_new, save_new, scene_name, MAX_STEM_BYTES};
pub use shown::GhostFile;
pub use surface::{SurfaceFile, SurfaceProblem};

use crate::scene::{GhostScene, Invalid, Shown, State};

/// The only schema version this build reads and writes.
pub const VERSION: u32 = 1;
/// Larger files are refused before they are parsed (1 MiB).
pub const MAX_BYTES: u64 = 1 << 20;
/// ron's recursion limit while parsing (a valid snapshot nests 2 deep).
pub const MAX_DEPTH: usize = 16;

/// The file form, field for field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SnapshotFile {
    #[serde(deserialize_with = "de_version")]
    pub version: u32,
    pub name: String,
    /// Written and read as plain text (`caption: "…"`), not `Some("…")`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_caption",
        deserialize_with = "de_caption"
    )]
    pub caption: Option<String>,
    pub params: ParamValues,
    pub size_effect: bool,
    pub sweep: SweepFile,
    pub model: Model,
    #[serde(default, skip_serializing_if = "is_truncated")]
    pub moments: Moments,
    /// Written and read as a plain group (`surface: (path: …)`), not `Some(…)`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "surface::ser",
        deserialize_with = "surface::de"
    )]
    pub surface: Option<SurfaceFile>,
    /// The seed of the contact simulation's surface (1 when absent),
    /// written and read as a plain number (`seed: 2`).
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_seed",
        deserialize_with = "de_seed"
    )]
    pub seed: Option<u64>,
    /// The view the snapshot was saved on (`shown.rs`).
    #[serde(default, skip_serializing_if = "shown::is_slopes")]
    pub view: crate::scene::View,
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "shown::ser_axis",
        deserialize_with = "shown::de_axis"
    )]
    pub map_y: Option<Axis>,
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "shown::ser_ghost",
        deserialize_with = "shown::de_ghost"
    )]
    pub ghost: Option<GhostFile>,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    pub axis: Axis,
    pub from: f64,
    pub to: f64,
}

/// Reads any integer, so that `version: 2` or `version: -1` is reported as an
/// unknown version rather than a type or range error. The refusal carries
/// only the number; `error.rs` words it.
fn de_version<'de, D: Deserializer<'de>>(d: D) -> Result<u32, D::Error> {
    match i64::deserialize(d)? {
        v if v == i64::from(VERSION) => Ok(VERSION),
        v => Err(D::Error::custom(v)),
    }
}

fn de_caption<'de, D: Deserializer<'de>>(d: D) -> Result<Option<String>, D::Error> {
    String::deserialize(d).map(Some)
}

fn ser_caption<S: Serializer>(c: &Option<String>, s: S) -> Result<S::Ok, S::Error> {
    c.as_deref().unwrap_or_default().serialize(s)
}

fn de_seed<'de, D: Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
    u64::deserialize(d).map(Some)
}

fn ser_seed<S: Serializer>(v: &Option<u64>, s: S) -> Result<S::Ok, S::Error> {
    v.unwrap_or(1).serialize(s)
}

fn is_truncated(m: &Moments) -> bool {
    *m == Moments::Truncated
}

impl State {
    /// Checks the size and encoding of raw file contents, then parses and
    /// validates them. A leading UTF-8 byte-order mark is skipped. A
    /// surface's relative path is taken from the current folder.
    pub fn from_bytes(bytes: &[u8]) -> Result<State, SnapshotError> {
        State::from_bytes_in(bytes, None)
    }

    /// [`State::from_bytes`] for a snapshot in the folder `base`, which a
    /// surface's relative path starts from (the current folder if `None`).
    pub fn from_bytes_in(bytes: &[u8], base: Option<&Path>) -> Result<State, SnapshotError> {
        check_size(bytes.len())?;
        let text = std::str::from_utf8(bytes).map_err(|e| {
            // The valid prefix is UTF-8 by definition.
            let valid = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or("");
            let (line, column) = error::line_col(valid);
            SnapshotError::NotUtf8 { line, column }
        })?;
        parse(text, base)
    }

    /// Parses and validates a snapshot text (a surface's relative path
    /// taken from the current folder).
    pub fn from_ron(text: &str) -> Result<State, SnapshotError> {
        check_size(text.len())?;
        parse(text, None)
    }

    /// Validates a parsed file: version, text fields, parameters, moments
    /// and sweep; reads its surface, if any, from the current folder.
    pub fn from_file(f: SnapshotFile) -> Result<State, SnapshotError> {
        State::from_file_in(f, None)
    }

    /// [`State::from_file`] with a surface's relative path taken from `base`.
    pub fn from_file_in(f: SnapshotFile, base: Option<&Path>) -> Result<State, SnapshotError> {
        if f.version != VERSION {
            return Err(SnapshotError::Version(f.version));
        }
        let params = Params::new(f.params).map_err(Invalid::Params)?;
        let sweep = Sweep::new(f.sweep.axis, f.sweep.from, f.sweep.to).map_err(Invalid::Sweep)?;
        let surface = match &f.surface {
            Some(sf) => Some(surface::read(sf, base).map_err(SnapshotError::Surface)?),
            None => None,
        };
        let params = match &surface {
            // What the data fixes comes from the data.
            Some(src) => Params::new(crate::surface::fixed_values(src, params.values()))
                .map_err(Invalid::Params)?,
            None => params,
        };
        let measured = surface.is_some();
        let ghost = f
            .ghost
            .as_ref()
            .map(|g| GhostScene::of(g, measured))
            .transpose()
            .map_err(Invalid::Shown)?;
        let state = State {
            name: f.name,
            caption: f.caption,
            params,
            size_effect: f.size_effect,
            sweep,
            model: f.model,
            moments: f.moments,
            surface,
            seed: f.seed,
            shown: Shown {
                view: f.view,
                map_y: f.map_y,
                ghost,
            },
        };
        state.check()?;
        Ok(state)
    }

    /// The file form, a surface's path relative to the current folder.
    pub fn to_file(&self) -> SnapshotFile {
        self.to_file_in(None)
    }

    /// The file form for a snapshot in the folder `base`: a surface's path
    /// is written relative to it (to the current folder if `None`).
    pub fn to_file_in(&self, base: Option<&Path>) -> SnapshotFile {
        SnapshotFile {
            version: VERSION,
            name: self.name.clone(),
            caption: self.caption.clone(),
            params: self.params.values(),
            size_effect: self.size_effect,
            sweep: SweepFile {
                axis: self.sweep.axis(),
                from: self.sweep.from(),
                to: self.sweep.to(),
            },
            model: self.model,
            moments: self.moments,
            surface: self.surface.as_ref().map(|s| surface::file_of(s, base)),
            seed: self.seed,
            view: self.shown.view,
            map_y: self.shown.map_y,
            ghost: self.shown.ghost.map(GhostScene::to_file),
        }
    }

    /// The snapshot as RON text (floats round-trip exactly), a surface's
    /// path relative to the current folder.
    pub fn to_ron(&self) -> String {
        self.to_ron_in(None)
    }

    /// [`State::to_ron`] for a snapshot in the folder `base`.
    pub fn to_ron_in(&self, base: Option<&Path>) -> String {
        let cfg = ron::ser::PrettyConfig::new().depth_limit(1);
        let mut s = ron::ser::to_string_pretty(&self.to_file_in(base), cfg)
            .expect("a snapshot of plain numbers and text always serializes");
        s.push('\n');
        s
    }
}

/// The one size check, before anything else looks at the text.
fn check_size(len: usize) -> Result<(), SnapshotError> {
    if len as u64 > MAX_BYTES {
        return Err(SnapshotError::TooLarge {
            bytes: Some(len as u64),
        });
    }
    Ok(())
}

/// Parses text already within [`MAX_BYTES`]: ron with its recursion limit
/// at [`MAX_DEPTH`], wrapped so that an error knows its field path.
fn parse(text: &str, base: Option<&Path>) -> Result<State, SnapshotError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(SnapshotError::Empty);
    }
    let opts = ron::Options::default().with_recursion_limit(MAX_DEPTH);
    let mut de = ron::Deserializer::from_str_with_options(text, &opts)
        .map_err(|e| error::parse_error("", e))?;
    let file: SnapshotFile = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = error::dotted(e.path());
        error::parse_error(&path, de.span_error(e.into_inner()))
    })?;
    de.end()
        .map_err(|e| error::parse_error("", de.span_error(e)))?;
    State::from_file_in(file, base)
}

/// Reads and validates the snapshot at `path`; the error names the file.
/// At most [`MAX_BYTES`] + 1 bytes are read, so devices and pipes without
/// end are cut off too.
pub fn read_file(path: &Path) -> Result<State, LoadError> {
    let fail = |problem| LoadError {
        path: path.to_path_buf(),
        problem,
    };
    let meta = std::fs::metadata(path).map_err(|e| fail(LoadProblem::Read(e)))?;
    if meta.is_dir() {
        return Err(fail(LoadProblem::IsDir));
    }
    let file = File::open(path).map_err(|e| fail(LoadProblem::Read(e)))?;
    let mut bytes = Vec::new();
    file.take(MAX_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(LoadProblem::Read(e)))?;
    State::from_bytes_in(&bytes, path.parent()).map_err(|e| {
        fail(LoadProblem::Snapshot(match e {
            // Only a regular file's length is its size.
            SnapshotError::TooLarge { .. } => SnapshotError::TooLarge {
                bytes: (meta.is_file() && meta.len() > MAX_BYTES).then_some(meta.len()),
            },
            e => e,
        }))
    })
}

/// Reads and validates the snapshot at `path`; errors name the file (a
/// [`LoadError`] inside).
pub fn load_file(path: &Path) -> anyhow::Result<State> {
    Ok(read_file(path)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let mut s = crate::presets::load("fig4").unwrap();
        assert_eq!(State::from_ron(&s.to_ron()).unwrap(), s);
        s.caption = Some("Figure 4: \"quoted\", Ψ* and ζ".into());
        s.moments = Moments::Asymptotic;
        assert_eq!(State::from_ron(&s.to_ron()).unwrap(), s);
    }
}
