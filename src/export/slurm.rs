//! `roughtui export … --seeds N --slurm-array M`: a SLURM batch script that
//! solves the ensemble as a job array of M tasks, task K writing part K/M
//! (`--shard K/M --output`), with the memory the largest grid needs and
//! the solver's threads from `SLURM_CPUS_PER_TASK`. Submitted again, the
//! tasks whose parts are done stop at once: only a failed or pre-empted
//! task's part is solved again. A grid beyond every node's memory (as
//! `sinfo` reports it) is refused before anything is submitted.

use std::io::Write;

use anyhow::bail;

use super::part::quote;
use super::shard::{check_view, ensemble, view_name};
use crate::cli::ExportArgs;
use crate::contact::convergence::{CELLS, PER_WAVELENGTH};
use crate::contact::sampling::{bytes_words, BYTES_PER_NODE};
use crate::contact::scene::SceneKey;
use crate::contact::{sweep_zetas, Grid, Sampling, Spec};
use crate::scene::State;

/// CPUs of a task when `--slurm-cpus` does not say.
pub const DEFAULT_CPUS: u32 = 2;
/// What a task takes besides its grid: the program, its tables and the
/// rows (measured peak less the grid's: docs/cluster.md).
pub const BASE_MB: u64 = 64;
/// contact-slopes solves on at least this side.
const SLOPES_GRID: usize = 256;

/// The largest grid side a task of `args`' view solves.
pub fn largest_grid(args: &ExportArgs, state: &State, spec: &Spec) -> anyhow::Result<usize> {
    if state.is_measured() {
        return Ok(SceneKey::with(state, spec.seeds.first, &spec.sampling)?.n);
    }
    let s = &spec.sampling;
    let sweep = || -> anyhow::Result<usize> {
        let most = state.roughness().zeta_max() * (1.0 + 1e-12);
        let mut n = 0;
        for z in sweep_zetas().into_iter().filter(|z| *z <= most) {
            n = n.max(s.nodes(z)?);
        }
        Ok(n)
    };
    Ok(match view_name(args).as_str() {
        "contact-sweep" => sweep()?,
        "contact-slopes" => sweep()?.max(SLOPES_GRID),
        // Pairs beyond the largest grid are named as not solved.
        "contact-convergence" => PER_WAVELENGTH
            .iter()
            .flat_map(|&k| CELLS.iter().map(move |&cell| (k, cell)))
            .filter_map(|(k, cell)| {
                Sampling {
                    cell,
                    grid: Grid::PerWavelength(k),
                    ..*s
                }
                .nodes(state.params.zeta())
                .ok()
            })
            .max()
            .unwrap_or(0),
        _ => s.nodes(state.params.zeta())?,
    })
}

/// The memory a task asks for, in MB: the grid's solve, a quarter more for
/// the allocator's slack, and [`BASE_MB`].
pub fn task_mb(n: usize) -> u64 {
    let grid = (n * n * BYTES_PER_NODE) as f64 / 1e6;
    (grid * 1.25).ceil() as u64 + BASE_MB
}

/// The largest node memory of the cluster in MB, as `sinfo` reports it;
/// `None` where there is no `sinfo` (the script made away from the
/// cluster: sbatch still refuses a --mem no node has).
fn node_mb() -> Option<u64> {
    use std::io::Read;
    use std::process::{Command, Stdio};
    let mut child = Command::new("sinfo")
        .args(["-h", "-o", "%m"])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    // A controller that does not answer: not checked, rather than waited for.
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().ok()? {
            break status;
        }
        if start.elapsed() > std::time::Duration::from_secs(10) {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let mut text = String::new();
    child.stdout.take()?.read_to_string(&mut text).ok()?;
    if !status.success() {
        return None;
    }
    text.lines()
        .filter_map(|l| l.trim().trim_end_matches('+').parse::<u64>().ok())
        .max()
}

/// A name for files and jobs: letters, digits, `-` and `_`.
fn plain(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect()
}

/// The export's arguments without those of the script itself.
fn task_args() -> Vec<String> {
    let args: Vec<String> = std::env::args().collect();
    let at = args
        .iter()
        .position(|a| a == "export")
        .map_or(args.len(), |i| i + 1);
    let mut out = vec![];
    let mut rest = args[at..].iter();
    while let Some(a) = rest.next() {
        match a.as_str() {
            "--slurm-array" | "--slurm-cpus" => {
                rest.next();
            }
            a if a.starts_with("--slurm-array=") || a.starts_with("--slurm-cpus=") => {}
            a => out.push(a.to_string()),
        }
    }
    out
}

/// Writes the batch script of `args`' ensemble in `tasks` tasks.
pub fn script(args: &ExportArgs, tasks: u32, out: &mut impl Write) -> anyhow::Result<()> {
    check_view(args, "--slurm-array")?;
    let all = ensemble(args, tasks, &format!("--slurm-array {tasks}"))?;
    let state = super::state_of(args)?;
    let spec = super::contact::spec_of(args, &state)?;
    let n = largest_grid(args, &state, &spec)?;
    let mb = task_mb(n);
    let grid_bytes = (n * n * BYTES_PER_NODE) as f64;
    if let Some(node) = node_mb() {
        if mb > node {
            bail!(
                "the {n} × {n} grid needs {mb} MB a task ({} for the solve, {BYTES_PER_NODE} \
                 bytes a node, a quarter more and {BASE_MB} MB for the program); the largest \
                 node of this cluster has {node} MB (sinfo): lower ζ, --cell or \
                 --per-wavelength",
                bytes_words(grid_bytes)
            );
        }
    }
    let cpus = args
        .cluster
        .slurm_cpus
        .unwrap_or(super::slurm::DEFAULT_CPUS);
    let view = view_name(args);
    let name = plain(&format!("roughtui-{}-{view}", state.name));
    let last = all.first.wrapping_add(u64::from(all.count) - 1);
    let parts = plain(&format!("{}-{view}-seeds-{}-{last}", state.name, all.first));
    let dir = std::env::current_dir()?.display().to_string();
    let exe = std::env::current_exe()?.display().to_string();
    let per_task = all.count.div_ceil(tasks);
    let mut cmd = quote(&exe) + " export";
    for a in task_args() {
        cmd.push(' ');
        cmd.push_str(&quote(&a));
    }
    let version = env!("CARGO_PKG_VERSION");
    let s = format!(
        "#!/bin/bash\n\
# roughtui {version}: scene {scene:?}, view {view}, {seeds} as a SLURM job array of {tasks}\n\
# tasks, task K solving part K/{tasks} (up to {per_task} seeds) on grids of up to {n} × {n}.\n\
#\n\
# Submit:  sbatch THIS-FILE (or pipe the export into sbatch)\n\
# Again:   the same; a task whose part is done stops at once, so that only the parts\n\
#          not done (a failed or pre-empted task's) are solved again.\n\
# Merge:   {roughtui} merge {parts}/part-*-of-{tasks}.csv > {parts}.csv\n\
#          (--format svg draws it; the CSV is the one `--seeds {count}` writes on one machine)\n\
#\n\
# --mem: the {n}² grid's solve takes about {grid} ({BYTES_PER_NODE} bytes a node), a quarter\n\
# more for the allocator and {BASE_MB} MB for the program. --cpus-per-task: the solver's\n\
# threads (RAYON_NUM_THREADS), which do not change a seed's numbers. Add the --partition,\n\
# --account and --time your cluster asks for (docs/cluster.md: the cost per seed).\n\
#SBATCH --job-name={name}\n\
#SBATCH --array=1-{tasks}\n\
#SBATCH --ntasks=1\n\
#SBATCH --cpus-per-task={cpus}\n\
#SBATCH --mem={mb}M\n\
#SBATCH --output=%x-%A_%a.log\n\
set -eu\n\
cd {qdir}\n\
parts={parts}\n\
mkdir -p \"$parts\"\n\
export RAYON_NUM_THREADS=\"${{SLURM_CPUS_PER_TASK:-1}}\"\n\
k=\"$SLURM_ARRAY_TASK_ID\"\n\
exec {cmd} --shard \"$k/{tasks}\" --output \"$parts/part-$k-of-{tasks}.csv\"\n",
        scene = state.name,
        seeds = all.words(),
        roughtui = quote(&exe),
        count = all.count,
        grid = bytes_words(grid_bytes),
        qdir = quote(&dir),
    );
    out.write_all(s.as_bytes())?;
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_task_asks_for_its_grid_and_the_program() {
        assert_eq!(task_mb(256), 9 + BASE_MB);
        assert_eq!(task_mb(4096), 2098 + BASE_MB);
        assert_eq!(plain("fig2 (mine)/x"), "fig2--mine--x");
    }
}
