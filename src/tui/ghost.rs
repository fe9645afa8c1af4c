//! The ghost: `g` pins the slopes view's curves as a dim reference that
//! stays while parameters change, so that a change can be compared with what
//! was there before; `g` again clears it. On a measured surface `g` first
//! pins the power law fitted over the band (the idealised surface the data
//! is compared with), then the curves. The legend names what differs.

use rough_model::{Axis, Curves};

use super::app::App;
use super::plots::{compute_plot, Plot};
use crate::physical::print::{fmt_len, fmt_param};
use crate::scene::{GhostOf, GhostScene, Shown, State};

/// What a ghost shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GhostKind {
    /// The curves as they were when pinned.
    Curves,
    /// The self-affine power law fitted to a measured surface over [q0, q1]
    /// (its H and h_rms, truncated moments).
    Fit,
}

/// Pinned curves and the state they were computed at.
#[derive(Clone, Debug, PartialEq)]
pub struct Ghost {
    pub plot: Plot,
    pub state: State,
    pub kind: GhostKind,
}

impl Ghost {
    /// The ghost a snapshot recorded, beside the scene `now`, computed
    /// anew at `points` points: a fit's is the self-affine power law
    /// (no surface), curves are the scene's own with the pinned settings.
    pub fn of_scene(now: &State, g: &GhostScene, points: usize) -> Ghost {
        let mut state = now.clone();
        state.caption = None;
        state.shown = Shown::default();
        state.params = g.params;
        state.size_effect = g.size_effect;
        state.model = g.model;
        state.moments = g.moments;
        let kind = match g.kind {
            GhostOf::Curves => GhostKind::Curves,
            GhostOf::Fit => {
                state.surface = None;
                GhostKind::Fit
            }
        };
        let spec = state.scene_spec(Curves::ALL, points.max(2));
        Ghost {
            plot: compute_plot(&spec),
            state,
            kind,
        }
    }

    /// The ghost as a snapshot records it.
    pub fn scene(&self) -> GhostScene {
        GhostScene {
            kind: match self.kind {
                GhostKind::Curves => GhostOf::Curves,
                GhostKind::Fit => GhostOf::Fit,
            },
            params: self.state.params,
            size_effect: self.state.size_effect,
            model: self.state.model,
            moments: self.state.moments,
        }
    }

    /// Whether the ghost still means something beside `now`: the same
    /// sweep, so the same x axis (and, for a fit, still a measured surface).
    pub fn fits(&self, now: &State) -> bool {
        self.state.sweep == now.sweep && (self.kind == GhostKind::Curves || now.is_measured())
    }

    /// What the ghost shows that the current curves do not: the pinned
    /// values of what changed since ("h_rms 19.8 nm, exact"), the swept
    /// parameter left out (it moves only the marker).
    pub fn label(&self, now: &State) -> String {
        let was = &self.state;
        if self.kind == GhostKind::Fit {
            return format!(
                "ghost: power-law fit H {:.2}, h_rms {}",
                was.params.hurst(),
                fmt_len(was.params.h_rms())
            );
        }
        let swept = was.sweep.axis();
        let mut parts: Vec<String> = Axis::ALL
            .into_iter()
            .filter(|a| *a != swept && was.params.get(*a) != now.params.get(*a))
            .map(|a| format!("{} {}", a.symbol(), fmt_param(a, was.params.get(a))))
            .collect();
        if was.model != now.model {
            parts.push(was.model.label().to_string());
        }
        if was.moments != now.moments {
            parts.push(format!("{} moments", was.moments.label()));
        }
        if was.size_effect != now.size_effect {
            let on = if was.size_effect { "on" } else { "off" };
            parts.push(format!("size effect {on}"));
        }
        if parts.is_empty() {
            "ghost = now".to_string()
        } else {
            format!("ghost: {}", parts.join(", "))
        }
    }
}

/// What the explorer shows besides the scene, as a snapshot records it.
pub fn shown(app: &App) -> Shown {
    Shown {
        view: app.view,
        map_y: app.map_y.filter(|a| *a != app.state.sweep.axis()),
        ghost: app.ghost.as_ref().map(Ghost::scene),
    }
}

/// Takes what a loaded snapshot showed (view, map axis, ghost) into the
/// explorer; the state keeps none of it (the explorer's own fields hold it).
pub fn restore(app: &mut App) {
    let shown = std::mem::take(&mut app.state.shown);
    app.view = shown.view;
    app.map_y = shown.map_y;
    app.ghost = shown.ghost.map(|g| {
        let points = super::layout::Regions::of_size(app.size)
            .map_or(200, |r| usize::from(r.graph.width) * 2);
        Ghost::of_scene(&app.state, &g, points)
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_label_names_what_changed() {
        let was = crate::presets::load("fig2").unwrap();
        let g = Ghost {
            plot: Plot::default(),
            state: was.clone(),
            kind: GhostKind::Curves,
        };
        assert_eq!(g.label(&was), "ghost = now");
        let mut now = was.clone();
        now.params = now.params.with(Axis::Zeta, 1000.0).unwrap();
        assert_eq!(
            g.label(&now),
            "ghost = now",
            "the swept value is the marker"
        );
        now.params = now.params.with(Axis::HRms, 4e-8).unwrap();
        now.model = now.model.other();
        now.size_effect = true;
        assert_eq!(
            g.label(&now),
            "ghost: h_rms 19.8 nm, closed form, size effect off"
        );
        assert!(g.fits(&now));
        now.sweep = rough_model::Sweep::new(Axis::Hurst, 0.1, 0.9).unwrap();
        assert!(!g.fits(&now));
    }
}
