//! Reading a file: its size checked, streamed or read whole, its format
//! sniffed, the reader for it, then the pipeline that computes the moment
//! table, the spectrum and the notes.

use std::path::Path;
use std::sync::Arc;

use sha2::{Digest, Sha256};

use crate::describe::describe;
use crate::error::{Problem, SurfaceError};
use crate::grid::Grid;
use crate::limits::MAX_BYTES;
use crate::measured::{Kind, Measured, Options};
use crate::{
    band, ce, channels, columns, grid, gwy, header, matrix, sniff, spectrum, stream, text, units,
    x3p,
};

/// Reads and computes the surface in `path`. Every refusal names the file
/// and, where there is one, the line.
pub fn read(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    read_keeping(path, opts, false)
}

/// [`read`], keeping a map's heights in [`Measured::heights`] (filled, the
/// mean or plane removed, no window: what the contact simulation solves);
/// `heights` stays `None` for what is not a map. [`read`] keeps none, so
/// that a surface only explored costs no more memory than its spectrum.
pub fn read_heights(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    read_keeping(path, opts, true)
}

fn read_keeping(path: &Path, opts: &Options, keep: bool) -> Result<Measured, SurfaceError> {
    let before = crate::prepare::KEEP_HEIGHTS.with(|k| k.replace(keep));
    let r = read_inner(path, opts);
    crate::prepare::KEEP_HEIGHTS.with(|k| k.set(before));
    r
}

fn read_inner(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    let fail = |line, problem| SurfaceError {
        path: path.to_path_buf(),
        line,
        problem,
    };
    let meta = std::fs::metadata(path).map_err(|e| fail(None, Problem::Read(e.to_string())))?;
    if meta.is_dir() {
        return Err(fail(None, Problem::IsDir));
    }
    if meta.len() > MAX_BYTES {
        return Err(fail(None, Problem::TooLarge(meta.len())));
    }
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let whole = |bytes: Vec<u8>| {
        if bytes.len() as u64 > MAX_BYTES {
            return Err(fail(None, Problem::TooLarge(bytes.len() as u64)));
        }
        parse_file(&bytes, opts, &ext).map_err(|(line, problem)| fail(line, problem))
    };
    let file = std::fs::File::open(path).map_err(|e| fail(None, Problem::Read(e.to_string())))?;
    match stream::read(file, meta.len(), &ext).map_err(|(line, problem)| fail(line, problem))? {
        stream::Streamed::Whole(bytes) => whole(bytes),
        // Header lines after the data: several channels, read whole.
        stream::Streamed::Matrix { rest, .. } if rest.has_headers() || opts.channel.is_some() => {
            drop(rest);
            let mut bytes = Vec::new();
            std::fs::File::open(path)
                .and_then(|f| {
                    std::io::Read::read_to_end(
                        &mut std::io::Read::take(f, MAX_BYTES + 1),
                        &mut bytes,
                    )
                })
                .map_err(|e| fail(None, Problem::Read(e.to_string())))?;
            whole(bytes)
        }
        stream::Streamed::Matrix { head, rest, sha256 } => {
            let read = || -> Result<Reading, (Option<usize>, Problem)> {
                check_options(opts)?;
                not_a_download(opts)?;
                from_scan(None, rest.scan(&head)?, opts)
            };
            read()
                .map(|r| measured(r, sha256, Vec::new()))
                .map_err(|(line, problem)| fail(line, problem))
        }
    }
}

/// The SHA-256 of `bytes`, lower-case hex (what a snapshot records).
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Computes the surface in a file's bytes; an error carries the 1-based
/// line it is about, if any. The format is detected from the content (see
/// docs/surfaces.md, "Reading the file"):
///
/// - ISO 25178-72 x3p (a zip holding `main.xml`) and Gwyddion's .gwy
///   (`GWYP`): maps and profiles;
/// - text, UTF-8 or else Windows-1252, with decimal points or (when the
///   first data row has them) decimal commas:
///   - a contact.engineering TXT download (a `# Columns:` header);
///   - a height matrix: a size header (`# Width:`/`# Height:`), or one, or
///     four or more numbers per row; one row or one column is a line
///     scan (three numbers a row are an XYZ point cloud, refused with
///     what to do);
///   - two columns: a line scan `x z` or a PSD table `q C^iso`
///     (`columns`' rules);
/// - any other format recognised (NetCDF, HDF5, .npy, TIFF, Zygo, Keyence,
///   Nanoscope …) is refused with a line saying how to convert it.
pub fn parse(bytes: &[u8], opts: &Options) -> Result<Measured, (Option<usize>, Problem)> {
    parse_file(bytes, opts, "")
}

/// The heights of an x3p or .gwy file as the file holds them, before any
/// detrending (undefined points NaN); text and other formats are refused.
pub fn read_grid(bytes: &[u8], opts: &Options) -> Result<Grid, (Option<usize>, Problem)> {
    match sniff::format(bytes, "") {
        sniff::Format::X3p => x3p::read(bytes),
        sniff::Format::Gwy => gwy::read(bytes, opts.channel.as_deref()),
        sniff::Format::Other(s) => Err((None, Problem::Format(s))),
        sniff::Format::Text => Err((
            None,
            Problem::Format("text: not an x3p or .gwy file".to_string()),
        )),
    }
}

/// [`parse`], told the file's extension (lower case) for formats that
/// have no magic bytes of their own.
fn parse_file(
    bytes: &[u8],
    opts: &Options,
    ext: &str,
) -> Result<Measured, (Option<usize>, Problem)> {
    check_options(opts)?;
    let format = sniff::format(bytes, ext);
    let no_channels = || {
        Err((
            None,
            Problem::Option(
                "--channel applies to files of several channels (Gwyddion's .gwy, \
                 its ASCII exports concatenated)"
                    .to_string(),
            ),
        ))
    };
    if opts.channel.is_some() && format == sniff::Format::X3p {
        return no_channels();
    }
    if let (Some(u), sniff::Format::X3p | sniff::Format::Gwy) = (opts.height_unit, &format) {
        return Err((
            None,
            Problem::Option(format!(
                "--height-unit {u} applies to text files: x3p and .gwy files carry their units"
            )),
        ));
    }
    let mut notes = Vec::new();
    let text = match format {
        sniff::Format::Other(s) => return Err((None, Problem::Format(s))),
        sniff::Format::X3p | sniff::Format::Gwy => {
            not_a_download(opts)?;
            let (sha256, read) = std::thread::scope(|s| {
                let hash = s.spawn(|| sha256_hex(bytes));
                let read = read_grid(bytes, opts).and_then(|g| grid::compute(g, opts, &mut notes));
                (hash.join().expect("hash thread"), read)
            });
            let (kind, computed) = read?;
            if let (Some(d), Kind::Line { .. }) = (opts.direction, kind) {
                return Err((
                    None,
                    Problem::Option(format!(
                        "--direction {} applies to a map, not to a line scan",
                        d.name()
                    )),
                ));
            }
            let what = if format == sniff::Format::X3p {
                "x3p"
            } else {
                "Gwyddion .gwy"
            };
            let summary = format!("{what} {}", describe(&kind, opts, ""));
            let r = Reading {
                kind,
                computed,
                summary,
                measurement: None,
            };
            return Ok(measured(r, sha256, notes));
        }
        sniff::Format::Text => {
            let (text, mut assumed) = sniff::text(bytes)?;
            notes.append(&mut assumed);
            text
        }
    };
    // Several channels: one is read.
    let blocks = channels::blocks(&text)?;
    let (text, skipped) = if blocks.is_empty() {
        if opts.channel.is_some() {
            return no_channels();
        }
        (&text[..], 0)
    } else {
        let (b, note) = channels::pick(&blocks, opts.channel.as_deref())?;
        notes.push(note);
        (b.text, b.first_line - 1)
    };
    // The hash runs beside the parse.
    let (sha256, read) = std::thread::scope(|s| {
        let hash = s.spawn(|| sha256_hex(bytes));
        let read = read_text(text, opts).map_err(|(l, p)| (l.map(|l| l + skipped), p));
        (hash.join().expect("hash thread"), read)
    });
    let r = read?;
    if let (Kind::Psd { .. }, Some(u)) = (&r.kind, opts.height_unit) {
        return Err((
            None,
            Problem::Option(format!(
                "--height-unit {u} does not apply to a PSD table: it holds no heights"
            )),
        ));
    }
    Ok(measured(r, sha256, notes))
}

fn check_options(opts: &Options) -> Result<(), (Option<usize>, Problem)> {
    match opts.pixel_size {
        Some(p) if !(p.is_finite() && p > 0.0) => Err((
            None,
            Problem::Option(format!("--pixel-size {p} m must be finite and > 0")),
        )),
        _ => Ok(()),
    }
}

/// `--series` is refused on what is not a contact.engineering download.
fn not_a_download(opts: &Options) -> Result<(), (Option<usize>, Problem)> {
    match &opts.series {
        Some(s) => Err((
            None,
            Problem::Option(format!(
                "--series '{s}' applies to a contact.engineering download of several \
                 measurements, not to this file"
            )),
        )),
        None => Ok(()),
    }
}

/// The surface from what was read: the reader's `notes` before the
/// pipeline's, the plausibility warning, the default fit band.
pub(crate) fn measured(r: Reading, sha256: String, mut notes: Vec<String>) -> Measured {
    let c = r.computed;
    notes.extend(c.notes);
    let heights = !matches!(r.kind, Kind::Psd { .. });
    notes.extend(units::plausibility(&c.table, heights));
    let band = band::self_affine(r.kind.dim(), &c.spectrum, &c.modes);
    Measured {
        kind: r.kind,
        table: Arc::new(c.table),
        spectrum: c.spectrum,
        sha256,
        summary: r.summary,
        notes,
        measurement: r.measurement,
        slopes: c.slopes,
        real: c.real,
        modes: c.modes,
        band,
        heights: c.heights,
    }
}

/// What [`read_text`] found.
pub(crate) struct Reading {
    kind: Kind,
    computed: spectrum::Computed,
    summary: String,
    measurement: Option<String>,
}

fn read_text(text: &str, opts: &Options) -> Result<Reading, (Option<usize>, Problem)> {
    let head = text::head(text)?;
    if ce::is_ce(&head.header) {
        let r = ce::read(text, opts)?;
        let summary = describe(&r.kind, opts, &r.label);
        return Ok(Reading {
            kind: r.kind,
            computed: r.computed,
            summary,
            measurement: r.measurement,
        });
    }
    not_a_download(opts)?;
    let scan = text::scan(text, head)?;
    from_scan(Some(text), scan, opts)
}

/// A scanned text file as a map, a line or a two-column table (`text`
/// for the last: `None` when it was streamed, as only matrices are).
pub(crate) fn from_scan(
    text: Option<&str>,
    scan: text::Scan<'_>,
    opts: &Options,
) -> Result<Reading, (Option<usize>, Problem)> {
    let header = header::Header::read(&scan.header)?;
    if let Some((line, t)) = scan
        .later
        .iter()
        .find(|(l, t)| !header::Header::read(&[(*l, t)]).map_or(true, |h| h.is_empty()))
    {
        let line = *line;
        return Err((
            Some(line),
            Problem::Several(format!(
                "a header line ('{t}') after the data: one channel per file, please"
            )),
        ));
    }
    if header.channels.len() > 1 {
        return Err((
            Some(header.channels[1]),
            Problem::Several("several channels: one channel per file, please".to_string()),
        ));
    }
    if scan.cols == 3 && scan.rows() >= 4 && !header.has_size() {
        return Err((
            scan.row_lines.first().copied(),
            Problem::Format(format!(
                "three numbers a row: looks like an XYZ point cloud (x y z), {}",
                crate::hints::XYZ_HINT
            )),
        ));
    }
    let (kind, computed) = match text {
        Some(text) if !header.is_matrix(scan.cols) => columns::read(text, scan, &header, opts)?,
        _ => matrix::read(scan, &header, opts)?,
    };
    if let (Some(d), false) = (opts.direction, matches!(kind, Kind::Profiles { .. })) {
        return Err((
            None,
            Problem::Option(format!(
                "--direction {} applies to a map, not to {}",
                d.name(),
                match kind {
                    Kind::Line { .. } => "a line scan",
                    _ => "a PSD table",
                }
            )),
        ));
    }
    let summary = describe(&kind, opts, "PSD table");
    Ok(Reading {
        kind,
        computed,
        summary,
        measurement: None,
    })
}
