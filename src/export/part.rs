//! A part of a sharded contact export: a CSV whose rows are single seeds'
//! (a `seed` column before the view's own), under the whole ensemble's `#`
//! lines and three of its own — which part of which seeds it is, the
//! command that made it, and how `roughtui merge` treats each column. The
//! columns' treatment follows their names, not a list of today's columns,
//! so that a view's new columns merge without a change here.

use std::path::PathBuf;

use anyhow::{bail, Context};

use crate::cli::Shard;
use crate::contact::Seeds;

/// A CSV as the exports write it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    /// The `#` lines, without the "# ".
    pub comments: Vec<String>,
    pub columns: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// `text` read: `#` lines, then the header, then rows of as many
    /// fields.
    pub fn parse(text: &str) -> anyhow::Result<Table> {
        let mut t = Table::default();
        let mut lines = text.lines().enumerate();
        for (_, l) in lines.by_ref() {
            if let Some(c) = l.strip_prefix('#') {
                t.comments
                    .push(c.strip_prefix(' ').unwrap_or(c).to_string());
                continue;
            }
            t.columns = l.split(',').map(str::to_string).collect();
            break;
        }
        if t.columns.iter().all(|c| c.is_empty()) {
            bail!("no CSV header");
        }
        for (i, l) in lines {
            if l.is_empty() {
                continue;
            }
            let row: Vec<String> = l.split(',').map(str::to_string).collect();
            if row.len() != t.columns.len() {
                bail!(
                    "line {}: {} fields where the header has {}",
                    i + 1,
                    row.len(),
                    t.columns.len()
                );
            }
            t.rows.push(row);
        }
        Ok(t)
    }

    /// The CSV text.
    pub fn text(&self) -> String {
        let mut s = String::new();
        for c in &self.comments {
            s.push_str("# ");
            s.push_str(c);
            s.push('\n');
        }
        s.push_str(&self.columns.join(","));
        s.push('\n');
        for r in &self.rows {
            s.push_str(&r.join(","));
            s.push('\n');
        }
        s
    }
}

/// How `roughtui merge` treats a column of a part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The realisation: the part's own column.
    Seed,
    /// The same for every seed: what tells the rows apart (the load, ζ,
    /// the grid, the theory's numbers).
    Key,
    /// A seed's own value: merged as the mean over the seeds (a NaN — no
    /// contact — left out, as one machine leaves it out).
    Mean,
    /// A mean's sample standard deviation over the seeds: the column of
    /// that index.
    Sd(usize),
    /// The largest over the seeds (the solver's residual).
    Max,
    /// How many seeds the row is over.
    Count,
    /// A seed's value of the other window of a fit (contact-slopes'
    /// `X_heavy`, the slope over the heaviest loads): merged as the
    /// ensemble's `X_fit_err`, |mean of X − mean of X_heavy| over the
    /// seeds, X the column of that index.
    FitErr(usize),
    /// A statistic of the seeds' means that their own values cannot give
    /// (a `*_fit_err` in a part, which a part of this version never
    /// writes): a part of it is refused rather than merged wrong.
    NotPooled,
}

/// Ends of the names of [`Role::NotPooled`] columns.
const NOT_POOLED: &[&str] = &["_fit_err"];
/// The end of the name of a [`Role::FitErr`] column in a part, and of the
/// merged column it becomes.
const HEAVY: &str = "_heavy";
const FIT_ERR: &str = "_fit_err";

/// The merged CSV's name of a part's column: `X_heavy` becomes
/// `X_fit_err`, every other name stays.
pub fn merged_name(column: &str, role: Role) -> String {
    match (role, column.strip_suffix(HEAVY)) {
        (Role::FitErr(_), Some(base)) => format!("{base}{FIT_ERR}"),
        _ => column.to_string(),
    }
}

/// Columns the same for every seed, besides the theory's (`theory_*`): the
/// load, ζ, the grid and the cell, and contact-slopes' load window.
const KEYS: &[&str] = &[
    "p_over_h",
    "p_over_h0",
    "zeta",
    "grid",
    "per_wavelength",
    "cell",
    "p_over_h_lightest",
    "p_over_h_heaviest",
];

/// The roles of `columns` (a part's, `seed` first) by their names: `seed`,
/// `seeds` (the count), `X_sd` (X's standard deviation), `residual` (the
/// largest), the keys, and every other column a seed's own value.
pub fn roles_of(columns: &[String]) -> Vec<Role> {
    columns
        .iter()
        .map(|c| match c.as_str() {
            "seed" => Role::Seed,
            "seeds" => Role::Count,
            "residual" => Role::Max,
            c if c.starts_with("theory_") || KEYS.contains(&c) => Role::Key,
            c if NOT_POOLED.iter().any(|e| c.ends_with(e)) => Role::NotPooled,
            c => {
                let of = |end: &str| {
                    c.strip_suffix(end)
                        .and_then(|base| columns.iter().position(|x| x == base))
                };
                match (of("_sd"), of(HEAVY)) {
                    (Some(i), _) => Role::Sd(i),
                    (None, Some(i)) => Role::FitErr(i),
                    (None, None) => Role::Mean,
                }
            }
        })
        .collect()
}

const ROLES: &str = "part columns = ";

/// The `#` line naming each column's role.
pub fn roles_line(columns: &[String], roles: &[Role]) -> String {
    let of = |want: fn(&Role) -> bool| -> String {
        let names: Vec<&str> = columns
            .iter()
            .zip(roles)
            .filter(|(_, r)| want(r))
            .map(|(c, _)| c.as_str())
            .collect();
        if names.is_empty() {
            "none".into()
        } else {
            names.join(", ")
        }
    };
    format!(
        "{ROLES}seed: the realisation, one row per seed; key: {}; mean: {}; sd: {}; largest: {}; \
         count: {}; fit error: {}; not merged: {} (roughtui merge groups the seeds' rows by the key \
         columns and writes each mean column's mean over the seeds, each sd column the sample \
         standard deviation of its mean column, the largest, the count, and for each fit error \
         column X_heavy the column X_fit_err = |mean of X − mean of X_heavy|)",
        of(|r| *r == Role::Key),
        of(|r| *r == Role::Mean),
        of(|r| matches!(r, Role::Sd(_))),
        of(|r| *r == Role::Max),
        of(|r| *r == Role::Count),
        of(|r| matches!(r, Role::FitErr(_))),
        of(|r| *r == Role::NotPooled),
    )
}

/// The roles a part's `#` line gives its `columns`.
pub fn roles_from(line: &str, columns: &[String]) -> anyhow::Result<Vec<Role>> {
    let body = line
        .strip_prefix(ROLES)
        .context("not a part's columns line")?;
    let body = body.split(" (").next().unwrap_or(body);
    let mut roles: Vec<Option<Role>> = vec![None; columns.len()];
    for group in body.split("; ") {
        let (kind, names) = group
            .split_once(": ")
            .with_context(|| format!("\"{group}\" is not ROLE: COLUMNS"))?;
        if kind == "seed" {
            let i = position(columns, "seed")?;
            roles[i] = Some(Role::Seed);
            continue;
        }
        if names == "none" {
            continue;
        }
        for name in names.split(", ") {
            let i = position(columns, name)?;
            roles[i] = Some(match kind {
                "key" => Role::Key,
                "mean" => Role::Mean,
                "largest" => Role::Max,
                "count" => Role::Count,
                "not merged" => Role::NotPooled,
                "fit error" => {
                    let base = name.strip_suffix(HEAVY).unwrap_or(name);
                    Role::FitErr(position(columns, base)?)
                }
                "sd" => {
                    let base = name.strip_suffix("_sd").unwrap_or(name);
                    Role::Sd(position(columns, base)?)
                }
                _ => bail!("no role \"{kind}\""),
            });
        }
    }
    roles
        .into_iter()
        .zip(columns)
        .map(|(r, c)| r.with_context(|| format!("column {c} has no role")))
        .collect()
}

fn position(columns: &[String], name: &str) -> anyhow::Result<usize> {
    columns
        .iter()
        .position(|c| c == name)
        .with_context(|| format!("no column {name}"))
}

/// The seeds of part `shard` of `all`: consecutive, the first parts one
/// seed more where the seeds do not divide evenly.
pub fn seeds_of(all: Seeds, shard: Shard) -> Seeds {
    let (n, m, k) = (all.count, shard.of, shard.k - 1);
    let (base, extra) = (n / m, n % m);
    Seeds {
        first: all.first.wrapping_add(u64::from(k * base + k.min(extra))),
        count: base + u32::from(k < extra),
    }
}

const SHARD: &str = "shard = ";

/// What a part's `shard =` line says.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ShardLine {
    pub shard: Shard,
    /// The whole ensemble.
    pub all: Seeds,
    /// The version of roughtui that solved it.
    pub version: String,
}

impl ShardLine {
    pub fn new(shard: Shard, all: Seeds) -> ShardLine {
        ShardLine {
            shard,
            all,
            version: env!("CARGO_PKG_VERSION").into(),
        }
    }

    /// This part's seeds.
    pub fn seeds(&self) -> Seeds {
        seeds_of(self.all, self.shard)
    }

    /// The `#` line.
    pub fn line(&self) -> String {
        format!(
            "{SHARD}{}/{}: {} of {}, solved by roughtui {} (roughtui merge puts the {} parts \
             together)",
            self.shard.k,
            self.shard.of,
            self.seeds().words(),
            self.all.words(),
            self.version,
            self.shard.of
        )
    }

    /// The line read back.
    pub fn parse(line: &str) -> anyhow::Result<ShardLine> {
        let bad = || format!("\"{line}\" is not a part's shard line");
        let body = line.strip_prefix(SHARD).with_context(bad)?;
        let (km, rest) = body.split_once(": ").with_context(bad)?;
        let shard = crate::cli::parse_shard(km).map_err(|e| anyhow::anyhow!("{e}"))?;
        let (_, rest) = rest.split_once(" of ").with_context(bad)?;
        let (all, rest) = rest.split_once(", solved by roughtui ").with_context(bad)?;
        let version = rest.split(' ').next().unwrap_or_default().to_string();
        let all = parse_words(all).with_context(bad)?;
        if all.count < shard.of {
            bail!("{}: {} parts of {} seeds", bad(), shard.of, all.count);
        }
        Ok(ShardLine {
            shard,
            all,
            version,
        })
    }
}

/// [`Seeds::words`] read back: "seed 3", "seeds 1–8".
fn parse_words(w: &str) -> Option<Seeds> {
    if let Some(n) = w.strip_prefix("seeds ") {
        let (a, b) = n.split_once('–')?;
        let (a, b): (u64, u64) = (a.parse().ok()?, b.parse().ok()?);
        let count = u32::try_from(b.wrapping_sub(a).wrapping_add(1)).ok()?;
        return Some(Seeds { first: a, count });
    }
    Some(Seeds::one(w.strip_prefix("seed ")?.parse().ok()?))
}

/// The `#` line of the command that made a part, as a shell would run it
/// again: `shard command = cd DIR && roughtui export ARGS`.
pub fn command_line(dir: &str, args: &[String]) -> String {
    let mut s = format!("{COMMAND}cd {} && roughtui export", quote(dir));
    for a in args {
        s.push(' ');
        s.push_str(&quote(a));
    }
    s
}

const COMMAND: &str = "shard command = ";

/// The folder and the export's arguments of a part's command line.
pub fn parse_command(line: &str) -> Option<(String, Vec<String>)> {
    let words = split_words(line.strip_prefix(COMMAND)?)?;
    match words.as_slice() {
        [cd, dir, and, bin, export, args @ ..]
            if cd == "cd" && and == "&&" && bin == "roughtui" && export == "export" =>
        {
            Some((dir.clone(), args.to_vec()))
        }
        _ => None,
    }
}

/// `s` as one shell word: as it is when it needs no quotes, else in single
/// quotes.
pub fn quote(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@%^".contains(c));
    if plain {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// Words of a line [`quote`] made (plain words, single quotes, `\'`).
fn split_words(line: &str) -> Option<Vec<String>> {
    let mut out = vec![];
    let mut word = String::new();
    let (mut started, mut quoted) = (false, false);
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '\'') => quoted = false,
            (true, c) => word.push(c),
            (false, '\'') => {
                quoted = true;
                started = true;
            }
            (false, '\\') => {
                word.push(chars.next()?);
                started = true;
            }
            (false, c) if c.is_whitespace() => {
                if started {
                    out.push(std::mem::take(&mut word));
                    started = false;
                }
            }
            (false, c) => {
                word.push(c);
                started = true;
            }
        }
    }
    if quoted {
        return None;
    }
    if started {
        out.push(word);
    }
    Some(out)
}

/// Lines only a part has: merge leaves them out.
pub fn is_part_only(line: &str) -> bool {
    line.starts_with(SHARD)
        || line.starts_with(COMMAND)
        || line.starts_with(ROLES)
        || line.starts_with(SCENE)
}

/// A scene line a part adds where its view's own lines do not name the
/// scene in full (contact-convergence's).
pub const SCENE: &str = "part scene: ";

/// One part as read.
pub struct Part {
    pub path: PathBuf,
    pub table: Table,
    pub shard: ShardLine,
    /// The export's arguments that made it, and the folder it ran in.
    pub command: Option<(String, Vec<String>)>,
    pub roles: Vec<Role>,
}

impl Part {
    pub fn name(&self) -> String {
        self.path.display().to_string()
    }
}

/// Refuses columns that the seeds' own values cannot give.
pub fn not_pooled(columns: &[String], roles: &[Role]) -> anyhow::Result<()> {
    if let Some((c, _)) = columns
        .iter()
        .zip(roles)
        .find(|(_, r)| **r == Role::NotPooled)
    {
        bail!(
            "the column {c} is a statistic of the seeds' means that their own rows cannot give \
             (|the mean slope over one window − over another|): this view is not merged from \
             parts"
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(s: &str) -> Vec<String> {
        s.split(',').map(str::to_string).collect()
    }

    #[test]
    fn roles_follow_the_names_and_read_back() {
        let c = names("seed,p_over_h,area,mean_gap,residual,theory_area,area_sd,seeds,area_corrected,area_corrected_sd,sim_total_slope_fit_err,area_heavy");
        let r = roles_of(&c);
        use Role::*;
        assert_eq!(
            r,
            [
                Seed,
                Key,
                Mean,
                Mean,
                Max,
                Key,
                Sd(2),
                Count,
                Mean,
                Sd(8),
                NotPooled,
                FitErr(2)
            ]
        );
        let line = roles_line(&c, &r);
        assert!(
            line.contains("key: p_over_h, theory_area; mean: area, mean_gap, area_corrected;"),
            "{line}"
        );
        assert_eq!(roles_from(&line, &c).unwrap(), r);
        // A column the line does not name is refused.
        assert!(roles_from(&line, &names("seed,p_over_h,extra")).is_err());
    }

    #[test]
    fn the_seeds_split_into_consecutive_parts() {
        let all = Seeds {
            first: 1,
            count: 10,
        };
        let parts: Vec<(u64, u32)> = (1..=4)
            .map(|k| seeds_of(all, Shard { k, of: 4 }))
            .map(|s| (s.first, s.count))
            .collect();
        assert_eq!(parts, [(1, 3), (4, 3), (7, 2), (9, 2)]);
        let one = seeds_of(all, Shard { k: 1, of: 1 });
        assert_eq!((one.first, one.count), (1, 10));
    }

    #[test]
    fn the_shard_and_command_lines_read_back() {
        let l = ShardLine::new(Shard { k: 2, of: 4 }, Seeds { first: 5, count: 8 });
        let text = l.line();
        assert!(
            text.starts_with("shard = 2/4: seeds 7–8 of seeds 5–12, solved by roughtui "),
            "{text}"
        );
        assert_eq!(ShardLine::parse(&text).unwrap(), l);
        let args: Vec<String> = [
            "--preset",
            "fig2",
            "--set",
            "h-rms=1 nm",
            "--surface",
            "it's.txt",
        ]
        .map(String::from)
        .to_vec();
        let c = command_line("/tmp/a dir", &args);
        assert_eq!(
            c,
            "shard command = cd '/tmp/a dir' && roughtui export --preset fig2 --set 'h-rms=1 nm' \
             --surface 'it'\\''s.txt'"
        );
        assert_eq!(parse_command(&c), Some(("/tmp/a dir".into(), args)));
    }
}
