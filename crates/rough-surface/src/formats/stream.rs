//! A large height matrix read without holding its text: the file is read
//! in blocks that are hashed as they come and parsed on worker threads,
//! their numbers appended in order to the one buffer of heights. A
//! 4096 × 4096 Gwyddion text map (≈ 195 MB) then needs its heights
//! (134 MB) and a block or two of text at a time, not the text and the
//! heights at once.
//!
//! Only a height matrix is streamed (a size header, or other than two
//! numbers per row, as [`crate::parse`] decides): a contact.engineering
//! download or a two-column table is read whole, as are files below
//! [`STREAM_FROM`].

use std::collections::BTreeMap;
use std::io::Read;
use std::sync::mpsc;
use std::sync::{Arc, Mutex};

use sha2::{Digest, Sha256};

use crate::error::{Failure, Problem};
use crate::formats::text::scan::{self, Chunk, Scan};

/// Files from this size on are streamed (smaller ones are read whole).
pub(crate) const STREAM_FROM: u64 = 32 << 20;

/// Bytes read at a time.
const BLOCK: usize = 4 << 20;

/// The header is looked for in this many bytes at most.
const HEAD_MAX: usize = 16 << 20;

/// What reading a file gave.
pub(crate) enum Streamed {
    /// Not a matrix to stream: the whole file, to parse as text.
    Whole(Vec<u8>),
    /// The matrix, its SHA-256 (lower-case hex) and the first block's text
    /// the scan's header lines borrow from.
    Matrix {
        head: String,
        rest: Rest,
        sha256: String,
    },
}

/// The streamed rows after the header (see [`Scan`]).
pub(crate) struct Rest {
    pub cols: usize,
    pub values: Vec<f64>,
    pub row_lines: Vec<usize>,
    pub later: Vec<(usize, String)>,
}

impl Rest {
    /// Whether a comment after the first row is a header line (another
    /// channel follows: the file is read whole).
    pub fn has_headers(&self) -> bool {
        self.later.iter().any(|(l, t)| {
            crate::formats::text::header::Header::read(&[(*l, t.as_str())])
                .map_or(true, |h| !h.is_empty())
        })
    }

    /// The scan of the file, its header lines read from `head`.
    pub fn scan<'a>(self, head: &'a str) -> Result<Scan<'a>, Failure> {
        let h = scan::head(head)?;
        Ok(Scan {
            header: h.header,
            later: self.later,
            cols: self.cols,
            values: self.values,
            row_lines: self.row_lines,
        })
    }
}

/// Reads up to `want` more bytes of `r` into `buf`; how many.
fn fill(r: &mut impl Read, buf: &mut Vec<u8>, want: usize) -> Result<usize, Problem> {
    let before = buf.len();
    r.take(want as u64)
        .read_to_end(buf)
        .map_err(|e| Problem::Read(e.to_string()))?;
    Ok(buf.len() - before)
}

fn utf8(bytes: &[u8], line0: usize) -> Result<&str, Failure> {
    std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        (Some(line0 + line + 1), Problem::NotText)
    })
}

/// Reads `file` of `len` bytes (its name's extension `ext`): streamed when
/// it is a large matrix of UTF-8 text with decimal points.
pub(crate) fn read(file: impl Read, len: u64, ext: &str) -> Result<Streamed, Failure> {
    read_in(file, (len, ext), STREAM_FROM, BLOCK)
}

/// [`read`] streaming from `from` bytes on, in blocks of `block`.
fn read_in(
    mut file: impl Read,
    (len, ext): (u64, &str),
    from: u64,
    block: usize,
) -> Result<Streamed, Failure> {
    let mut first = Vec::with_capacity(if len < from { len as usize + 1 } else { block });
    if len < from {
        fill(&mut file, &mut first, crate::limits::MAX_BYTES as usize + 1)
            .map_err(|p| (None, p))?;
        return Ok(Streamed::Whole(first));
    }
    // The first blocks, up to a line end past the first data row: the
    // header and the first rows.
    let cut = loop {
        let got = fill(&mut file, &mut first, block).map_err(|p| (None, p))?;
        let cut = first.iter().rposition(|&b| b == b'\n');
        let found = cut.is_some_and(|c| {
            std::str::from_utf8(&first[..=c])
                .ok()
                .and_then(|t| scan::head(t).ok())
                .is_some_and(|h| h.first.is_some())
        });
        if found || got == 0 || first.len() > HEAD_MAX {
            break cut;
        }
    };
    let Some(cut) = cut else {
        return whole(first, file);
    };
    let tail = first.split_off(cut + 1);
    let head_text = match utf8(&first, 0) {
        Ok(t) => t.strip_prefix('\u{feff}').unwrap_or(t),
        Err(_) => {
            first.extend_from_slice(&tail);
            return whole(first, file);
        }
    };
    // Anything but plain UTF-8 text with decimal points (a binary format,
    // Windows-1252, decimal commas) and any header it cannot read are left
    // to the whole file's reading, which names them.
    let plain = crate::formats::sniff::format(&first, ext) == crate::formats::sniff::Format::Text
        && crate::formats::sniff::text(&first).is_ok_and(|(_, assumed)| assumed.is_empty());
    let h = scan::head(head_text).ok().filter(|_| plain);
    let header = h
        .as_ref()
        .and_then(|h| crate::formats::text::header::Header::read(&h.header).ok());
    let (Some(h), Some(header)) = (h, header) else {
        first.extend_from_slice(&tail);
        return whole(first, file);
    };
    let matrix = match h.first {
        // Three columns without a size are a profile or a point cloud,
        // read whole.
        Some((_, _, cols)) => {
            !crate::formats::text::ce::is_ce(&h.header)
                && header.is_matrix(cols)
                && (cols != 3 || header.has_size())
        }
        None => false,
    };
    if !matrix {
        first.extend_from_slice(&tail);
        return whole(first, file);
    }
    let (first_line, start, cols) = h.first.expect("a matrix has a first row");
    let bom = first.len() - head_text.len();
    let body0 = first[bom + start..].to_vec();
    let first_len = body0
        .iter()
        .position(|&b| b == b'\n')
        .unwrap_or(body0.len())
        + 1;
    let per_value = (first_len / cols).max(2);
    let head = String::from_utf8(first[bom..bom + start].to_vec()).expect("checked above");
    let mut hasher = Sha256::new();
    hasher.update(&first);
    hasher.update(&tail);
    let rest = stream(
        file,
        (len, block),
        (body0, tail),
        &mut hasher,
        (first_line, cols, per_value),
    )?;
    let sha256 = hasher
        .finalize()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    Ok(Streamed::Matrix { head, rest, sha256 })
}

/// The rest of `file` after `first` (read), whole.
fn whole(mut first: Vec<u8>, mut file: impl Read) -> Result<Streamed, Failure> {
    fill(&mut file, &mut first, crate::limits::MAX_BYTES as usize + 1).map_err(|p| (None, p))?;
    Ok(Streamed::Whole(first))
}

type Job = (usize, Vec<u8>);
type Done = (usize, Result<Chunk, Failure>);

/// Parses the body: `body0` (the first block's rows, already hashed) and
/// then `carry` and the rest of `file`, hashed here, in blocks cut at line
/// ends, on worker threads; appended in order.
fn stream(
    mut file: impl Read,
    (len, block_size): (u64, usize),
    (body0, mut carry): (Vec<u8>, Vec<u8>),
    hasher: &mut Sha256,
    (first_line, cols, per_value): (usize, usize, usize),
) -> Result<Rest, Failure> {
    let workers = crate::threads::count();
    // Room for every height, from the first row's bytes per number (with a
    // margin; pages never written cost no memory).
    let estimate = (len as usize / per_value) * 5 / 4 + cols;
    let mut rest = Rest {
        cols,
        values: Vec::with_capacity(estimate),
        row_lines: Vec::new(),
        later: Vec::new(),
    };
    let (job_tx, job_rx) = mpsc::sync_channel::<Job>(workers);
    let job_rx = Arc::new(Mutex::new(job_rx));
    let (done_tx, done_rx) = mpsc::channel::<Done>();
    std::thread::scope(|s| -> Result<(), Failure> {
        for _ in 0..workers {
            let (rx, tx) = (Arc::clone(&job_rx), done_tx.clone());
            s.spawn(move || loop {
                let job = rx.lock().expect("job queue").recv();
                let Ok((k, bytes)) = job else { break };
                let parsed = match std::str::from_utf8(&bytes) {
                    Ok(t) => scan::parse_chunk(t, cols, per_value),
                    Err(e) => {
                        let line = bytes[..e.valid_up_to()]
                            .iter()
                            .filter(|&&b| b == b'\n')
                            .count();
                        Err((Some(line), Problem::NotText))
                    }
                };
                if tx.send((k, parsed)).is_err() {
                    break;
                }
            });
        }
        drop(done_tx);
        // The reader: blocks cut at line ends, hashed, handed on; the
        // parsed blocks appended in order as they come back.
        let mut pending: BTreeMap<usize, Result<Chunk, Failure>> = BTreeMap::new();
        let (mut next, mut line0) = (0usize, first_line);
        let mut failed: Option<Failure> = None;
        let mut append = |pending: &mut BTreeMap<usize, Result<Chunk, Failure>>,
                          next: &mut usize,
                          rest: &mut Rest|
         -> Result<(), Failure> {
            while let Some(c) = pending.remove(next) {
                let c = c.map_err(|(l, p)| (l.map(|l| l + line0), p))?;
                rest.values.extend_from_slice(&c.values);
                rest.row_lines.extend(c.row_lines.iter().map(|l| l + line0));
                rest.later
                    .extend(c.comments.into_iter().map(|(l, t)| (l + line0, t)));
                line0 += c.lines;
                *next += 1;
            }
            Ok(())
        };
        let mut sent = 0usize;
        let send = |k: usize, bytes: Vec<u8>| job_tx.send((k, bytes)).is_ok();
        if !send(sent, body0) {
            return Err((None, Problem::Read("a parse thread stopped".into())));
        }
        sent += 1;
        loop {
            let mut block = std::mem::take(&mut carry);
            let got = fill(&mut file, &mut block, block_size).map_err(|p| (None, p))?;
            let end = got == 0;
            if !end {
                hasher.update(&block[block.len() - got..]);
                if let Some(cut) = block.iter().rposition(|&b| b == b'\n') {
                    carry = block.split_off(cut + 1);
                } else {
                    carry = block;
                    continue;
                }
            }
            if !block.is_empty() {
                if !send(sent, block) {
                    break;
                }
                sent += 1;
            }
            while let Ok((k, c)) = done_rx.try_recv() {
                pending.insert(k, c);
            }
            if let Err(e) = append(&mut pending, &mut next, &mut rest) {
                failed = Some(e);
                break;
            }
            if end {
                break;
            }
        }
        drop(job_tx);
        if failed.is_none() {
            for (k, c) in done_rx.iter() {
                pending.insert(k, c);
                if let Err(e) = append(&mut pending, &mut next, &mut rest) {
                    failed = Some(e);
                    break;
                }
            }
        }
        match failed {
            Some(e) => Err(e),
            None => Ok(()),
        }
    })?;
    Ok(rest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::Options;
    use crate::read::{from_scan, measured, parse, sha256_hex};

    fn streamed(text: &str, block: usize) -> Result<crate::measured::Measured, Failure> {
        let bytes = text.as_bytes();
        match read_in(bytes, (bytes.len() as u64, ""), 0, block)? {
            Streamed::Whole(_) => panic!("not streamed"),
            Streamed::Matrix { head, rest, sha256 } => {
                assert_eq!(sha256, sha256_hex(bytes));
                let r = from_scan(None, rest.scan(&head)?, &Options::default())?;
                Ok(measured(r, sha256, Vec::new(), &Options::default()))
            }
        }
    }

    /// Blocks of any size, cut anywhere, read as the whole text does.
    #[test]
    fn blocks_read_as_the_whole() {
        let mut t = String::from("\u{feff}# Width: 3 µm\n# Height: 2 µm\n# Value units: nm\n");
        for j in 0..40 {
            let row: Vec<String> = (0..24)
                .map(|i| match (i, j) {
                    (3, 7) => "nan".to_string(),
                    _ => format!("{}", ((i * 37 + j * 11) % 19) as f64 * 0.25 - 1.5),
                })
                .collect();
            t.push_str(&row.join(" "));
            t.push_str(if j == 20 { " # a comment\n\n" } else { "\n" });
        }
        let whole = parse(t.as_bytes(), &Options::default()).unwrap();
        for block in [7, 64, 100, 1000, 1 << 20] {
            let s = streamed(&t, block).unwrap();
            assert_eq!(s.table, whole.table, "block {block}");
            assert_eq!(s.spectrum, whole.spectrum);
            assert_eq!(s.notes, whole.notes);
            assert_eq!(s.sha256, whole.sha256);
        }
        // A refusal names the same line, and a missing end of line is read.
        let bad = t.replacen("nan", "x", 1);
        let want = parse(bad.as_bytes(), &Options::default()).unwrap_err();
        assert_eq!(want.0, Some(11));
        for block in [7, 64, 1000] {
            assert_eq!(streamed(&bad, block).unwrap_err(), want);
            let cut = t.trim_end();
            assert_eq!(streamed(cut, block).unwrap().table, whole.table);
        }
        // Two columns are not streamed, nor three without a size (a
        // profile's validity column or empty cells, or a point cloud).
        let two = "1 2\n3 4\n5 6\n7 8\n";
        assert!(matches!(
            read_in(two.as_bytes(), (16, ""), 0, 4).unwrap(),
            Streamed::Whole(b) if b == two.as_bytes()
        ));
        let three = "X;Y;valid\n1;2;1\n3;4;0\n5;6;1\n7;8;1\n";
        assert!(matches!(
            read_in(three.as_bytes(), (40, ""), 0, 4).unwrap(),
            Streamed::Whole(b) if b == three.as_bytes()
        ));
    }
}
