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
    pub later: Vec<(usize, String)>,
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

/// One field as a number: finite, or NaN for an undefined point (`nan`,
/// `NaN`, `-nan` as C and numpy print it); infinities are refused.
pub(crate) fn number(field: &str) -> Result<f64, Problem> {
    if let Some(v) = crate::formats::text::decimal::fast(field) {
        return Ok(v);
    }
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) if v.is_nan() => Ok(f64::NAN),
        Ok(_) => Err(Problem::NotFinite(field.to_string())),
        Err(_) => Err(Problem::NotNumber(field.to_string())),
    }
}

/// A number that must be defined (`what`: a wavevector, a PSD value).
pub(crate) fn defined(field: &str, what: &'static str) -> Result<f64, Problem> {
    match number(field)? {
        v if v.is_nan() => Err(Problem::UndefinedValue(what)),
        v => Ok(v),
    }
}

/// A delimiter that ends a cell even when the cell is empty.
fn is_hard(b: u8) -> bool {
    matches!(b, b',' | b';')
}

/// A line split at its comment: (data, comment text after `#`).
fn split_comment(line: &str) -> (&str, Option<&str>) {
    match line.find('#') {
        Some(i) => (&line[..i], Some(line[i + 1..].trim())),
        None => (line, None),
    }
}

/// Numbers of the data part `data`, appended to `out`; how many, and
/// whether the line ended with a comma or semicolon.
///
/// Between commas or semicolons an empty cell is an undefined point (NaN):
/// `1,,3` and `,2,3` hold three cells. One comma or semicolon at the end of
/// the line closes the last cell (`1,2,3,` holds three); a row one cell
/// short that ends with one has its last cell empty ([`parse_chunk`]).
fn row(data: &str, out: &mut Vec<f64>) -> Result<(usize, bool), Problem> {
    let b = data.as_bytes();
    let (mut i, mut n) = (0, 0);
    // Commas or semicolons since the last cell (or the line's start).
    let mut hard = 0usize;
    while i < b.len() {
        if is_sep(b[i]) {
            hard += usize::from(is_hard(b[i]));
            i += 1;
            continue;
        }
        let s = i;
        while i < b.len() && !is_sep(b[i]) {
            i += 1;
        }
        let empty = if n == 0 { hard } else { hard.saturating_sub(1) };
        out.extend(std::iter::repeat_n(f64::NAN, empty));
        n += empty;
        // Separators are ASCII, so s..i lies on character boundaries.
        out.push(number(&data[s..i])?);
        n += 1;
        hard = 0;
    }
    if n > 0 && hard > 1 {
        out.extend(std::iter::repeat_n(f64::NAN, hard - 1));
        n += hard - 1;
    }
    Ok((n, n > 0 && hard > 0))
}

/// A part of the body, parsed with line numbers relative to its start
/// (0-based).
#[derive(Default)]
pub(crate) struct Chunk {
    pub values: Vec<f64>,
    pub row_lines: Vec<usize>,
    pub comments: Vec<(usize, String)>,
    /// Lines in the part (a last line without its end counts).
    pub lines: usize,
}

pub(crate) fn parse_chunk(body: &str, cols: usize, per_value: usize) -> Result<Chunk, Failure> {
    let mut c = Chunk {
        values: Vec::with_capacity(body.len() / per_value + cols),
        ..Chunk::default()
    };
    for (i, line) in body.split('\n').enumerate() {
        c.lines = i + 1;
        let (data, comment) = split_comment(line);
        let before = c.values.len();
        let (mut got, open) = row(data, &mut c.values).map_err(|p| (Some(i), p))?;
        if open && got + 1 == cols {
            c.values.push(f64::NAN);
            got += 1;
        }
        if got == 0 {
            if let Some(t) = comment {
                c.comments.push((i, t.to_string()));
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
    pub first: Option<(usize, usize, usize)>,
}

/// Rows looked at to tell a closing comma from an empty last cell.
const PROBE_ROWS: usize = 64;

/// The cells per row, from the first data row (cells, ends with a comma)
/// and the text after it: where every row of the first few ends with a
/// comma or semicolon, it closes the row (`1,2,3,`); otherwise a row ending
/// with one has an empty last cell (`1,2,` of three columns).
fn columns(first: (usize, bool), rest: &str) -> usize {
    let mut probe = Vec::new();
    let rows = std::iter::once(Ok(first)).chain(
        rest.split('\n')
            .map(|l| row(split_comment(l).0, &mut probe))
            .filter(|r| !matches!(r, Ok((0, _))))
            .take(PROBE_ROWS),
    );
    let (mut all_open, mut one_more) = (true, false);
    for r in rows {
        let Ok((n, open)) = r else { break };
        all_open &= open;
        // A full row past the first's cells (not one like the first, nor
        // a row cut short).
        one_more |= !open && n == first.0 + 1;
    }
    first.0 + usize::from(first.1 && one_more && !all_open)
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
                let first = row(data, &mut probe).map_err(|p| (Some(i + 1), p))?;
                let cols = columns(first, &text[offset.min(text.len())..]);
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
        crate::threads::count()
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
    let chunks: Vec<Result<Chunk, Failure>> = if parts.len() == 1 {
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
            .extend(c.comments.into_iter().map(|(l, t)| (l + line0, t)));
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
        assert_eq!(s.later, vec![(7, "d".to_string())]);
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
    fn empty_cells_and_nan_are_undefined() {
        let nan = |t: &str| {
            let s = scan(t, head(t).unwrap()).unwrap();
            let v: Vec<Option<f64>> = s
                .values
                .iter()
                .map(|v| (!v.is_nan()).then_some(*v))
                .collect();
            (s.cols, v)
        };
        let (c, v) = nan("1,,3\n,5,6\n7,8,\n");
        assert_eq!(c, 3);
        assert_eq!(
            v,
            vec![
                Some(1.),
                None,
                Some(3.),
                None,
                Some(5.),
                Some(6.),
                Some(7.),
                Some(8.),
                None
            ]
        );
        // The first row's last cell empty.
        assert_eq!(
            nan("1;2;\n4;5;6\n").1,
            vec![Some(1.), Some(2.), None, Some(4.), Some(5.), Some(6.)]
        );
        // A comma closing every row is no cell.
        assert_eq!(
            nan("1,2,\n3,4,\n"),
            (2, vec![Some(1.), Some(2.), Some(3.), Some(4.)])
        );
        assert_eq!(nan("1,2,,\n3,4,,\n").0, 3);
        // A Dektak profile cut inside its last row: still three cells.
        assert_eq!(head("1,2,,\n3,4,,\n5,6\n").unwrap().first.unwrap().2, 3);
        assert_eq!(nan("nan 2 NaN -nan\n").1, vec![None, Some(2.), None, None]);
        assert_eq!(
            head("1 inf\n").err().unwrap(),
            (Some(1), Problem::NotFinite("inf".into()))
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
