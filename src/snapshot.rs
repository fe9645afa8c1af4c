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

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::Context;

use rough_model::{Axis, Model, ParamValues, Params, Sweep};
use serde::{Deserialize, Serialize};

/// The only schema version this build reads and writes.
pub const VERSION: u32 = 1;

/// The file form, field for field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SnapshotFile {
    pub version: u32,
    pub name: String,
    pub params: ParamsFile,
    pub size_effect: bool,
    pub sweep: SweepFile,
    pub model: Model,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParamsFile {
    pub h0_over_e: f64,
    pub h_rms: f64,
    pub zeta: f64,
    pub hurst: f64,
    pub r_star: f64,
    pub q0: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    pub axis: Axis,
    pub from: f64,
    pub to: f64,
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

/// Why a snapshot text was rejected (without the file name; callers add it).
#[derive(Debug, Clone, PartialEq)]
pub enum SnapshotError {
    Syntax(String),
    Version(u32),
    Invalid(String),
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::Syntax(m) => write!(f, "{m}"),
            SnapshotError::Version(v) => write!(
                f,
                "unknown snapshot version {v}: this build reads version {VERSION}"
            ),
            SnapshotError::Invalid(m) => write!(f, "{m}"),
        }
    }
}

impl std::error::Error for SnapshotError {}

impl State {
    /// Parses and validates a snapshot text.
    pub fn from_ron(text: &str) -> Result<State, SnapshotError> {
        let file: SnapshotFile = ron::from_str(text).map_err(|e| {
            SnapshotError::Syntax(format!(
                "line {}, column {}: {}",
                e.span.start.line, e.span.start.col, e.code
            ))
        })?;
        State::from_file(file)
    }

    pub fn from_file(f: SnapshotFile) -> Result<State, SnapshotError> {
        if f.version != VERSION {
            return Err(SnapshotError::Version(f.version));
        }
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

/// Reads and validates the snapshot at `path`; errors name the file.
pub fn load_file(path: &Path) -> anyhow::Result<State> {
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read snapshot {}", path.display()))?;
    State::from_ron(&text).map_err(|e| anyhow::anyhow!("snapshot {}: {e}", path.display()))
}

/// `{name}-{YYYYMMDD-HHMMSS}` (UTC) for a save at `time`.
pub fn default_stem(name: &str, time: SystemTime) -> String {
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
        "{name}-{y:04}{m:02}{d:02}-{:02}{:02}{:02}",
        rem / 3600,
        rem / 60 % 60,
        rem % 60
    )
}

/// Writes `state` to `dir/{stem}.ron`, never overwriting: if that name is
/// taken, `{stem}-2.ron`, `{stem}-3.ron`, …. The text goes to a temporary
/// file in `dir` first and is renamed into place without replacing anything.
/// Returns the path written.
pub fn save_new(dir: &Path, stem: &str, state: &State) -> anyhow::Result<PathBuf> {
    let text = state.to_ron();
    let tmp = dir.join(format!(".{stem}.ron.tmp{}", std::process::id()));
    {
        let mut f = std::fs::File::create(&tmp)
            .with_context(|| format!("cannot write in {}", dir.display()))?;
        let written = f.write_all(text.as_bytes()).and_then(|()| f.sync_all());
        if let Err(e) = written {
            let _ = std::fs::remove_file(&tmp);
            return Err(e).with_context(|| format!("cannot write {}", tmp.display()));
        }
    }
    for n in 1..10_000u32 {
        let name = if n == 1 {
            format!("{stem}.ron")
        } else {
            format!("{stem}-{n}.ron")
        };
        let target = dir.join(name);
        // hard_link fails if the target exists: an atomic no-clobber rename.
        match std::fs::hard_link(&tmp, &target) {
            Ok(()) => {
                let _ = std::fs::remove_file(&tmp);
                return Ok(target);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                return Err(e).with_context(|| format!("cannot save {}", target.display()));
            }
        }
    }
    let _ = std::fs::remove_file(&tmp);
    anyhow::bail!(
        "cannot save: too many snapshots named {stem} in {}",
        dir.display()
    )
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

    #[test]
    fn stems_carry_utc_date_and_time() {
        let t = UNIX_EPOCH + std::time::Duration::from_secs(1_795_275_012);
        assert_eq!(default_stem("fig2", t), "fig2-20261121-153012");
    }
}
