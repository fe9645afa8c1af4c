//! `roughtui merge --format svg`: the merged ensemble's picture, the one
//! `roughtui export --format svg` draws of the same `--seeds N` on one
//! machine. The scene comes from the command a part records (its preset,
//! snapshot or surface file, read again and checked against the parts'
//! lines); the numbers from the merged table.

use anyhow::{bail, Context};
use clap::Parser;

use super::part::{Part, Table};
use crate::cli::{Cli, Command, ExportArgs};
use crate::contact::scene::SceneKey;
use crate::figure::{ContactLoads, ContactSweep};
use crate::scene::State;

/// The export arguments a part records, read again (in the folder they
/// ran in, when it is there, so that a relative file name finds its file).
fn export_args(part: &Part) -> anyhow::Result<ExportArgs> {
    let (dir, args) = part.command.clone().with_context(|| {
        format!(
            "{}: no `# shard command` line, so the scene to draw is not known",
            part.path.display()
        )
    })?;
    let argv = ["roughtui".to_string(), "export".to_string()]
        .into_iter()
        .chain(args);
    let cli = Cli::try_parse_from(argv)
        .map_err(|e| anyhow::anyhow!("{}: its command does not parse: {e}", part.path.display()))?;
    let Some(Command::Export(a)) = cli.command else {
        bail!("{}: its command is not an export", part.path.display());
    };
    if std::path::Path::new(&dir).is_dir() {
        std::env::set_current_dir(&dir)?;
    }
    Ok(a)
}

/// A column of `t` as numbers.
fn column(t: &Table, name: &str) -> anyhow::Result<Vec<f64>> {
    let i = t
        .columns
        .iter()
        .position(|c| c == name)
        .with_context(|| format!("the merged table has no column {name}"))?;
    Ok(t.rows
        .iter()
        .map(|r| r[i].parse().unwrap_or(f64::NAN))
        .collect())
}

/// The picture of the merged `table` of `part`'s ensemble.
pub fn picture(part: &Part, table: &Table) -> anyhow::Result<String> {
    let args = export_args(part)?;
    let view = super::shard::view_name(&args);
    if !["contact", "contact-sweep", "contact-slopes"].contains(&view.as_str()) {
        bail!(
            "--view {view} is a table: merge writes it as CSV only (pictures: contact, \
             contact-sweep, contact-slopes)"
        );
    }
    let state = super::state_of(&args)?;
    check_scene(&state, table, part)?;
    let spec = super::contact::spec_of(&args, &state)?;
    let sd = spec.seeds.count > 1;
    match view.as_str() {
        "contact" => {
            let n = if state.is_measured() {
                SceneKey::with(&state, spec.seeds.first, &spec.sampling)?.n
            } else {
                spec.sampling.nodes(state.params.zeta())?
            };
            let cols = |names: [&str; 3]| -> anyhow::Result<[Vec<f64>; 3]> {
                Ok([
                    column(table, names[0])?,
                    column(table, names[1])?,
                    column(table, names[2])?,
                ])
            };
            let d = ContactLoads {
                surface: super::contact::words_of(n, state.is_measured(), &spec),
                per_asperity: spec.sampling.hardness != crate::contact::Hardness::Global,
                psi: state
                    .roughness()
                    .surface(&state.params, state.moments)
                    .indices
                    .psi_in_use(state.size_effect)
                    .to_f64(),
                p_over_h: column(table, "p_over_h")?,
                area: cols(["area", "elastic_area", "plastic_area"])?,
                sd: if sd {
                    Some(cols(["area_sd", "elastic_area_sd", "plastic_area_sd"])?)
                } else {
                    None
                },
                ..ContactLoads::default()
            };
            super::contact::loads_picture(&state, d)
        }
        "contact-sweep" => {
            let words = super::contact::words_of(0, state.is_measured(), &spec);
            let d = ContactSweep {
                surface: super::contact::sweep_words(words, state.is_measured()),
                load: crate::contact::SWEEP_LOAD,
                load_in_h0: spec.sampling.loads == crate::contact::LoadScale::H0,
                hardness: super::contact::hardness_short(&state, spec.sampling.hardness),
                zeta: column(table, "zeta")?,
                share: column(table, "plastic_share")?,
                sd: if sd {
                    Some(column(table, "plastic_share_sd")?)
                } else {
                    None
                },
                ..ContactSweep::default()
            };
            super::contact::sweep_picture(&state, d)
        }
        "contact-slopes" => {
            let names = ["elastic", "plastic", "total"];
            let of = |end: &str| -> anyhow::Result<[Vec<f64>; 3]> {
                let [a, b, c] = names.map(|n| column(table, &format!("sim_{n}_slope{end}")));
                Ok([a?, b?, c?])
            };
            let measured = state.is_measured().then(|| {
                column(table, "grid")
                    .ok()
                    .and_then(|g| g.first().copied())
                    .map_or(0, |g| g as usize)
            });
            let d = super::contact_slopes::picture_of(
                &state,
                &spec,
                measured,
                column(table, "zeta")?,
                of("")?,
                of("_sd")?,
            );
            let svg = crate::figure::render_contact_slopes(&state, &d)?;
            Ok(svg)
        }
        view => bail!("no picture of --view {view}"),
    }
}

/// Refuses a scene that is not the parts' any more (its file changed since
/// they were solved): each of its parameter lines must be theirs.
fn check_scene(state: &State, table: &Table, part: &Part) -> anyhow::Result<()> {
    let lines = crate::figure::scene_text::full_lines_of(state, "", String::new());
    for l in lines.iter().skip(1).filter(|l| l.contains(" = ")) {
        if !table.comments.iter().any(|c| c == l) {
            bail!(
                "the scene {} names is not the parts' any more (`# {l}` is not in them): its file \
                 changed since they were solved",
                part.path.display()
            );
        }
    }
    Ok(())
}
