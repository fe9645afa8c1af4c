//! Measured rough surfaces: a file in, a [`Measured`] out — the moment
//! table the model truncates at any q1, the log-binned spectrum the
//! spectrum view draws, and what identifies the file (SHA-256).
//!
//! Conventions follow SurfaceTopography (the library under
//! contact.engineering), so that its numbers are the reference; docs/model.md,
//! "Measured surfaces", states them.

mod allow;
mod amplitude;
mod anisotropy;
mod assumed;
mod band;
mod bins;
mod ce;
mod channels;
mod columns;
mod colunits;
mod container;
mod decimal;
mod describe;
mod detrend;
mod error;
mod fill;
mod fit;
mod grid;
mod gwy;
mod header;
mod hints;
mod limits;
mod matrix;
mod measured;
mod prepare;
mod profiles;
mod psd;
mod read;
mod readers;
mod realspace;
mod sniff;
mod spectrum;
mod stream;
mod text;
mod threads;
mod units;
mod validity;
mod x3p;

pub use amplitude::Amplitude;
pub use anisotropy::{Slopes, RATIO as ANISOTROPY_RATIO};
pub use detrend::Detrend;
pub use error::{Problem, SurfaceError};
pub use fill::MAX_UNDEFINED;
pub use fit::{PowerLawFit, Verdict, MIN_POINTS as MIN_FIT_POINTS};
pub use grid::Grid;
pub use limits::MAX_BYTES;
pub use measured::{Direction, Kind, Measured, Options};
pub use prepare::Heights;
pub use read::{parse, parse_named, read, read_grid, read_grid_named, read_heights, sha256_hex};
pub use realspace::RealSpace;
pub use units::HeightUnit;
