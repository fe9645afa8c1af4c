//! The `#` lines of a sharded export: each seed's own run says "seed 3"
//! where the ensemble says "seeds 1–8", and a few lines hold a statistic of
//! the seeds' solutions (the realisations' rms height). A part keeps those
//! per seed (`seed 3: …`); merge pools them into the line one machine
//! writes for all the seeds.

use std::collections::BTreeMap;

use anyhow::bail;

use crate::contact::{Seeds, Stat};
use crate::physical::csv_number;

/// Lines holding a statistic of the seeds' solutions, by their start.
const STATISTICS: &[&str] = &["surface = matched to", "kappa = "];
/// A statistic followed, where there are several seeds, by its sample
/// standard deviation: the text before the number and the unit after it.
const WITH_SD: &[(&str, &str)] = &[("its own h_rms ", " m")];
/// The note of one realisation, and of several.
const ONE_NOTE: &str = " (one realisation: the *_sd columns are NaN)";
fn many_note(n: u32) -> String {
    format!(" (columns: means over {n} realisations; *_sd: their sample standard deviation)")
}
const NOT_SOLVED: &str = "not solved: ";
const PER_SEED: &str = "seed ";

/// One seed's line in the ensemble's words: its "seed S" the ensemble's
/// seeds, its one-realisation note the ensemble's.
fn ensemble_words(line: &str, seed: u64, all: Seeds) -> String {
    if line.starts_with(NOT_SOLVED) {
        return line.to_string();
    }
    let own = Seeds::one(seed).words();
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(i) = rest.find(&own) {
        let after = &rest[i + own.len()..];
        out.push_str(&rest[..i]);
        if after.starts_with(|c: char| c.is_ascii_digit()) {
            out.push_str(&own);
        } else {
            out.push_str(&all.words());
        }
        rest = after;
    }
    out.push_str(rest);
    if all.count > 1 {
        out = out.replace(ONE_NOTE, &many_note(all.count));
    }
    out
}

/// A seed's lines split: the others in order, and the "not solved" lines
/// by the index of the line they come before.
fn split(lines: &[String]) -> (Vec<&str>, BTreeMap<usize, Vec<&str>>) {
    let (mut body, mut notes) = (vec![], BTreeMap::<usize, Vec<&str>>::new());
    for l in lines {
        if l.starts_with(NOT_SOLVED) {
            notes.entry(body.len()).or_default().push(l);
        } else {
            body.push(l.as_str());
        }
    }
    (body, notes)
}

/// The `#` lines of a part from its seeds' own (each seed's run alone):
/// the ensemble's words, a statistic's line once per seed (`seed S: …`),
/// every seed's "not solved" lines.
pub fn combine(seeds: &[(u64, Vec<String>)], all: Seeds) -> anyhow::Result<Vec<String>> {
    let worded: Vec<(u64, Vec<String>)> = seeds
        .iter()
        .map(|(s, ls)| (*s, ls.iter().map(|l| ensemble_words(l, *s, all)).collect()))
        .collect();
    let split: Vec<_> = worded.iter().map(|(s, ls)| (*s, split(ls))).collect();
    let Some((_, (first, _))) = split.first() else {
        bail!("a part without seeds");
    };
    if let Some((s, _)) = split.iter().find(|(_, (b, _))| b.len() != first.len()) {
        bail!("seed {s}'s run has other `#` lines than the part's first seed's");
    }
    let mut out = vec![];
    let notes_at = |i: usize, out: &mut Vec<String>| {
        for (_, (_, notes)) in &split {
            for n in notes.get(&i).into_iter().flatten() {
                if !out.iter().any(|o| o == n) {
                    out.push(n.to_string());
                }
            }
        }
    };
    for (i, line) in first.iter().enumerate() {
        notes_at(i, &mut out);
        let statistic = STATISTICS.iter().any(|p| line.starts_with(p))
            || split.iter().any(|(_, (b, _))| b[i] != *line);
        if statistic {
            for (s, (b, _)) in &split {
                out.push(format!("{PER_SEED}{s}: {}", b[i]));
            }
        } else {
            out.push(line.to_string());
        }
    }
    notes_at(first.len(), &mut out);
    Ok(out)
}

/// A line of a part, as merge reads it.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// The same in every part.
    Common(String),
    /// A statistic, each seed's line.
    PerSeed(Vec<(u64, String)>),
}

/// A part's `#` lines read (its part-only lines left out): the items in
/// order, and the "not solved" lines by the index of the item they come
/// before.
pub fn items(lines: &[String]) -> (Vec<Item>, BTreeMap<usize, Vec<String>>) {
    let (mut out, mut notes) = (Vec::<Item>::new(), BTreeMap::<usize, Vec<String>>::new());
    for l in lines {
        if super::part::is_part_only(l) {
            continue;
        }
        if l.starts_with(NOT_SOLVED) {
            notes.entry(out.len()).or_default().push(l.clone());
            continue;
        }
        let per_seed = l
            .strip_prefix(PER_SEED)
            .and_then(|r| r.split_once(": "))
            .and_then(|(s, text)| Some((s.parse::<u64>().ok()?, text)));
        match (per_seed, out.last_mut()) {
            (Some((s, text)), Some(Item::PerSeed(v)))
                if text.split(" = ").next() == v[0].1.split(" = ").next() =>
            {
                v.push((s, text.to_string()))
            }
            (Some((s, text)), _) => out.push(Item::PerSeed(vec![(s, text.to_string())])),
            (None, _) => out.push(Item::Common(l.clone())),
        }
    }
    (out, notes)
}

/// A number of a line: where it starts and ends.
fn numbers(line: &str) -> Vec<(usize, usize)> {
    let b = line.as_bytes();
    let mut out = vec![];
    let mut i = 0;
    while i < b.len() {
        let starts =
            b[i].is_ascii_digit() || (b[i] == b'-' && b.get(i + 1).is_some_and(u8::is_ascii_digit));
        let glued = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b"_.".contains(&b[i - 1]));
        if !starts || glued {
            i += 1;
            continue;
        }
        let mut j = i + 1;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j + 1 < b.len() && b[j] == b'.' && b[j + 1].is_ascii_digit() {
            j += 1;
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
        }
        if j < b.len() && (b[j] == b'e' || b[j] == b'E') {
            let mut k = j + 1;
            if k < b.len() && (b[k] == b'-' || b[k] == b'+') {
                k += 1;
            }
            if k < b.len() && b[k].is_ascii_digit() {
                while k < b.len() && b[k].is_ascii_digit() {
                    k += 1;
                }
                j = k;
            }
        }
        out.push((i, j));
        i = j;
    }
    out
}

/// The seeds' lines of a statistic as one machine writes it over all of
/// them: each number that differs between the seeds their mean (and, for
/// [`WITH_SD`], its sample standard deviation after the unit).
pub fn pool(lines: &[(u64, String)]) -> anyhow::Result<String> {
    let Some((_, first)) = lines.first() else {
        bail!("a statistic without seeds");
    };
    let spans: Vec<Vec<(usize, usize)>> = lines.iter().map(|(_, l)| numbers(l)).collect();
    let skeleton = |l: &str, s: &[(usize, usize)]| -> Vec<String> {
        let mut parts = vec![];
        let mut at = 0;
        for &(a, b) in s {
            parts.push(l[at..a].to_string());
            at = b;
        }
        parts.push(l[at..].to_string());
        parts
    };
    let base = skeleton(first, &spans[0]);
    for ((s, l), sp) in lines.iter().zip(&spans) {
        if skeleton(l, sp) != base {
            bail!(
                "seed {s}'s line \"{l}\" is not the first seed's \"{first}\" but for its numbers"
            );
        }
    }
    let mut out = String::new();
    let mut sd_after: Option<(&str, f64)> = None;
    for (k, text) in base.iter().enumerate() {
        match sd_after.take() {
            // The unit comes first, then the deviation.
            Some((unit, sd)) => {
                out.push_str(unit);
                out.push_str(&format!(
                    " (mean over the seeds, sd {})",
                    csv_number::format(sd)
                ));
                out.push_str(&text[unit.len()..]);
            }
            None => out.push_str(text),
        }
        let Some(&(a, b)) = spans[0].get(k) else {
            break;
        };
        let values: Vec<&str> = lines
            .iter()
            .zip(&spans)
            .map(|((_, l), sp)| &l[sp[k].0..sp[k].1])
            .collect();
        let with_sd = WITH_SD
            .iter()
            .find(|(before, unit)| text.ends_with(before) && base[k + 1].starts_with(unit))
            .filter(|_| lines.len() > 1);
        if with_sd.is_none() && values.iter().all(|v| *v == &first[a..b]) {
            out.push_str(&first[a..b]);
            continue;
        }
        let stat = Stat::of(values.iter().map(|v| v.parse::<f64>().unwrap_or(f64::NAN)));
        out.push_str(&csv_number::format(stat.mean));
        sd_after = with_sd.map(|(_, unit)| (*unit, stat.sd));
    }
    Ok(out)
}

/// The "not solved" lines of all seeds as one machine writes them: each
/// once, and of a load some seeds could not carry, the first such seed's
/// ("p̄/H = 1, seed 3: …"), in the order of the loads.
pub fn pool_not_solved(lines: &[String]) -> Vec<String> {
    let mut plain: Vec<String> = vec![];
    let mut by_load: Vec<(String, u64, String)> = vec![];
    for l in lines {
        let seeded = l
            .split_once(", seed ")
            .and_then(|(what, rest)| Some((what, rest.split(':').next()?.parse::<u64>().ok()?)));
        match seeded {
            Some((what, seed)) => match by_load.iter_mut().find(|(w, _, _)| w == what) {
                Some(e) if seed < e.1 => *e = (what.to_string(), seed, l.clone()),
                Some(_) => {}
                None => by_load.push((what.to_string(), seed, l.clone())),
            },
            None if !plain.contains(l) => plain.push(l.clone()),
            None => {}
        }
    }
    let first_number = |w: &str| {
        numbers(w)
            .first()
            .and_then(|&(a, b)| w[a..b].parse::<f64>().ok())
            .unwrap_or(f64::INFINITY)
    };
    by_load.sort_by(|a, b| first_number(&a.0).total_cmp(&first_number(&b.0)));
    plain.extend(by_load.into_iter().map(|(_, _, l)| l));
    plain
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(v: &[&str]) -> Vec<String> {
        v.iter().map(|x| x.to_string()).collect()
    }

    #[test]
    fn a_seeds_words_become_the_ensembles() {
        let all = Seeds { first: 1, count: 8 };
        assert_eq!(
            ensemble_words(
                "grid, seed 3 (one realisation: the *_sd columns are NaN)",
                3,
                all
            ),
            "grid, seeds 1–8 (columns: means over 8 realisations; *_sd: their sample standard \
             deviation)"
        );
        assert_eq!(
            ensemble_words("seed 31, seed 3.", 3, all),
            "seed 31, seeds 1–8."
        );
        assert_eq!(
            ensemble_words("not solved: x, seed 3: y", 3, all),
            "not solved: x, seed 3: y"
        );
    }

    #[test]
    fn statistics_are_kept_per_seed_and_pooled() {
        let all = Seeds { first: 1, count: 2 };
        let run = |seed: u64, h: &str| {
            (
                seed,
                s(&[
                    "roughtui 0.1.0: scene \"fig2\"",
                    &format!("simulation = grid 64, seed {seed} (one realisation: the *_sd columns are NaN)"),
                    &format!("surface = matched to sqrt(2 m2) = 0.006; its own h_rms {h} m against the scene's 2e-8 m"),
                    "units: m",
                ]),
            )
        };
        let part = combine(&[run(1, "3e-8"), run(2, "5e-8")], all).unwrap();
        assert_eq!(part[1], "simulation = grid 64, seeds 1–2 (columns: means over 2 realisations; *_sd: their sample standard deviation)");
        assert!(part[2].starts_with("seed 1: surface = "), "{part:?}");
        assert!(part[3].starts_with("seed 2: surface = "), "{part:?}");
        let (items, _) = items(&part);
        assert_eq!(items.len(), 4);
        let Item::PerSeed(v) = &items[2] else {
            panic!("{items:?}")
        };
        let sd = Stat::of([3e-8, 5e-8]).sd;
        assert_eq!(
            pool(v).unwrap(),
            format!(
                "surface = matched to sqrt(2 m2) = 0.006; its own h_rms 4e-8 m (mean over the \
                 seeds, sd {}) against the scene's 2e-8 m",
                csv_number::format(sd)
            )
        );
        // One seed: its line as it is.
        assert_eq!(pool(&v[..1]).unwrap(), v[0].1);
        // A line that differs in more than numbers is refused.
        let bad = [(1, "a 1 b".to_string()), (2, "a 2 c".to_string())];
        assert!(pool(&bad).is_err());
        assert_eq!(
            pool(&[(1, "k = 2 x".into()), (2, "k = 4 x".into())]).unwrap(),
            "k = 3 x"
        );
    }

    #[test]
    fn not_solved_loads_keep_their_first_seed_in_load_order() {
        let lines = s(&[
            "not solved: p̄/H = 1, seed 4: beyond",
            "not solved: p̄/H = 0.5, seed 5: beyond",
            "not solved: p̄/H = 1, seed 2: beyond",
            "not solved: 16 per wavelength, cell 4: too large",
            "not solved: 16 per wavelength, cell 4: too large",
        ]);
        assert_eq!(
            pool_not_solved(&lines),
            s(&[
                "not solved: 16 per wavelength, cell 4: too large",
                "not solved: p̄/H = 0.5, seed 5: beyond",
                "not solved: p̄/H = 1, seed 2: beyond",
            ])
        );
    }
}
