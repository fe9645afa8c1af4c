//! The contact solver's rows of `roughtui bench`.
//!
//! - One load: fig2's surface at ζ = 32 (a 256² grid) and ζ = 64 (512²),
//!   cell 1, p̄ = 0.01 H_use (the contact view's first), the surface
//!   synthesised and the load solved from a cold start, as the view does
//!   for its first result. Targets: 0.5 s and 2 s.
//! - The curve: fig2's whole 13-load curve at ζ = 128 on its cell of one
//!   longest wavelength and 1024² (`export --preset fig2 --view contact
//!   --seed 1 --cell 1 --contact-grid 1024`), each load started from the
//!   last one's answer, every pass on all cores. Target 30 s; before this
//!   solver, 359 s and 5 738 iterations.

use std::fmt::Write as _;
use std::time::Instant;

use rough_model::Axis;

use crate::contact::scene::SceneKey;
use crate::contact::{Grid, Sampling, DEFAULT_SEED};

/// One grid's measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct SolverTime {
    pub zeta: f64,
    pub n: usize,
    /// Median seconds of surface + solve.
    pub seconds: f64,
    /// Of which the surface's synthesis (median, s).
    pub surface_seconds: f64,
    pub iterations: usize,
    pub residual: f64,
    pub area: f64,
    pub plastic_share: f64,
    /// The target for this grid, s.
    pub target: f64,
}

/// The load solved, p̄/H_use.
pub const LOAD: f64 = 0.01;

/// The curve's target, s.
pub const CURVE_TARGET: f64 = 30.0;
/// The curve before the solver kept its directions through releases and ran
/// on all cores (same machine, same command): seconds and iterations.
pub const CURVE_BEFORE: (f64, usize) = (359.0, 5738);

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// fig2 at `zeta` on a cell of one longest wavelength.
fn key(zeta: f64, grid: Grid) -> anyhow::Result<SceneKey> {
    let mut state = crate::presets::load("fig2")?;
    state.params = state
        .params
        .with(Axis::Zeta, zeta)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let sampling = Sampling {
        cell: 1,
        grid,
        ..Sampling::default()
    };
    SceneKey::with(&state, DEFAULT_SEED, &sampling)
}

/// fig2 at `zeta`, `samples` cold solves.
pub fn time_solver(zeta: f64, samples: usize, target: f64) -> anyhow::Result<SolverTime> {
    let key = key(zeta, Grid::PerWavelength(8))?;
    let (mut total, mut surface, mut last) = (vec![], vec![], None);
    for _ in 0..samples.max(1) {
        let t = Instant::now();
        let mut c = key.build()?;
        let built = t.elapsed().as_secs_f64();
        let h = key.hardness();
        let r = c.solve(LOAD * h, h, &rough_contact::Options::default())?;
        total.push(t.elapsed().as_secs_f64());
        surface.push(built);
        last = Some(r);
    }
    let r = last.ok_or_else(|| anyhow::anyhow!("no sample"))?;
    Ok(SolverTime {
        zeta,
        n: key.n,
        seconds: median(total),
        surface_seconds: median(surface),
        iterations: r.iterations,
        residual: r.residual,
        area: r.area,
        plastic_share: if r.area > 0.0 {
            r.plastic_area / r.area
        } else {
            0.0
        },
        target,
    })
}

/// The whole curve's measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveTime {
    pub zeta: f64,
    pub n: usize,
    /// Wall seconds, surface and 13 loads.
    pub seconds: f64,
    /// CPU seconds of the process meanwhile (all threads), if known.
    pub cpu_seconds: Option<f64>,
    pub iterations: usize,
    /// The 1-minute load average before the run, if known.
    pub load_average: Option<f64>,
    /// Areas at p̄ = 0.01 H: total and plastic.
    pub area: f64,
    pub plastic: f64,
}

/// fig2's 13 loads at `zeta` on an `n`² grid, cell 1.
pub fn time_curve(zeta: f64, n: usize) -> anyhow::Result<CurveTime> {
    let key = key(zeta, Grid::Side(n))?;
    let load_average = load_average();
    let cpu0 = cpu_seconds();
    let t = Instant::now();
    let mut c = key.build()?;
    let h = key.hardness();
    let (mut iterations, mut at) = (0, None);
    for p in crate::contact::loads(crate::contact::DEFAULT_LOADS) {
        let r = c.solve(p * h, h, &rough_contact::Options::default())?;
        iterations += r.iterations;
        if p == LOAD {
            at = Some(r);
        }
    }
    let seconds = t.elapsed().as_secs_f64();
    let r = at.ok_or_else(|| anyhow::anyhow!("no load at p̄ = {LOAD} H"))?;
    Ok(CurveTime {
        zeta,
        n: key.n,
        seconds,
        cpu_seconds: cpu0.zip(cpu_seconds()).map(|(a, b)| b - a),
        iterations,
        load_average,
        area: r.area,
        plastic: r.plastic_area,
    })
}

/// The process's user + system CPU seconds (Linux's /proc/self/stat).
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command's closing parenthesis; utime and stime are
    // the 14th and 15th of the line.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// The 1-minute load average (Linux's /proc/loadavg).
pub(crate) fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

/// The rows as the bench prints them.
pub fn report(rows: &[SolverTime], curve: Option<&CurveTime>) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\ncontact solver (fig2's surface, cell 1, seed {DEFAULT_SEED}, p̄ = {LOAD} H, cold start, \
         median of 3; memory about ten N² arrays of f64):"
    );
    let _ = writeln!(
        out,
        "| grid | ζ | s | surface s | iterations | residual | A/A0 | plastic share | target s | met |"
    );
    let _ = writeln!(out, "|---|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let _ = writeln!(
            out,
            "| {n}² | {} | {:.3} | {:.3} | {} | {:.1e} | {:.4} | {:.4} | {} | {} |",
            r.zeta,
            r.seconds,
            r.surface_seconds,
            r.iterations,
            r.residual,
            r.area,
            r.plastic_share,
            r.target,
            if r.seconds <= r.target { "yes" } else { "no" },
            n = r.n,
        );
    }
    if let Some(c) = curve {
        let cores = rough_contact::threads();
        let _ = writeln!(
            out,
            "\nfig2's 13-load curve (ζ = {}, cell 1, {n}², seed {DEFAULT_SEED}; `export --view \
             contact --cell 1 --contact-grid {n}`), {cores} thread{}, load average {} before:",
            c.zeta,
            if cores == 1 { "" } else { "s" },
            c.load_average
                .map_or("unknown".into(), |l| format!("{l:.1}")),
            n = c.n,
        );
        let _ = writeln!(
            out,
            "| | wall s | CPU s | iterations | A/A0 at 0.01 H | plastic | target s | met |"
        );
        let _ = writeln!(out, "|---|---|---|---|---|---|---|---|");
        let _ = writeln!(
            out,
            "| before | {:.0} | | {} | | | | |",
            CURVE_BEFORE.0, CURVE_BEFORE.1
        );
        let _ = writeln!(
            out,
            "| now | {:.1} | {} | {} | {:.6} | {:.6} | {CURVE_TARGET} | {} |",
            c.seconds,
            c.cpu_seconds.map_or(String::new(), |s| format!("{s:.1}")),
            c.iterations,
            c.area,
            c.plastic,
            if c.seconds <= CURVE_TARGET {
                "yes"
            } else {
                "no"
            },
        );
    }
    out
}

/// Both grids and, with `curve`, the 13-load curve.
pub fn run(samples: usize, curve: bool) -> anyhow::Result<String> {
    let rows = [(32.0, 0.5), (64.0, 2.0)]
        .into_iter()
        .map(|(z, target)| time_solver(z, samples, target))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let curve = curve.then(|| time_curve(128.0, 1024)).transpose()?;
    Ok(report(&rows, curve.as_ref()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rows_measure_the_view_first_result_and_a_curve() {
        // ζ = 4 (32²) keeps the debug build quick; the row's fields are
        // the solve's own.
        let t = time_solver(4.0, 1, 0.5).unwrap();
        assert_eq!(t.n, 32);
        assert!(t.seconds > 0.0 && t.surface_seconds <= t.seconds);
        assert!(t.iterations > 0 && t.residual <= 1e-8);
        assert!(t.area > 0.0 && t.area < 1.0);
        let c = time_curve(4.0, 64).unwrap();
        assert_eq!(c.n, 64);
        assert!(c.iterations > 13 && c.area > 0.0 && c.plastic <= c.area);
        let out = report(&[t], Some(&c));
        assert!(out.contains("| 32² | 4 | "), "{out}");
        assert!(out.contains("| before | 359 | | 5738 |"), "{out}");
        assert!(
            out.contains("fig2's 13-load curve (ζ = 4, cell 1, 64²"),
            "{out}"
        );
    }
}
