//! `roughtui bench`: speed against error of every way of computing the
//! initial slopes.
//!
//! Each method of [`rough_study::compare`] is timed over the ψ grid of the
//! mpmath reference ([`rough_study::SLOPES_CSV`], embedded in the binary) and
//! compared with it under [`rough_study::rel_err`]. Nothing in the table is
//! hard-coded: every row is a measurement of this run. Timings of whole
//! computations follow the table, one line each ([`timings`]).

pub mod contact;
pub mod measured;
pub mod plan;
mod table;
mod targets;

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

use rough_model::{Curves, Scene, SceneSpec};

use rough_study::compare::{accurate_range, max_error, methods, shipped_closed};
use rough_study::{rel_err, slopes_reference, SLOPES_CSV};

use crate::cli::BenchArgs;
use crate::physical::short_number;
pub use table::{fmt_err, render_table, Row, HEADER};

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

/// Median µs of `samples` calls of `f` after one untimed call.
fn time_call<T>(samples: u32, mut f: impl FnMut() -> T) -> f64 {
    black_box(f());
    let mut v: Vec<f64> = (0..samples.max(1))
        .map(|_| {
            let t = Instant::now();
            black_box(f());
            t.elapsed().as_nanos() as f64 / 1e3
        })
        .collect();
    median(&mut v)
}

/// Median µs of one fig2 scene, 4 curves × 400 points, exact model.
fn time_scene(passes: u32) -> anyhow::Result<f64> {
    let state = crate::presets::load("fig2")?;
    let spec = SceneSpec {
        model: rough_model::Model::Exact,
        ..state.scene_spec(Curves::ALL, 400)
    };
    Scene::compute(&spec)?;
    Ok(time_call(passes.max(1) * 4, || {
        Scene::compute(black_box(&spec)).ok()
    }))
}

/// The lines after the table that time whole computations, one each.
fn timings(passes: u32) -> anyhow::Result<Vec<String>> {
    Ok(vec![format!(
        "scene fig2, exact, 4 curves × 400 points: {:.1} µs (median).",
        time_scene(passes)?
    )])
}

/// Measures every method and renders the table and its notes, then the
/// speed targets ([`targets::table`]; with `whole_commands`, also
/// `roughtui export` as a command of this executable against the NumPy
/// peer).
pub fn report(passes: u32, whole_commands: bool) -> anyhow::Result<String> {
    let (mut out, rows) = slopes(passes)?;
    out.push_str(&speed_targets(&rows, passes, whole_commands)?);
    Ok(out)
}

/// The speed targets' table under its title.
fn speed_targets(rows: &[Row], passes: u32, whole_commands: bool) -> anyhow::Result<String> {
    Ok(format!(
        "\nSpeed targets, measured in this run (times are wall clock on a machine that may \
         be shared: compare the ratios):\n{}",
        targets::table(rows, passes, whole_commands)?
    ))
}

/// The slopes' table, its notes and the scene's timing; the table's rows.
fn slopes(passes: u32) -> anyhow::Result<(String, Vec<Row>)> {
    let reference = slopes_reference(SLOPES_CSV)?;
    let grid: Vec<f64> = reference
        .iter()
        .map(|r| r.psi)
        .filter(|&p| p != 0.0)
        .collect();
    let ms = methods();
    let rows: Vec<Row> = ms
        .iter()
        .map(|m| Row {
            name: m.name.to_string(),
            terms: m.terms.clone(),
            ns_per_point: time_method(m.f, &grid, passes),
            err: max_error(m, &reference),
        })
        .collect();
    let mut out = render_table(&rows);
    let lo = grid.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = grid.iter().copied().fold(0.0, f64::max);
    let _ = writeln!(
        out,
        "\n{} reference ψ (mpmath, {} … {}, and ψ = 0 for errors only); ns/point is the \
         median of {} timed passes; errors are the max over elastic, plastic and total.",
        reference.len(),
        short_number(lo),
        short_number(hi),
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
        let range = accurate_range(m, &reference, 1e-12);
        let _ = writeln!(out, "- {}: {}", m.name, table::fmt_range(range));
    }
    if let Some(one) = reference.iter().find(|r| r.psi == 1.0) {
        let c = shipped_closed(1.0);
        let e = (0..3)
            .map(|i| rel_err(c[i], one.exact[i]))
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
    for line in timings(passes)? {
        let _ = writeln!(out, "{line}");
    }
    Ok((out, rows))
}

/// ζ and H0/E steps timed per measured surface.
const SURFACE_STEPS: usize = 41;

/// `roughtui bench`: first what it will run and about how long that takes
/// ([`plan`]); then the slopes table and timings, the contact solver, its
/// 13-load curve (not with `--quick`) and a synthetic 1024 × 1024 measured
/// surface; with `--surface FILE`, that file instead. With `check_only`
/// (`ROUGHTUI_CHECK_ONLY=1`) it says what it would run, reads the file it
/// names, and stops.
pub fn run(args: &BenchArgs, check_only: bool) -> anyhow::Result<()> {
    let start = Instant::now();
    let reference = slopes_reference(SLOPES_CSV)?;
    print!("{}", plan::text(args, methods().len(), reference.len()));
    if !check_only {
        if let Some(l) = contact::load_average() {
            println!("The load average is {l:.1} now.");
        }
    }
    // The plan shows before the work starts, even through a pipe.
    std::io::Write::flush(&mut std::io::stdout())?;
    if let Some(path) = &args.surface {
        let options = args.surface_options();
        if check_only {
            crate::surface::SurfaceSource::read(path, options)?;
            return Ok(());
        }
        let t = measured::time_file(path, options, SURFACE_STEPS)?;
        print!(
            "{}",
            measured::report(&path.display().to_string(), &t, SURFACE_STEPS)
        );
        return Ok(());
    }
    if check_only {
        return Ok(());
    }
    println!();
    // Each part's seconds, said at the end beside the plan's.
    let mut took = Vec::new();
    let mut part = Instant::now();
    let mut lap = |took: &mut Vec<f64>| {
        took.push(part.elapsed().as_secs_f64());
        part = Instant::now();
    };
    let (text, rows) = slopes(args.passes)?;
    print!("{text}");
    lap(&mut took);
    print!("{}", speed_targets(&rows, args.passes, true)?);
    lap(&mut took);
    print!("{}", contact::run(3, !args.quick)?);
    lap(&mut took);
    let t = measured::time_synthetic(1024, SURFACE_STEPS)?;
    print!(
        "{}",
        measured::report("synthetic 1024 × 1024 map", &t, SURFACE_STEPS)
    );
    lap(&mut took);
    let parts: Vec<String> = ["slopes", "targets", "contact solver", "map"]
        .iter()
        .zip(&took)
        .map(|(what, s)| match s {
            s if *s < 1.0 => format!("{what} {s:.2} s"),
            s => format!("{what} {s:.1} s"),
        })
        .collect();
    println!(
        "\nroughtui bench took {:.1} s ({}){}.",
        start.elapsed().as_secs_f64(),
        parts.join(", "),
        contact::load_average().map_or(String::new(), |l| format!(
            "; the load average is {l:.1} now"
        ))
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_measures_every_method() {
        let out = report(1, false).unwrap();
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
        assert!(out.contains("scene fig2, exact, 4 curves × 400 points: "));
        let targets: Vec<&str> = out
            .lines()
            .skip_while(|l| !l.starts_with("| target |"))
            .skip(2)
            .collect();
        assert_eq!(targets.len(), 4, "{out}");
        for (t, want) in targets.iter().zip([
            "| closed (shipped) / exact (shipped), ns/point |",
            "| regime map 200 × 60, fig2",
            "| regime map 200 × 60, fig4",
            "| slopes view, which cells each curve covers |",
        ]) {
            assert!(t.starts_with(want), "{t}");
            assert!(t.ends_with("| yes |") || t.ends_with("| no |"), "{t}");
        }
    }
}
