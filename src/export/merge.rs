//! `roughtui merge PART…`: the parts of a sharded contact export put back
//! together into the CSV one machine's `--seeds N` writes. The parts must
//! be of one scene, one set of options and one version, and hold every
//! seed once; the rows are grouped by their key columns and each mean,
//! sample standard deviation, largest value and count computed again from
//! the seeds' own values, in seed order, as one machine computes them.

use std::collections::HashMap;
use std::io::Write;
use std::path::Path;

use anyhow::{bail, Context};

use super::lines::{items, pool, pool_not_solved, Item};
use super::part::{
    merged_name, not_pooled, parse_command, roles_from, Part, Role, ShardLine, Table,
};
use crate::cli::MergeArgs;
use crate::contact::Stat;
use crate::physical::csv_number;

/// Reads the part at `path`.
fn read(path: &Path) -> anyhow::Result<Part> {
    let name = path.display();
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read the part {name}"))?;
    let table = Table::parse(&text).with_context(|| format!("{name}: not a CSV"))?;
    let not_part = || {
        format!(
            "{name} is not a part of a sharded export (no `# shard =` line): parts come from \
             `roughtui export … --seeds N --shard K/M`"
        )
    };
    let shard = table
        .comments
        .iter()
        .find(|c| c.starts_with("shard = "))
        .with_context(not_part)?;
    let shard = ShardLine::parse(shard).with_context(|| name.to_string())?;
    let roles = table
        .comments
        .iter()
        .find(|c| c.starts_with("part columns = "))
        .with_context(not_part)?;
    let roles = roles_from(roles, &table.columns).with_context(|| name.to_string())?;
    let command = table.comments.iter().find_map(|c| parse_command(c));
    Ok(Part {
        path: path.to_path_buf(),
        table,
        shard,
        command,
        roles,
    })
}

/// An export's options as items ("--cell 2"), `--shard` left out, sorted:
/// two commands that ask the same give the same.
fn options(args: &[String]) -> Vec<String> {
    let mut out: Vec<String> = vec![];
    let mut it = args.iter().peekable();
    while let Some(a) = it.next() {
        let item = match a.split_once('=') {
            Some((flag, value)) if a.starts_with("--") => format!("{flag} {value}"),
            _ if a.starts_with("--") => match it.peek() {
                Some(v) if !v.starts_with("--") => format!("{a} {}", it.next().unwrap_or(a)),
                _ => a.clone(),
            },
            _ => a.clone(),
        };
        if !item.starts_with("--shard") {
            out.push(item);
        }
    }
    out.sort();
    out
}

/// What options `y` has that `x` (of `an`) has not, or the other way, in
/// words: "`--cell 1` where a.csv has `--cell 2`".
fn difference(x: &[String], y: &[String], an: &str) -> String {
    let flag = |o: &str| o.split(' ').next().unwrap_or_default().to_string();
    let extra = y.iter().find(|o| !x.contains(o));
    let lacks = x.iter().find(|o| !y.contains(o));
    match (extra, lacks) {
        (Some(e), Some(l)) if flag(e) == flag(l) => format!("`{e}` where {an} has `{l}`"),
        (Some(e), _) => format!("`{e}`, which {an} has not"),
        (None, Some(l)) => format!("no `{l}`, which {an} has"),
        (None, None) => "the same options in another order".into(),
    }
}

/// Refuses parts that are not of one ensemble: one version, one set of
/// seeds, one set of options, one scene, one table; each in one line
/// naming the difference.
fn check_same(parts: &[Part]) -> anyhow::Result<()> {
    let a = &parts[0];
    for b in &parts[1..] {
        let (an, bn) = (a.name(), b.name());
        if a.shard.version != b.shard.version {
            bail!(
                "{bn} was solved by roughtui {}, {an} by roughtui {}: the parts of one ensemble \
                 come from one version",
                b.shard.version,
                a.shard.version
            );
        }
        if a.shard.all != b.shard.all {
            bail!(
                "{bn} is a part of {}, {an} of {}: the parts of one ensemble share its seeds",
                b.shard.all.words(),
                a.shard.all.words()
            );
        }
        if let (Some((_, x)), Some((_, y))) = (&a.command, &b.command) {
            let (x, y) = (options(x), options(y));
            if x != y {
                bail!(
                    "{bn} was made with other options than {an}: {}",
                    difference(&x, &y, &an)
                );
            }
        }
        let (x, y) = (items(&a.table.comments).0, items(&b.table.comments).0);
        for (p, q) in x.iter().zip(&y) {
            if let (Item::Common(p), Item::Common(q)) = (p, q) {
                if p != q {
                    bail!(
                        "{bn} is a part of another scene or options than {an}: `# {q}` where \
                         {an} has `# {p}`"
                    );
                }
            }
        }
        let scene = |p: &Part| -> Vec<String> {
            p.table
                .comments
                .iter()
                .filter(|c| c.starts_with(super::part::SCENE))
                .cloned()
                .collect()
        };
        if let Some((p, q)) = scene(a).iter().zip(&scene(b)).find(|(p, q)| p != q) {
            bail!("{bn} is a part of another scene than {an}: `# {q}` where {an} has `# {p}`");
        }
        if x.len() != y.len() || a.table.columns != b.table.columns || a.roles != b.roles {
            bail!("{bn} is not a part of the same table as {an}: its `#` lines or columns differ");
        }
    }
    Ok(())
}

/// Refuses a seed given twice or missing: every seed of the ensemble once.
fn check_seeds(parts: &[Part]) -> anyhow::Result<()> {
    let all = parts[0].shard.all;
    let mut owner: HashMap<u64, &Part> = HashMap::new();
    for p in parts {
        for s in p.shard.seeds().iter() {
            if let Some(q) = owner.insert(s, p) {
                let (k, m) = (p.shard.shard.k, p.shard.shard.of);
                let (j, n) = (q.shard.shard.k, q.shard.shard.of);
                bail!(
                    "seed {s} is in two parts: {} (part {j}/{n}) and {} (part {k}/{m}); each seed \
                     is merged once",
                    q.name(),
                    p.name()
                );
            }
        }
    }
    let missing: Vec<u64> = all.iter().filter(|s| !owner.contains_key(s)).collect();
    if let Some(&first) = missing.first() {
        let of = parts[0].shard.shard.of;
        let parts_missing: Vec<String> = (1..=of)
            .map(|k| crate::cli::Shard { k, of })
            .filter(|&sh| {
                super::part::seeds_of(all, sh)
                    .iter()
                    .any(|s| missing.contains(&s))
            })
            .map(|sh| format!("{}/{of}", sh.k))
            .collect();
        bail!(
            "{} of {} missing: no part given holds {} (part {} not given); a missing seed is \
             never averaged over",
            if missing.len() == 1 {
                format!("seed {first}")
            } else {
                format!("{} seeds", missing.len())
            },
            all.words(),
            if missing.len() == 1 {
                "it".to_string()
            } else {
                format!("seeds {}", words(&missing))
            },
            parts_missing.join(", ")
        );
    }
    Ok(())
}

/// Seeds in short: "3, 4, 9".
fn words(seeds: &[u64]) -> String {
    let w: Vec<String> = seeds.iter().take(8).map(u64::to_string).collect();
    let more = if seeds.len() > 8 { ", …" } else { "" };
    format!("{}{more}", w.join(", "))
}

/// The merged `#` lines: the parts' lines with each statistic pooled and
/// the "not solved" lines of all seeds.
fn comments(parts: &[Part]) -> anyhow::Result<Vec<String>> {
    let mut merged: Option<Vec<Item>> = None;
    let mut notes: HashMap<usize, Vec<String>> = HashMap::new();
    for p in parts {
        let (its, ns) = items(&p.table.comments);
        for (i, n) in ns {
            notes.entry(i).or_default().extend(n);
        }
        let seeds: Vec<u64> = p.shard.seeds().iter().collect();
        let Some(merged) = merged.as_mut() else {
            merged = Some(its);
            continue;
        };
        for (m, it) in merged.iter_mut().zip(its) {
            if let (Item::Common(_), Item::Common(_)) = (&*m, &it) {
                continue;
            }
            // A statistic: in a part where it is one line (one seed, or
            // seeds that agree), that line is each of its seeds'.
            let earlier = std::mem::replace(m, Item::PerSeed(vec![]));
            let earlier = match earlier {
                Item::Common(l) => parts_seeds(parts, p).map(|s| (s, l.clone())).collect(),
                Item::PerSeed(v) => v,
            };
            let this = match it {
                Item::Common(l) => seeds.iter().map(|&s| (s, l.clone())).collect(),
                Item::PerSeed(v) => v,
            };
            *m = Item::PerSeed([earlier, this].concat());
        }
    }
    let merged = merged.unwrap_or_default();
    let mut out = vec![];
    let at = |i: usize, out: &mut Vec<String>| {
        if let Some(n) = notes.get(&i) {
            out.extend(pool_not_solved(n));
        }
    };
    let all = parts[0].shard.all;
    for (i, it) in merged.iter().enumerate() {
        at(i, &mut out);
        match it {
            Item::Common(l) => out.push(l.clone()),
            Item::PerSeed(v) => {
                let mut v = v.clone();
                v.sort_by_key(|(s, _)| *s);
                let given: Vec<u64> = v.iter().map(|(s, _)| *s).collect();
                if given != all.iter().collect::<Vec<_>>() {
                    bail!(
                        "the parts' `# seed S: {}` lines are not one for each seed of {}",
                        v[0].1.split(" = ").next().unwrap_or_default(),
                        all.words()
                    );
                }
                out.push(pool(&v)?);
            }
        }
    }
    at(merged.len(), &mut out);
    Ok(out)
}

/// The seeds of the parts before `p`.
fn parts_seeds<'a>(parts: &'a [Part], p: &'a Part) -> impl Iterator<Item = u64> + 'a {
    parts
        .iter()
        .take_while(move |q| !std::ptr::eq(*q, p))
        .flat_map(|q| q.shard.seeds().iter())
}

/// The merged rows: each key's rows over the seeds, in the first seed's
/// order; a key some seed could not solve (a load beyond what its
/// asperities carry, a grid beyond its node's memory — a `# not solved`
/// line says which) left out, as one machine leaves it out.
fn rows(parts: &[Part]) -> anyhow::Result<Vec<Vec<String>>> {
    let roles = &parts[0].roles;
    let seed_col = roles
        .iter()
        .position(|r| *r == Role::Seed)
        .context("a part without its seed column")?;
    let key_of = |row: &[String]| -> Vec<String> {
        roles
            .iter()
            .zip(row)
            .filter(|(r, _)| **r == Role::Key)
            .map(|(_, f)| f.clone())
            .collect()
    };
    let key_words = |row: &[String]| -> String {
        let cols = &parts[0].table.columns;
        roles
            .iter()
            .zip(row)
            .zip(cols)
            .filter(|((r, _), _)| **r == Role::Key)
            .take(3)
            .map(|((_, f), c)| format!("{c} = {f}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    // Every row by seed, in seed order.
    let mut by_seed: Vec<(u64, &Part, &Vec<String>)> = vec![];
    for p in parts {
        let mine: Vec<u64> = p.shard.seeds().iter().collect();
        for (i, r) in p.table.rows.iter().enumerate() {
            let seed: u64 = r[seed_col]
                .parse()
                .ok()
                .filter(|s| mine.contains(s))
                .with_context(|| {
                    format!(
                        "{}: row {} has seed \"{}\", not one of the part's {}",
                        p.name(),
                        i + 1,
                        r[seed_col],
                        p.shard.seeds().words()
                    )
                })?;
            by_seed.push((seed, p, r));
        }
    }
    by_seed.sort_by_key(|(s, _, _)| *s);
    let mut order: Vec<Vec<String>> = vec![];
    let mut groups: HashMap<Vec<String>, Vec<(u64, &Vec<String>)>> = HashMap::new();
    for (seed, p, r) in &by_seed {
        let key = key_of(r);
        let g = groups.entry(key.clone()).or_default();
        if g.iter().any(|(s, _)| s == seed) {
            bail!("{}: seed {seed} has two rows at {}", p.name(), key_words(r));
        }
        if g.is_empty() {
            order.push(key);
        }
        g.push((*seed, r));
    }
    let all: Vec<u64> = parts[0].shard.all.iter().collect();
    let explained = |seed: u64| {
        parts.iter().any(|p| {
            p.shard.seeds().iter().any(|s| s == seed)
                && p.table
                    .comments
                    .iter()
                    .any(|c| c.starts_with("not solved: "))
        })
    };
    let mut out = vec![];
    for key in order {
        let g = &groups[&key];
        if g.len() < all.len() {
            if let Some(&s) = all
                .iter()
                .find(|s| !g.iter().any(|(x, _)| x == *s) && !explained(**s))
            {
                bail!(
                    "seed {s} has no row at {} and no `# not solved` line says why: its part is \
                     incomplete",
                    key_words(g[0].1)
                );
            }
            continue;
        }
        out.push(pooled(roles, g));
    }
    if out.is_empty() {
        bail!("no row was solved for every seed (the `# not solved` lines say why)");
    }
    Ok(out)
}

/// One row over the seeds `g` (in seed order), by the columns' roles.
fn pooled(roles: &[Role], g: &[(u64, &Vec<String>)]) -> Vec<String> {
    let values = |c: usize| {
        g.iter()
            .map(move |(_, r)| r[c].parse::<f64>().unwrap_or(f64::NAN))
    };
    roles
        .iter()
        .enumerate()
        .filter(|(_, r)| **r != Role::Seed)
        .map(|(c, r)| match r {
            Role::Key | Role::Seed => g[0].1[c].clone(),
            Role::Mean => csv_number::format(Stat::of(values(c)).mean),
            Role::Sd(of) => csv_number::format(Stat::of(values(*of)).sd),
            Role::Max => csv_number::format(values(c).fold(0.0, f64::max)),
            Role::Count => g.len().to_string(),
            // As one machine: |mean of the light window's − mean of the
            // heavy window's| over the seeds.
            Role::FitErr(of) => {
                csv_number::format((Stat::of(values(*of)).mean - Stat::of(values(c)).mean).abs())
            }
            Role::NotPooled => String::new(),
        })
        .collect()
}

/// The merged table of `parts`.
pub fn merge(parts: &[Part]) -> anyhow::Result<Table> {
    check_same(parts)?;
    not_pooled(&parts[0].table.columns, &parts[0].roles)?;
    check_seeds(parts)?;
    let comments = comments(parts)?;
    let rows = rows(parts)?;
    let columns = parts[0]
        .table
        .columns
        .iter()
        .zip(&parts[0].roles)
        .filter(|(_, r)| **r != Role::Seed)
        .map(|(c, r)| merged_name(c, *r))
        .collect();
    Ok(Table {
        comments,
        columns,
        rows,
    })
}

/// Runs `roughtui merge`: the merged CSV or its picture to `out`.
pub fn run(args: &MergeArgs, out: &mut impl Write) -> anyhow::Result<()> {
    let parts: Vec<Part> = args
        .parts
        .iter()
        .map(|p| read(p))
        .collect::<Result<_, _>>()?;
    let table = merge(&parts)?;
    let text = match args.format {
        crate::cli::FormatArg::Csv => table.text(),
        crate::cli::FormatArg::Svg => super::merge_svg::picture(&parts[0], &table)?,
    };
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// `roughtui merge`, to stdout or `--output`.
pub fn main(args: &MergeArgs) -> anyhow::Result<()> {
    match &args.output {
        Some(path) => super::output::write_to(path, |w| run(args, &mut &mut *w)),
        None => {
            let stdout = std::io::stdout();
            let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
            run(args, &mut out)
        }
    }
}
