//! `roughtui export --view contact|contact-sweep|contact-map`: the scene's
//! surface solved by the boundary-element contact (`crate::contact`), as
//! CSV (the scene in `#` lines laid out as every other view's, then what
//! the simulation adds) or as pictures drawn by `crate::figure`.

use std::io::Write;

use anyhow::bail;
use rough_model::{areas, Axis};

use crate::cli::{ExportArgs, FormatArg};
use crate::contact::scene::{classify, classify_capped, SceneKey};
use crate::contact::{
    self, load_rows, sweep_rows, Sampling, Seeds, Simulation, Spec, DEFAULT_LOADS, DEFAULT_SEED,
    MAX_LOADS, SWEEP_LOAD,
};
pub use crate::contact::{CONTACT_HEADER, SWEEP_HEADER};
use crate::figure::scene_text::full_lines_of;
use crate::figure::{self, ContactLoads, ContactMap, ContactSweep};
use crate::physical::csv_number;
use crate::scene::State;

/// The options of the contact views only.
pub fn contact_options(args: &ExportArgs) -> [(bool, &'static str); 6] {
    let [h, l, c, g, k] = args.simulate.given();
    [(args.seeds.is_some(), "--seeds"), h, l, c, g, k]
}

/// What `args` ask to simulate of `state`: the sampling and the seeds
/// (the snapshot's seed first when --seed is not given).
pub fn spec_of(args: &ExportArgs, state: &State) -> anyhow::Result<Spec> {
    args.simulate.check(state)?;
    Ok(Spec {
        sampling: args.simulate.sampling(Sampling::default()),
        seeds: Seeds {
            first: args.seed.or(state.seed).unwrap_or(DEFAULT_SEED),
            count: args.seeds.unwrap_or(1),
        },
    })
}

/// `roughtui export --view contact|contact-sweep`.
pub fn export(args: &ExportArgs, out: &mut impl Write) -> anyhow::Result<()> {
    if args.view == crate::cli::ViewArg::ContactMap {
        return export_map(args, out);
    }
    if args.view == crate::cli::ViewArg::ContactConvergence {
        return export_convergence(args, out);
    }
    let sweep = args.view == crate::cli::ViewArg::ContactSweep;
    let name = if sweep { "contact-sweep" } else { "contact" };
    let at = if sweep {
        "ζ = 1, 2, …, 128 and p̄/H = 0.01"
    } else {
        "--points loads from 1e-3 H to H"
    };
    super::refuse_given(
        name,
        &format!("it solves the scene's surface at {at} (--seed picks the surface)"),
        &[
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
            (args.sweep.is_some(), "--sweep"),
            (sweep && args.points.is_some(), "--points"),
        ],
    )?;
    let points = args.points.unwrap_or(DEFAULT_LOADS);
    if points > MAX_LOADS {
        bail!("--points {points} is too many for --view contact: at most {MAX_LOADS} loads (each is a solution)");
    }
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    match (args.format, sweep) {
        (FormatArg::Csv, false) => {
            let span = figure::contact_span(&state, &contact::loads(points));
            let scene = full_lines_of(&state, "contact", span);
            contact::write_contact(out, &state, points, &spec, &scene)
        }
        (FormatArg::Csv, true) => {
            let in_h0 = spec.sampling.loads == contact::LoadScale::H0;
            let span = figure::sweep_span(&state, SWEEP_LOAD, in_h0);
            let scene = full_lines_of(&state, "contact-sweep", span);
            contact::write_contact_sweep(out, &state, &spec, &scene)
        }
        (FormatArg::Svg, false) => write_svg(out, &contact_svg(&state, points, &spec)?),
        (FormatArg::Svg, true) => write_svg(out, &sweep_svg(&state, &spec)?),
    }
}

fn write_svg(out: &mut impl Write, svg: &str) -> anyhow::Result<()> {
    out.write_all(svg.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The solved surface in words, for the pictures: "128×128 nodes, a cell
/// of 2 longest wavelengths, seeds 1…4".
fn surface_words(sim: &Simulation, spec: &Spec) -> String {
    words_of(sim.contact.n(), sim.measured.is_some(), spec)
}

/// [`surface_words`] of an `n`-node grid, of a measured map or not.
pub fn words_of(n: usize, measured: bool, spec: &Spec) -> String {
    if measured {
        format!("{n}×{n} nodes of the measured map")
    } else {
        format!(
            "{n}×{n} nodes, a cell of {}, {}",
            spec.sampling.cell_words(),
            spec.seeds.words()
        )
    }
}

/// The surfaces of a ζ sweep in words (each ζ its own grid): the measured
/// map, or the cell and the seeds.
pub fn sweep_words(surface: String, measured: bool) -> String {
    if measured {
        return "the measured map".to_string();
    }
    surface
        .split_once(", ")
        .map_or(surface.clone(), |(_, s)| s.to_string())
}

/// `n` loads log-spaced from `from` to `to`.
fn log_points(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from * (to / from).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The contact view as a picture: the simulated areas at the loads, the
/// theory's at 120 loads between the same ends.
fn contact_svg(state: &State, points: usize, spec: &Spec) -> anyhow::Result<String> {
    // Loads beyond a hardness per asperity are left out (the CSV names
    // them); the picture draws those solved.
    let (sim, rows, _, _) = load_rows(state, points, spec)?;
    let surface = surface_words(&sim, spec);
    let p_over_h: Vec<f64> = rows.iter().map(|r| r.p_over_h).collect();
    let d = ContactLoads {
        surface,
        per_asperity: sim.local.is_some(),
        psi: sim.psi.to_f64(),
        area: [
            rows.iter().map(|r| r.area.mean).collect(),
            rows.iter().map(|r| r.elastic.mean).collect(),
            rows.iter().map(|r| r.plastic.mean).collect(),
        ],
        sd: (spec.seeds.count > 1).then(|| {
            [
                rows.iter().map(|r| r.area.sd).collect(),
                rows.iter().map(|r| r.elastic.sd).collect(),
                rows.iter().map(|r| r.plastic.sd).collect(),
            ]
        }),
        p_over_h,
        ..ContactLoads::default()
    };
    loads_picture(state, d)
}

/// The contact view's picture of the simulated areas `d`, with the
/// theory's at 120 loads between the same ends.
pub fn loads_picture(state: &State, mut d: ContactLoads) -> anyhow::Result<String> {
    let psi = state
        .roughness()
        .surface(&state.params, state.moments)
        .indices
        .psi_in_use(state.size_effect);
    let (from, to) = (d.p_over_h[0], d.p_over_h[d.p_over_h.len() - 1]);
    for x in log_points(from, to, 120) {
        if let Ok(a) = areas(state.model, psi, x) {
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
fn sweep_svg(state: &State, spec: &Spec) -> anyhow::Result<String> {
    let (sim, rows, _) = sweep_rows(state, spec)?;
    let surface = sweep_words(surface_words(&sim, spec), sim.measured.is_some());
    let zeta: Vec<f64> = rows.iter().map(|r| r.zeta).collect();
    let d = ContactSweep {
        surface,
        load: SWEEP_LOAD,
        load_in_h0: spec.sampling.loads == contact::LoadScale::H0,
        hardness: hardness_short(state, spec.sampling.hardness),
        share: rows.iter().map(|r| r.share().mean).collect(),
        sd: (spec.seeds.count > 1).then(|| rows.iter().map(|r| r.share().sd).collect()),
        zeta,
        ..ContactSweep::default()
    };
    sweep_picture(state, d)
}

/// The ζ sweep's picture of the simulated shares `d`, with the theory's at
/// 100 ζ between the same ends.
pub fn sweep_picture(state: &State, mut d: ContactSweep) -> anyhow::Result<String> {
    let (from, to) = (d.zeta[0], d.zeta[d.zeta.len() - 1]);
    let scale = match d.load_in_h0 {
        true => contact::LoadScale::H0,
        false => contact::LoadScale::InUse,
    };
    let roughness = state.roughness();
    for z in log_points(from, to.max(from * 1.0001), 100) {
        let Ok(p) = state.params.with(Axis::Zeta, z) else {
            continue;
        };
        let ix = roughness.surface(&p, state.moments).indices;
        let psi = ix.psi_in_use(state.size_effect);
        let p_over_h = scale.over_in_use(d.load, ix.hardness_in_use(state.size_effect));
        if let Ok(a) = areas(state.model, psi, p_over_h) {
            if a.total > 0.0 {
                d.theory_zeta.push(z);
                d.theory_share.push(a.plastic / a.total);
            }
        }
    }
    figure::render_contact_sweep(state, &d)
}

/// Where the hardness applies, in the pictures' words.
pub fn hardness_short(state: &State, hardness: contact::Hardness) -> String {
    match hardness {
        contact::Hardness::Global if state.size_effect => "H_y(R_s) at every node".into(),
        contact::Hardness::Global => "H0 at every node".into(),
        contact::Hardness::Asperity => {
            "each asperity's H0 √(1 + R*/(1.2 R)), R its patch's fitted radius".into()
        }
        contact::Hardness::Summit => {
            "each node's H0 √(1 + R*/(1.2 R)), R its summit's curvature radius".into()
        }
    }
}

/// The contact map of `state` at p̄/H_use = `load` as a picture: `nodes`
/// (n × n, 0 out, 1 elastic, 2 at the hardness), `area` and `plastic` the
/// areas, `seed` the surface's (none for a measured map). The explorer's
/// `p` on the contact view draws it too.
pub fn map_picture(
    state: &State,
    (nodes, n, side): (&[u8], usize, f64),
    load: f64,
    (area, plastic): (f64, f64),
    seed: Option<u64>,
) -> anyhow::Result<String> {
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
    super::refuse_given(
        "contact-map",
        &format!("it solves the scene's surface at p̄ = {SWEEP_LOAD} H (--seed picks the surface)"),
        &[
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
            (args.sweep.is_some(), "--sweep"),
            (args.points.is_some(), "--points"),
        ],
    )?;
    if args.seeds.is_some() {
        bail!("--seeds does not apply to --view contact-map: it draws one realisation's map (--seed picks it)");
    }
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    let seed = spec.seeds.first;
    let key = SceneKey::with(&state, seed, &spec.sampling)?;
    let mut sim = Simulation::with(&state, seed, &spec.sampling)?;
    let (r, _) = sim.solve(SWEEP_LOAD, &mut |_, _| true)?;
    let nodes = match &sim.last_caps {
        Some(caps) => classify_capped(sim.contact.pressure(), caps),
        None => classify(sim.contact.pressure(), sim.hardness),
    };
    let map: Vec<u8> = nodes.into_iter().map(|v| v as u8).collect();
    let n = key.n;
    let side = contact::solved_side(&state, &key)?;
    let seed = key.surface.is_none().then_some(seed);
    let areas = (r.area, r.plastic_area);
    match args.format {
        FormatArg::Svg => out
            .write_all(map_picture(&state, (&map, n, side), SWEEP_LOAD, areas, seed)?.as_bytes())?,
        FormatArg::Csv => {
            let hy = state.hardness_name();
            let mut s = String::new();
            let span = map_span(&state, n, side, SWEEP_LOAD, seed);
            for l in full_lines_of(&state, "contact-map", span) {
                s.push_str(&format!("# {l}\n"));
            }
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

/// `roughtui export --view contact-convergence`: the scene at p̄ = 0.01 H on
/// 4, 8, 16 nodes per shortest wavelength × cells of 1, 2, 4.
fn export_convergence(args: &ExportArgs, out: &mut impl std::io::Write) -> anyhow::Result<()> {
    super::refuse_given(
        "contact-convergence",
        &format!(
            "it solves the scene's surface at p̄ = {SWEEP_LOAD} H on 4, 8 and 16 nodes per \
             shortest wavelength and cells of 1, 2 and 4 (--seed and --seeds pick the surfaces)"
        ),
        &[
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
            (args.sweep.is_some(), "--sweep"),
            (args.points.is_some(), "--points"),
            (args.simulate.cell.is_some(), "--cell"),
            (args.simulate.contact_grid.is_some(), "--contact-grid"),
            (args.simulate.per_wavelength.is_some(), "--per-wavelength"),
        ],
    )?;
    if args.format == FormatArg::Svg {
        bail!("--view contact-convergence is a table: CSV only");
    }
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    contact::convergence::write(out, &state, &spec, SWEEP_LOAD)
}
