//! `roughtui export --view contact-slopes`: the simulation's initial slopes
//! against ζ beside the theory's (`crate::contact::slopes`), as CSV or as
//! the paper's figure with the simulation's points.

use std::io::Write;

use rough_model::{slopes, Axis, Sweep};

use super::contact::{hardness_short, spec_of};
use crate::cli::{ExportArgs, FormatArg};
use crate::contact::slopes::{rows, write};
use crate::contact::Spec;
use crate::figure::scene_text::full_lines_of;
use crate::figure::{self, ContactSlopes};
use crate::scene::State;

/// Points along the theory's curves in the picture.
const THEORY_POINTS: usize = 200;

/// What the view spans, in full.
fn span(state: &State) -> String {
    format!(
        "contact-slopes = zeta = 1, 2, 4, …, 128 (a measured map: those it resolves), each on \
         its own grid, initial slopes {}·dA/dpbar/A0",
        state.hardness_name()
    )
}

/// `roughtui export --view contact-slopes`.
pub fn export(args: &ExportArgs, out: &mut impl Write) -> anyhow::Result<()> {
    super::refuse_given(
        "contact-slopes",
        "it fits the scene's areas at five light loads p̄/(E* h′) = 0.5 … 8·10⁻³ at ζ = 1, 2, \
         …, 128 (--seed and --seeds pick the surfaces)",
        &[
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
            (args.sweep.is_some(), "--sweep"),
            (args.points.is_some(), "--points"),
            (args.simulate.load_scale.is_some(), "--load-scale"),
        ],
    )?;
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    match args.format {
        FormatArg::Csv => {
            let scene = full_lines_of(&state, "contact-slopes", span(&state));
            write(out, &state, &spec, &scene, args.cluster.part)
        }
        FormatArg::Svg => {
            let svg = figure::render_contact_slopes(&state, &picture(&state, &spec)?)?;
            out.write_all(svg.as_bytes())?;
            out.flush()?;
            Ok(())
        }
    }
}

/// The picture's numbers: the simulation's slopes, the theory's along the
/// scene's ζ sweep (1 … 1e4 where it sweeps something else).
pub fn picture(state: &State, spec: &Spec) -> anyhow::Result<ContactSlopes> {
    let (sim, rows) = rows(state, spec)?;
    let n = sim.contact.n();
    let stats: Vec<_> = rows.iter().map(|r| r.stats()).collect();
    let zeta = rows.iter().map(|r| r.zeta).collect();
    let slope = [0, 1, 2].map(|k| stats.iter().map(|s| s[k].mean).collect());
    let sd = [0, 1, 2].map(|k| stats.iter().map(|s| s[k].sd).collect());
    Ok(picture_of(
        state,
        spec,
        sim.measured.is_some().then_some(n),
        zeta,
        slope,
        sd,
    ))
}

/// The picture's numbers from the simulation's slopes (elastic, plastic,
/// total) and their sds at each ζ — solved here, or merged from parts —
/// with the theory's curves; `measured`, the map's grid side.
pub fn picture_of(
    state: &State,
    spec: &Spec,
    measured: Option<usize>,
    zeta: Vec<f64>,
    slope: [Vec<f64>; 3],
    sd: [Vec<f64>; 3],
) -> ContactSlopes {
    let surface = match measured {
        Some(n) => format!("{n}×{n} nodes of the measured map"),
        None => format!(
            "a cell of {}, {}",
            spec.sampling.cell_words(),
            spec.seeds.words()
        ),
    };
    let mut d = ContactSlopes {
        surface,
        hardness: hardness_short(state, spec.sampling.hardness),
        zeta,
        slope,
        sd: (spec.seeds.count > 1).then_some(sd),
        ..ContactSlopes::default()
    };
    let (from, to) = match state.sweep.axis() {
        Axis::Zeta => (state.sweep.from(), state.sweep.to()),
        _ => (1.0, 1e4),
    };
    let to = to.min(state.roughness().zeta_max());
    let Ok(sweep) = Sweep::new(Axis::Zeta, from, to.max(from * 1.0001)) else {
        return d;
    };
    for z in sweep.points(THEORY_POINTS) {
        let Ok(p) = state.params.with(Axis::Zeta, z) else {
            continue;
        };
        let psi = state
            .roughness()
            .surface(&p, state.moments)
            .indices
            .psi_in_use(state.size_effect);
        let s = slopes(state.model, psi);
        d.theory_zeta.push(z);
        d.theory[0].push(s.elastic);
        d.theory[1].push(s.plastic);
        d.theory[2].push(s.total);
        d.persson
            .push((2.0 / std::f64::consts::PI).sqrt() / psi.to_f64());
    }
    d
}
