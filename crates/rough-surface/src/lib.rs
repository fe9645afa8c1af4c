//! Measured rough surfaces: a file in, a [`Measured`] out — the moment
//! table the model truncates at any q1, the log-binned spectrum the
//! spectrum view draws, and what identifies the file (SHA-256).
//!
//! Conventions follow SurfaceTopography (the library under
//! contact.engineering), so that its numbers are the reference; docs/model.md,
//! "Measured surfaces", states them.

mod describe;
mod error;
mod formats;
mod heights;
pub mod lengths;
mod limits;
mod measured;
mod read;
mod spectrum;
mod threads;
mod units;

pub use error::{Problem, SurfaceError};
pub use formats::readers::grid::Grid;
pub use heights::detrend::Detrend;
pub use heights::fill::MAX_UNDEFINED;
pub use heights::prepare::Heights;
pub use limits::MAX_BYTES;
pub use measured::{Kind, Measured, Options};
pub use read::{parse, parse_named, read, read_grid, read_grid_named, read_heights, sha256_hex};
pub use spectrum::amplitude::Amplitude;
pub use spectrum::anisotropy::{Slopes, RATIO as ANISOTROPY_RATIO};
pub use spectrum::fit::{PowerLawFit, Verdict, MIN_POINTS as MIN_FIT_POINTS};
pub use spectrum::profiles::Direction;
pub use spectrum::realspace::RealSpace;
pub use units::HeightUnit;
