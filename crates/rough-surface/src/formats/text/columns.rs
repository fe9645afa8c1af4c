//! Two-column tables without a size header: a line scan `x z` (metres, or
//! Gwyddion's XYZ-export units) or an isotropic PSD table `q C^iso`.
//!
//! Which one is decided from the content, documented in docs/surfaces.md:
//!
//! 1. A header line naming the columns decides: its first word `q`, `k`,
//!    `wavevector` or `wavenumber`, or any word `psd`, marks a PSD table;
//!    first word `x`, `position` or `distance`, or a `Lateral units:`
//!    label, marks a line scan.
//! 2. Otherwise the second column decides whether it *looks like a PSD*:
//!    every q > 0, C > 0 on at least half the rows, the positive C span at
//!    least two decades and fall with q (log-log least-squares slope ≤ −1).
//!    Heights (either sign, or a narrow positive range) never do.
//! 3. A table that looks like a PSD but whose first column is also
//!    uniformly spaced (a raw FFT's q) could be either: refused, asking for
//!    a header line `# q C` or `# x z`.
//!
//! A line scan's x must then be uniform: every x within 1% of the spacing
//! (plus the rounding of its printed digits, see [`Precision`]) of the
//! least-squares line x_i = a + i Δx, so that the rounding of the first and
//! last x does not set the spacing (a Dektak export prints x to 0.1 µm at a
//! spacing of 0.156 µm); a jitter of 1% of Δx moves the phase of the
//! shortest wave by at most 2π·1%/2, and its PSD by ~1e-3. The scan spans
//! L = n Δx (as SurfaceTopography's XYZ reader, which takes Δx from the
//! end points and reads x uniform only to an absolute 1e-6 in file units).

use rough_model::Dim;

use crate::error::{Failure, Problem};
use crate::formats::text::header::Header;
use crate::formats::text::psd;
use crate::formats::text::scan::Scan;
use crate::measured::{Kind, Options};
use crate::spectrum::compute::{self, Computed};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Hint {
    Psd,
    Scan,
}

fn hint(lines: &[(usize, &str)], header: &Header) -> Option<Hint> {
    let (mut psd, mut scan) = (
        false,
        header.x_unit.is_some() || crate::formats::text::colunits::names_profile(lines),
    );
    for (_, text) in lines {
        let lower = text.to_lowercase();
        let words: Vec<&str> = lower
            .split(|c: char| c.is_whitespace() || matches!(c, ',' | ';' | '#'))
            .filter(|w| !w.is_empty())
            .collect();
        // "x/mm", "x(mm)": the name before its unit.
        let first = words
            .first()
            .map(|w| w.split(['/', '(', '[']).next().unwrap_or(w));
        match first {
            Some("q" | "k" | "wavevector" | "wavenumber") => psd = true,
            Some("x" | "position" | "distance") => scan = true,
            _ => {}
        }
        psd |= words
            .iter()
            .any(|w| w.trim_matches(|c: char| !c.is_alphanumeric()) == "psd");
    }
    match (psd, scan) {
        (true, false) => Some(Hint::Psd),
        (false, true) => Some(Hint::Scan),
        _ => None,
    }
}

/// Rule 2: every q > 0 and C > 0 on at least half the rows, spanning two
/// decades and falling with q.
fn looks_like_psd(x: &[f64], y: &[f64]) -> bool {
    if x.len() < 3 || x.iter().any(|&q| q <= 0.0) {
        return false;
    }
    let pts: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .filter(|(_, &c)| c > 0.0)
        .map(|(&q, &c)| (q.ln(), c.ln()))
        .collect();
    if pts.len() < 3 || 2 * pts.len() < x.len() {
        return false;
    }
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
    if hi - lo < 2.0 * std::f64::consts::LN_10 {
        return false;
    }
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    sxx > 0.0 && sxy / sxx <= -1.0
}

/// Significant digits printed in `field` ("1.250e-06" → 4, "0.0012" → 2).
fn digits(field: &str) -> i32 {
    let mantissa = field.split(['e', 'E']).next().unwrap_or("");
    mantissa
        .chars()
        .filter(|c| c.is_ascii_digit())
        .skip_while(|&c| c == '0')
        .count() as i32
}

/// The power of ten of the last digit printed in `field` ("0.2" → −1,
/// "1.250e-06" → −9, "1500" → 0).
fn last_place(field: &str) -> i32 {
    let (mantissa, exp) = match field.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (field, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| {
        f.chars().take_while(char::is_ascii_digit).count() as i32
    });
    exp.saturating_sub(decimals)
}

/// How finely a column of x is printed: the most significant digits any
/// field shows (a `%e` format shows the same number everywhere, the
/// shortest round-trip format up to 17 somewhere) and the finest decimal
/// place any shows (a fixed `%.1f` format, as a Dektak export's, the same
/// place everywhere). An x is known to half a unit in the coarser of the
/// two: its `digits`-th significant digit, or the column's `place`.
#[derive(Clone, Copy, Debug)]
struct Precision {
    digits: i32,
    place: i32,
}

impl Precision {
    fn of(fields: &[&str]) -> Precision {
        Precision {
            digits: fields.iter().map(|f| digits(f)).max().unwrap_or(17).max(1),
            place: fields.iter().map(|f| last_place(f)).min().unwrap_or(-300),
        }
    }

    /// Half a unit in the last digit `x` is known to.
    fn resolution(self, x: f64) -> f64 {
        resolution(x, self.digits).max(0.5 * 10f64.powi(self.place.max(-300)))
    }
}

/// Half a unit in the `d`-th significant digit of `x` (0 for x = 0: a
/// printed zero is exact).
fn resolution(x: f64, d: i32) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        0.5 * 10f64.powi(x.abs().log10().floor() as i32 - d + 1)
    }
}

/// The least-squares line through (i, x_i): its intercept and slope.
fn line_fit(x: &[f64]) -> (f64, f64) {
    let n = x.len();
    let mi = (n - 1) as f64 / 2.0;
    let mx = x.iter().sum::<f64>() / n as f64;
    let (mut sii, mut six) = (0.0, 0.0);
    for (i, v) in x.iter().enumerate() {
        let d = i as f64 - mi;
        sii += d * d;
        six += d * (v - mx);
    }
    let dx = six / sii;
    (mx - dx * mi, dx)
}

/// The spacing of uniform x, or the first x off the grid (its index).
fn uniform(x: &[f64], fields: &[&str]) -> Result<f64, (usize, Problem)> {
    let n = x.len();
    let (x0, xl) = (x[0], x[n - 1]);
    let (a, dx) = line_fit(x);
    if xl <= x0 || xl.is_nan() || x0.is_nan() || dx.is_nan() || dx <= 0.0 {
        return Err((
            n - 1,
            Problem::Unknown(format!(
                "x must increase along a line scan: the last x = {xl} is not above the first x = {x0}"
            )),
        ));
    }
    let p = Precision::of(fields);
    // The fitted line's own error: each x is off by at most its
    // resolution, which moves the line by at most twice the largest.
    let line = 2.0 * p.resolution(x0).max(p.resolution(xl));
    for (i, &xi) in x.iter().enumerate() {
        // Off the line, or a step off the spacing (a sample left out
        // moves the line by half a step only).
        let (expected, off) = match i.checked_sub(1).map(|j| x[j]) {
            Some(prev)
                if (xi - prev - dx).abs() > 0.02 * dx + p.resolution(xi) + p.resolution(prev) =>
            {
                (prev + dx, true)
            }
            _ => {
                let e = a + i as f64 * dx;
                (e, (xi - e).abs() > 0.01 * dx + p.resolution(xi) + line)
            }
        };
        if off {
            return Err((
                i,
                Problem::NonUniform {
                    x: xi,
                    expected,
                    spacing: dx,
                },
            ));
        }
    }
    Ok(dx)
}

pub(crate) fn read(
    text: &str,
    scan: Scan<'_>,
    header: &Header,
    opts: &Options,
) -> Result<(Kind, Computed), Failure> {
    let lines = &scan.row_lines;
    let x: Vec<f64> = scan.values.iter().step_by(2).copied().collect();
    let y: Vec<f64> = scan.values.iter().skip(1).step_by(2).copied().collect();
    // x (or q) is never undefined; neither is a PSD's C (checked below).
    let undefined = |v: &[f64]| v.iter().position(|v| v.is_nan()).map(|i| lines[i]);
    if let Some(line) = undefined(&x) {
        return Err((Some(line), Problem::UndefinedValue("x or q")));
    }
    let kind = match hint(&scan.header, header) {
        Some(h) => h,
        None => {
            if looks_like_psd(&x, &y) {
                let all: Vec<&str> = text.split('\n').collect();
                let fields = first_fields(&all, lines);
                if uniform(&x, &fields).is_ok() {
                    return Err((None, Problem::Ambiguous));
                }
                Hint::Psd
            } else {
                Hint::Scan
            }
        }
    };
    if kind == Hint::Psd {
        if let Some(line) = undefined(&y) {
            return Err((Some(line), Problem::UndefinedValue("PSD value")));
        }
        if opts.periodic || opts.pixel_size.is_some() {
            return Err((
                None,
                Problem::Option(
                    "--periodic and --pixel-size do not apply to a PSD table".to_string(),
                ),
            ));
        }
        return psd::table(Dim::Areal, x, y, lines);
    }
    if let Some(p) = opts.pixel_size {
        return Err((
            None,
            Problem::Option(format!(
                "--pixel-size {} does not apply: an x z line scan gives its spacing",
                crate::lengths::typed_length(p)
            )),
        ));
    }
    let n = x.len();
    if n < 4 {
        return Err((
            None,
            Problem::TooFew {
                axis: "the line",
                got: n,
            },
        ));
    }
    let all: Vec<&str> = text.split('\n').collect();
    let fields = first_fields(&all, lines);
    let dx = uniform(&x, &fields).map_err(|(i, p)| (Some(lines[i]), p))?;
    let (sx, sz, note) = scales(&scan.header, header, opts)?;
    let z: Vec<f64> = y.iter().map(|v| v / sz).collect();
    let l = n as f64 * dx / sx;
    let mut c = compute::line(z, l, opts.periodic, opts.detrend_mode()).map_err(|p| (None, p))?;
    c.notes.extend(note);
    Ok((Kind::Line { n, l }, c))
}

/// An `x z` table's x and z units per metre (divide by them) and the notes
/// on the units it assumed: a header naming the columns' units (`x (mm),z
/// (um)`) first, else the labels (`Lateral units`, `Value units`), else
/// `--lateral-unit` for x, else metres, said; heights without a unit take
/// the x unit.
fn scales(
    lines: &[(usize, &str)],
    header: &Header,
    opts: &Options,
) -> Result<(f64, f64, Vec<String>), Failure> {
    use crate::units::{canonical, heights, Source};
    let unit = |u: &str, line: usize| {
        crate::units::per_metre(u).ok_or((Some(line), Problem::UnknownUnit(u.to_string())))
    };
    let (x, z) = match crate::formats::text::colunits::scan_units(lines) {
        Some((line, x, z)) => (x.map(|u| (u, line)), z.map(|u| (u, line))),
        None => (header.x_unit.clone(), header.value_unit.clone()),
    };
    let mut notes = Vec::new();
    let sx = match (&x, opts.lateral_unit) {
        (Some((u, line)), None) => unit(u, *line)?,
        (Some((u, line)), Some(g)) => {
            let per = unit(u, *line)?;
            notes.push(if per != g.per_metre {
                format!(
                    "x read in {} (--lateral-unit; the file says {})",
                    g.name,
                    canonical(per)
                )
            } else {
                format!("x read in {} (--lateral-unit, as the file says)", g.name)
            });
            g.per_metre
        }
        (None, Some(g)) => {
            notes.push(format!("x read in {} (--lateral-unit)", g.name));
            g.per_metre
        }
        (None, None) => {
            notes.push("x read in m (the file names no unit; --lateral-unit to change)".into());
            1.0
        }
    };
    let (sz, note) = match (&z, &x, opts.lateral_unit) {
        (Some((u, l)), _, _) => heights(Source::File(u, *l), opts.height_unit)?,
        (None, Some((u, l)), _) => heights(
            Source::Lateral(u, *l, "the x column's unit"),
            opts.height_unit,
        )?,
        (None, None, Some(g)) if opts.height_unit.is_none() => (
            g.per_metre,
            Some(format!(
                "heights read in {} (the x column's unit; --height-unit to change)",
                g.name
            )),
        ),
        (None, None, _) => heights(Source::Nothing, opts.height_unit)?,
    };
    // --height-unit is confirmed where it does not overrule the file.
    let confirm = opts.height_unit.map(|g| {
        let why = if z.is_some() {
            "--height-unit, as the file says"
        } else {
            "--height-unit; the file names no unit for them"
        };
        format!("heights read in {} ({why})", g.name)
    });
    notes.extend(note.or(confirm));
    Ok((sx, sz, notes))
}

/// The first field of every data row, as written.
fn first_fields<'a>(all: &[&'a str], lines: &[usize]) -> Vec<&'a str> {
    lines
        .iter()
        .map(|&l| {
            let line = all[l - 1];
            let data = line.split('#').next().unwrap_or("");
            data.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
                .find(|f| !f.is_empty())
                .unwrap_or("")
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printed_digits() {
        assert_eq!(digits("1.250e-06"), 4);
        assert_eq!(digits("0.0012"), 2);
        assert_eq!(digits("-12"), 2);
        assert_eq!(digits("0"), 0);
        assert_eq!(resolution(1.25e-6, 4), 0.5e-9);
        assert_eq!(resolution(350.0, 2), 5.0);
        assert_eq!(resolution(0.0, 2), 0.0);
    }

    #[test]
    fn printed_places() {
        assert_eq!(last_place("0.2"), -1);
        assert_eq!(last_place("1499.8"), -1);
        assert_eq!(last_place("1.250e-06"), -9);
        assert_eq!(last_place("1500"), 0);
        assert_eq!(last_place("0.5e-2147483648"), i32::MIN);
        let p = Precision::of(&["0.0", "0.2", "1499.8"]);
        assert_eq!((p.digits, p.place), (5, -1));
        // A fixed-point column is known to its decimal place everywhere.
        assert!((p.resolution(0.2) - 0.05).abs() < 1e-15);
        let p = Precision::of(&["1.250e-06", "1.250e-03"]);
        assert!((p.resolution(1.25e-3) - 0.5e-6).abs() < 1e-20);
    }

    /// x = 0.156 i printed to one decimal, as a Dektak export prints it: the
    /// least-squares spacing (numpy's `polyfit(i, round(0.156 i, 1), 1)`)
    /// is within 0.07 % of the true one, where the end points' (6.1 − 0)/39
    /// is 0.26 % off; the end points' rounding to 5 significant digits used
    /// to refuse the column as not uniform.
    #[test]
    fn least_squares_spacing_of_few_digits() {
        let fields: Vec<String> = (0..40)
            .map(|i| format!("{:.1}", 0.156 * i as f64))
            .collect();
        let refs: Vec<&str> = fields.iter().map(String::as_str).collect();
        let x: Vec<f64> = refs.iter().map(|f| f.parse().unwrap()).collect();
        let dx = uniform(&x, &refs).unwrap();
        assert!((dx - 0.15590056285178233).abs() < 1e-14, "{dx}");
        assert!(((dx - 0.156) / 0.156).abs() < 7e-4);
        let ends = (x[39] - x[0]) / 39.0;
        assert!(((ends - 0.156) / 0.156).abs() > 2.5e-3);
        // A 1500 µm scan of 9600 points printed so (Dektak's own layout).
        let fields: Vec<String> = (0..9600)
            .map(|i| format!("{:.1}", 0.15625 * i as f64 + 0.003))
            .collect();
        let refs: Vec<&str> = fields.iter().map(String::as_str).collect();
        let x: Vec<f64> = refs.iter().map(|f| f.parse().unwrap()).collect();
        let dx = uniform(&x, &refs).unwrap();
        assert!(((dx - 0.15625) / 0.15625).abs() < 1e-6, "{dx}");
        // A sample left out is still found.
        let mut gap = x.clone();
        gap.remove(4000);
        let mut f2 = refs.clone();
        f2.remove(4000);
        assert!(uniform(&gap, &f2).is_err());
    }

    #[test]
    fn psd_looks() {
        let q: Vec<f64> = (0..20).map(|i| 1e5 * 1.5f64.powi(i)).collect();
        let c: Vec<f64> = q.iter().map(|q| q.powf(-3.6)).collect();
        assert!(looks_like_psd(&q, &c));
        let z: Vec<f64> = (0..20).map(|i| (i as f64).sin() * 1e-9).collect();
        assert!(!looks_like_psd(&q, &z));
        // Positive heights in a narrow range.
        let z: Vec<f64> = (0..20).map(|i| 1e-6 + (i as f64).sin() * 1e-8).collect();
        assert!(!looks_like_psd(&q, &z));
    }
}
