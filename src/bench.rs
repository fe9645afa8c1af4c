//! `roughtui bench`: speed against error of every way of computing the
//! initial slopes.
//!
//! Each method is timed over the ψ grid of the committed mpmath reference
//! (`crates/rough-model/tests/data/slopes.csv`, embedded in the binary) and
//! compared with it. Nothing in the table is hard-coded: every row is a
//! measurement of this run.
//!
//! Relative error is |got − want|/|want| over the three slopes (elastic,
//! plastic, total); a reference 0 (|value| < 1e-320) accepts |got| ≤ 1e-300;
//! a reference below 1e-300 accepts any |got| ≤ 1e-300 (the model's contract
//! allows results below 1e-300 to be 0, so their digits are not asked for);
//! ∞ = ∞ is exact; NaN counts as an infinite error.

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

use anyhow::{bail, Context};
use libm::erfc;
use rough_model::slopes::forms;
use rough_model::{Curves, Scene, SceneSpec, Slopes};

use crate::cli::BenchArgs;

/// The mpmath reference, embedded so that `roughtui bench` works anywhere.
pub const REFERENCE_CSV: &str = include_str!("../crates/rough-model/tests/data/slopes.csv");

/// The table's header, fixed by the command's contract.
pub const HEADER: &str = "| method | terms | ns/point | max rel error | worst psi |";

/// √(2/π).
const SQRT_2_OVER_PI: f64 = 0.797_884_560_802_865_4;

/// The load of the finite-difference row, p̄/H.
pub const FINITE_RHO: f64 = 1e-6;

/// One row of the reference: ψ, the exact and the closed-form slopes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefRow {
    pub psi: f64,
    /// Elastic, plastic, total of the exact model.
    pub exact: [f64; 3],
    /// Elastic, plastic, total of the paper's closed form.
    pub closed: [f64; 3],
}

/// Parses the reference CSV: `#` comment lines, a header naming the columns,
/// then one row per ψ. Columns are found by name, so their order may change.
pub fn parse_reference(text: &str) -> anyhow::Result<Vec<RefRow>> {
    let mut lines = text
        .lines()
        .map(str::trim)
        .enumerate()
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (_, header) = lines.next().context("reference: no header line")?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let col = |name: &str| {
        names
            .iter()
            .position(|n| *n == name)
            .with_context(|| format!("reference: no column {name:?}"))
    };
    let idx = [
        col("psi")?,
        col("exact_elastic")?,
        col("exact_plastic")?,
        col("exact_total")?,
        col("closed_elastic")?,
        col("closed_plastic")?,
        col("closed_total")?,
    ];
    let mut rows = Vec::new();
    for (i, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            bail!(
                "reference line {}: {} fields, expected {}",
                i + 1,
                fields.len(),
                names.len()
            );
        }
        let mut v = [0.0; 7];
        for (slot, &j) in v.iter_mut().zip(&idx) {
            *slot = parse_value(fields[j])
                .with_context(|| format!("reference line {}: bad number {:?}", i + 1, fields[j]))?;
        }
        rows.push(RefRow {
            psi: v[0],
            exact: [v[1], v[2], v[3]],
            closed: [v[4], v[5], v[6]],
        });
    }
    if rows.is_empty() {
        bail!("reference: no data rows");
    }
    Ok(rows)
}

fn parse_value(s: &str) -> anyhow::Result<f64> {
    let v = match s.to_ascii_lowercase().as_str() {
        "inf" | "+inf" | "infinity" => f64::INFINITY,
        "-inf" | "-infinity" => f64::NEG_INFINITY,
        t => t.parse::<f64>()?,
    };
    if v.is_nan() {
        bail!("NaN in reference");
    }
    Ok(v)
}

/// Relative error of `got` against the reference value `want` (see the
/// module doc for the conventions at 0, tiny values, ∞ and NaN).
pub fn rel_error(got: f64, want: f64) -> f64 {
    if got.is_nan() {
        return f64::INFINITY;
    }
    if want.is_infinite() {
        return if got == want { 0.0 } else { f64::INFINITY };
    }
    if want == 0.0 {
        return if got.abs() <= 1e-300 {
            0.0
        } else {
            f64::INFINITY
        };
    }
    if want.abs() < 1e-300 && got.abs() <= 1e-300 {
        return 0.0;
    }
    ((got - want) / want).abs()
}

/// Which reference columns a row is compared with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Against {
    Exact,
    Closed,
}

/// A way of computing (elastic, plastic, total) from ψ.
pub struct Method {
    pub name: &'static str,
    pub terms: String,
    pub against: Against,
    pub f: fn(f64) -> [f64; 3],
}

fn arr(s: Slopes) -> [f64; 3] {
    [s.elastic, s.plastic, s.total]
}

/// Every method uses the same limits at ψ = 0 and ψ = ∞, where 1/ψ is not a
/// number the formulas can take.
#[inline(always)]
fn guarded(psi: f64, f: impl FnOnce(f64) -> [f64; 3]) -> [f64; 3] {
    if psi == 0.0 {
        [f64::INFINITY, 0.0, f64::INFINITY]
    } else if psi == f64::INFINITY {
        [0.0, 1.0, 1.0]
    } else {
        f(psi)
    }
}

fn shipped_exact(psi: f64) -> [f64; 3] {
    arr(rough_model::exact(psi))
}

fn shipped_closed(psi: f64) -> [f64; 3] {
    arr(rough_model::closed_form(psi))
}

/// Image sums only (`rough_model::slopes::forms::image`), `N` terms per sum.
fn image<const N: u32>(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(forms::image(psi, N)))
}

/// Fourier sums only (`rough_model::slopes::forms::fourier`), `K` terms per sum.
fn fourier<const K: u32>(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(forms::fourier(psi, K)))
}

/// The closed form exactly as the paper writes it, in plain f64:
/// S_tot = √(2/π) x + x²/(e^{2x²} − 1) + x² erfc(√2 x)/(1 − e^{−2x²}),
/// S_pl = √(2/π) x e^{−x²/2} + x² erfc(x/√2) coth(x²), S_el = S_tot − S_pl.
fn closed_naive(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| {
        let x = 1.0 / psi;
        let u = x * x;
        let s2 = std::f64::consts::SQRT_2;
        let tot = SQRT_2_OVER_PI * x
            + u / ((2.0 * u).exp() - 1.0)
            + u * erfc(s2 * x) / (1.0 - (-2.0 * u).exp());
        let pl = SQRT_2_OVER_PI * x * (-0.5 * u).exp() + u * erfc(x / s2) / u.tanh();
        [tot - pl, pl, tot]
    })
}

/// Slopes as A(ρ)/ρ at ρ = [`FINITE_RHO`].
fn finite(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| {
        // The shipped exact finite-load areas (`rough_model::areas`).
        match rough_model::areas::exact_areas(psi, FINITE_RHO) {
            Ok(a) => [
                a.elastic / FINITE_RHO,
                a.plastic / FINITE_RHO,
                a.total / FINITE_RHO,
            ],
            Err(_) => [f64::NAN; 3],
        }
    })
}

/// Every method in the table, in order.
pub fn methods() -> Vec<Method> {
    let series_row = |name, n: u32, f| Method {
        name,
        terms: format!("{n} per sum"),
        against: Against::Exact,
        f,
    };
    vec![
        Method {
            name: "exact (shipped)",
            terms: "5 per sum (Fourier x²<π, image x²≥π)".into(),
            against: Against::Exact,
            f: shipped_exact,
        },
        series_row("image 1", 1, image::<1>),
        series_row("image 2", 2, image::<2>),
        series_row("image 4", 4, image::<4>),
        series_row("image 8", 8, image::<8>),
        series_row("image 64", 64, image::<64>),
        series_row("fourier 8", 8, fourier::<8>),
        series_row("fourier 64", 64, fourier::<64>),
        Method {
            name: "closed, naive (paper's formula, f64)",
            terms: "closed".into(),
            against: Against::Closed,
            f: closed_naive,
        },
        Method {
            name: "closed (shipped)",
            terms: "closed + series at small x".into(),
            against: Against::Closed,
            f: shipped_closed,
        },
        Method {
            name: "closed (shipped) model error vs exact",
            terms: "closed + series at small x".into(),
            against: Against::Exact,
            f: shipped_closed,
        },
        Method {
            name: "finite load A(ρ)/ρ, ρ = 1e-6",
            terms: "shipped areas".into(),
            against: Against::Exact,
            f: finite,
        },
    ]
}

/// The error of one method over the reference grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStat {
    pub max: f64,
    pub worst_psi: f64,
}

/// Max relative error over the grid and the three slopes; the first ψ where
/// it occurs.
pub fn max_error(m: &Method, reference: &[RefRow]) -> ErrorStat {
    let mut st = ErrorStat {
        max: 0.0,
        worst_psi: reference.first().map_or(f64::NAN, |r| r.psi),
    };
    for r in reference {
        let got = (m.f)(r.psi);
        let want = match m.against {
            Against::Exact => r.exact,
            Against::Closed => r.closed,
        };
        for i in 0..3 {
            let e = rel_error(got[i], want[i]);
            if e > st.max {
                st = ErrorStat {
                    max: e,
                    worst_psi: r.psi,
                };
            }
        }
    }
    st
}

/// Median nanoseconds per point of `f` over `grid`, from `passes` timed
/// passes after one untimed warm-up pass. A pass repeats the grid enough
/// times to last ≥ 200 µs.
pub fn time_method(f: fn(f64) -> [f64; 3], grid: &[f64], passes: u32) -> f64 {
    let run = |reps: usize| {
        let t = Instant::now();
        for _ in 0..reps {
            for &psi in grid {
                black_box(f(black_box(psi)));
            }
        }
        t.elapsed().as_nanos() as f64
    };
    let first = run(1).max(1.0);
    let reps = ((200_000.0 / first).ceil() as usize).clamp(1, 1000);
    let mut samples: Vec<f64> = (0..passes.max(1))
        .map(|_| run(reps) / (reps * grid.len()) as f64)
        .collect();
    median(&mut samples)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The longest run of consecutive grid points (sorted by ψ, ψ > 0) where
/// `m` is within `tol`, as text.
pub fn accurate_range(m: &Method, reference: &[RefRow], tol: f64) -> String {
    let mut rows: Vec<&RefRow> = reference.iter().filter(|r| r.psi > 0.0).collect();
    rows.sort_by(|a, b| a.psi.total_cmp(&b.psi));
    let (mut best, mut start, mut len) = ((0, 0), 0, 0);
    for (i, r) in rows.iter().enumerate() {
        if max_error(m, std::slice::from_ref(*r)).max <= tol {
            if len == 0 {
                start = i;
            }
            len += 1;
            if len > best.1 {
                best = (start, len);
            }
        } else {
            len = 0;
        }
    }
    if best.1 == 0 {
        return "nowhere".into();
    }
    let (a, b) = (rows[best.0].psi, rows[best.0 + best.1 - 1].psi);
    let all = best.1 == rows.len();
    format!(
        "ψ from {} to {}{}",
        fmt_psi(a),
        fmt_psi(b),
        if all { " (all ψ > 0)" } else { "" }
    )
}

/// One measured row of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub name: String,
    pub terms: String,
    pub ns_per_point: f64,
    pub err: ErrorStat,
}

/// Errors print like `3.2e-15`; ∞ as `inf`, exact as `0`.
pub fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e.is_infinite() {
        "inf".into()
    } else {
        format!("{e:.1e}")
    }
}

/// ψ with four significant digits: plain between 1e-3 and 1e4, else `1.5e-8`.
pub fn fmt_psi(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.digits$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        let t = format!("{v:.3e}");
        let (m, e) = t.split_once('e').unwrap_or((&t, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        format!("{m}e{e}")
    }
}

/// The markdown table of `rows`.
pub fn render_table(rows: &[Row]) -> String {
    let mut s = String::new();
    s.push_str(HEADER);
    s.push('\n');
    s.push_str("|---|---|---:|---:|---:|\n");
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.1} | {} | {} |",
            r.name,
            r.terms,
            r.ns_per_point,
            fmt_err(r.err.max),
            fmt_psi(r.err.worst_psi)
        );
    }
    s
}

/// Median µs of one fig2 scene, 4 curves × 400 points, exact model.
fn time_scene(passes: u32) -> anyhow::Result<f64> {
    let state = crate::presets::load("fig2")?;
    let spec = SceneSpec {
        model: rough_model::Model::Exact,
        ..state.scene_spec(Curves::ALL, 400)
    };
    Scene::compute(&spec)?;
    let mut samples: Vec<f64> = (0..passes.max(1) * 4)
        .map(|_| {
            let t = Instant::now();
            let s = Scene::compute(black_box(&spec));
            black_box(s.ok());
            t.elapsed().as_nanos() as f64 / 1e3
        })
        .collect();
    Ok(median(&mut samples))
}

/// Measures every method and renders the table and its notes.
pub fn report(passes: u32) -> anyhow::Result<String> {
    let reference = parse_reference(REFERENCE_CSV)?;
    let grid: Vec<f64> = reference
        .iter()
        .map(|r| r.psi)
        .filter(|&p| p != 0.0)
        .collect();
    let mut rows = Vec::new();
    let ms = methods();
    for m in &ms {
        rows.push(Row {
            name: m.name.to_string(),
            terms: m.terms.clone(),
            ns_per_point: time_method(m.f, &grid, passes),
            err: max_error(m, &reference),
        });
    }
    let mut out = render_table(&rows);
    let lo = grid.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = grid.iter().copied().fold(0.0, f64::max);
    let _ = writeln!(
        out,
        "\n{} reference ψ (mpmath, {} … {}, and ψ = 0 for errors only); ns/point is the \
         median of {} timed passes; errors are the max over elastic, plastic and total.",
        reference.len(),
        fmt_psi(lo),
        fmt_psi(hi),
        passes.max(1)
    );
    let _ = writeln!(
        out,
        "Every method returns the limits at ψ = 0 and ψ = ∞. Image and Fourier rows sum each \
         slope in its own series (S_el by its alternating image sum or its odd-k Fourier sum), \
         in plain f64."
    );
    let _ = writeln!(
        out,
        "Where each method is within 1e-12 (longest run of the sorted grid):"
    );
    for m in &ms {
        let _ = writeln!(
            out,
            "- {}: {}",
            m.name,
            accurate_range(m, &reference, 1e-12)
        );
    }
    if let Some(one) = reference.iter().find(|r| r.psi == 1.0) {
        let c = shipped_closed(1.0);
        let e = (0..3)
            .map(|i| rel_error(c[i], one.exact[i]))
            .fold(0.0, f64::max);
        let _ = writeln!(
            out,
            "closed-form model error at ψ = 1: {} (elastic {:.4} against the exact {:.4}).",
            fmt_err(e),
            c[0],
            one.exact[0]
        );
    }
    // The finite row away from ψ ≲ ρ, where no finite load gives the slope.
    if let Some(fin) = ms.iter().find(|m| m.name.starts_with("finite")) {
        let at = |psi: f64| {
            reference
                .iter()
                .filter(|r| r.psi >= psi)
                .min_by(|a, b| a.psi.total_cmp(&b.psi))
                .map_or(f64::NAN, |r| max_error(fin, std::slice::from_ref(r)).max)
        };
        let _ = writeln!(
            out,
            "finite load: error {} at ψ = 1, {} at ψ = 1e-3, {} at ψ = 1e-5 (truncation ~ (ρ/ψ)², \
             rounding ~ ε/ρ).",
            fmt_err(at(1.0)),
            fmt_err(at(1e-3)),
            fmt_err(at(1e-5)),
        );
    }
    let _ = writeln!(
        out,
        "scene fig2, exact, 4 curves × 400 points: {:.1} µs (median).",
        time_scene(passes)?
    );
    Ok(out)
}

/// `roughtui bench`.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    print!("{}", report(args.passes)?);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_parses_with_corners() {
        let r = parse_reference(REFERENCE_CSV).unwrap();
        assert!(r.len() > 100);
        assert!(r.iter().any(|x| x.psi == 0.0));
        assert!(r.iter().any(|x| x.psi <= 1e-8) && r.iter().any(|x| x.psi >= 1e8));
        let zero = r.iter().find(|x| x.psi == 0.0).unwrap();
        assert_eq!(zero.exact, [f64::INFINITY, 0.0, f64::INFINITY]);
    }

    #[test]
    fn parser_finds_columns_by_name_and_rejects_bad_rows() {
        let t = "# c\npsi,exact_total,exact_plastic,exact_elastic,closed_elastic,closed_plastic,closed_total\n1.0,3,2,1,4,5,6\n";
        let r = parse_reference(t).unwrap();
        assert_eq!(r[0].exact, [1.0, 2.0, 3.0]);
        assert_eq!(r[0].closed, [4.0, 5.0, 6.0]);
        assert!(parse_reference("psi,exact_elastic\n1,2\n").is_err());
        let bad = "psi,exact_elastic,exact_plastic,exact_total,closed_elastic,closed_plastic,closed_total\n1,2,3\n";
        assert!(parse_reference(bad).is_err());
    }

    #[test]
    fn report_measures_every_method() {
        let out = report(1).unwrap();
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines[0], HEADER);
        let rows: Vec<&str> = lines
            .iter()
            .skip(2)
            .take_while(|l| l.starts_with('|'))
            .copied()
            .collect();
        assert_eq!(rows.len(), methods().len());
        for (row, m) in rows.iter().zip(methods()) {
            let cells: Vec<&str> = row.trim_matches('|').split('|').map(str::trim).collect();
            assert_eq!(cells[0], m.name);
            let ns: f64 = cells[2].parse().unwrap();
            assert!(ns > 0.0 && ns.is_finite(), "{row}");
        }
        let shipped = rows.iter().find(|r| r.contains("shipped")).unwrap();
        assert!(shipped.contains("exact"));
    }

    #[test]
    fn psi_format() {
        assert_eq!(fmt_psi(0.55), "0.55");
        assert_eq!(fmt_psi(12.090201005025126), "12.09");
        assert_eq!(fmt_psi(1.998), "1.998");
        assert_eq!(fmt_psi(1e-308), "1e-308");
        assert_eq!(fmt_psi(1.7976931348623157e308), "1.798e308");
        assert_eq!(fmt_psi(2.6023616895101482e-2), "0.02602");
        assert_eq!(fmt_psi(0.0), "0");
        assert_eq!(fmt_err(3.2e-15), "3.2e-15");
    }

    #[test]
    fn rel_error_conventions() {
        assert_eq!(rel_error(f64::INFINITY, f64::INFINITY), 0.0);
        assert_eq!(rel_error(1.0, f64::INFINITY), f64::INFINITY);
        assert_eq!(rel_error(1e-301, 0.0), 0.0);
        assert_eq!(rel_error(1e-200, 0.0), f64::INFINITY);
        assert_eq!(rel_error(0.0, 1e-305), 0.0);
        assert_eq!(rel_error(2e-305, 1e-305), 0.0);
        assert_eq!(rel_error(2e-300, 1e-301), 19.0);
        assert_eq!(rel_error(0.0, 1e-200), 1.0);
        assert_eq!(rel_error(f64::NAN, 1.0), f64::INFINITY);
        assert!((rel_error(1.5, 1.0) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn table_has_exact_header_and_every_row() {
        let rows: Vec<Row> = methods()
            .iter()
            .map(|m| Row {
                name: m.name.into(),
                terms: m.terms.clone(),
                ns_per_point: 12.3,
                err: ErrorStat {
                    max: 3.2e-15,
                    worst_psi: 1.0,
                },
            })
            .collect();
        let t = render_table(&rows);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines[0], HEADER);
        assert_eq!(lines.len(), 2 + rows.len());
        for need in ["shipped", "image 1 ", "image 2 ", "image 4 ", "image 8 "] {
            assert!(t.contains(need), "{need}");
        }
        assert!(t.contains("image 64"));
        assert!(t.contains("fourier 8") && t.contains("fourier 64"));
        assert!(t.contains("naive") && t.contains("model error"));
        assert!(t.contains("finite"));
        assert!(lines[2].contains("| 3.2e-15 |"), "{}", lines[2]);
        for l in &lines[2..] {
            assert_eq!(l.matches('|').count(), 6, "{l}");
        }
    }

    #[test]
    fn methods_agree_where_they_should() {
        let r = parse_reference(REFERENCE_CSV).unwrap();
        let ms = methods();
        let err = |name: &str| max_error(ms.iter().find(|m| m.name == name).unwrap(), &r).max;
        assert!(err("exact (shipped)") <= 1e-12);
        assert!(err("closed (shipped)") <= 1e-12);
        // The closed form is a different model: ~0.106 vs 0.0288 at ψ = 1.
        assert!(err("closed (shipped) model error vs exact") > 1.0);
        // Finite load tends to the slopes where ψ ≫ ρ.
        for psi in [1.0, 0.1] {
            let want = shipped_exact(psi);
            for (g, w) in finite(psi).iter().zip(want) {
                assert!(rel_error(*g, w) < 1e-6, "ψ = {psi}: {g} vs {w}");
            }
        }
        // Fourier and images agree with the exact method on their own sides.
        let f = fourier::<8>(3.0);
        let e = shipped_exact(3.0);
        let i8 = image::<8>(0.1);
        let e2 = shipped_exact(0.1);
        for k in 0..3 {
            assert!(rel_error(f[k], e[k]) < 1e-13);
        }
        for (g, w) in i8.iter().zip(e2) {
            assert!(rel_error(*g, w) < 1e-13);
        }
    }
}
