//! The loaded scene's caption, kept while the scene is the one it
//! describes: a changed surface, size effect, sweep, model or moments is
//! shown (and saved, and pictured) without it, and it comes back with that
//! scene.

use rough_model::{Model, Moments, Params, Sweep};

use crate::scene::State;

/// The most rows of a caption shown in a class or a lesson.
pub const MAX_CAPTION_ROWS: usize = 4;

/// The text the caption's rows show: the scene's caption, or while a
/// poll is open (outside a lesson, whose captions are written for their
/// polls) the line that says it waits.
pub fn text(app: &crate::tui::app::App) -> &str {
    let open = app.class.open_question().is_some() && app.class.step.is_none();
    if open {
        "(the caption shows after the reveal)"
    } else {
        app.state.caption.as_deref().unwrap_or("")
    }
}

/// The rows the caption region asks for in a served class or a lesson:
/// the lecturer's class line, the step line, the caption wrapped to the
/// width (at most [`MAX_CAPTION_ROWS`]) and the claims line; 0 (the usual
/// rows) outside them, whose screens keep their layout.
pub fn rows(app: &crate::tui::app::App) -> u16 {
    let lines = usize::from(app.class.view.is_some()) + usize::from(app.class.step.is_some());
    if lines == 0 {
        return 0;
    }
    let g = app.theme.glyphs;
    let width = usize::from(app.size.0);
    let caption = crate::tui::wrap::wrap(&g.text(text(app)), width, MAX_CAPTION_ROWS, g.cut());
    (lines + caption.len() + 1) as u16
}

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
