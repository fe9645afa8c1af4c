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
mod withheld;

pub use claims::{claims, shown_claims, Claim, ClaimKind, TRUNCATION_ZETA};
pub use colour::{
    share_ansi16, share_ansi256, share_char, share_colour, ANSI16_SCALE, ANSI256_SCALE, RAMP,
};
pub use map::{axis_arg, MapCache, MapSpec, RegimeMap, DEFAULT_GRID};
pub use moments::{moment_comments, MomentSeries};
pub use rough_model::slopes::{ELASTIC_BELOW, PLASTIC_ABOVE};
pub use series::{IndexSeries, LoadCurve};
pub use spectrum::{NotMeasured, SpectrumSeries};
pub use svg::{
    contact_span, render_contact, render_contact_map, render_contact_slopes, render_contact_sweep,
    render_moments_svg, render_svg, sweep_span, ContactLoads, ContactMap, ContactSlopes,
    ContactSweep,
};
pub use svg::{phone_note, render_phone, render_phone_with, LegendEntry, Picture, UPRIGHT, WIDE};
pub use withheld::{Withheld, INDICES, SLOPES};

/// The views, named where the scene keeps the one shown.
pub use crate::scene::View;

use rough_model::Axis;

/// What a view needs besides the state: grid sizes and the map's y axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FigureOptions {
    /// Points along a curve (slopes, indices, load), both ends included.
    pub points: usize,
    /// Map cells across and up.
    pub grid: (usize, usize),
    /// The map's y axis; `None` picks [`MapSpec::default_y`].
    pub map_y: Option<Axis>,
    /// What the picture leaves out while a poll's answer waits.
    pub withheld: Withheld,
}

impl Default for FigureOptions {
    fn default() -> Self {
        FigureOptions {
            points: 200,
            grid: DEFAULT_GRID,
            map_y: None,
            withheld: Withheld::NONE,
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
