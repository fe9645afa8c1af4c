//! Reading a file: its size checked, streamed or read whole, its format
//! sniffed, the reader for it, then the pipeline that computes the moment
//! table, the spectrum and the notes.

use std::path::Path;
use std::sync::Arc;

use sha2::{Digest, Sha256};

use crate::describe::describe;
use crate::error::{Problem, SurfaceError};
use crate::formats::readers::grid::{self, Grid};
use crate::formats::text::{ce, channels, columns, header, matrix, scan};
use crate::formats::{self, gz, sniff, stream};
use crate::heights::allow;
use crate::limits::MAX_BYTES;
use crate::measured::{Kind, Measured, Options};
use crate::spectrum::{band, compute};
use crate::units::{self, Advice};

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
    let before = crate::heights::prepare::KEEP_HEIGHTS.with(|k| k.replace(keep));
    let r = allow::with(opts.max_undefined, || read_inner(path, opts));
    crate::heights::prepare::KEEP_HEIGHTS.with(|k| k.set(before));
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
    let ext = gz::extension(path);
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
                .map(|r| measured(r, sha256, Vec::new(), opts))
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
    allow::with(opts.max_undefined, || parse_file(bytes, opts, ""))
}

/// [`parse`] of a file named `name`: its extension names the formats that
/// have no magic bytes of their own (Sensofar `.plu`), and a `.gz`'s
/// inner name the format of what it holds.
pub fn parse_named(
    bytes: &[u8],
    name: &str,
    opts: &Options,
) -> Result<Measured, (Option<usize>, Problem)> {
    let ext = gz::extension(Path::new(name));
    allow::with(opts.max_undefined, || parse_file(bytes, opts, &ext))
}

/// The heights of a binary file (x3p, .gwy, an instrument's own format;
/// gzip-compressed too) as the file holds them, in metres, before any
/// detrending (undefined points NaN); text and other formats are refused.
pub fn read_grid(bytes: &[u8], opts: &Options) -> Result<Grid, (Option<usize>, Problem)> {
    read_grid_named(bytes, "", opts)
}

/// [`read_grid`] of a file named `name` (as [`parse_named`]).
pub fn read_grid_named(
    bytes: &[u8],
    name: &str,
    opts: &Options,
) -> Result<Grid, (Option<usize>, Problem)> {
    let ext = gz::extension(Path::new(name));
    if bytes.starts_with(gz::MAGIC) {
        let inner = gz::unpack(bytes)?;
        if inner.starts_with(gz::MAGIC) {
            return Err((
                None,
                Problem::Format("a gzip-compressed file inside a gzip-compressed file".into()),
            ));
        }
        let ext = gz::inner_of(bytes, &ext);
        return formats::grid_of(&sniff::format(&inner, &ext), &inner, opts);
    }
    formats::grid_of(&sniff::format(bytes, &ext), bytes, opts)
}

/// [`parse`], told the file's extension (lower case) for formats that
/// have no magic bytes of their own.
fn parse_file(
    bytes: &[u8],
    opts: &Options,
    ext: &str,
) -> Result<Measured, (Option<usize>, Problem)> {
    check_options(opts)?;
    if bytes.starts_with(gz::MAGIC) {
        let inner = gz::unpack(bytes)?;
        if inner.starts_with(gz::MAGIC) {
            return Err((
                None,
                Problem::Format("a gzip-compressed file inside a gzip-compressed file".into()),
            ));
        }
        let mut m = parse_file(&inner, opts, &gz::inner_of(bytes, ext))?;
        m.sha256 = sha256_hex(bytes);
        return Ok(m);
    }
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
    if opts.channel.is_some()
        && format == sniff::Format::X3p
        && !crate::formats::container::is_container(bytes)
    {
        return no_channels();
    }
    let mut notes = Vec::new();
    let text = match format {
        sniff::Format::Other(s) => return Err((None, Problem::Format(s))),
        sniff::Format::X3p if crate::formats::container::is_container(bytes) => {
            let mut m =
                crate::formats::container::read(bytes, opts, &|b, o, e| parse_file(b, o, e))?;
            m.sha256 = sha256_hex(bytes);
            return Ok(m);
        }
        sniff::Format::X3p | sniff::Format::Gwy | sniff::Format::Native(_) => {
            not_a_download(opts)?;
            let (sha256, read) = std::thread::scope(|s| {
                let hash = s.spawn(|| sha256_hex(bytes));
                let read = formats::grid_of(&format, bytes, opts)
                    .and_then(|g| grid::compute(g, opts, &mut notes));
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
            let what = match format {
                sniff::Format::X3p => "x3p",
                sniff::Format::Native(n) => n.name,
                _ => "Gwyddion .gwy",
            };
            let summary = format!("{what} {}", describe(&kind, opts, ""));
            // The file's units, unless the reader said it assumed them.
            let assumed = notes.iter().any(|n| n.starts_with("heights read in"));
            let r = Reading {
                kind,
                computed,
                summary,
                measurement: None,
                advice: if assumed {
                    Advice::Height
                } else {
                    Advice::File(what)
                },
            };
            return Ok(measured(r, sha256, notes, opts));
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
    if let (Kind::Psd { .. }, Some(d)) = (&r.kind, opts.detrend) {
        return Err((
            None,
            Problem::Option(format!(
                "--detrend {} does not apply to a PSD table: it holds no heights",
                d.name()
            )),
        ));
    }
    if let (Kind::Psd { .. }, Some(u)) = (&r.kind, opts.height_unit) {
        return Err((
            None,
            Problem::Option(format!(
                "--height-unit {u} does not apply to a PSD table: it holds no heights"
            )),
        ));
    }
    Ok(measured(r, sha256, notes, opts))
}

fn check_options(opts: &Options) -> Result<(), (Option<usize>, Problem)> {
    crate::heights::detrend::check_periodic(opts.detrend_mode(), opts.periodic)
        .map_err(|p| (None, p))?;
    match opts.pixel_size {
        Some(p) if !(p.is_finite() && p > 0.0) => Err((
            None,
            Problem::Option(format!(
                "--pixel-size {} must be finite and > 0",
                crate::lengths::typed_length(p)
            )),
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
/// pipeline's, the form removed where `opts` chose another than the
/// default, the plausibility warning, the default fit band.
pub(crate) fn measured(
    r: Reading,
    sha256: String,
    mut notes: Vec<String>,
    opts: &Options,
) -> Measured {
    let c = r.computed;
    notes.extend(c.notes);
    notes.extend(crate::describe::detrend_note(&r.kind, opts));
    let advice = match r.kind {
        Kind::Psd { .. } => Advice::Table,
        _ => r.advice,
    };
    notes.extend(units::plausibility(&c.table, advice));
    if let (Some(r), Some(n)) = (&c.real, r.kind.points()) {
        notes.extend(crate::spectrum::amplitude::scars(
            &r.amplitude,
            r.rms_height,
            n,
        ));
    }
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
    computed: compute::Computed,
    summary: String,
    measurement: Option<String>,
    /// What the plausibility line may advise.
    advice: Advice,
}

fn read_text(text: &str, opts: &Options) -> Result<Reading, (Option<usize>, Problem)> {
    let head = scan::head(text)?;
    if ce::is_ce(&head.header) {
        if let Some(u) = opts.lateral_unit {
            return Err(no_lateral(u, "a contact.engineering download"));
        }
        let r = ce::read(text, opts)?;
        let summary = describe(&r.kind, opts, &r.label);
        return Ok(Reading {
            kind: r.kind,
            computed: r.computed,
            summary,
            measurement: r.measurement,
            advice: Advice::Table,
        });
    }
    not_a_download(opts)?;
    let scan = scan::scan(text, head)?;
    from_scan(Some(text), scan, opts)
}

/// A scanned text file as a map, a line or a two-column table (`text`
/// for the last: `None` when it was streamed, as only matrices are).
pub(crate) fn from_scan(
    text: Option<&str>,
    scan: scan::Scan<'_>,
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
    let mut scan = scan;
    let profile_notes = match text {
        Some(_) => crate::formats::text::validity::as_profile(&mut scan, &header)?,
        None => Vec::new(),
    };
    if scan.cols == 3 && scan.rows() >= 4 && !header.has_size() {
        return Err((
            scan.row_lines.first().copied(),
            Problem::Format(format!(
                "three numbers a row: looks like an XYZ point cloud (x y z), {}",
                crate::formats::hints::XYZ_HINT
            )),
        ));
    }
    let columns = text.is_some() && !header.is_matrix(scan.cols);
    if let (Some(u), false) = (opts.lateral_unit, columns) {
        return Err(no_lateral(
            u,
            "a height matrix: its sizes' unit is its header's ('# Width: 12 µm')",
        ));
    }
    let (kind, mut computed) = match text {
        Some(text) if columns => columns::read(text, scan, &header, opts)?,
        _ => matrix::read(scan, &header, opts)?,
    };
    computed.notes.splice(0..0, profile_notes);
    if let (Some(u), Kind::Psd { .. }) = (opts.lateral_unit, kind) {
        return Err(no_lateral(u, "a PSD table"));
    }
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
        advice: if columns {
            Advice::HeightOrLateral
        } else {
            Advice::Height
        },
    })
}

/// `--lateral-unit` on a file whose x unit is not to be said.
fn no_lateral(u: crate::units::HeightUnit, what: &str) -> (Option<usize>, Problem) {
    (
        None,
        Problem::Option(format!(
            "--lateral-unit {u} applies to an x z line scan and to files that give no \
             lateral unit, not to {what}"
        )),
    )
}
