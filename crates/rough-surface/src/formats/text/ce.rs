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
use crate::formats::text::psd;
use crate::formats::text::scan::defined;
use crate::measured::{Kind, Options};
use crate::spectrum::compute::Computed;
use crate::units::per_metre;

const AREAL: &str = "q/π × 2D PSD";
const PROFILE: &str = "1D PSD along x";
const UNRELIABLE: &str = " (incl. unreliable data)";

/// Whether header comments mark a contact.engineering download.
pub(crate) fn is_ce(header: &[(usize, &str)]) -> bool {
    header.iter().any(|(_, t)| t.starts_with("Columns:"))
}

struct Block {
    /// The measurement ("# Topography: NAME") the block belongs to.
    measurement: Option<String>,
    name: String,
    /// The `Columns:` line.
    line: usize,
    units: String,
    q: Vec<f64>,
    v: Vec<f64>,
    lines: Vec<usize>,
}

/// What a download gave: the table, its label for the summary, the
/// measurement read and the notes.
pub(crate) struct Read {
    pub kind: Kind,
    pub computed: Computed,
    pub label: String,
    pub measurement: Option<String>,
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

fn fourth(u: &str) -> Option<f64> {
    let u = u.trim();
    let len = u.strip_suffix('⁴').or_else(|| u.strip_suffix("^4"))?;
    Some(per_metre(len)?.powi(4))
}

/// The measurement a header comment starts ("Topography: knee").
fn measurement(comment: &str) -> Option<&str> {
    ["Topography:", "Measurement:"]
        .iter()
        .find_map(|p| comment.strip_prefix(p))
        .map(str::trim)
        .filter(|n| !n.is_empty())
}

/// The parenthesised units of a `Columns:` line, in order.
fn units(columns: &str) -> Vec<&str> {
    columns
        .split('(')
        .skip(1)
        .filter_map(|s| s.split(')').next())
        .collect()
}

pub(crate) fn read(text: &str, opts: &Options) -> Result<Read, Failure> {
    if opts.periodic || opts.pixel_size.is_some() || opts.direction.is_some() {
        return Err((
            None,
            Problem::Option(
                "--periodic, --pixel-size and --direction do not apply to a PSD".to_string(),
            ),
        ));
    }
    let mut blocks: Vec<Block> = Vec::new();
    let mut name = String::new();
    let mut current: Option<String> = None;
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
                    measurement: current.clone(),
                    name: std::mem::take(&mut name),
                    line: line_no,
                    units: t.to_string(),
                    q: Vec::new(),
                    v: Vec::new(),
                    lines: Vec::new(),
                }),
                Some(t) if !t.is_empty() && !t.chars().all(|c| c == '-' || c == '=') => {
                    if let Some(m) = measurement(t) {
                        current = Some(m.to_string());
                    }
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
        // A third column, the standard error of an average, is not read
        // (contact.engineering writes `nan` there for a single measurement).
        let at = |p| (Some(line_no), p);
        b.q.push(defined(fields[0], "wavevector").map_err(at)?);
        b.v.push(defined(fields[1], "PSD value").map_err(at)?);
        b.lines.push(line_no);
    }
    let mut measurements: Vec<&str> = Vec::new();
    for m in blocks.iter().filter_map(|b| b.measurement.as_deref()) {
        if !measurements.contains(&m) {
            measurements.push(m);
        }
    }
    let list = || {
        measurements
            .iter()
            .map(|m| format!("'{m}'"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let chosen: Option<String> = match &opts.series {
        Some(want) => {
            let found = measurements
                .iter()
                .find(|m| **m == want.trim())
                .or_else(|| {
                    measurements
                        .iter()
                        .find(|m| m.eq_ignore_ascii_case(want.trim()))
                });
            match found {
                Some(m) => Some(m.to_string()),
                None if measurements.is_empty() => {
                    return Err((
                        None,
                        Problem::Option(format!(
                            "--series '{want}': this download names no measurements \
                             (no '# Topography: NAME' line)"
                        )),
                    ))
                }
                None => {
                    return Err((
                        None,
                        Problem::Option(format!(
                            "--series '{want}' is not in this download: it holds {}",
                            list()
                        )),
                    ))
                }
            }
        }
        None => measurements.first().map(|m| m.to_string()),
    };
    let mut notes = Vec::new();
    if measurements.len() > 1 && opts.series.is_none() {
        notes.push(format!(
            "{} measurements in this download ({}): '{}' read, --series NAME reads another",
            measurements.len(),
            list(),
            chosen.as_deref().unwrap_or_default()
        ));
    }
    blocks.retain(|b| chosen.is_none() || b.measurement == chosen);
    let pick = |n: &str| blocks.iter().position(|b| b.name == n && !b.q.is_empty());
    let named = [
        (AREAL.to_string(), Dim::Areal),
        (format!("{AREAL}{UNRELIABLE}"), Dim::Areal),
        (PROFILE.to_string(), Dim::Profile),
        (format!("{PROFILE}{UNRELIABLE}"), Dim::Profile),
    ]
    .iter()
    .find_map(|(n, d)| pick(n).map(|i| (i, Some(*d))));
    // Without a series name, one table read by its units: m⁴ is C^iso,
    // m³ a profile's C1D.
    let with_data: Vec<usize> = (0..blocks.len())
        .filter(|&i| !blocks[i].q.is_empty())
        .collect();
    let (index, series) = match (named, with_data.as_slice()) {
        (Some(n), _) => n,
        (None, [only]) => (*only, None),
        (None, _) => {
            let names: Vec<String> = blocks.iter().map(|b| format!("'{}'", b.name)).collect();
            return Err((
                None,
                Problem::Unknown(format!(
                    "a contact.engineering download without a '{AREAL}' or '{PROFILE}' series \
                     (found {}): download the power spectrum analysis",
                    names.join(", ")
                )),
            ));
        }
    };
    let b = blocks.swap_remove(index);
    let u = units(&b.units);
    let fx = u.first().and_then(|u| per_length(u));
    let (dim, fy, scaled) = match (series, u.get(1)) {
        (Some(d), Some(u)) => (d, cubed(u), d == Dim::Areal),
        (None, Some(u)) => match (fourth(u), cubed(u)) {
            (Some(f), _) => (Dim::Areal, Some(f), false),
            (None, Some(f)) => (Dim::Profile, Some(f), false),
            _ => (Dim::Areal, None, false),
        },
        (_, None) => (Dim::Areal, None, false),
    };
    let (Some(fx), Some(fy)) = (fx, fy) else {
        let want = if series.is_some() {
            "a PSD in m³ or µm³ …"
        } else {
            "a PSD in m⁴ (areal C^iso) or m³ (profile C1D), or µm⁴, µm³ …"
        };
        return Err((
            Some(b.line),
            Problem::UnknownUnit(format!(
                "{} (expected a wavevector in 1/m or µm⁻¹ … and {want})",
                b.units
            )),
        ));
    };
    let q: Vec<f64> = b.q.iter().map(|q| q * fx).collect();
    let c: Vec<f64> = if scaled {
        // The series is C^iso · q/π.
        q.iter()
            .zip(&b.v)
            .map(|(q, v)| std::f64::consts::PI * (v / fy) / q)
            .collect()
    } else {
        b.v.iter().map(|v| v / fy).collect()
    };
    let (kind, mut computed) = psd::table(dim, q, c, &b.lines)?;
    computed.notes = notes;
    let label = match (&chosen, series) {
        (Some(m), _) => format!("contact.engineering PSD of '{m}'"),
        (None, Some(_)) => "contact.engineering PSD".to_string(),
        (None, None) => "PSD table".to_string(),
    };
    Ok(Read {
        kind,
        computed,
        label,
        measurement: chosen,
    })
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
