//! The contact solver's row of `roughtui bench`: fig2's surface at ζ = 32
//! (a 256² grid) and ζ = 64 (512²), one load p̄ = 0.01 H_use (the contact
//! view's first), the surface synthesised and the load solved from a cold
//! start, as the view does for its first result. Targets: 0.5 s and 2 s.

use std::fmt::Write as _;
use std::time::Instant;

use rough_model::Axis;

use crate::contact::scene::SceneKey;
use crate::contact::DEFAULT_SEED;

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

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// fig2 at `zeta`, `samples` cold solves.
pub fn time_solver(zeta: f64, samples: usize, target: f64) -> anyhow::Result<SolverTime> {
    let mut state = crate::presets::load("fig2")?;
    state.params = state
        .params
        .with(Axis::Zeta, zeta)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let key = SceneKey::of(&state, DEFAULT_SEED)?;
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

/// The rows as the bench prints them.
pub fn report(rows: &[SolverTime]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\ncontact solver (fig2's surface, seed {DEFAULT_SEED}, p̄ = {LOAD} H, cold start, \
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
    out
}

/// Both grids.
pub fn run(samples: usize) -> anyhow::Result<String> {
    let rows = [(32.0, 0.5), (64.0, 2.0)]
        .into_iter()
        .map(|(z, target)| time_solver(z, samples, target))
        .collect::<anyhow::Result<Vec<_>>>()?;
    Ok(report(&rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_row_measures_the_view_first_result() {
        // ζ = 4 (32²) keeps the debug build quick; the row's fields are
        // the solve's own.
        let t = time_solver(4.0, 1, 0.5).unwrap();
        assert_eq!(t.n, 32);
        assert!(t.seconds > 0.0 && t.surface_seconds <= t.seconds);
        assert!(t.iterations > 0 && t.residual <= 1e-8);
        assert!(t.area > 0.0 && t.area < 1.0);
        let out = report(&[t]);
        assert!(out.contains("| 32² | 4 | "), "{out}");
    }
}
