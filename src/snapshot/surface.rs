//! A snapshot's measured surface: its file form (path, SHA-256, how it was
//! read), and reading the file it names back when the snapshot is loaded.

use std::fmt;
use std::path::{Path, PathBuf};

use rough_surface::{Detrend, Direction, Options, Problem, SurfaceError};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::surface::{relative_to, SurfaceSource};

/// The `surface` group of a snapshot.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceFile {
    /// Relative to the snapshot's folder, or absolute.
    pub path: String,
    /// SHA-256 of the file's bytes when the snapshot was saved, lower-case hex.
    pub sha256: String,
    #[serde(default, skip_serializing_if = "is_false")]
    pub periodic: bool,
    /// Sample spacing in metres for data without a size header; written as
    /// a plain number, not `Some(…)`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_number",
        deserialize_with = "de_number"
    )]
    pub pixel_size: Option<f64>,
    /// The measurement read from a download of several (`--series`);
    /// written plain, `series: "steel"`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_plain",
        deserialize_with = "de_plain"
    )]
    pub series: Option<String>,
    /// A map read as its profiles along `x` or `y` (`--direction`);
    /// written plain, `direction: x`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_plain",
        deserialize_with = "de_plain"
    )]
    pub direction: Option<DirectionName>,
    /// The channel read of a file of several (its number or title), when
    /// one was chosen.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub channel: Option<String>,
    /// The heights' unit given with `--height-unit` ("nm"), if any.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_text",
        deserialize_with = "de_text"
    )]
    pub height_unit: Option<String>,
    /// The lateral unit given with `--lateral-unit` ("µm") for a file that
    /// gives none, if any.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_text",
        deserialize_with = "de_text"
    )]
    pub lateral_unit: Option<String>,
    /// The share of undefined points filled at most, in percent
    /// (`--max-undefined`), when it is not the default 10 %.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_number",
        deserialize_with = "de_number"
    )]
    pub max_undefined: Option<f64>,
    /// The Hurst fit band set by hand, (q_lo, q_hi) in 1/m; absent: the
    /// self-affine stretch found from the data.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_pair",
        deserialize_with = "de_pair"
    )]
    pub fit_band: Option<(f64, f64)>,
    /// The form removed from the heights (`--detrend`), written plain,
    /// `detrend: curvature`; absent: the default (the plane, the mean of
    /// periodic data), so snapshots from before it load unchanged.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "ser_detrend",
        deserialize_with = "de_detrend"
    )]
    pub detrend: Option<Detrend>,
}

fn ser_detrend<S: Serializer>(v: &Option<Detrend>, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_unit_variant("Detrend", 0, v.unwrap_or_default().name())
}

fn de_detrend<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Detrend>, D::Error> {
    /// The names `detrend:` takes.
    const MODES: &[&str] = &["none", "mean", "plane", "curvature"];
    struct Mode;
    impl serde::de::Visitor<'_> for Mode {
        type Value = Detrend;
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("one of none, mean, plane, curvature")
        }
        fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Detrend, E> {
            Detrend::parse(v).ok_or_else(|| E::unknown_variant(v, MODES))
        }
    }
    d.deserialize_identifier(Mode).map(Some)
}

fn ser_pair<S: Serializer>(v: &Option<(f64, f64)>, s: S) -> Result<S::Ok, S::Error> {
    v.unwrap_or_default().serialize(s)
}

fn de_pair<'de, D: Deserializer<'de>>(d: D) -> Result<Option<(f64, f64)>, D::Error> {
    <(f64, f64)>::deserialize(d).map(Some)
}

fn ser_text<S: Serializer>(v: &Option<String>, s: S) -> Result<S::Ok, S::Error> {
    v.as_deref().unwrap_or_default().serialize(s)
}

fn de_text<'de, D: Deserializer<'de>>(d: D) -> Result<Option<String>, D::Error> {
    String::deserialize(d).map(Some)
}

/// `direction: x` or `direction: y` in a snapshot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum DirectionName {
    #[serde(rename = "x")]
    X,
    #[serde(rename = "y")]
    Y,
}

impl From<DirectionName> for Direction {
    fn from(d: DirectionName) -> Direction {
        match d {
            DirectionName::X => Direction::X,
            DirectionName::Y => Direction::Y,
        }
    }
}

impl From<Direction> for DirectionName {
    fn from(d: Direction) -> DirectionName {
        match d {
            Direction::X => DirectionName::X,
            Direction::Y => DirectionName::Y,
        }
    }
}

fn is_false(b: &bool) -> bool {
    !*b
}

fn ser_number<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    v.unwrap_or_default().serialize(s)
}

fn de_number<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
    f64::deserialize(d).map(Some)
}

fn ser_plain<S: Serializer, T: Serialize>(v: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(v) => v.serialize(s),
        None => s.serialize_none(),
    }
}

fn de_plain<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Option<T>, D::Error> {
    T::deserialize(d).map(Some)
}

pub(super) fn ser<S: Serializer>(v: &Option<SurfaceFile>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(f) => f.serialize(s),
        None => s.serialize_none(),
    }
}

pub(super) fn de<'de, D: Deserializer<'de>>(d: D) -> Result<Option<SurfaceFile>, D::Error> {
    SurfaceFile::deserialize(d).map(Some)
}

/// Why a snapshot's surface could not be shown.
#[derive(Clone, Debug, PartialEq)]
pub enum SurfaceProblem {
    /// No file where the snapshot says (as recorded, and where that led).
    Missing { recorded: String, looked: PathBuf },
    /// The file is there but refused (file, line and problem inside).
    Bad(SurfaceError),
    /// `pixel_size` is not a length > 0.
    PixelSize(f64),
    /// `height_unit` is not a length unit.
    HeightUnit(String),
    /// `lateral_unit` is not a length unit.
    LateralUnit(String),
    /// `max_undefined` is not a percentage in (0, 100).
    MaxUndefined(f64),
    /// `fit_band` is not two wavevectors 0 < q_lo < q_hi.
    FitBand(f64, f64),
}

impl fmt::Display for SurfaceProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SurfaceProblem::Missing { recorded, looked } => write!(
                f,
                "its surface file {recorded} is missing (looked for {}): \
                 put the file back there or fix surface.path",
                looked.display()
            ),
            SurfaceProblem::Bad(e) => write!(f, "its surface: {e}"),
            SurfaceProblem::PixelSize(v) => write!(
                f,
                "surface.pixel_size = {v} is out of range: it must be a length > 0 in metres"
            ),
            SurfaceProblem::FitBand(a, b) => write!(
                f,
                "surface.fit_band = ({a}, {b}) is out of range: two wavevectors in 1/m, \
                 0 < the first < the second"
            ),
            SurfaceProblem::HeightUnit(u) => write!(
                f,
                "surface.height_unit = {u:?} is not a length unit: m, mm, µm, nm, Å or pm"
            ),
            SurfaceProblem::LateralUnit(u) => write!(
                f,
                "surface.lateral_unit = {u:?} is not a length unit: m, mm, µm, nm, Å or pm"
            ),
            SurfaceProblem::MaxUndefined(v) => write!(
                f,
                "surface.max_undefined = {v} is out of range: a percentage above 0 and \
                 below 100"
            ),
        }
    }
}

impl std::error::Error for SurfaceProblem {}

/// Reads the surface `sf` names, its relative path taken from `base` (the
/// current folder if `None`). A SHA-256 other than the recorded one is kept
/// in the source, to be reported; the file is shown as it is now.
pub(super) fn read(sf: &SurfaceFile, base: Option<&Path>) -> Result<SurfaceSource, SurfaceProblem> {
    if let Some(v) = sf.pixel_size {
        if !(v.is_finite() && v > 0.0) {
            return Err(SurfaceProblem::PixelSize(v));
        }
    }
    let recorded = Path::new(&sf.path);
    let path = match base {
        Some(b) if recorded.is_relative() => b.join(recorded),
        _ => recorded.to_path_buf(),
    };
    let height_unit = match &sf.height_unit {
        Some(u) => Some(
            rough_surface::HeightUnit::parse(u)
                .ok_or_else(|| SurfaceProblem::HeightUnit(u.clone()))?,
        ),
        None => None,
    };
    let lateral_unit = match &sf.lateral_unit {
        Some(u) => Some(
            rough_surface::HeightUnit::parse(u)
                .ok_or_else(|| SurfaceProblem::LateralUnit(u.clone()))?,
        ),
        None => None,
    };
    if let Some(v) = sf.max_undefined {
        if !(v > 0.0 && v < 100.0) {
            return Err(SurfaceProblem::MaxUndefined(v));
        }
    }
    let options = Options {
        periodic: sf.periodic,
        pixel_size: sf.pixel_size,
        series: sf.series.clone(),
        direction: sf.direction.map(Into::into),
        channel: sf.channel.clone(),
        height_unit,
        lateral_unit,
        max_undefined: sf.max_undefined.map(|p| p / 100.0),
        detrend: sf.detrend,
    };
    let mut src = SurfaceSource::read(&path, options).map_err(|e| {
        let missing = matches!(&e.problem, Problem::Read(_)) && !path.exists();
        if missing {
            SurfaceProblem::Missing {
                recorded: sf.path.clone(),
                looked: crate::surface::absolute(&path),
            }
        } else {
            SurfaceProblem::Bad(e)
        }
    })?;
    if let Some((a, b)) = sf.fit_band {
        if !(a > 0.0 && b > a && b.is_finite()) {
            return Err(SurfaceProblem::FitBand(a, b));
        }
        src.fit_band = Some((a, b));
    }
    if src.measured.sha256 != sf.sha256 {
        src.recorded_sha256 = Some(sf.sha256.clone());
    }
    Ok(src)
}

/// The file form of `src` for a snapshot in `base` (the current folder if
/// `None`): the path relative to it where possible. The SHA-256 is the
/// file's as read (a changed file's new one: the snapshot now describes it).
pub(super) fn file_of(src: &SurfaceSource, base: Option<&Path>) -> SurfaceFile {
    let base = base
        .map(Path::to_path_buf)
        .unwrap_or_else(|| std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")));
    SurfaceFile {
        path: relative_to(&src.path, &base).to_string_lossy().into_owned(),
        sha256: src.measured.sha256.clone(),
        periodic: src.options.periodic,
        pixel_size: src.options.pixel_size,
        series: src.options.series.clone(),
        direction: src.options.direction.map(Into::into),
        channel: src.options.channel.clone(),
        height_unit: src.options.height_unit.map(|u| u.name.to_string()),
        lateral_unit: src.options.lateral_unit.map(|u| u.name.to_string()),
        max_undefined: src.options.max_undefined.map(|s| s * 100.0),
        fit_band: src.fit_band,
        detrend: src.options.detrend,
    }
}
