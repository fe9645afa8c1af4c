//! `roughtui export`: the scene's curves as CSV.

use std::io::Write;

use rough_model::{Curves, Model, Scene, SceneSpec};

use crate::snapshot::State;

/// The CSV header, fixed by the command's contract.
pub const HEADER: &str = "x,psi,hardness_ratio,elastic,plastic,total,persson_elastic";

/// Writes the CSV of `state` at `points` points (both ends included).
pub fn write_csv(
    out: &mut impl Write,
    state: &State,
    points: usize,
    model: Option<Model>,
) -> anyhow::Result<()> {
    let spec = SceneSpec {
        base: state.params,
        sweep: state.sweep,
        size_effect: state.size_effect,
        model: model.unwrap_or(state.model),
        curves: Curves::ALL,
        points,
    };
    let s = Scene::compute(&spec)?;
    writeln!(out, "{HEADER}")?;
    for i in 0..s.x.len() {
        writeln!(
            out,
            "{},{},{},{},{},{},{}",
            s.x[i],
            s.psi[i],
            s.hardness_ratio[i],
            s.elastic[i],
            s.plastic[i],
            s.total[i],
            s.persson_elastic[i]
        )?;
    }
    out.flush()?;
    Ok(())
}
