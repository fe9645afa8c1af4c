//! What a file read is, and how to read it: [`Options`] in, [`Measured`]
//! out.

use std::sync::Arc;

use rough_model::{Dim, MomentTable};

use crate::heights::detrend::Detrend;
use crate::heights::prepare::Heights;
use crate::spectrum::anisotropy::Slopes;
use crate::spectrum::band;
use crate::spectrum::fit::{self, PowerLawFit};
use crate::spectrum::profiles::Direction;
use crate::spectrum::realspace::RealSpace;
use crate::units::HeightUnit;

/// How to read a file whose content does not say everything.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// The data is periodic: no detrending beyond the mean, no window.
    pub periodic: bool,
    /// Sample spacing in metres, for data without a size header.
    pub pixel_size: Option<f64>,
    /// The measurement to read from a file holding several (a
    /// contact.engineering download): its name; the first when `None`.
    pub series: Option<String>,
    /// A map read as its profiles along one direction (line-scan
    /// conventions, [`Kind::Profiles`]) instead of as an area.
    pub direction: Option<Direction>,
    /// The channel to read of a file of several: its number (a .gwy's N of
    /// `/N/data`; a text file's channels from 0 in order) or its title;
    /// `None` takes the first whose values are heights (a unit of length).
    pub channel: Option<String>,
    /// The heights' unit, whatever the file says (`--height-unit`).
    pub height_unit: Option<HeightUnit>,
    /// The lateral unit (sizes, x positions) of a file that gives none
    /// (`--lateral-unit`).
    pub lateral_unit: Option<HeightUnit>,
    /// The largest share of undefined points filled, 0 to 1
    /// (`--max-undefined PERCENT`); [`crate::MAX_UNDEFINED`] when `None`.
    pub max_undefined: Option<f64>,
    /// The form removed before anything is computed (`--detrend`); `None`:
    /// the plane, or the mean of periodic data ([`Options::detrend_mode`]).
    pub detrend: Option<Detrend>,
}

impl Options {
    /// The form removed: the one asked, else the plane (the mean on
    /// periodic data).
    pub fn detrend_mode(&self) -> Detrend {
        self.detrend.unwrap_or(if self.periodic {
            Detrend::Mean
        } else {
            Detrend::Plane
        })
    }
}

/// What kind of data a file held.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A topography map of nx × ny samples spanning lx × ly metres.
    Map {
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
    },
    /// A line scan of n samples spanning l metres.
    Line { n: usize, l: f64 },
    /// A PSD table of `points` rows: areal (C^iso, m⁴) or profile (C1D, m³).
    Psd { dim: Dim, points: usize },
    /// A map of nx × ny samples over lx × ly read as its profiles along
    /// `direction` (`--direction`): the PSD averaged over them, profile
    /// moments as for a line scan.
    Profiles {
        direction: Direction,
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
    },
}

impl Kind {
    /// Areal sums (maps, isotropic PSDs) or profile sums (lines, profile PSDs).
    pub fn dim(&self) -> Dim {
        match self {
            Kind::Map { .. } => Dim::Areal,
            Kind::Line { .. } | Kind::Profiles { .. } => Dim::Profile,
            Kind::Psd { dim, .. } => *dim,
        }
    }

    /// How many heights it holds (a PSD table none).
    pub fn points(&self) -> Option<usize> {
        match *self {
            Kind::Map { nx, ny, .. } | Kind::Profiles { nx, ny, .. } => Some(nx * ny),
            Kind::Line { n, .. } => Some(n),
            Kind::Psd { .. } => None,
        }
    }
}

/// A measured surface, ready for the model.
#[derive(Clone, Debug)]
pub struct Measured {
    pub kind: Kind,
    /// The moments at any cutoff; q0 and the largest ζ come from it.
    pub table: Arc<MomentTable>,
    /// The spectrum for display, log-binned, (q in 1/m, PSD) with q
    /// increasing: C^iso (m⁴) for areal data, C1D (m³) for profiles, in
    /// SurfaceTopography's convention.
    pub spectrum: Vec<(f64, f64)>,
    /// SHA-256 of the file's bytes, lower-case hex.
    pub sha256: String,
    /// One line saying what was read and how it was treated, e.g.
    /// "map 256 × 128, 12 µm × 6 µm, plane removed, Hann window".
    pub summary: String,
    /// What the reader assumed or repaired, one line each, in the words the
    /// screen's status line, the side panel, export's stderr and CSV
    /// comments all print: "heights read in µm (the width's unit;
    /// --height-unit to change)", "decimal commas read", "312 undefined
    /// points (0.4 %) filled". Empty when the file said everything.
    ///
    /// Contract between readers and the map pipeline: a reader stores an
    /// undefined point (NaN, `nan`, an empty cell, a masked or invalid
    /// point of x3p/gwy) as `f64::NAN` in the heights it hands on; the
    /// pipeline fills or refuses them and adds the note.
    pub notes: Vec<String>,
    /// The measurement read from a file of several (a contact.engineering
    /// download's "Topography: NAME"), for the caption.
    pub measurement: Option<String>,
    /// A map's rms slopes along x and along y (its spectrum to the largest
    /// ζ); a note says when they differ by more than
    /// [`crate::ANISOTROPY_RATIO`].
    pub slopes: Option<Slopes>,
    /// Sq and Sdq of a map, Rq and RΔq of a line scan (real space, after
    /// the detrend, no window); `None` for PSD tables.
    pub real: Option<RealSpace>,
    /// The Fourier modes averaged in each point of `spectrum` (the fit's
    /// weights); empty for PSD tables, whose points weigh the same.
    pub modes: Vec<f64>,
    /// The default Hurst fit band, 1/m: the spectrum's self-affine
    /// stretch (`band`'s rules); `None` with too few points.
    pub band: Option<(f64, f64)>,
    /// A map's heights for the contact simulation, when read with
    /// [`crate::read_heights`] ([`Heights`]: filled,
    /// detrended, not windowed); `None` for lines, profiles and PSD tables.
    pub heights: Option<Arc<Heights>>,
}

impl Measured {
    /// Least-squares power law through the spectrum's points with q in
    /// [q_lo, q_hi]; `None` with fewer than two points there.
    pub fn fit(&self, q_lo: f64, q_hi: f64) -> Option<PowerLawFit> {
        fit::fit(
            self.kind.dim(),
            &self.spectrum,
            &self.modes,
            q_lo,
            q_hi,
            self.table.q0(),
        )
    }

    /// The fit over the default band ([`Measured::band`]).
    pub fn default_fit(&self) -> Option<PowerLawFit> {
        let (lo, hi) = self.band?;
        // The band's ends are data points: a rounding below one still takes it.
        self.fit(lo * (1.0 - 1e-12), hi * (1.0 + 1e-12))
    }

    /// The default fit band of a spectrum, for a [`Measured`] built by hand
    /// (a benchmark's synthetic surface).
    pub fn find_band(dim: Dim, spectrum: &[(f64, f64)], modes: &[f64]) -> Option<(f64, f64)> {
        band::self_affine(dim, spectrum, modes)
    }
}
