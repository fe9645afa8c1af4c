//! What the scene is shown as besides its parameters: the view, the
//! regime map's y axis and the ghost (pinned curves).

use rough_model::{Axis, Model, Moments, Params};
use serde::{Deserialize, Serialize};

use super::View;

/// What a ghost shows: the curves as pinned, or the power law fitted to a
/// measured surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum GhostOf {
    Curves,
    Fit,
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
