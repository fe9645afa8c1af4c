//! `roughtui export`: any view as CSV or SVG on stdout.
//!
//! The state comes from `--preset`/`--load`/`--surface` (fig2 when none is
//! given) with `--set`, `--model`, `--moments`, `--size-effect` and
//! `--sweep` applied on top. Options that do not apply to the chosen view
//! or scene are refused, so that a mistyped command never silently prints
//! something else.

mod contact;
mod contact_slopes;
mod lines;
pub mod merge;
mod merge_svg;
mod moments;
mod output;
mod part;
mod shard;
mod slopes;
mod slurm;
mod surface;
mod views;

use std::io::Write;

use anyhow::bail;
use rough_model::Sweep;

pub use contact::{
    hardness_short, map_picture as contact_map_picture, CONTACT_HEADER, SWEEP_HEADER,
};
pub use moments::{write_moments, MOMENTS_HEADER};
pub use slopes::{write_csv, HEADER};
pub use surface::write as write_surface;
pub use views::{
    write_indices, write_load, write_map, write_spectrum, INDICES_HEADER, LOAD_HEADER, MAP_HEADER,
    SPECTRUM_HEADER,
};

use crate::cli::{ExportArgs, FormatArg, OnOff, ViewArg};
use crate::figure::{render_svg, FigureOptions, View, DEFAULT_GRID};
use crate::scene::State;

/// Points along a curve when `--points` is not given.
pub const DEFAULT_POINTS: usize = 200;

/// Most points of a curve in a picture (a 900-pixel-wide chart needs far
/// fewer; more would only make the file large).
pub const MAX_SVG_POINTS: usize = 20_000;

/// Refuses the first option `given` (whether it was, its name) that does
/// not apply to `--view VIEW`: "--grid does not apply to --view VIEW: WHY".
pub(crate) fn refuse_given(view: &str, why: &str, given: &[(bool, &str)]) -> anyhow::Result<()> {
    match given.iter().find(|(g, _)| *g) {
        Some((_, opt)) => bail!("{opt} does not apply to --view {view}: {why}"),
        None => Ok(()),
    }
}

/// The state `args` describe: the source with every override applied
/// (model, moments, size effect and sweep first, so that `--set hurst=1
/// --moments truncated` works), checked.
pub fn state_of(args: &ExportArgs) -> anyhow::Result<State> {
    let mut state = crate::cli::setup::load_base(&args.source, &args.setup)?;
    let scene = (state.model, state.moments, state.size_effect, state.sweep);
    if let Some(w) = state.surface_warning() {
        // The export goes on with the file as it is now; the user is told.
        let _ = writeln!(std::io::stderr(), "roughtui: warning: {w}");
    }
    for n in state.surface.iter().flat_map(|s| s.notes()) {
        // "warning: …" notes say so themselves.
        let kind = if n.starts_with("warning:") {
            ""
        } else {
            "note: "
        };
        let _ = writeln!(std::io::stderr(), "roughtui: {kind}{n}");
    }
    if let Some(m) = args.model {
        state.model = m.into();
    }
    if let Some(m) = args.moments {
        if state.is_measured() {
            bail!(
                "--moments does not apply to a measured surface: its moments are summed \
                 from the data, not from a power law"
            );
        }
        state.moments = m.into();
    }
    if let Some(s) = args.size_effect {
        state.size_effect = s == OnOff::On;
    }
    if let Some(sweep) = &args.sweep {
        let axis = sweep.axis;
        for (v, typed) in [sweep.from, sweep.to].into_iter().zip(&sweep.typed) {
            crate::physical::check(axis, v, typed).map_err(|e| anyhow::anyhow!("--sweep: {e}"))?;
        }
        state.sweep =
            Sweep::new(axis, sweep.from, sweep.to).map_err(|e| anyhow::anyhow!("--sweep: {e}"))?;
    }
    if scene != (state.model, state.moments, state.size_effect, state.sweep) {
        // The caption describes the scene as saved, its numbers those of
        // its model and moments; a picture of another scene goes without
        // it (the scene line under the chart names the settings).
        state.caption = None;
    }
    crate::cli::setup::apply_setup(&mut state, &args.setup)?;
    state.check()?;
    Ok(state)
}

/// The view's options from `args`, refusing those that do not apply.
pub fn options_of(args: &ExportArgs) -> anyhow::Result<(View, FigureOptions)> {
    let Some(view) = args.view.figure() else {
        bail!(
            "the moments and contact views are written by export::moments and \
             crate::contact, not as figures"
        );
    };
    let name = view.name();
    if view == View::Load && args.sweep.is_some() {
        bail!(
            "--sweep does not apply to --view load: it shows the areas at the current parameters"
        );
    }
    if view == View::Spectrum {
        refuse_given(
            "spectrum",
            "it shows the data's spectrum (the fit over q0…q1, q1 set with --set zeta=VALUE)",
            &[
                (args.sweep.is_some(), "--sweep"),
                (args.points.is_some(), "--points"),
            ],
        )?;
    }
    if view == View::Map {
        if args.points.is_some() {
            bail!("--points does not apply to --view map: its size is --grid COLSxROWS");
        }
    } else {
        for (given, opt) in [
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
        ] {
            if given {
                bail!("{opt} applies only to --view map, not to --view {name}");
            }
        }
    }
    Ok((
        view,
        FigureOptions {
            points: args.points.unwrap_or(DEFAULT_POINTS),
            grid: args.grid.unwrap_or(DEFAULT_GRID),
            map_y: args.map_y.map(Into::into),
            ..FigureOptions::default()
        },
    ))
}

/// `roughtui export`, to stdout or `--output` (a part already done there
/// skipped).
pub fn main(args: &ExportArgs) -> anyhow::Result<()> {
    match &args.cluster.output {
        Some(path) => {
            if let Some(shard) = args.cluster.shard {
                if shard::done(args, shard, path)? {
                    return Ok(());
                }
            }
            output::refuse_existing(path)?;
            output::write_to(path, |w| run(args, &mut &mut *w))
        }
        None => {
            let stdout = std::io::stdout();
            let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
            run(args, &mut out)
        }
    }
}

/// Runs `roughtui export`: writes the view to `out`. Every refusal happens
/// before anything is written.
pub fn run(args: &ExportArgs, out: &mut impl Write) -> anyhow::Result<()> {
    if let Some(shard) = args.cluster.shard {
        return shard::run(args, shard, out);
    }
    if let Some(tasks) = args.cluster.slurm_array {
        return slurm::script(args, tasks, out);
    }
    if args.view == ViewArg::Moments {
        moments::check(args)?;
        for (given, opt) in contact::contact_options(args) {
            if given {
                bail!("{opt} applies only to the contact views, not to --view moments");
            }
        }
        let state = state_of(args)?;
        let points = args.points.unwrap_or(DEFAULT_POINTS);
        return moments::run(args.format, &state, points, out);
    }
    if args.view == ViewArg::Surface {
        return surface::export(args, out);
    }
    if args.view == ViewArg::ContactSlopes {
        return contact_slopes::export(args, out);
    }
    if args.view.figure().is_none() {
        return contact::export(args, out);
    }
    for (given, opt) in contact::contact_options(args) {
        if given {
            bail!(
                "{opt} applies only to the contact views (--view contact, contact-sweep, \
                 contact-map), not to --view {}",
                clap::ValueEnum::to_possible_value(&args.view)
                    .map_or_else(String::new, |v| v.get_name().to_string())
            );
        }
    }
    let (view, opts) = options_of(args)?;
    let state = state_of(args)?;
    if args.format == FormatArg::Svg {
        if opts.points > MAX_SVG_POINTS {
            bail!(
                "--points {} is too many for --format svg: at most {MAX_SVG_POINTS} \
                 (CSV takes up to 10000000)",
                opts.points
            );
        }
        let svg = render_svg(view, &state, &opts)?;
        out.write_all(svg.as_bytes())?;
        out.flush()?;
        return Ok(());
    }
    // What the reader assumed or repaired, before the header (the moments
    // view writes its own).
    for n in state.surface.iter().flat_map(|s| s.notes()) {
        writeln!(out, "# {n}")?;
    }
    match view {
        View::Slopes => write_csv(out, &state, opts.points),
        View::Indices => write_indices(out, &state, opts.points),
        View::Map => write_map(out, &state, &opts),
        View::Load => write_load(out, &state, opts.points),
        View::Spectrum => write_spectrum(out, &state),
        View::Contact => contact::export(args, out),
    }
}
