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

use crate::figure::View;

/// What a ghost shows: the curves as pinned, or the power law fitted to a
/// measured surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum GhostOf {
    Curves,
    Fit,
}

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

/// A ghost's scene, validated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GhostScene {
    pub kind: GhostOf,
    pub params: Params,
    pub size_effect: bool,
    pub model: Model,
    pub moments: Moments,
}

/// What the view showed, validated. The default is a fresh start: the
/// slopes view, the map's default y axis, no ghost.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shown {
    pub view: View,
    pub map_y: Option<Axis>,
    pub ghost: Option<GhostScene>,
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

impl Shown {
    /// Whether a scene (`measured` or not) can show this: the spectrum view
    /// and a fit's ghost need a measured surface.
    pub fn check(&self, measured: bool) -> Result<(), String> {
        if !self.view.exists(measured) {
            return Err(format!(
                "view: {} needs a measured surface (surface: …)",
                self.view.name()
            ));
        }
        if self
            .ghost
            .is_some_and(|g| g.kind == GhostOf::Fit && !measured)
        {
            return Err("ghost: kind Fit needs a measured surface (surface: …)".into());
        }
        Ok(())
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
