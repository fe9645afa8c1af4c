//! Measured rough surfaces: a file in, a [`Measured`] out — the moment
//! table the model truncates at any q1, the log-binned spectrum the
//! spectrum view draws, and what identifies the file (SHA-256).
//!
//! Conventions follow SurfaceTopography (the library under
//! contact.engineering), so that its numbers are the reference; MODEL.md,
//! "Measured surfaces", states them.

mod error;
mod fit;
mod psd;

use std::io::Read;
use std::path::Path;
use std::sync::Arc;

use rough_model::{Dim, MomentTable};
use sha2::{Digest, Sha256};

pub use error::{Problem, SurfaceError};
pub use fit::PowerLawFit;

/// Files larger than this are refused before they are read (512 MiB).
pub const MAX_BYTES: u64 = 512 << 20;

/// How to read a file whose content does not say everything.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    /// The data is periodic: no detrending beyond the mean, no window.
    pub periodic: bool,
    /// Sample spacing in metres, for data without a size header.
    pub pixel_size: Option<f64>,
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
}

impl Kind {
    /// Areal sums (maps, isotropic PSDs) or profile sums (lines, profile PSDs).
    pub fn dim(&self) -> Dim {
        match self {
            Kind::Map { .. } => Dim::Areal,
            Kind::Line { .. } => Dim::Profile,
            Kind::Psd { dim, .. } => *dim,
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
}

impl Measured {
    /// Least-squares power law through the spectrum's points with q in
    /// [q_lo, q_hi]; `None` with fewer than two points there.
    pub fn fit(&self, q_lo: f64, q_hi: f64) -> Option<PowerLawFit> {
        fit::fit(self.kind.dim(), &self.spectrum, q_lo, q_hi, self.table.q0())
    }
}

/// Reads and computes the surface in `path`. Every refusal names the file
/// and, where there is one, the line.
pub fn read(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    let fail = |line, problem| SurfaceError {
        path: path.to_path_buf(),
        line,
        problem,
    };
    let meta = std::fs::metadata(path).map_err(|e| fail(None, Problem::Read(e.to_string())))?;
    if meta.is_dir() {
        return Err(fail(None, Problem::IsDir));
    }
    if meta.len() > MAX_BYTES {
        return Err(fail(None, Problem::TooLarge(meta.len())));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| fail(None, Problem::Read(e.to_string())))?;
    if bytes.len() as u64 > MAX_BYTES {
        return Err(fail(None, Problem::TooLarge(bytes.len() as u64)));
    }
    parse(&bytes, opts).map_err(|(line, problem)| fail(line, problem))
}

/// The SHA-256 of `bytes`, lower-case hex (what a snapshot records).
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Computes the surface in a file's bytes; an error carries the 1-based
/// line it is about, if any.
pub fn parse(bytes: &[u8], opts: &Options) -> Result<Measured, (Option<usize>, Problem)> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1;
        (Some(line), Problem::NotText)
    })?;
    let _ = opts;
    let (kind, table, spectrum) = psd::read(text)?;
    Ok(Measured {
        kind,
        table: Arc::new(table),
        spectrum,
        sha256: sha256_hex(bytes),
    })
}
