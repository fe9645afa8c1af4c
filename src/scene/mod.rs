//! The scene every view reads: the parameters, the sweep, the model and
//! moments, the measured surface if any, the simulation's seed and what it
//! is shown as (view, map axis, ghost). Validated on every change
//! ([`State::check`]); `snapshot` saves and loads it as RON, `presets`
//! holds the paper's, the command line and the explorer edit it
//! ([`set`], [`set_q0`]). A caption is kept while the scene is the one it
//! describes ([`KeptCaption`], [`same_scene`]).

mod caption;
mod edit;
mod invalid;
mod measured;
mod shown;
mod view;

use rough_model::{Curves, Model, Moments, Params, Roughness, SceneSpec, Sweep};

use crate::surface::SurfaceSource;
pub use caption::{same_scene, swept_out, KeptCaption};
pub use edit::{set, set_q0, set_value, HURST_ONE_SET};
pub use invalid::{Invalid, TextProblem};
pub use measured::{fitted_params, synthetic};
pub use shown::{GhostOf, GhostScene, Shown};
pub use view::View;

/// Longest accepted `name`, in characters.
pub const MAX_NAME_CHARS: usize = 64;
/// Longest accepted `caption`, in characters.
pub const MAX_CAPTION_CHARS: usize = 300;

/// A validated scene: what every view, the export, the simulation and a
/// snapshot work from.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    pub name: String,
    /// What the scene shows, in words (shown under the header).
    pub caption: Option<String>,
    pub params: Params,
    pub size_effect: bool,
    pub sweep: Sweep,
    pub model: Model,
    pub moments: Moments,
    /// The measured surface the scene is computed on; `None` for the
    /// paper's power law.
    pub surface: Option<SurfaceSource>,
    /// The seed of the contact simulation's random phases; `None`: the
    /// default (1).
    pub seed: Option<u64>,
    /// What the view showed when the snapshot was saved (the explorer
    /// takes it on loading and keeps its own view state meanwhile).
    pub shown: Shown,
}

/// `text` as the value of a text field: at most `max` characters, none of
/// them control characters.
fn check_text(field: &'static str, text: &str, max: usize) -> Result<(), Invalid> {
    let chars = text.chars().count();
    let problem = if chars > max {
        TextProblem::TooLong { chars, max }
    } else if let Some(c) = text.chars().find(|c| c.is_control()) {
        TextProblem::Control(c)
    } else {
        return Ok(());
    };
    Err(Invalid::Text { field, problem })
}

/// Whether `name` is acceptable as a snapshot's display name.
pub fn check_name(name: &str) -> Result<(), Invalid> {
    check_text("name", name, MAX_NAME_CHARS)
}

/// Whether `caption` is acceptable as a snapshot's caption.
pub fn check_caption(caption: &str) -> Result<(), Invalid> {
    check_text("caption", caption, MAX_CAPTION_CHARS)
}

impl State {
    /// What parameters and sweep cannot check alone: the text fields,
    /// whether the moments can be computed at these parameters, and, on a
    /// measured surface, that the sweep is over a parameter and both the
    /// sweep and ζ lie within the data. A state that passes loads back
    /// after [`crate::snapshot::save_new`].
    pub fn check(&self) -> Result<(), Invalid> {
        check_name(&self.name)?;
        if let Some(c) = &self.caption {
            check_caption(c)?;
        }
        self.shown
            .check(self.is_measured())
            .map_err(Invalid::Shown)?;
        let r = self.roughness();
        r.check_sweep(&self.sweep).map_err(Invalid::Surface)?;
        r.check(&self.params).map_err(Invalid::Surface)?;
        if r.is_measured() {
            return Ok(());
        }
        self.moments.check(&self.params).map_err(Invalid::Moments)
    }

    /// The source of the scene's moments: the power law, or the measured
    /// surface's table.
    pub fn roughness(&self) -> Roughness {
        match &self.surface {
            Some(s) => Roughness::Measured(std::sync::Arc::clone(&s.measured.table)),
            None => Roughness::SelfAffine,
        }
    }

    /// The hardness in use by its own name: H_y with the size effect, H0
    /// without (H alone is the Hurst exponent).
    pub fn hardness_name(&self) -> &'static str {
        if self.size_effect {
            "H_y"
        } else {
            "H0"
        }
    }

    /// The index in use by its name: Ψ* with the size effect, Ψ_P without.
    pub fn index_name(&self) -> &'static str {
        if self.size_effect {
            "Ψ*"
        } else {
            "Ψ_P"
        }
    }

    /// Whether the scene is a measured surface's.
    pub fn is_measured(&self) -> bool {
        self.surface.is_some()
    }

    /// What loading found changed about the surface file, if anything: its
    /// SHA-256 differs from the one the snapshot recorded.
    pub fn surface_warning(&self) -> Option<String> {
        let s = self.surface.as_ref()?;
        let was = s.recorded_sha256.as_ref()?;
        Some(format!(
            "surface {} changed since the snapshot was saved (SHA-256 {}… then, {}… now): \
             showing it as it is now",
            s.file_name(),
            &was[..was.len().min(12)],
            &s.measured.sha256[..s.measured.sha256.len().min(12)]
        ))
    }

    /// The scene this state describes, with `curves` at `points` points
    /// (callers override what they vary, e.g. export's `--model`).
    pub fn scene_spec(&self, curves: Curves, points: usize) -> SceneSpec {
        SceneSpec {
            base: self.params,
            sweep: self.sweep,
            size_effect: self.size_effect,
            model: self.model,
            moments: self.moments,
            roughness: self.roughness(),
            curves,
            points,
        }
    }
}

#[cfg(test)]
mod tests {
    use rough_model::{Curves, Moments};

    #[test]
    fn scene_spec_carries_every_field() {
        let mut s = crate::presets::load("fig4").unwrap();
        s.moments = Moments::Asymptotic;
        let spec = s.scene_spec(Curves::ALL, 7);
        assert_eq!(spec.base, s.params);
        assert_eq!(spec.sweep, s.sweep);
        assert_eq!(spec.size_effect, s.size_effect);
        assert_eq!(spec.model, s.model);
        assert_eq!(spec.moments, Moments::Asymptotic);
        assert_eq!(spec.curves, Curves::ALL);
        assert_eq!(spec.points, 7);
    }
}
