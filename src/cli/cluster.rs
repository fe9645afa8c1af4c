//! The options that take a contact ensemble past one machine: `export
//! --shard K/M` (one part of the seeds), `--output FILE` (written whole or
//! not at all), `--slurm-array M` (a SLURM job array of the parts) and
//! `roughtui merge PART…` (the parts put back together).

use std::path::PathBuf;

use clap::Args;

use super::FormatArg;

/// Shard K of M: the part of the seeds one task solves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which part, 1 … `of`.
    pub k: u32,
    /// How many parts.
    pub of: u32,
}

/// Export's options for ensembles solved on several machines.
#[derive(Debug, Args, Clone, Default)]
pub struct Cluster {
    /// Solve part K of M of the --seeds (contact, contact-sweep,
    /// contact-slopes, contact-convergence): each of its seeds' own rows (a `seed` column)
    /// under the whole ensemble's `#` lines; `roughtui merge` puts the M
    /// parts together.
    #[arg(long, value_name = "K/M", value_parser = parse_shard)]
    pub shard: Option<Shard>,
    /// Write to FILE instead of stdout: a temporary file beside it, renamed
    /// when complete, so that a killed run leaves no finished-looking file;
    /// an existing FILE is never overwritten (a part already done is
    /// skipped).
    #[arg(long, value_name = "FILE", conflicts_with = "slurm_array")]
    pub output: Option<PathBuf>,
    /// Print a SLURM batch script that solves the --seeds as a job array of
    /// M tasks, one part each, with the memory the grid needs (`sbatch` it;
    /// submitted again, it solves only the parts not done).
    #[arg(long, value_name = "M", value_parser = parse_tasks, conflicts_with = "shard")]
    pub slurm_array: Option<u32>,
    /// CPUs (solver threads) of each array task (default 2).
    #[arg(long, value_name = "N", value_parser = parse_cpus, requires = "slurm_array")]
    pub slurm_cpus: Option<u32>,
    /// Set by `--shard` on each seed's own export (not an option): a
    /// statistic of the seeds' means is written as what each seed gives
    /// towards it (contact-slopes writes the heavy window's slopes,
    /// `*_heavy`, where the ensemble has `*_fit_err`).
    #[arg(skip)]
    pub part: bool,
}

/// `roughtui merge`.
#[derive(Debug, Args, Clone)]
pub struct MergeArgs {
    /// The parts (`roughtui export … --seeds N --shard K/M`), all of them,
    /// in any order.
    #[arg(required = true, value_name = "PART")]
    pub parts: Vec<PathBuf>,
    /// The merged CSV, exactly as one machine's `--seeds N` writes it, or
    /// its picture (contact, contact-sweep).
    #[arg(long, value_enum, default_value_t = FormatArg::Csv)]
    pub format: FormatArg,
    /// Write to FILE instead of stdout (whole or not at all; never over an
    /// existing file).
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// `--shard K/M`: 1 ≤ K ≤ M.
pub fn parse_shard(s: &str) -> Result<Shard, String> {
    let malformed = || format!("must be K/M, part K of M (1 ≤ K ≤ M), e.g. 2/4, not \"{s}\"");
    let (k, m) = s.trim().split_once('/').ok_or_else(malformed)?;
    let (k, m): (u32, u32) = match (k.trim().parse(), m.trim().parse()) {
        (Ok(k), Ok(m)) => (k, m),
        _ => return Err(malformed()),
    };
    if m == 0 {
        return Err(format!("{s}: M, the number of parts, must be at least 1"));
    }
    if k == 0 || k > m {
        return Err(format!(
            "{s}: part {k} of {m} does not exist: K runs from 1 to {m}"
        ));
    }
    Ok(Shard { k, of: m })
}

/// `--slurm-array M`: 1 … [`crate::contact::MAX_SEEDS`] tasks.
fn parse_tasks(s: &str) -> Result<u32, String> {
    match s.trim().parse::<u32>() {
        Ok(n) if (1..=crate::contact::MAX_SEEDS).contains(&n) => Ok(n),
        _ => Err(format!(
            "must be a whole number of tasks from 1 to {}",
            crate::contact::MAX_SEEDS
        )),
    }
}

/// `--slurm-cpus N`: 1 … 1024.
fn parse_cpus(s: &str) -> Result<u32, String> {
    match s.trim().parse::<u32>() {
        Ok(n) if (1..=1024).contains(&n) => Ok(n),
        _ => Err("must be a whole number of CPUs from 1 to 1024".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shard_is_k_of_m() {
        assert_eq!(parse_shard("2/4"), Ok(Shard { k: 2, of: 4 }));
        assert_eq!(parse_shard(" 1 / 1 "), Ok(Shard { k: 1, of: 1 }));
        for (bad, says) in [
            ("2", "must be K/M"),
            ("a/4", "must be K/M"),
            ("-1/4", "must be K/M"),
            ("2/4/6", "must be K/M"),
            ("5/4", "part 5 of 4 does not exist"),
            ("0/4", "part 0 of 4 does not exist"),
            ("0/0", "M, the number of parts, must be at least 1"),
        ] {
            let e = parse_shard(bad).unwrap_err();
            assert!(e.contains(says), "{bad}: {e}");
        }
    }
}
