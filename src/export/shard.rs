//! `roughtui export … --seeds N --shard K/M`: part K of M of a contact
//! ensemble. Each of the part's seeds is exported on its own, exactly as
//! `--seed S` alone writes it (a seed's solves never depend on the other
//! seeds, nor on the threads), and the part keeps every seed's rows with a
//! `seed` column, under the ensemble's `#` lines (`super::lines`) and its
//! own three (`super::part`). `roughtui merge` (`super::merge`) puts the
//! parts back together.

use std::io::Write;
use std::path::Path;

use anyhow::{bail, Context};

use super::lines::combine;
use super::part::{command_line, parse_command, roles_line, roles_of, ShardLine, Table, SCENE};
use crate::cli::{Cluster, ExportArgs, FormatArg, Shard};
use crate::contact::Seeds;
use crate::figure::scene_text::full_lines_of;

/// The views that solve seeds and average over them.
pub const VIEWS: &[&str] = &[
    "contact",
    "contact-sweep",
    "contact-convergence",
    "contact-slopes",
];

/// The name of `args`' view.
pub fn view_name(args: &ExportArgs) -> String {
    clap::ValueEnum::to_possible_value(&args.view)
        .map_or_else(String::new, |v| v.get_name().to_string())
}

/// Refuses what `opt` (`--shard`, `--slurm-array`) does not apply to.
pub fn check_view(args: &ExportArgs, opt: &str) -> anyhow::Result<()> {
    let view = view_name(args);
    if !VIEWS.contains(&view.as_str()) {
        bail!(
            "{opt} applies to the views that solve --seeds ({}), not to --view {view}",
            VIEWS.join(", ")
        );
    }
    if args.format == FormatArg::Svg {
        bail!(
            "{opt} writes CSV parts: draw the merged ensemble with `roughtui merge --format svg \
             PART…`"
        );
    }
    Ok(())
}

/// The ensemble `args` ask for: the state's seeds (checked against the
/// parts `of`).
pub fn ensemble(args: &ExportArgs, of: u32, opt: &str) -> anyhow::Result<Seeds> {
    let state = super::state_of(args)?;
    let all = super::contact::spec_of(args, &state)?.seeds;
    if state.is_measured() && all.count > 1 {
        bail!(
            "--seeds {} does not apply to a measured map: it is solved on its own heights, one \
             realisation",
            all.count
        );
    }
    if of > all.count {
        bail!(
            "{opt}: {of} parts of {} would leave a part without a seed: --seeds N takes at least \
             as many seeds as parts",
            all.words()
        );
    }
    Ok(all)
}

/// The export's arguments as given (after `export`), `--output` left out:
/// what a part says made it.
fn given_args() -> Vec<String> {
    let args: Vec<String> = std::env::args().collect();
    let Some(at) = args.iter().position(|a| a == "export") else {
        return vec![];
    };
    let mut out = vec![];
    let mut rest = args[at + 1..].iter();
    while let Some(a) = rest.next() {
        if a == "--output" {
            rest.next();
        } else if !a.starts_with("--output=") {
            out.push(a.clone());
        }
    }
    out
}

/// The part's `shard command =` line: the folder and the arguments.
fn command() -> String {
    let dir = std::env::current_dir().map_or_else(|_| ".".into(), |d| d.display().to_string());
    command_line(&dir, &given_args())
}

/// The solver's threads from SLURM's `SLURM_CPUS_PER_TASK` where
/// `RAYON_NUM_THREADS` does not set them (before the first solve starts
/// the pool). A seed's numbers do not depend on them.
fn threads_from_slurm() {
    if std::env::var_os("RAYON_NUM_THREADS").is_none() {
        if let Some(n) = std::env::var_os("SLURM_CPUS_PER_TASK") {
            std::env::set_var("RAYON_NUM_THREADS", n);
        }
    }
}

/// Whether `path` holds this very part already (then the run is skipped);
/// a file that is something else is refused, never overwritten.
pub fn done(args: &ExportArgs, shard: Shard, path: &Path) -> anyhow::Result<bool> {
    if !path.exists() {
        return Ok(false);
    }
    let all = ensemble(args, shard.of, "--shard")?;
    let want = ShardLine::new(shard, all).line();
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let table = Table::parse(&text).unwrap_or_default();
    let has = |line: &str| table.comments.iter().any(|c| c == line);
    let same_command = table
        .comments
        .iter()
        .filter_map(|c| parse_command(c))
        .any(|(_, a)| a == given_args());
    if has(&want) && same_command && !table.rows.is_empty() {
        let _ = writeln!(
            std::io::stderr(),
            "roughtui: part {}/{} ({}) is done already: {}; nothing to solve",
            shard.k,
            shard.of,
            super::part::seeds_of(all, shard).words(),
            path.display()
        );
        return Ok(true);
    }
    bail!(
        "--output {}: the file exists and is not part {}/{} of this export; roughtui does not \
         overwrite a file (remove it or choose another name)",
        path.display(),
        shard.k,
        shard.of
    )
}

/// Writes part `shard` of `args`' ensemble to `out`.
pub fn run(args: &ExportArgs, shard: Shard, out: &mut impl Write) -> anyhow::Result<()> {
    check_view(args, "--shard")?;
    let all = ensemble(args, shard.of, &format!("--shard {}/{}", shard.k, shard.of))?;
    let line = ShardLine::new(shard, all);
    threads_from_slurm();
    // A batch task's log says what it solves, on how many threads, and
    // how long it took.
    let task = std::env::var_os("SLURM_JOB_ID").is_some();
    let start = std::time::Instant::now();
    let what = format!("part {}/{} ({})", shard.k, shard.of, line.seeds().words());
    if task {
        let _ = writeln!(
            std::io::stderr(),
            "roughtui: {what} of {}: solving on {} threads",
            all.words(),
            rough_contact::threads()
        );
    }
    let mut runs = vec![];
    let mut columns: Option<Vec<String>> = None;
    let mut rows = vec![];
    for seed in line.seeds().iter() {
        let one = ExportArgs {
            seed: Some(seed),
            seeds: Some(1),
            cluster: Cluster {
                part: true,
                ..Cluster::default()
            },
            ..args.clone()
        };
        let mut buf = vec![];
        super::run(&one, &mut buf).with_context(|| format!("seed {seed}"))?;
        let t = Table::parse(&String::from_utf8_lossy(&buf))
            .with_context(|| format!("seed {seed}'s export"))?;
        if columns.is_none() {
            let all = [vec!["seed".to_string()], t.columns.clone()].concat();
            super::part::not_pooled(&all, &roles_of(&all))?;
        }
        if columns.as_ref().is_some_and(|c| *c != t.columns) {
            bail!("seed {seed}'s export has other columns than the part's first seed's");
        }
        for r in t.rows {
            rows.push([vec![seed.to_string()], r].concat());
        }
        columns.get_or_insert(t.columns);
        runs.push((seed, t.comments));
    }
    let columns = [vec!["seed".to_string()], columns.unwrap_or_default()].concat();
    let mut comments = combine(&runs, all)?;
    if !comments.iter().any(|c| c.starts_with("roughtui ")) {
        // The view's lines do not name the scene in full: the part does,
        // so that parts of other scenes are told apart.
        let state = super::state_of(args)?;
        let scene = full_lines_of(&state, &view_name(args), String::new());
        comments.extend(
            scene
                .into_iter()
                .filter(|l| !l.is_empty())
                .map(|l| format!("{SCENE}{l}")),
        );
    }
    let roles = roles_of(&columns);
    comments.push(line.line());
    comments.push(command());
    comments.push(roles_line(&columns, &roles));
    let table = Table {
        comments,
        columns,
        rows,
    };
    out.write_all(table.text().as_bytes())?;
    out.flush()?;
    if task {
        let _ = writeln!(
            std::io::stderr(),
            "roughtui: {what} solved in {:.1} s",
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}
