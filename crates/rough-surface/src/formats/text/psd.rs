//! PSD tables: q (1/m) and C in SurfaceTopography's convention — areal
//! C^iso (m⁴) or a profile's C1D (m³) — interpolated as a power law
//! between neighbouring points and integrated exactly (the model's
//! [`MomentTable::from_psd`]).

use rough_model::{Dim, MomentTable, TableError};

use crate::error::{Failure, Problem};
use crate::measured::Kind;
use crate::spectrum::compute::Computed;

/// The table of `q` and `c`, whose point i came from 1-based line
/// `lines[i]` (for refusals).
pub(crate) fn table(
    dim: Dim,
    q: Vec<f64>,
    c: Vec<f64>,
    lines: &[usize],
) -> Result<(Kind, Computed), Failure> {
    let table = MomentTable::from_psd(dim, &q, &c).map_err(|e| {
        let line = match &e {
            TableError::BadWavevector { index, .. }
            | TableError::BadValue { index, .. }
            | TableError::NotIncreasing { index, .. } => lines.get(*index).copied(),
            _ => None,
        };
        (line, Problem::Table(e))
    })?;
    let kind = Kind::Psd {
        dim,
        points: q.len(),
    };
    let spectrum = q.into_iter().zip(c).collect();
    Ok((
        kind,
        Computed {
            table,
            spectrum,
            notes: Vec::new(),
            slopes: None,
            real: None,
            modes: Vec::new(),
            heights: None,
        },
    ))
}
