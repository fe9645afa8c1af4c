//! `roughtui export --view contact|contact-sweep|contact-map`: the scene's
//! surface solved by the boundary-element contact (`crate::contact`).

use std::io::Write;

use anyhow::bail;

use crate::cli::{ExportArgs, FormatArg};
use crate::contact::map_svg::{caption, map_svg};
use crate::contact::scene::{classify, SceneKey};
use crate::contact::{
    self, Grid, Sampling, Seeds, Spec, DEFAULT_LOADS, DEFAULT_SEED, MAX_LOADS, SWEEP_LOAD,
};
use crate::scene::State;

/// The options of the contact views only.
pub fn contact_options(args: &ExportArgs) -> [(bool, &'static str); 5] {
    [
        (args.seeds.is_some(), "--seeds"),
        (args.hardness.is_some(), "--hardness"),
        (args.cell.is_some(), "--cell"),
        (args.contact_grid.is_some(), "--contact-grid"),
        (args.per_wavelength.is_some(), "--per-wavelength"),
    ]
}

/// What `args` ask to simulate of `state`: the sampling and the seeds
/// (the snapshot's seed first when --seed is not given).
pub fn spec_of(args: &ExportArgs, state: &State) -> anyhow::Result<Spec> {
    if state.is_measured() {
        for (given, opt) in contact_options(args).into_iter().skip(2) {
            if given {
                bail!(
                    "{opt} does not apply to a measured map: it is solved on its own heights, \
                     its square and grid set by the data and ζ"
                );
            }
        }
    }
    let mut sampling = Sampling::default();
    if let Some(k) = args.cell {
        sampling.cell = k;
    }
    if let Some(n) = args.contact_grid {
        sampling.grid = Grid::Side(n);
    }
    if let Some(k) = args.per_wavelength {
        sampling.grid = Grid::PerWavelength(k);
    }
    if args.hardness == Some(crate::cli::HardnessArg::Asperity) {
        sampling.hardness = contact::Hardness::Asperity;
    }
    Ok(Spec {
        sampling,
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
    let spec = spec_of(args, &state)?;
    match (args.format, sweep) {
        (FormatArg::Csv, false) => contact::write_contact(out, &state, points, &spec),
        (FormatArg::Csv, true) => contact::write_contact_sweep(out, &state, &spec),
        (FormatArg::Svg, false) => contact::svg::contact(out, &state, points, &spec),
        (FormatArg::Svg, true) => contact::svg::sweep(out, &state, &spec),
    }
}

/// `roughtui export --view contact-map`: the scene's surface at
/// p̄ = 0.01 H, as SVG or as CSV digits.
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
    if args.seeds.is_some() {
        bail!("--seeds does not apply to --view contact-map: it draws one realisation's map (--seed picks it)");
    }
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    let seed = spec.seeds.first;
    let key = SceneKey::with(&state, seed, &spec.sampling)?;
    let mut c = key.build()?;
    let h = key.hardness();
    let r = c.solve(SWEEP_LOAD * h, h, &rough_contact::Options::default())?;
    let map = classify(c.pressure(), h);
    let n = key.n;
    let seed = key.surface.is_none().then_some(seed);
    let (title, note) = caption(&state.name, n, seed, SWEEP_LOAD, r.area, r.plastic_area);
    match args.format {
        FormatArg::Svg => out.write_all(map_svg(&map, n, &title, &note).as_bytes())?,
        FormatArg::Csv => {
            let mut s = format!(
                "# {title}\n# {note}\n# one line per grid row (y), one value per node (x): \
                 0 out of contact, 1 elastic (0 < p < H), 2 at the hardness\n"
            );
            for row in map.chunks(n) {
                for (i, v) in row.iter().enumerate() {
                    if i > 0 {
                        s.push(',');
                    }
                    s.push(char::from(b'0' + *v as u8));
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
    for (given, opt) in [
        (args.grid.is_some(), "--grid"),
        (args.map_y.is_some(), "--map-y"),
        (args.sweep.is_some(), "--sweep"),
        (args.points.is_some(), "--points"),
        (args.cell.is_some(), "--cell"),
        (args.contact_grid.is_some(), "--contact-grid"),
        (args.per_wavelength.is_some(), "--per-wavelength"),
    ] {
        if given {
            bail!(
                "{opt} does not apply to --view contact-convergence: it solves the scene's \
                 surface at p̄ = {SWEEP_LOAD} H on 4, 8 and 16 nodes per shortest wavelength and \
                 cells of 1, 2 and 4 (--seed and --seeds pick the surfaces)"
            );
        }
    }
    if args.format == FormatArg::Svg {
        bail!("--view contact-convergence is a table: CSV only");
    }
    let state = super::state_of(args)?;
    let spec = spec_of(args, &state)?;
    contact::convergence::write(out, &state, &spec, SWEEP_LOAD)
}
