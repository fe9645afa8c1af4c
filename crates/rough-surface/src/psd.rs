//! Two-column PSD tables: q (1/m) and C^iso (m⁴), SurfaceTopography's
//! convention; `#` starts a comment.

use rough_model::{Dim, MomentTable};

use crate::error::Problem;
use crate::Kind;

type Read = (Kind, MomentTable, Vec<(f64, f64)>);

/// The numbers of one data line, or `None` for a blank or comment line.
pub(crate) fn numbers(line: &str) -> Option<Result<Vec<f64>, Problem>> {
    let data = line.split('#').next().unwrap_or("").trim();
    if data.is_empty() {
        return None;
    }
    Some(
        data.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
            .map(|f| match f.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                Ok(_) => Err(Problem::NotFinite(f.to_string())),
                Err(_) => Err(Problem::NotNumber(f.to_string())),
            })
            .collect(),
    )
}

pub(crate) fn read(text: &str) -> Result<Read, (Option<usize>, Problem)> {
    let (mut q, mut c, mut lines) = (Vec::new(), Vec::new(), Vec::new());
    for (i, line) in text.lines().enumerate() {
        let Some(row) = numbers(line) else { continue };
        let row = row.map_err(|p| (Some(i + 1), p))?;
        if row.len() != 2 {
            return Err((
                Some(i + 1),
                Problem::Ragged {
                    got: row.len(),
                    want: 2,
                },
            ));
        }
        q.push(row[0]);
        c.push(row[1]);
        lines.push(i + 1);
    }
    if q.is_empty() {
        return Err((None, Problem::Empty));
    }
    let table = MomentTable::from_psd(Dim::Areal, &q, &c).map_err(|e| {
        let line = match &e {
            rough_model::TableError::BadWavevector { index, .. }
            | rough_model::TableError::BadValue { index, .. }
            | rough_model::TableError::NotIncreasing { index, .. } => lines.get(*index).copied(),
            _ => None,
        };
        (line, Problem::Table(e))
    })?;
    let kind = Kind::Psd {
        dim: Dim::Areal,
        points: q.len(),
    };
    Ok((kind, table, q.into_iter().zip(c).collect()))
}
