//! Text files of several channels: Gwyddion's ASCII exports concatenated
//! into one file, each block headed by its own `# Channel:` line (and its
//! own `# Width:`, `# Height:`, `# Value units:`), as SurfaceTopography's
//! text reader takes them: the first channel whose values are lengths, the
//! others (phase, voltage …) left aside; `--channel N|TITLE` picks another.

use crate::error::{Failure, Problem};
use crate::formats::text::header::Header;
use crate::units::per_metre;

/// One channel's lines.
pub(crate) struct Block<'a> {
    pub title: String,
    /// The value unit as written ("" without one: metres).
    pub unit: String,
    /// The block's text, from its `Channel:` line to the next.
    pub text: &'a str,
    /// Its first line's number in the file, 1-based.
    pub first_line: usize,
}

impl Block<'_> {
    fn is_length(&self) -> bool {
        self.unit.is_empty() || per_metre(&self.unit).is_some()
    }

    fn describe(&self, n: usize) -> String {
        let unit = if self.unit.is_empty() {
            "m"
        } else {
            &self.unit
        };
        format!("{n} '{}' ({unit})", self.title)
    }
}

/// The text of a `Channel:` label line (a comment's or the whole line's).
fn label(line: &str) -> Option<String> {
    let t = line.trim();
    let t = t.strip_prefix('#').unwrap_or(t).trim();
    let h = Header::read(&[(0, t)]).ok()?;
    if h.channels.is_empty() {
        return None;
    }
    let title = t.split_once([':', '=', '：']).map_or("", |(_, v)| v.trim());
    Some(title.to_string())
}

/// The blocks of a file with two or more `Channel:` lines; empty when it
/// has fewer (one channel, read as it is).
pub(crate) fn blocks(text: &str) -> Result<Vec<Block<'_>>, Failure> {
    let mut starts = Vec::new();
    let mut offset = 0;
    for (i, line) in text.split('\n').enumerate() {
        if let Some(title) = label(line) {
            starts.push((offset, i + 1, title));
        }
        offset += line.len() + 1;
    }
    if starts.len() < 2 {
        return Ok(Vec::new());
    }
    let mut out = Vec::with_capacity(starts.len());
    for (k, (start, first_line, title)) in starts.iter().enumerate() {
        // Lines before the first label go with the first block.
        let from = if k == 0 { 0 } else { *start };
        let to = starts.get(k + 1).map_or(text.len(), |s| s.0);
        let block = &text[from..to.min(text.len())];
        let lines: Vec<(usize, &str)> = block
            .split('\n')
            .enumerate()
            .map(|(j, l)| (first_line + j, l.trim().trim_start_matches('#').trim()))
            .filter(|(_, l)| !l.starts_with(|c: char| c.is_ascii_digit() || c == '-'))
            .collect();
        let header = Header::read(&lines)?;
        let unit = header.value_unit.map(|(u, _)| u).unwrap_or_default();
        out.push(Block {
            title: title.clone(),
            unit,
            text: block,
            first_line: if k == 0 { 1 } else { *first_line },
        });
    }
    Ok(out)
}

/// The block `choice` names (its number from 0, or its title), else the
/// first whose values are lengths; the note saying so.
pub(crate) fn pick<'b, 'a>(
    blocks: &'b [Block<'a>],
    choice: Option<&str>,
) -> Result<(&'b Block<'a>, String), Failure> {
    let all = blocks
        .iter()
        .enumerate()
        .map(|(n, b)| b.describe(n))
        .collect::<Vec<_>>()
        .join(", ");
    let bad = |s: String| (None, Problem::Several(s));
    let (n, b) = match choice.map(str::trim) {
        None => blocks
            .iter()
            .enumerate()
            .find(|(_, b)| b.is_length())
            .ok_or_else(|| {
                bad(format!(
                    "no channel holds heights (values in a unit of length): {all}"
                ))
            })?,
        Some(c) => {
            let found = match c.parse::<usize>() {
                Ok(n) => blocks.get(n).map(|b| (n, b)),
                Err(_) => blocks
                    .iter()
                    .enumerate()
                    .find(|(_, b)| b.title.eq_ignore_ascii_case(c)),
            };
            let (n, b) =
                found.ok_or_else(|| bad(format!("no channel '{c}'; the channels are {all}")))?;
            if !b.is_length() {
                return Err(bad(format!(
                    "channel {} holds values in {}, not a length: the channels are {all}",
                    b.describe(n),
                    b.unit
                )));
            }
            (n, b)
        }
    };
    let others: Vec<String> = blocks
        .iter()
        .enumerate()
        .filter(|(m, _)| *m != n)
        .map(|(m, o)| o.describe(m))
        .collect();
    let note = format!(
        "channel {} read; also in the file: {} (--channel N or TITLE)",
        b.describe(n),
        others.join(", ")
    );
    Ok((b, note))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gwyddion_exports_concatenated() {
        let t = "# Channel: Phase\n# Width: 4 µm\n# Value units: deg\n1 2 3 4\n\
                 # Channel: Height\n# Width: 4 µm\n# Value units: nm\n5 6 7 8\n";
        let b = blocks(t).unwrap();
        assert_eq!(b.len(), 2);
        assert_eq!((b[0].title.as_str(), b[0].unit.as_str()), ("Phase", "deg"));
        assert_eq!((b[1].first_line, b[1].unit.as_str()), (5, "nm"));
        let (h, note) = pick(&b, None).unwrap();
        assert!(h.text.starts_with("# Channel: Height") && h.text.ends_with("8\n"));
        assert_eq!(
            note,
            "channel 1 'Height' (nm) read; also in the file: 0 'Phase' (deg) \
             (--channel N or TITLE)"
        );
        assert!(pick(&b, Some("phase")).is_err());
        assert!(blocks("# Channel: Height\n1 2 3 4\n").unwrap().is_empty());
    }
}
