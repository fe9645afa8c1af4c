//! What a snapshot's view showed besides the scene: the view itself, the
//! regime map's y axis and the ghost (pinned curves). All three are
//! optional fields, written only when they differ from a fresh start, so a
//! snapshot saved on the slopes view without a ghost reads as before and
//! older snapshots load on the slopes view.
//!
//! ```text
//!     view: Map,                         // optional, Slopes when absent
//!     map_y: HRms,                       // optional
//!     ghost: (kind: Curves, params: (…), size_effect: false, model: Exact),
//!                                        // optional; moments as in the scene
//! ```

use rough_model::{Axis, Model, Moments, ParamValues, Params};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::scene::{GhostOf, GhostScene, View};

/// The `ghost` group of a snapshot: the scene the pinned curves were
/// computed at (the sweep is the snapshot's own).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GhostFile {
    pub kind: GhostOf,
    pub params: ParamValues,
    pub size_effect: bool,
    pub model: Model,
    #[serde(default, skip_serializing_if = "super::is_truncated")]
    pub moments: Moments,
}

impl GhostScene {
    /// Checks a file's ghost: parameters in the model's domain, moments
    /// that can be computed there, a fit only on a measured surface.
    pub fn of(f: &GhostFile, measured: bool) -> Result<GhostScene, String> {
        let params = Params::new(f.params).map_err(|e| format!("ghost.params: {e}"))?;
        f.moments
            .check(&params)
            .map_err(|e| format!("ghost: {e}"))?;
        if f.kind == GhostOf::Fit && !measured {
            return Err("ghost: kind Fit needs a measured surface (surface: …)".into());
        }
        Ok(GhostScene {
            kind: f.kind,
            params,
            size_effect: f.size_effect,
            model: f.model,
            moments: f.moments,
        })
    }

    pub fn to_file(self) -> GhostFile {
        GhostFile {
            kind: self.kind,
            params: self.params.values(),
            size_effect: self.size_effect,
            model: self.model,
            moments: self.moments,
        }
    }
}

pub(super) fn is_slopes(v: &View) -> bool {
    *v == View::Slopes
}

pub(super) fn ser_axis<S: Serializer>(v: &Option<Axis>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(a) => a.serialize(s),
        None => s.serialize_none(),
    }
}

pub(super) fn de_axis<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Axis>, D::Error> {
    Axis::deserialize(d).map(Some)
}

pub(super) fn ser_ghost<S: Serializer>(v: &Option<GhostFile>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(g) => g.serialize(s),
        None => s.serialize_none(),
    }
}

pub(super) fn de_ghost<'de, D: Deserializer<'de>>(d: D) -> Result<Option<GhostFile>, D::Error> {
    GhostFile::deserialize(d).map(Some)
}
