//! Measured rough surfaces: a file in, a [`Measured`] out — the moment
//! table the model truncates at any q1, the log-binned spectrum the
//! spectrum view draws, and what identifies the file (SHA-256).
//!
//! Conventions follow SurfaceTopography (the library under
//! contact.engineering), so that its numbers are the reference; docs/model.md,
//! "Measured surfaces", states them.

mod allow;
mod anisotropy;
mod assumed;
mod band;
mod bins;
mod ce;
mod channels;
mod columns;
mod colunits;
mod decimal;
mod error;
mod fill;
mod fit;
mod grid;
mod gwy;
mod header;
mod matrix;
mod prepare;
mod profiles;
mod psd;
mod readers;
mod realspace;
mod sniff;
mod spectrum;
mod stream;
mod text;
mod units;
mod x3p;

use std::path::Path;
use std::sync::Arc;

use rough_model::{Dim, MomentTable};
use sha2::{Digest, Sha256};

pub use anisotropy::{Slopes, RATIO as ANISOTROPY_RATIO};
pub use error::{Problem, SurfaceError};
pub use fill::MAX_UNDEFINED;
pub use fit::{PowerLawFit, Verdict, MIN_POINTS as MIN_FIT_POINTS};
pub use grid::Grid;
pub use prepare::Heights;
pub use realspace::RealSpace;
pub use units::HeightUnit;

/// Files larger than this are refused before they are read (512 MiB).
pub const MAX_BYTES: u64 = 512 << 20;

/// Threads for the parallel passes (parse, plane, window, FFTs, Sq): the
/// machine's cores, at most four; asked once (the answer reads cgroup
/// files).
pub(crate) fn threads() -> usize {
    static N: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *N.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get().min(4)))
}

/// How to read a file whose content does not say everything.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// The data is periodic: no detrending beyond the mean, no window.
    pub periodic: bool,
    /// Sample spacing in metres, for data without a size header.
    pub pixel_size: Option<f64>,
    /// The measurement to read from a file holding several (a
    /// contact.engineering download): its name; the first when `None`.
    pub series: Option<String>,
    /// A map read as its profiles along one direction (line-scan
    /// conventions, [`Kind::Profiles`]) instead of as an area.
    pub direction: Option<Direction>,
    /// The channel to read of a file of several: its number (a .gwy's N of
    /// `/N/data`; a text file's channels from 0 in order) or its title;
    /// `None` takes the first whose values are heights (a unit of length).
    pub channel: Option<String>,
    /// The heights' unit, whatever the file says (`--height-unit`).
    pub height_unit: Option<HeightUnit>,
    /// The lateral unit (sizes, x positions) of a file that gives none
    /// (`--lateral-unit`).
    pub lateral_unit: Option<HeightUnit>,
    /// The largest share of undefined points filled, 0 to 1
    /// (`--max-undefined PERCENT`); [`MAX_UNDEFINED`] when `None`.
    pub max_undefined: Option<f64>,
}

/// A direction on a map: x along its rows, y across them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    X,
    Y,
}

impl Direction {
    pub fn name(self) -> &'static str {
        match self {
            Direction::X => "x",
            Direction::Y => "y",
        }
    }
}

/// What kind of data a file held.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A topography map of nx × ny samples spanning lx × ly metres.
    Map {
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
    },
    /// A line scan of n samples spanning l metres.
    Line { n: usize, l: f64 },
    /// A PSD table of `points` rows: areal (C^iso, m⁴) or profile (C1D, m³).
    Psd { dim: Dim, points: usize },
    /// A map of nx × ny samples over lx × ly read as its profiles along
    /// `direction` (`--direction`): the PSD averaged over them, profile
    /// moments as for a line scan.
    Profiles {
        direction: Direction,
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
    },
}

impl Kind {
    /// Areal sums (maps, isotropic PSDs) or profile sums (lines, profile PSDs).
    pub fn dim(&self) -> Dim {
        match self {
            Kind::Map { .. } => Dim::Areal,
            Kind::Line { .. } | Kind::Profiles { .. } => Dim::Profile,
            Kind::Psd { dim, .. } => *dim,
        }
    }
}

/// A measured surface, ready for the model.
#[derive(Clone, Debug)]
pub struct Measured {
    pub kind: Kind,
    /// The moments at any cutoff; q0 and the largest ζ come from it.
    pub table: Arc<MomentTable>,
    /// The spectrum for display, log-binned, (q in 1/m, PSD) with q
    /// increasing: C^iso (m⁴) for areal data, C1D (m³) for profiles, in
    /// SurfaceTopography's convention.
    pub spectrum: Vec<(f64, f64)>,
    /// SHA-256 of the file's bytes, lower-case hex.
    pub sha256: String,
    /// One line saying what was read and how it was treated, e.g.
    /// "map 256 × 128, 12 µm × 6 µm, plane removed, Hann window".
    pub summary: String,
    /// What the reader assumed or repaired, one line each, in the words the
    /// screen's status line, the side panel, export's stderr and CSV
    /// comments all print: "heights read in µm (the width's unit;
    /// --height-unit to change)", "decimal commas read", "312 undefined
    /// points (0.4 %) filled". Empty when the file said everything.
    ///
    /// Contract between readers and the map pipeline: a reader stores an
    /// undefined point (NaN, `nan`, an empty cell, a masked or invalid
    /// point of x3p/gwy) as `f64::NAN` in the heights it hands on; the
    /// pipeline fills or refuses them and adds the note.
    pub notes: Vec<String>,
    /// The measurement read from a file of several (a contact.engineering
    /// download's "Topography: NAME"), for the caption.
    pub measurement: Option<String>,
    /// A map's rms slopes along x and along y (its spectrum to the largest
    /// ζ); a note says when they differ by more than
    /// [`ANISOTROPY_RATIO`].
    pub slopes: Option<Slopes>,
    /// Sq and Sdq of a map, Rq and RΔq of a line scan (real space, after
    /// the detrend, no window); `None` for PSD tables.
    pub real: Option<RealSpace>,
    /// The Fourier modes averaged in each point of `spectrum` (the fit's
    /// weights); empty for PSD tables, whose points weigh the same.
    pub modes: Vec<f64>,
    /// The default Hurst fit band, 1/m: the spectrum's self-affine
    /// stretch (`band`'s rules); `None` with too few points.
    pub band: Option<(f64, f64)>,
    /// A map's heights for the contact simulation, when read with
    /// [`read_heights`] ([`Heights`]: filled,
    /// detrended, not windowed); `None` for lines, profiles and PSD tables.
    pub heights: Option<Arc<Heights>>,
}

impl Measured {
    /// Least-squares power law through the spectrum's points with q in
    /// [q_lo, q_hi]; `None` with fewer than two points there.
    pub fn fit(&self, q_lo: f64, q_hi: f64) -> Option<PowerLawFit> {
        fit::fit(
            self.kind.dim(),
            &self.spectrum,
            &self.modes,
            q_lo,
            q_hi,
            self.table.q0(),
        )
    }

    /// The fit over the default band ([`Measured::band`]).
    pub fn default_fit(&self) -> Option<PowerLawFit> {
        let (lo, hi) = self.band?;
        // The band's ends are data points: a rounding below one still takes it.
        self.fit(lo * (1.0 - 1e-12), hi * (1.0 + 1e-12))
    }

    /// The default fit band of a spectrum, for a [`Measured`] built by hand
    /// (a benchmark's synthetic surface).
    pub fn find_band(dim: Dim, spectrum: &[(f64, f64)], modes: &[f64]) -> Option<(f64, f64)> {
        band::self_affine(dim, spectrum, modes)
    }
}

/// Reads and computes the surface in `path`. Every refusal names the file
/// and, where there is one, the line.
pub fn read(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    read_keeping(path, opts, false)
}

std::thread_local! {
    /// Set while [`read_heights`] reads on this thread.
    static KEEP_HEIGHTS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether the read under way keeps a map's heights ([`read_heights`]).
pub(crate) fn keeping_heights() -> bool {
    KEEP_HEIGHTS.with(|k| k.get())
}

/// [`read`], keeping a map's heights in [`Measured::heights`] (filled, the
/// mean or plane removed, no window: what the contact simulation solves);
/// `heights` stays `None` for what is not a map. [`read`] keeps none, so
/// that a surface only explored costs no more memory than its spectrum.
pub fn read_heights(path: &Path, opts: &Options) -> Result<Measured, SurfaceError> {
    read_keeping(path, opts, true)
}

fn read_keeping(path: &Path, opts: &Options, keep: bool) -> Result<Measured, SurfaceError> {
    let before = KEEP_HEIGHTS.with(|k| k.replace(keep));
    let r = allow::with(opts, || read_inner(path, opts));
    KEEP_HEIGHTS.with(|k| k.set(before));
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
    let ext = readers::gz::extension(path);
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
    allow::with(opts, || parse_file(bytes, opts, ""))
}

/// [`parse`] of a file named `name`: its extension names the formats that
/// have no magic bytes of their own (Sensofar `.plu`), and a `.gz`'s
/// inner name the format of what it holds.
pub fn parse_named(
    bytes: &[u8],
    name: &str,
    opts: &Options,
) -> Result<Measured, (Option<usize>, Problem)> {
    let ext = readers::gz::extension(Path::new(name));
    allow::with(opts, || parse_file(bytes, opts, &ext))
}

/// The heights of a binary file (x3p, .gwy, an instrument's own format;
/// gzip-compressed too) as the file holds them, in metres, before any
/// detrending (undefined points NaN); text and other formats are refused.
pub fn read_grid(bytes: &[u8], opts: &Options) -> Result<Grid, (Option<usize>, Problem)> {
    if bytes.starts_with(readers::gz::MAGIC) {
        return read_grid(&readers::gz::unpack(bytes)?, opts);
    }
    grid_of(&sniff::format(bytes, ""), bytes, opts)
}

/// The grid of `bytes` in `format`.
fn grid_of(
    format: &sniff::Format,
    bytes: &[u8],
    opts: &Options,
) -> Result<Grid, (Option<usize>, Problem)> {
    match format {
        sniff::Format::X3p => x3p::read(bytes),
        sniff::Format::Gwy => gwy::read(bytes, opts.channel.as_deref()),
        sniff::Format::Native(n) => readers::read(*n, bytes, opts),
        sniff::Format::Other(s) => Err((None, Problem::Format(s.clone()))),
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
    if bytes.starts_with(readers::gz::MAGIC) {
        let inner = readers::gz::unpack(bytes)?;
        if inner.starts_with(readers::gz::MAGIC) {
            return Err((
                None,
                Problem::Format("a gzip-compressed file inside a gzip-compressed file".into()),
            ));
        }
        let mut m = parse_file(&inner, opts, readers::gz::inner(ext))?;
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
    if opts.channel.is_some() && format == sniff::Format::X3p {
        return no_channels();
    }
    let mut notes = Vec::new();
    let text = match format {
        sniff::Format::Other(s) => return Err((None, Problem::Format(s))),
        sniff::Format::X3p | sniff::Format::Gwy | sniff::Format::Native(_) => {
            not_a_download(opts)?;
            let (sha256, read) = std::thread::scope(|s| {
                let hash = s.spawn(|| sha256_hex(bytes));
                let read =
                    grid_of(&format, bytes, opts).and_then(|g| grid::compute(g, opts, &mut notes));
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
                sniff::Format::Native(n) => n.name(),
                _ => "Gwyddion .gwy",
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
fn measured(r: Reading, sha256: String, mut notes: Vec<String>) -> Measured {
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
struct Reading {
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
fn from_scan(
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
                sniff::XYZ_HINT
            )),
        ));
    }
    let (kind, computed) = match text {
        Some(text) if !is_matrix(&header, scan.cols) => columns::read(text, scan, &header, opts)?,
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

/// Whether rows of `cols` numbers under `header` are a height matrix
/// (else a two-column table).
fn is_matrix(header: &header::Header, cols: usize) -> bool {
    header.has_size() || cols != 2
}

/// A length for people: "12 µm".
fn length(m: f64) -> String {
    let (scale, unit) = [
        (1.0, "m"),
        (1e-3, "mm"),
        (1e-6, "µm"),
        (1e-9, "nm"),
        (1e-12, "pm"),
    ]
    .into_iter()
    .find(|(s, _)| m >= *s * 0.9995)
    .unwrap_or((1e-12, "pm"));
    format!("{:.4} {unit}", m / scale)
        .replace(".0000 ", " ")
        .replace("000 ", " ")
        .replace("00 ", " ")
}

fn describe(kind: &Kind, opts: &Options, psd: &str) -> String {
    let treat = |what: &str| {
        if opts.periodic {
            "periodic, mean removed".to_string()
        } else {
            format!("{what} removed, Hann window")
        }
    };
    match *kind {
        Kind::Map { nx, ny, lx, ly } => format!(
            "map {nx} × {ny}, {} × {}, {}",
            length(lx),
            length(ly),
            treat("plane")
        ),
        Kind::Line { n, l } => format!("line scan of {n} points, {}, {}", length(l), treat("line")),
        Kind::Profiles {
            direction,
            nx,
            ny,
            lx,
            ly,
        } => {
            let d = direction.name();
            let count = if direction == Direction::X { ny } else { nx };
            format!(
                "map {nx} × {ny}, {} × {}, its {count} profiles along {d}, {}",
                length(lx),
                length(ly),
                if opts.periodic {
                    "periodic, mean removed".to_string()
                } else {
                    format!("plane removed, Hann window along {d}")
                }
            )
        }
        Kind::Psd { dim, points } => format!(
            "{psd}, {points} points, {}",
            match dim {
                Dim::Areal => "isotropic C(q)",
                Dim::Profile => "profile C1D(q)",
            }
        ),
    }
}
