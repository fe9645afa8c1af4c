//! contact.engineering's TXT download of a power-spectrum analysis: blocks
//! written by `np.savetxt` with a header
//!
//! ```text
//! # q/π × 2D PSD
//! # ------------
//! # Columns: Wavevector (1/m), PSD (m³)
//! 1.0e+05 2.0e-25
//! ```
//!
//! one block per series ("1D PSD along x", "1D PSD along y",
//! "q/π × 2D PSD", and each "(incl. unreliable data)"), one set per
//! analysed measurement; recent versions convert to SI, older ones write the
//! measurement's unit (`µm⁻¹`, `µm³`). A third column (standard error of
//! an average) is ignored.
//!
//! Read: the first "q/π × 2D PSD" block as the isotropic PSD,
//! C^iso = (π/q)·value; without one, the first "1D PSD along x" as a
//! profile PSD C1D; the reliable series before the "(incl. unreliable
//! data)" one.

use rough_model::Dim;

use crate::error::{Failure, Problem};
use crate::header::per_metre;
use crate::psd;
use crate::spectrum::Computed;
use crate::text::defined;
use crate::{Kind, Options};

const AREAL: &str = "q/π × 2D PSD";
const PROFILE: &str = "1D PSD along x";
const UNRELIABLE: &str = " (incl. unreliable data)";

/// Whether header comments mark a contact.engineering download.
pub(crate) fn is_ce(header: &[(usize, &str)]) -> bool {
    header.iter().any(|(_, t)| t.starts_with("Columns:"))
}

struct Block {
    name: String,
    /// The `Columns:` line.
    line: usize,
    units: String,
    q: Vec<f64>,
    v: Vec<f64>,
    lines: Vec<usize>,
}

/// Per metre of the length whose inverse is q's unit ("1/m", "µm⁻¹" …):
/// q_SI = q · this.
fn per_length(u: &str) -> Option<f64> {
    let u: String = u.chars().filter(|c| !c.is_whitespace()).collect();
    let len = u
        .strip_prefix("1/")
        .or_else(|| u.strip_suffix("⁻¹"))
        .or_else(|| u.strip_suffix("^-1"))?;
    per_metre(len)
}

fn cubed(u: &str) -> Option<f64> {
    let u = u.trim();
    let len = u.strip_suffix('³').or_else(|| u.strip_suffix("^3"))?;
    Some(per_metre(len)?.powi(3))
}

/// The parenthesised units of a `Columns:` line, in order.
fn units(columns: &str) -> Vec<&str> {
    columns
        .split('(')
        .skip(1)
        .filter_map(|s| s.split(')').next())
        .collect()
}

pub(crate) fn read(text: &str, opts: &Options) -> Result<(Kind, Computed), Failure> {
    if opts.periodic || opts.pixel_size.is_some() {
        return Err((
            None,
            Problem::Option("--periodic and --pixel-size do not apply to a PSD".to_string()),
        ));
    }
    let mut blocks: Vec<Block> = Vec::new();
    let mut name = String::new();
    for (i, line) in text.split('\n').enumerate() {
        let line_no = i + 1;
        let (data, comment) = match line.find('#') {
            Some(k) => (&line[..k], Some(line[k + 1..].trim())),
            None => (line, None),
        };
        let fields: Vec<&str> = data
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
            .collect();
        if fields.is_empty() {
            match comment {
                Some(t) if t.starts_with("Columns:") => blocks.push(Block {
                    name: std::mem::take(&mut name),
                    line: line_no,
                    units: t.to_string(),
                    q: Vec::new(),
                    v: Vec::new(),
                    lines: Vec::new(),
                }),
                Some(t) if !t.is_empty() && !t.chars().all(|c| c == '-' || c == '=') => {
                    name = t.to_string();
                }
                _ => {}
            }
            continue;
        }
        let Some(b) = blocks.last_mut() else {
            return Err((
                Some(line_no),
                Problem::Unknown("data before the first '# Columns:' line".to_string()),
            ));
        };
        if fields.len() < 2 || fields.len() > 3 {
            return Err((
                Some(line_no),
                Problem::Ragged {
                    got: fields.len(),
                    want: 2,
                },
            ));
        }
        let at = |p| (Some(line_no), p);
        b.q.push(defined(fields[0], "wavevector").map_err(at)?);
        b.v.push(defined(fields[1], "PSD value").map_err(at)?);
        b.lines.push(line_no);
    }
    let pick = |n: &str| blocks.iter().position(|b| b.name == n && !b.q.is_empty());
    let (index, dim) = [
        (AREAL.to_string(), Dim::Areal),
        (format!("{AREAL}{UNRELIABLE}"), Dim::Areal),
        (PROFILE.to_string(), Dim::Profile),
        (format!("{PROFILE}{UNRELIABLE}"), Dim::Profile),
    ]
    .iter()
    .find_map(|(n, d)| pick(n).map(|i| (i, *d)))
    .ok_or_else(|| {
        let names: Vec<String> = blocks.iter().map(|b| format!("'{}'", b.name)).collect();
        (
            None,
            Problem::Unknown(format!(
                "a contact.engineering download without a '{AREAL}' or '{PROFILE}' series \
                 (found {}): download the power spectrum analysis",
                names.join(", ")
            )),
        )
    })?;
    let b = blocks.swap_remove(index);
    let u = units(&b.units);
    let (fx, fy) = match (
        u.first().and_then(|u| per_length(u)),
        u.get(1).and_then(|u| cubed(u)),
    ) {
        (Some(fx), Some(fy)) => (fx, fy),
        _ => {
            return Err((
                Some(b.line),
                Problem::UnknownUnit(format!(
                    "{} (expected a wavevector in 1/m or µm⁻¹ … and a PSD in m³ or µm³ …)",
                    b.units
                )),
            ))
        }
    };
    let q: Vec<f64> = b.q.iter().map(|q| q * fx).collect();
    let c: Vec<f64> = match dim {
        // The series is C^iso · q/π.
        Dim::Areal => q
            .iter()
            .zip(&b.v)
            .map(|(q, v)| std::f64::consts::PI * (v / fy) / q)
            .collect(),
        Dim::Profile => b.v.iter().map(|v| v / fy).collect(),
    };
    psd::table(dim, q, c, &b.lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_of_both_versions() {
        assert_eq!(per_length("1/m"), Some(1.0));
        assert_eq!(per_length("µm⁻¹"), Some(1e6));
        assert_eq!(per_length("1 / nm"), Some(1e9));
        assert_eq!(cubed("m³"), Some(1.0));
        assert_eq!(cubed("µm³"), Some(1e18));
        assert_eq!(
            units("Columns: Wavevector (1/m), PSD (m³), standard error of average PSD (m³)"),
            vec!["1/m", "m³", "m³"]
        );
    }
}
