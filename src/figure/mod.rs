//! What the explorer's views and `roughtui export` show, computed without
//! any terminal code: the index series, the load curve, the regime map and
//! the claims a preset's caption makes, plus the SVG picture of any view.
//!
//! Every number here comes from the model crate (`rough_model`): this module
//! only arranges grids and sweeps around it. The views cycle in the order of
//! [`View::ALL`] (slopes → indices → map → load, then spectrum on a measured
//! surface: the other views exist for every scene, the spectrum only for
//! measured data).
//!
//! - [`IndexSeries`]: Ψ_GW, Ψ_P, Ψ*, eq. 13's Ψ*asy and H_y/H0 along the sweep.
//! - [`LoadCurve`]: A/A0 elastic, plastic, total against p̄/H in [0, 1] at
//!   the current parameters, with the initial-slope line from the origin.
//! - [`MapSpec`], [`RegimeMap`], [`MapCache`]: the plastic share S_pl/S_tot
//!   over the swept parameter (across) and a second parameter (up), cached
//!   so that it is recomputed only when something it depends on changes.
//! - [`share_colour`], [`share_char`]: the map's sequential colour scale and
//!   its NO_COLOR character ramp; [`ELASTIC_BELOW`], [`PLASTIC_ABOVE`]: this
//!   program's regime thresholds (the paper sets none).
//! - [`claims`]: where the plastic share passes ½ and where the index in use
//!   crosses 1 along the sweep, located by bisection, and where the total
//!   slope has a minimum (golden section, then Newton on its derivative).
//! - [`SpectrumSeries`]: a measured surface's spectrum, the power law
//!   fitted over the band [q0, q1] and the cutoff q1.
//! - [`render_svg`]: any view as a self-contained SVG document (the
//!   explorer saves it with `snapshot::save_file_new`).

mod claims;
mod colour;
mod map;
mod minimum;
mod moments;
pub mod scene_text;
mod series;
mod spectrum;
mod svg;

pub use claims::{claims, shown_claims, Claim, ClaimKind, TRUNCATION_ZETA};
pub use colour::{
    share_ansi16, share_ansi256, share_char, share_colour, ANSI16_SCALE, ANSI256_SCALE, RAMP,
};
pub use map::{axis_arg, MapCache, MapSpec, RegimeMap, DEFAULT_GRID};
pub use moments::{moment_comments, MomentSeries};
pub use rough_model::slopes::{ELASTIC_BELOW, PLASTIC_ABOVE};
pub use series::{IndexSeries, LoadCurve};
pub use spectrum::{NotMeasured, SpectrumSeries};
pub use svg::{render_moments_svg, render_svg};

use rough_model::Axis;

/// One of the explorer's charts, each exportable as CSV or SVG (a
/// snapshot records it as `view: Map`).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum View {
    /// Initial slopes of the contact areas against the swept parameter.
    #[default]
    Slopes,
    /// The plasticity indices against the swept parameter.
    Indices,
    /// The regime map: plastic share over two parameters.
    Map,
    /// Contact areas against the load at the current parameters.
    Load,
    /// A measured surface's spectrum with the fitted power law and q1.
    Spectrum,
    /// The scene's surface solved by the boundary-element contact beside
    /// the theory's areas (the explorer only; `export --view contact`).
    Contact,
}

impl View {
    /// Every view, in Tab order.
    pub const ALL: [View; 6] = [
        View::Slopes,
        View::Indices,
        View::Map,
        View::Load,
        View::Spectrum,
        View::Contact,
    ];

    /// The views of a power-law scene, in Tab order.
    const POWER_LAW: [View; 5] = [
        View::Slopes,
        View::Indices,
        View::Map,
        View::Load,
        View::Contact,
    ];

    /// The views a scene has, in Tab order: the spectrum only on a
    /// measured surface; the contact view last.
    pub fn cycle(measured: bool) -> &'static [View] {
        if measured {
            &View::ALL
        } else {
            &View::POWER_LAW
        }
    }

    /// Whether a scene (`measured` or not) has this view.
    pub fn exists(self, measured: bool) -> bool {
        View::cycle(measured).contains(&self)
    }

    /// The view's name on the command line (`--view NAME`).
    pub fn name(self) -> &'static str {
        match self {
            View::Slopes => "slopes",
            View::Indices => "indices",
            View::Map => "map",
            View::Load => "load",
            View::Spectrum => "spectrum",
            View::Contact => "contact",
        }
    }

    /// The view called `name` (as [`View::name`] gives it).
    pub fn parse(name: &str) -> Option<View> {
        View::ALL.into_iter().find(|v| v.name() == name)
    }

    /// The next view in Tab order of a scene (`measured` or not): after
    /// load comes the spectrum on a measured surface, then contact.
    pub fn next(self, measured: bool) -> View {
        let all = View::cycle(measured);
        let i = all.iter().position(|&v| v == self).unwrap_or(0);
        all[(i + 1) % all.len()]
    }

    /// The previous view in Tab order (Shift-Tab).
    pub fn prev(self, measured: bool) -> View {
        let all = View::cycle(measured);
        let i = all.iter().position(|&v| v == self).unwrap_or(0);
        all[(i + all.len() - 1) % all.len()]
    }
}

/// What a view needs besides the state: grid sizes and the map's y axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FigureOptions {
    /// Points along a curve (slopes, indices, load), both ends included.
    pub points: usize,
    /// Map cells across and up.
    pub grid: (usize, usize),
    /// The map's y axis; `None` picks [`MapSpec::default_y`].
    pub map_y: Option<Axis>,
}

impl Default for FigureOptions {
    fn default() -> Self {
        FigureOptions {
            points: 200,
            grid: DEFAULT_GRID,
            map_y: None,
        }
    }
}

/// The unit of a parameter ("m" for lengths, "" for ratios).
pub fn axis_unit(axis: Axis) -> &'static str {
    match axis {
        Axis::HRms | Axis::RStar => "m",
        _ => "",
    }
}

#[cfg(test)]
mod tests {
    use super::View;

    #[test]
    fn views_cycle_in_tab_order_both_ways() {
        for (measured, n) in [(false, 5), (true, 6)] {
            let mut v = View::Slopes;
            let mut seen = vec![];
            for _ in 0..n {
                seen.push(v.name());
                assert_eq!(v.next(measured).prev(measured), v);
                v = v.next(measured);
            }
            assert_eq!(seen[..4], ["slopes", "indices", "map", "load"]);
            assert_eq!(v, View::Slopes);
        }
        assert_eq!(View::Slopes.prev(false), View::Contact);
        assert_eq!(View::Load.next(false), View::Contact);
        assert_eq!(View::Slopes.prev(true), View::Contact);
        assert_eq!(View::Load.next(true), View::Spectrum);
        assert_eq!(View::Spectrum.next(true), View::Contact);
        // A view the scene lacks goes on from the start.
        assert_eq!(View::Spectrum.next(false), View::Indices);
    }

    #[test]
    fn names_parse_back() {
        for v in View::ALL {
            assert_eq!(View::parse(v.name()), Some(v));
        }
        assert_eq!(View::parse("Map"), None);
        assert_eq!(View::parse(""), None);
    }
}
