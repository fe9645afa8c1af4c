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

// Saving is wired up by the TUI's `s` key.
#[allow(dead_code)]
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let s = crate::presets::load("fig4").unwrap();
        let back = State::from_ron(&s.to_ron()).unwrap();
        assert_eq!(back, s);
    }
}
