//! The loaded scene's caption, kept while the scene is the one it
//! describes: a changed surface, size effect, sweep, model or moments is
//! shown (and saved, and pictured) without it, and it comes back with that
//! scene. The same test says whether a poll's truth is still the scene's.

use rough_model::{Model, Moments, Params, Sweep};

use super::State;

/// What a caption describes: the parameters, the size effect, the sweep,
/// the model and the moments (its numbers are theirs: after `a` the
/// caption's "≈ 320" would not be the claims' 407).
type Scene = (Params, bool, Sweep, Model, Moments);

fn scene_of(s: &State) -> Scene {
    (
        swept_out(s, s.params),
        s.size_effect,
        s.sweep,
        s.model,
        s.moments,
    )
}

/// Whether `a` and `b` are one scene (the marker aside): what a poll's
/// truth was computed on.
pub fn same_scene(a: &State, b: &State) -> bool {
    scene_of(a) == scene_of(b) && a.surface == b.surface
}

/// `params` with the swept value, which only moves the marker, at the
/// sweep's start.
pub fn swept_out(s: &State, params: Params) -> Params {
    params
        .with(s.sweep.axis(), s.sweep.from())
        .unwrap_or(params)
}

/// A caption and the scene it describes.
#[derive(Debug, Default)]
pub struct KeptCaption(Option<(Scene, String)>);

impl KeptCaption {
    /// `state`'s caption, for `state`'s scene.
    pub fn of(state: &State) -> KeptCaption {
        KeptCaption(state.caption.clone().map(|c| (scene_of(state), c)))
    }

    /// Sets `state`'s caption: the kept one if the scene is its own, else none.
    pub fn apply(&self, state: &mut State) {
        let scene = scene_of(state);
        state.caption = (self.0.as_ref())
            .filter(|(s, _)| *s == scene)
            .map(|(_, c)| c.clone());
    }
}
