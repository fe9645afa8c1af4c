//! The ghost: `g` pins the slopes view's curves as a dim reference that
//! stays while parameters change, so that a change can be compared with what
//! was there before; `g` again clears it. On a measured surface `g` first
//! pins the power law fitted over the band (the idealised surface the data
//! is compared with), then the curves. The legend names what differs.

use rough_model::Axis;

use super::fmt::{fmt_len, fmt_param};
use super::plots::Plot;
use crate::snapshot::State;

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
