//! One computation repeated, for instruction counts: `scripts/bench_callgrind.sh`
//! runs this under `valgrind --tool=callgrind` once per WHAT and subtracts
//! the `none` run, so that the counts are those of the computation alone
//! (all threads summed). Instruction counts do not depend on the machine's
//! load, unlike the times of `roughtui bench`.
//!
//! ```sh
//! cargo build --release --example cost
//! target/release/examples/cost WHAT N
//! ```
//!
//! WHAT: `none`, `exact` or `closed` (N passes over the 1250 reference ψ of
//! `roughtui bench`), `map-fig2` or `map-fig4` (N regime maps of 200 × 60
//! cells), `export-fig2` (N CSV exports of fig2 at 200 000 points into
//! memory).

use std::hint::black_box;

use rough_study::{slopes_reference, SLOPES_CSV};
use roughtui::figure::{MapSpec, RegimeMap};
use roughtui::presets;

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let (what, n) = match args.as_slice() {
        [_, what, n] => (what.as_str(), n.parse::<usize>()?),
        _ => anyhow::bail!("usage: cost WHAT N (see the source's doc)"),
    };
    let grid: Vec<f64> = slopes_reference(SLOPES_CSV)?
        .iter()
        .map(|r| r.psi)
        .filter(|&p| p != 0.0)
        .collect();
    let map = |preset: &str| -> anyhow::Result<MapSpec> {
        Ok(MapSpec::of(&presets::load(preset)?, (200, 60), None)?)
    };
    match what {
        "none" => {
            black_box(&grid);
        }
        "exact" | "closed" => {
            let f: fn(f64) -> rough_model::Slopes = if what == "exact" {
                |p| rough_model::exact(p)
            } else {
                |p| rough_model::closed_form(p)
            };
            for _ in 0..n {
                for &psi in &grid {
                    black_box(f(black_box(psi)));
                }
            }
        }
        "map-fig2" | "map-fig4" => {
            let spec = map(&what[4..])?;
            for _ in 0..n {
                black_box(RegimeMap::compute(black_box(&spec)));
            }
        }
        "export-fig2" => {
            let state = presets::load("fig2")?;
            for _ in 0..n {
                let mut out = Vec::with_capacity(24 << 20);
                roughtui::export::write_csv(&mut out, &state, 200_000)?;
                black_box(out);
            }
        }
        _ => anyhow::bail!("unknown WHAT {what}"),
    }
    println!("points per pass: {}", grid.len());
    Ok(())
}
