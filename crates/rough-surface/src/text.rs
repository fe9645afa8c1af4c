//! Text files as rows of numbers: the header before the first data row,
//! comments, and every row's numbers, each refusal naming its line.
//!
//! A data row is a line whose first field is a number; fields are separated
//! by white space, commas or semicolons; `#` starts a comment. Lines before
//! the first data row that do not start with a number are header lines
//! (Gwyddion and SurfaceTopography write theirs as comments). Large bodies
//! are parsed on several threads (std's `f64` parser is already the fast
//! Eisel–Lemire algorithm).

use crate::error::{Failure, Problem};

/// The rows of a text file.
#[derive(Debug, Default)]
pub(crate) struct Scan<'a> {
    /// Header lines before the first data row, 1-based line and text (a
    /// comment's text after `#`, trimmed; or a whole non-numeric line).
    pub header: Vec<(usize, &'a str)>,
    /// Comments after the first data row.
    pub later: Vec<(usize, &'a str)>,
    /// Numbers per row (the first row's).
    pub cols: usize,
    /// Every row's numbers, row after row.
    pub values: Vec<f64>,
    /// The 1-based line of each row.
    pub row_lines: Vec<usize>,
}

impl Scan<'_> {
    pub fn rows(&self) -> usize {
        self.row_lines.len()
    }
}

fn is_sep(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b',' | b';' | b'\r' | 0x0b | 0x0c)
}

/// The fields of a line's data part.
fn fields(data: &str) -> impl Iterator<Item = &str> {
    data.split(|c: char| c.is_ascii() && is_sep(c as u8))
        .filter(|f| !f.is_empty())
}

/// One field as a finite number.
pub(crate) fn number(field: &str) -> Result<f64, Problem> {
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(Problem::NotFinite(field.to_string())),
        Err(_) => Err(Problem::NotNumber(field.to_string())),
    }
}

/// A line split at its comment: (data, comment text after `#`).
fn split_comment(line: &str) -> (&str, Option<&str>) {
    match line.find('#') {
        Some(i) => (&line[..i], Some(line[i + 1..].trim())),
        None => (line, None),
    }
}

/// Numbers of the data part `data`, appended to `out`; how many.
fn row(data: &str, out: &mut Vec<f64>) -> Result<usize, Problem> {
    let b = data.as_bytes();
    let (mut i, mut n) = (0, 0);
    while i < b.len() {
        while i < b.len() && is_sep(b[i]) {
            i += 1;
        }
        if i == b.len() {
            break;
        }
        let s = i;
        while i < b.len() && !is_sep(b[i]) {
            i += 1;
        }
        // Separators are ASCII, so s..i lies on character boundaries.
        out.push(number(&data[s..i])?);
        n += 1;
    }
    Ok(n)
}

/// A part of the body, parsed with line numbers relative to its start.
#[derive(Default)]
struct Chunk<'a> {
    values: Vec<f64>,
    row_lines: Vec<usize>,
    comments: Vec<(usize, &'a str)>,
    lines: usize,
}

fn parse_chunk(body: &str, cols: usize, per_value: usize) -> Result<Chunk<'_>, Failure> {
    let mut c = Chunk {
        values: Vec::with_capacity(body.len() / per_value + cols),
        ..Chunk::default()
    };
    for (i, line) in body.split('\n').enumerate() {
        c.lines = i + 1;
        let (data, comment) = split_comment(line);
        let before = c.values.len();
        let got = row(data, &mut c.values).map_err(|p| (Some(i), p))?;
        if got == 0 {
            if let Some(t) = comment {
                c.comments.push((i, t));
            }
            continue;
        }
        if got != cols {
            c.values.truncate(before);
            return Err((Some(i), Problem::Ragged { got, want: cols }));
        }
        c.row_lines.push(i);
    }
    if body.ends_with('\n') {
        c.lines -= 1;
    }
    Ok(c)
}

/// Whether a first data row is written with decimal commas ("1,5 2,25").
fn decimal_comma(data: &str) -> Option<String> {
    let words: Vec<&str> = data
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|w| !w.is_empty())
        .collect();
    let comma = |w: &str| {
        let b = w.as_bytes();
        w.matches(',').count() == 1
            && !w.contains('.')
            && b.windows(3)
                .any(|t| t[1] == b',' && t[0].is_ascii_digit() && t[2].is_ascii_digit())
    };
    (words.len() >= 2 && words.iter().all(|w| comma(w))).then(|| words[0].to_string())
}

/// Body bytes from which the parse is split over threads.
const PARALLEL_FROM: usize = 1 << 20;

/// The lines before the first data row.
pub(crate) struct Head<'a> {
    /// Header lines (see [`Scan::header`]).
    pub header: Vec<(usize, &'a str)>,
    /// The first data row's 1-based line, byte offset and field count.
    first: Option<(usize, usize, usize)>,
}

/// Reads the header, up to the first data row.
pub(crate) fn head(text: &str) -> Result<Head<'_>, Failure> {
    let mut header = Vec::new();
    let mut offset = 0;
    for (i, line) in text.split('\n').enumerate() {
        let start = offset;
        offset += line.len() + 1;
        let (data, comment) = split_comment(line);
        match fields(data).next() {
            None => {
                if let Some(t) = comment {
                    header.push((i + 1, t));
                }
            }
            Some(f) if f.parse::<f64>().is_err() => header.push((i + 1, line.trim())),
            Some(_) => {
                if let Some(w) = decimal_comma(data) {
                    return Err((Some(i + 1), Problem::DecimalComma(w)));
                }
                let mut probe = Vec::new();
                let cols = row(data, &mut probe).map_err(|p| (Some(i + 1), p))?;
                return Ok(Head {
                    header,
                    first: Some((i + 1, start, cols)),
                });
            }
        }
    }
    Ok(Head {
        header,
        first: None,
    })
}

/// Reads `text` into its header and rows.
pub(crate) fn scan<'a>(text: &'a str, head: Head<'a>) -> Result<Scan<'a>, Failure> {
    let Some((first_line, start, cols)) = head.first else {
        return Err((None, Problem::Empty));
    };
    // Bytes per number on the first row, to size the buffers.
    let first_len = text[start..].find('\n').unwrap_or(text.len() - start) + 1;
    let per_value = (first_len / cols).max(2);
    let mut s = Scan {
        header: head.header,
        cols,
        ..Scan::default()
    };
    let body = &text[start..];
    let threads = if body.len() >= PARALLEL_FROM {
        std::thread::available_parallelism().map_or(1, |n| n.get().min(4))
    } else {
        1
    };
    // Split at line ends.
    let mut parts = Vec::with_capacity(threads);
    let mut rest = body;
    for k in (1..=threads).rev() {
        let cut = if k == 1 {
            rest.len()
        } else {
            let at = rest.len() / k;
            rest[at..].find('\n').map_or(rest.len(), |j| at + j + 1)
        };
        let (a, b) = rest.split_at(cut);
        parts.push(a);
        rest = b;
    }
    let chunks: Vec<Result<Chunk<'_>, Failure>> = if parts.len() == 1 {
        vec![parse_chunk(parts[0], cols, per_value)]
    } else {
        std::thread::scope(|sc| {
            let handles: Vec<_> = parts
                .iter()
                .map(|p| sc.spawn(move || parse_chunk(p, cols, per_value)))
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("parse thread"))
                .collect()
        })
    };
    let total: usize = chunks
        .iter()
        .map(|c| c.as_ref().map_or(0, |c| c.values.len()))
        .sum();
    s.values.reserve_exact(total);
    let mut line0 = first_line;
    for c in chunks {
        let c = c.map_err(|(l, p)| (l.map(|l| l + line0), p))?;
        s.values.extend_from_slice(&c.values);
        s.row_lines.extend(c.row_lines.iter().map(|l| l + line0));
        s.later
            .extend(c.comments.iter().map(|&(l, t)| (l + line0, t)));
        line0 += c.lines;
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_comments_and_lines() {
        let t = "# a\nWidth: 3\n\n1 2 3\n4,5;6 # c\n\n# d\n7\t8 9\n";
        let s = scan(t, head(t).unwrap()).unwrap();
        assert_eq!(s.header, vec![(1, "a"), (2, "Width: 3")]);
        assert_eq!(s.later, vec![(7, "d")]);
        assert_eq!(s.cols, 3);
        assert_eq!(s.values, vec![1., 2., 3., 4., 5., 6., 7., 8., 9.]);
        assert_eq!(s.row_lines, vec![4, 5, 8]);
    }

    #[test]
    fn threads_keep_lines() {
        let mut t = String::from("# h\n");
        let n = 200_000;
        for i in 0..n {
            t.push_str(&format!("{i} {}\n", i + 1));
        }
        let s = scan(&t, head(&t).unwrap()).unwrap();
        assert_eq!(s.rows(), n);
        assert_eq!(s.row_lines[n - 1], n + 1);
        assert_eq!(s.values[2 * n - 1], n as f64);
        t.push_str("1 2 3\n");
        assert_eq!(
            scan(&t, head(&t).unwrap()).unwrap_err(),
            (Some(n + 2), Problem::Ragged { got: 3, want: 2 })
        );
        let bad = t.replacen("150000 150001", "150000 x", 1);
        assert_eq!(
            scan(&bad, head(&bad).unwrap()).unwrap_err(),
            (Some(150_002), Problem::NotNumber("x".into()))
        );
    }

    #[test]
    fn decimal_commas_are_named() {
        let all = |t: &'static str| scan(t, head(t)?);
        assert_eq!(
            all("1,5 2,25\n").unwrap_err(),
            (Some(1), Problem::DecimalComma("1,5".into()))
        );
        assert_eq!(all("1.5, 2.25\n").unwrap().values, vec![1.5, 2.25]);
        assert_eq!(all("1,2,3\n").unwrap().values, vec![1., 2., 3.]);
    }
}
