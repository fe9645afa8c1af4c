//! `roughtui export --view contact|contact-sweep|contact-map`: the scene's
//! surface solved by the boundary-element contact (`crate::contact`), as
//! CSV (the scene in `#` lines laid out as every other view's, then what
//! the simulation adds) or as pictures drawn by `crate::figure`.

use std::io::Write;

use anyhow::bail;
use rough_model::{areas, Axis};

use crate::cli::{ExportArgs, FormatArg};
use crate::contact::scene::{classify, SceneKey};
use crate::contact::{
    self, load_rows, sweep_rows, Simulation, DEFAULT_LOADS, DEFAULT_SEED, MAX_LOADS, SWEEP_LOAD,
};
use crate::figure::scene_text::full_lines_of;
use crate::figure::{self, ContactLoads, ContactMap, ContactSweep};
use crate::physical::csv_number;
use crate::scene::State;

/// The contact view's CSV header.
pub const CONTACT_HEADER: &str = "p_over_h,area,elastic_area,plastic_area,mean_gap,iterations,\
residual,theory_area,theory_elastic_area,theory_plastic_area";
/// The ζ sweep's CSV header.
pub const SWEEP_HEADER: &str = "zeta,p_over_h,plastic_share,theory_plastic_share,area,\
theory_area,grid,iterations,residual";

/// `roughtui export --view contact|contact-sweep`.
pub fn export(args: &ExportArgs, out: &mut impl Write) -> anyhow::Result<()> {
    if args.view == crate::cli::ViewArg::ContactMap {
        return export_map(args, out);
    }
    let sweep = args.view == crate::cli::ViewArg::ContactSweep;
    let name = if sweep { "contact-sweep" } else { "contact" };
    for (given, opt) in [
        (args.grid.is_some(), "--grid"),
        (args.map_y.is_some(), "--map-y"),
        (args.sweep.is_some(), "--sweep"),
        (sweep && args.points.is_some(), "--points"),
    ] {
        if given {
            bail!(
                "{opt} does not apply to --view {name}: it solves the scene's surface at \
                 {} (--seed picks the surface)",
                if sweep {
                    "ζ = 1, 2, …, 128 and p̄/H = 0.01"
                } else {
                    "--points loads from 1e-3 H to H"
                }
            );
        }
    }
    let points = args.points.unwrap_or(DEFAULT_LOADS);
    if points > MAX_LOADS {
        bail!("--points {points} is too many for --view contact: at most {MAX_LOADS} loads (each is a solution)");
    }
    let state = super::state_of(args)?;
    let seed = args.seed.or(state.seed).unwrap_or(DEFAULT_SEED);
    let text = match (args.format, sweep) {
        (FormatArg::Csv, false) => contact_csv(&state, points, seed)?,
        (FormatArg::Csv, true) => sweep_csv(&state, seed)?,
        (FormatArg::Svg, false) => contact_svg(&state, points, seed)?,
        (FormatArg::Svg, true) => sweep_svg(&state, seed)?,
    };
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The solved surface in words, for the pictures ("128 × 128 nodes, seed
/// 1") and for the `#` lines (how it was made, every number).
fn surface_words(sim: &Simulation) -> (String, String) {
    let n = sim.contact.n();
    match &sim.measured {
        Some(m) => (
            format!("{n}×{n} nodes of the measured map"),
            format!("{m}, wavevectors q ≤ zeta q0 kept"),
        ),
        None => (
            format!("{n}×{n} nodes, seed {}", sim.seed),
            format!(
                "periodic {n} × {n} grid of side 2π/q0, power-law Gaussian surface, seed {}",
                sim.seed
            ),
        ),
    }
}

/// What the simulation adds to the scene's `#` lines.
fn simulation_lines(state: &State, sim: &Simulation) -> Vec<String> {
    let psi = if state.size_effect {
        "psi_star"
    } else {
        "psi_p"
    };
    let h = state.hardness_name();
    vec![
        format!(
            "simulation = elastic–perfectly-plastic BEM (rough-contact), pressures capped at \
             hardness_in_use_over_e = {} ({h}/E*); the surface rescaled to rms_slope = {} \
             (the scene's sqrt(2 m2))",
            csv_number::format(sim.hardness),
            csv_number::format(sim.rms_slope)
        ),
        format!(
            "theory = the {} model's finite-load areas at the index in use {psi} = {}",
            state.model.label(),
            csv_number::format(sim.psi.to_f64())
        ),
        "units: areas as fractions of A0, mean_gap in m; residual: rms violation of the \
         contact conditions over h_rms"
            .to_string(),
    ]
}

fn comment_lines(out: &mut String, lines: &[String]) {
    for l in lines {
        out.push_str("# ");
        out.push_str(l);
        out.push('\n');
    }
}

fn push_row(buf: &mut String, fields: &[f64]) {
    for (k, v) in fields.iter().enumerate() {
        if k > 0 {
            buf.push(',');
        }
        csv_number::push(buf, *v);
    }
    buf.push('\n');
}

/// The contact view as CSV.
fn contact_csv(state: &State, points: usize, seed: u64) -> anyhow::Result<String> {
    let (sim, rows) = load_rows(state, points, seed)?;
    let loads: Vec<f64> = rows.iter().map(|r| r.p_over_h).collect();
    let (_, made) = surface_words(&sim);
    let mut out = String::new();
    comment_lines(
        &mut out,
        &full_lines_of(state, "contact", figure::contact_span(state, &loads, &made)),
    );
    comment_lines(&mut out, &simulation_lines(state, &sim));
    out.push_str(CONTACT_HEADER);
    out.push('\n');
    for r in &rows {
        push_row(
            &mut out,
            &[
                r.p_over_h,
                r.sim.area,
                r.sim.elastic_area,
                r.sim.plastic_area,
                r.sim.mean_gap,
                r.sim.iterations as f64,
                r.sim.residual,
                r.theory.total,
                r.theory.elastic,
                r.theory.plastic,
            ],
        );
    }
    Ok(out)
}

/// The ζ sweep as CSV.
fn sweep_csv(state: &State, seed: u64) -> anyhow::Result<String> {
    let (sim, rows) = sweep_rows(state, seed)?;
    let zetas: Vec<f64> = rows.iter().map(|r| r.zeta).collect();
    let (_, made) = surface_words(&sim);
    let mut out = String::new();
    let span = figure::sweep_span(state, &zetas, SWEEP_LOAD, &made);
    comment_lines(&mut out, &full_lines_of(state, "contact-sweep", span));
    comment_lines(&mut out, &simulation_lines(state, &sim));
    out.push_str(
        "# the simulation and theory lines above are the first zeta's; each zeta solves its \
         own grid (column grid) and hardness\n",
    );
    out.push_str(SWEEP_HEADER);
    out.push('\n');
    for r in &rows {
        push_row(
            &mut out,
            &[
                r.zeta,
                SWEEP_LOAD,
                r.share(),
                r.theory_share(),
                r.sim.area,
                r.theory.total,
                r.grid as f64,
                r.sim.iterations as f64,
                r.sim.residual,
            ],
        );
    }
    Ok(out)
}

/// `n` loads log-spaced from `from` to `to`.
fn log_points(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from * (to / from).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The contact view as a picture: the simulated areas at the loads, the
/// theory's at 120 loads between the same ends.
fn contact_svg(state: &State, points: usize, seed: u64) -> anyhow::Result<String> {
    let (sim, rows) = load_rows(state, points, seed)?;
    let (surface, _) = surface_words(&sim);
    let p_over_h: Vec<f64> = rows.iter().map(|r| r.p_over_h).collect();
    let (from, to) = (p_over_h[0], p_over_h[p_over_h.len() - 1]);
    let mut d = ContactLoads {
        surface,
        psi: sim.psi.to_f64(),
        area: [
            rows.iter().map(|r| r.sim.area).collect(),
            rows.iter().map(|r| r.sim.elastic_area).collect(),
            rows.iter().map(|r| r.sim.plastic_area).collect(),
        ],
        p_over_h,
        ..ContactLoads::default()
    };
    for x in log_points(from, to, 120) {
        if let Ok(a) = areas(sim.model, sim.psi, x) {
            d.theory_p.push(x);
            d.theory[0].push(a.total);
            d.theory[1].push(a.elastic);
            d.theory[2].push(a.plastic);
        }
    }
    figure::render_contact(state, &d)
}

/// The ζ sweep as a picture: the simulated shares at each solved ζ, the
/// theory's at 100 ζ between the same ends.
fn sweep_svg(state: &State, seed: u64) -> anyhow::Result<String> {
    let (sim, rows) = sweep_rows(state, seed)?;
    let (surface, _) = surface_words(&sim);
    let surface = match &sim.measured {
        Some(_) => "the measured map".to_string(),
        None => surface
            .split_once(", ")
            .map_or(surface.clone(), |(_, s)| s.to_string()),
    };
    let zeta: Vec<f64> = rows.iter().map(|r| r.zeta).collect();
    let (from, to) = (zeta[0], zeta[zeta.len() - 1]);
    let mut d = ContactSweep {
        surface,
        load: SWEEP_LOAD,
        share: rows.iter().map(|r| r.share()).collect(),
        zeta,
        ..ContactSweep::default()
    };
    let roughness = state.roughness();
    for z in log_points(from, to.max(from * 1.0001), 100) {
        let Ok(p) = state.params.with(Axis::Zeta, z) else {
            continue;
        };
        let psi = roughness
            .surface(&p, state.moments)
            .indices
            .psi_in_use(state.size_effect);
        if let Ok(a) = areas(state.model, psi, SWEEP_LOAD) {
            if a.total > 0.0 {
                d.theory_zeta.push(z);
                d.theory_share.push(a.plastic / a.total);
            }
        }
    }
    figure::render_contact_sweep(state, &d)
}

/// The contact map of `state` at p̄/H_use = `load` as a picture: `nodes`
/// (n × n, 0 out, 1 elastic, 2 at the hardness), `area` and `plastic` the
/// areas, `seed` the surface's (none for a measured map). The explorer's
/// `p` on the contact view draws it too.
pub fn map_picture(
    state: &State,
    (nodes, n): (&[u8], usize),
    load: f64,
    (area, plastic): (f64, f64),
    seed: Option<u64>,
) -> anyhow::Result<String> {
    let side = contact::solved_side(state)?;
    let m = ContactMap {
        seed,
        nodes,
        n,
        side,
        load,
        area,
        plastic,
    };
    figure::render_contact_map(state, &m, map_span(state, n, side, load, seed))
}

/// What the contact map spans, in full.
fn map_span(state: &State, n: usize, side: f64, load: f64, seed: Option<u64>) -> String {
    let h = state.hardness_name();
    let what = match seed {
        Some(s) => format!("periodic Gaussian surface, seed {s}"),
        None => "the measured map".into(),
    };
    format!(
        "contact-map = p_over_h = pbar/{h} = {}; simulation: {n} × {n} grid of side {} m, {what}",
        csv_number::format(load),
        csv_number::format(side)
    )
}

/// `roughtui export --view contact-map`: the scene's surface at
/// p̄ = 0.01 H_use, as SVG or as CSV digits.
fn export_map(args: &ExportArgs, out: &mut impl std::io::Write) -> anyhow::Result<()> {
    for (given, opt) in [
        (args.grid.is_some(), "--grid"),
        (args.map_y.is_some(), "--map-y"),
        (args.sweep.is_some(), "--sweep"),
        (args.points.is_some(), "--points"),
    ] {
        if given {
            bail!(
                "{opt} does not apply to --view contact-map: it solves the scene's surface at \
                 p̄ = {SWEEP_LOAD} H (--seed picks the surface)"
            );
        }
    }
    let state = super::state_of(args)?;
    let seed = args.seed.or(state.seed).unwrap_or(DEFAULT_SEED);
    let key = SceneKey::of(&state, seed)?;
    let mut c = key.build()?;
    let h = key.hardness();
    let r = c.solve(SWEEP_LOAD * h, h, &rough_contact::Options::default())?;
    let map: Vec<u8> = classify(c.pressure(), h)
        .into_iter()
        .map(|v| v as u8)
        .collect();
    let n = key.n;
    let seed = key.surface.is_none().then_some(seed);
    let areas = (r.area, r.plastic_area);
    match args.format {
        FormatArg::Svg => {
            out.write_all(map_picture(&state, (&map, n), SWEEP_LOAD, areas, seed)?.as_bytes())?
        }
        FormatArg::Csv => {
            let hy = state.hardness_name();
            let side = contact::solved_side(&state)?;
            let mut s = String::new();
            let span = map_span(&state, n, side, SWEEP_LOAD, seed);
            comment_lines(&mut s, &full_lines_of(&state, "contact-map", span));
            let share = if r.area > 0.0 {
                r.plastic_area / r.area
            } else {
                0.0
            };
            s.push_str(&format!(
                "# area = {} (A/A0), plastic_share = {} (the part of it at the hardness)\n\
                 # one line per grid row (y, from the top), one value per node (x): 0 out of \
                 contact, 1 elastic (0 < p < {hy}), 2 at the hardness (p = {hy})\n",
                csv_number::format(r.area),
                csv_number::format(share)
            ));
            for row in map.chunks(n) {
                for (i, v) in row.iter().enumerate() {
                    if i > 0 {
                        s.push(',');
                    }
                    s.push(char::from(b'0' + *v));
                }
                s.push('\n');
            }
            out.write_all(s.as_bytes())?;
        }
    }
    out.flush()?;
    Ok(())
}
