//! ISO 25178-72 (ISO 5436-2 XML) files, `.x3p`: a zip holding `main.xml`
//! and the heights in `bindata/data.bin` (or in `main.xml` as a
//! `DataList`), read as the standard and x3pio read them:
//!
//! - `Record1`: the feature type (SUR a map, PRF a profile; a point cloud,
//!   PCL, is refused with what to do) and the axes `CX`, `CY`, `CZ`: x and
//!   y incremental (`AxisType` I) with an `Increment` in metres (1 when
//!   missing), z absolute (A) of `DataType` I (int16), L (int32), F
//!   (float32) or D (float64), its stored values times its `Increment`;
//!   offsets only place the data and are not needed;
//! - `Record3`: `MatrixDimension` (`SizeX` columns, `SizeY` rows, `SizeZ`
//!   layers, the first read), the binary files (little-endian, x fastest)
//!   and their MD5 checksums, and the validity file (`bindata/valid.bin`,
//!   one bit per point, least significant bit first, 0 = invalid);
//! - `Record4`: the file holding the MD5 checksum of `main.xml`.
//!
//! Invalid points, NaN and infinities are undefined points (NaN). A
//! binary file whose checksum does not match is refused; `main.xml`'s is a
//! warning (an edited header, read as x3pio reads it); a missing checksum
//! is not checked.
//! Every size is checked before it is used: members unpack to no more than
//! [`crate::limits::MAX_BYTES`] and to exactly what `main.xml` says.

use std::io::{Cursor, Read};

use md5::{Digest, Md5};
use roxmltree::{Document, Node, ParsingOptions};
use zip::ZipArchive;

use crate::error::{Failure, Problem};
use crate::formats::readers::grid::Grid;

/// A zip file's first bytes.
pub(crate) const MAGIC: &[u8] = b"PK\x03\x04";
/// `main.xml` is read up to this size (a `DataList` of 2048² points takes
/// ~40 MB).
const MAX_XML: u64 = 64 << 20;
/// XML nodes read at most (a `DataList` takes two per point).
const MAX_NODES: u32 = 1 << 24;

fn bad(s: impl AsRef<str>) -> Failure {
    (None, Problem::Format(format!("x3p: {}", s.as_ref())))
}

type Zip<'a> = ZipArchive<Cursor<&'a [u8]>>;

/// Why a zip archive cannot be opened, for people: what is wrong with the
/// file, not the zip library's own names for its parts.
pub(crate) fn unreadable(e: &zip::result::ZipError) -> String {
    use zip::result::ZipError;
    let why = match e {
        ZipError::InvalidArchive(m) if m.contains("EOCD") || m.contains("end") => {
            "it is cut short or damaged: its directory of members, at the end of the \
             archive, is missing or incomplete"
                .to_string()
        }
        ZipError::InvalidArchive(_) | ZipError::Io(_) => {
            "it is cut short or damaged: its directory of members cannot be read".to_string()
        }
        ZipError::UnsupportedArchive(m) => format!("it uses a zip feature not read ({m})"),
        ZipError::InvalidPassword => "it is encrypted".to_string(),
        ZipError::CompressionMethodNotSupported(m) => {
            format!("it is compressed with method {m}, which is not read")
        }
        _ => "its members' sizes cannot be read".to_string(),
    };
    format!("not a readable zip archive: {why}")
}

/// The folder of `main.xml` in the zip ("" at the root; x3pio also reads
/// an x3p zipped by hand, whose members sit in one folder), `None` when
/// there is no `main.xml`.
fn folder(zip: &Zip<'_>) -> Option<String> {
    let names: Vec<String> = zip
        .file_names()
        .filter_map(|n| n.ok())
        .map(|n| n.into_owned())
        .filter(|n| !n.starts_with("__MACOSX/"))
        .collect();
    if names.iter().any(|n| n == "main.xml") {
        return Some(String::new());
    }
    let mut inner = names.iter().filter_map(|n| {
        let (dir, file) = n.rsplit_once('/')?;
        (file == "main.xml" && !dir.contains('/')).then(|| format!("{dir}/"))
    });
    match (inner.next(), inner.next()) {
        (Some(d), None) => Some(d),
        _ => None,
    }
}

/// What a zip without `main.xml` probably is.
fn other_zip(zip: &Zip<'_>) -> String {
    let names: Vec<String> = zip
        .file_names()
        .filter_map(|n| n.ok())
        .map(|n| n.into_owned())
        .collect();
    let has = |f: &dyn Fn(&str) -> bool| names.iter().any(|n| f(n));
    if has(&|n| n == "Vk4File") {
        crate::formats::hints::hint("a Keyence .vk6/.vk7 file")
    } else if has(&|n| n.ends_with("header.properties"))
        && has(&|n| n.starts_with("segments/") || n.starts_with("index/"))
    {
        "a JPK force file (.jpk-force or .jpk-qi-data: force curves, a zip of segments): \
         it holds no heights; a scan's heights are in its .jpk image"
            .to_string()
    } else if has(&|n| n.ends_with(".npy")) {
        "looks like a NumPy .npz archive: save one height array as text with \
         numpy.savetxt (rows of heights) and add '# Width:' and '# Height:' lines"
            .to_string()
    } else if has(&|n| n.eq_ignore_ascii_case("index.xml")) {
        crate::formats::hints::hint("a Sensofar .plux file")
    } else if has(&|n| n == "xl/workbook.xml") {
        "looks like an Excel spreadsheet (.xlsx): save the sheet of heights as CSV (a \
         map's rows of heights, or a profile's x and z columns with their units in the \
         header) and read that"
            .to_string()
    } else if has(&|n| n == "word/document.xml" || n == "content.xml") {
        "looks like an office document, not height data".to_string()
    } else {
        "a zip archive without main.xml: not an x3p file (an x3p holds main.xml \
         and bindata/data.bin)"
            .to_string()
    }
}

type Member<'z, 'a> = zip::read::ZipFile<'z, Cursor<&'a [u8]>>;

/// The member `name` and the bytes it unpacks to: refused above `limit`
/// bytes, or when it does not hold `expected` bytes.
fn open<'z, 'a>(
    zip: &'z mut Zip<'a>,
    name: &str,
    limit: u64,
    expected: Option<(u64, &dyn Fn() -> String)>,
) -> Result<(Member<'z, 'a>, u64), Failure> {
    let f = zip
        .by_name(name)
        .map_err(|e| bad(format!("{name} is missing or unreadable ({e})")))?;
    let declared = f.size();
    if let Some((want, says)) = expected {
        if declared != want {
            return Err(bad(format!(
                "{} take {want} bytes but {name} holds {declared}",
                says()
            )));
        }
    }
    if declared > limit {
        return Err(bad(format!(
            "{name} unpacks to {declared} bytes: more than the {} MB read",
            limit >> 20
        )));
    }
    Ok((f, declared))
}

fn unpacking(name: &str) -> impl Fn(std::io::Error) -> Failure + '_ {
    move |e| bad(format!("{name} cannot be unpacked: {e}"))
}

/// Refuses a member with bytes beyond its declared size.
fn no_more(f: &mut Member<'_, '_>, name: &str, declared: u64) -> Result<(), Failure> {
    let mut more = [0u8; 1];
    if f.read(&mut more).map_err(unpacking(name))? > 0 {
        return Err(bad(format!(
            "{name} unpacks to more bytes where the zip says {declared} (the file is damaged)"
        )));
    }
    Ok(())
}

/// The member `name`, unpacked (see [`open`]).
fn member(
    zip: &mut Zip<'_>,
    name: &str,
    limit: u64,
    expected: Option<(u64, &dyn Fn() -> String)>,
) -> Result<Vec<u8>, Failure> {
    let (mut f, declared) = open(zip, name, limit, expected)?;
    // Grown as the bytes arrive beyond 16 MiB: a member that claims more
    // than it holds allocates no more than it holds.
    let mut out = Vec::with_capacity(declared.min(16 << 20) as usize);
    (&mut f)
        .take(declared)
        .read_to_end(&mut out)
        .map_err(unpacking(name))?;
    if out.len() as u64 != declared {
        return Err(bad(format!(
            "{name} unpacks to {} bytes where the zip says {declared} (the file is damaged)",
            out.len()
        )));
    }
    no_more(&mut f, name, declared)?;
    Ok(out)
}

/// Unpacks the member `name` of `expected` bytes a piece at a time (each a
/// multiple of 8 bytes but the last), handing each to `each` while another
/// thread computes its MD5; returns the MD5 (lower-case hex). The data is
/// never held whole.
fn stream(
    zip: &mut Zip<'_>,
    name: &str,
    expected: (u64, &dyn Fn() -> String),
    mut each: impl FnMut(&[u8]),
) -> Result<String, Failure> {
    const PIECE: usize = 1 << 20;
    let (mut f, declared) = open(zip, name, crate::limits::MAX_BYTES, Some(expected))?;
    let (tx, rx) = std::sync::mpsc::sync_channel::<Vec<u8>>(8);
    std::thread::scope(|s| {
        let sum = s.spawn(move || {
            let mut m = Md5::new();
            for piece in rx {
                m.update(&piece);
            }
            m.finalize().iter().map(|b| format!("{b:02x}")).collect()
        });
        let mut left = declared;
        let mut buf = vec![0u8; PIECE.min(declared as usize)];
        let read = (|| {
            while left > 0 {
                let n = PIECE.min(left as usize);
                f.read_exact(&mut buf[..n]).map_err(|e| {
                    if e.kind() == std::io::ErrorKind::UnexpectedEof {
                        bad(format!(
                            "{name} unpacks to fewer bytes than the zip says ({declared}): \
                             the file is damaged"
                        ))
                    } else {
                        unpacking(name)(e)
                    }
                })?;
                each(&buf[..n]);
                // The MD5 thread has gone only if it panicked.
                let _ = tx.send(buf[..n].to_vec());
                left -= n as u64;
            }
            no_more(&mut f, name, declared)
        })();
        drop(tx);
        let sum = sum.join().expect("MD5 thread");
        read.map(|()| sum)
    })
}

fn md5_hex(b: &[u8]) -> String {
    Md5::digest(b).iter().map(|b| format!("{b:02x}")).collect()
}

/// Refuses `data` (member `name`) when its MD5 is not `recorded` (a
/// missing or malformed checksum is not checked).
fn check_md5(name: &str, data: &[u8], recorded: Option<&str>) -> Result<(), Failure> {
    match recorded {
        Some(r) => check_sum(name, &md5_hex(data), r),
        None => Ok(()),
    }
}

/// The checksum `recorded` (lower case) where it is a well-formed MD5
/// that is not `got`.
fn differs(got: &str, recorded: &str) -> Option<String> {
    let r = recorded.trim();
    let r = r.get(..32).unwrap_or(r);
    let formed = r.len() == 32 && r.bytes().all(|c| c.is_ascii_hexdigit());
    (formed && !got.eq_ignore_ascii_case(r)).then(|| r.to_ascii_lowercase())
}

/// Refuses member `name` when its MD5 `got` is not `recorded` (a
/// malformed checksum is not checked).
fn check_sum(name: &str, got: &str, recorded: &str) -> Result<(), Failure> {
    match differs(got, recorded) {
        Some(r) => Err(bad(format!(
            "the MD5 checksum of {name} is {got} where the file records {r}: \
             it was changed or damaged after it was written"
        ))),
        None => Ok(()),
    }
}

/// The child element `name` of `n` (namespaces aside).
fn child<'a, 'i>(n: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    n.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// The trimmed text of the element at `path` below `n`.
fn text_at<'a>(n: Node<'a, '_>, path: &[&str]) -> Option<&'a str> {
    let mut n = n;
    for p in path {
        n = child(n, p)?;
    }
    Some(n.text().unwrap_or("").trim())
}

/// A number in `main.xml` at `path`; `default` when missing or empty.
fn number(root: Node<'_, '_>, path: &[&str], default: Option<f64>) -> Result<f64, Failure> {
    let at = || path.join("/");
    match text_at(root, path) {
        Some(t) if !t.is_empty() => t
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| bad(format!("main.xml: {} = '{t}' is not a number", at()))),
        _ => default.ok_or_else(|| bad(format!("main.xml has no {}", at()))),
    }
}

fn size(root: Node<'_, '_>, name: &str) -> Result<usize, Failure> {
    let v = number(root, &["Record3", "MatrixDimension", name], None)?;
    if v >= 1.0 && v.fract() == 0.0 && v <= u32::MAX as f64 {
        Ok(v as usize)
    } else {
        Err(bad(format!(
            "main.xml: Record3/MatrixDimension/{name} = {v} is not a count of points"
        )))
    }
}

/// Bytes per stored height, how to read one, and the type's name.
type DataType = (usize, fn(&[u8]) -> f64, &'static str);

/// The z axis's `DataType`.
fn data_type(t: &str) -> Result<DataType, Failure> {
    Ok(match t {
        "I" => (2, |b| i16::from_le_bytes([b[0], b[1]]) as f64, "int16"),
        "L" => (
            4,
            |b| i32::from_le_bytes(b[..4].try_into().expect("4")) as f64,
            "int32",
        ),
        "F" => (
            4,
            |b| f32::from_le_bytes(b[..4].try_into().expect("4")) as f64,
            "float32",
        ),
        "D" => (
            8,
            |b| f64::from_le_bytes(b[..8].try_into().expect("8")),
            "float64",
        ),
        t => {
            return Err(bad(format!(
                "main.xml: the z axis's DataType '{t}' is none of I, L, F, D"
            )))
        }
    })
}

/// A member path of a link, within the folder of `main.xml`.
fn link(dir: &str, l: &str) -> Result<String, Failure> {
    let l = l.trim().trim_start_matches("./").replace('\\', "/");
    if l.starts_with('/') || l.contains("..") || l.contains(':') {
        return Err(bad(format!("main.xml links to '{l}', outside the file")));
    }
    Ok(format!("{dir}{l}"))
}

/// Reads an x3p file's first layer.
pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let mut zip = ZipArchive::new(Cursor::new(bytes)).map_err(|e| bad(unreadable(&e)))?;
    let Some(dir) = folder(&zip) else {
        return Err((None, Problem::Format(other_zip(&zip))));
    };
    let xml_name = format!("{dir}main.xml");
    let xml_bytes = member(&mut zip, &xml_name, MAX_XML, None)?;
    let xml = std::str::from_utf8(&xml_bytes)
        .map_err(|e| bad(format!("main.xml is not UTF-8 text ({e})")))?;
    let xml = xml.strip_prefix('\u{feff}').unwrap_or(xml);
    let doc = Document::parse_with_options(
        xml,
        ParsingOptions {
            allow_dtd: false,
            nodes_limit: MAX_NODES,
            ..ParsingOptions::default()
        },
    )
    .map_err(|e| bad(format!("main.xml is not well-formed XML ({e})")))?;
    let root = doc.root_element();
    let record1 = child(root, "Record1").ok_or_else(|| bad("main.xml has no Record1"))?;
    let record3 = child(root, "Record3").ok_or_else(|| bad("main.xml has no Record3"))?;
    // The checksum of main.xml itself, in md5sum's format ("HEX *NAME");
    // a line naming another member (SurfaceTopography 1.27 writes
    // bindata/data.bin's there) is left to main.xml's own checksums. One
    // that does not match is a warning: main.xml was edited after it was
    // written (x3pio reads such files too), and the heights' own checksums
    // still guard them.
    let mut xml_note = None;
    if let Some(name) = text_at(root, &["Record4", "ChecksumFile"]).filter(|n| !n.is_empty()) {
        let name = link(&dir, name)?;
        if zip.index_for_name(&name).is_some() {
            let sums = member(&mut zip, &name, 1 << 16, None)?;
            for line in String::from_utf8_lossy(&sums).lines() {
                let mut w = line.split_whitespace();
                let sum = w.next();
                let of = w.next().map(|n| n.trim_start_matches('*'));
                let got = md5_hex(&xml_bytes);
                if let (true, Some(r)) = (
                    of.is_none_or(|n| n == "main.xml"),
                    sum.and_then(|s| differs(&got, s)),
                ) {
                    xml_note = Some(format!(
                        "warning: the MD5 checksum of main.xml is {got} where {name} records \
                         {r}: main.xml was changed after it was written; read as it is"
                    ));
                }
            }
        }
    }
    let feature = text_at(record1, &["FeatureType"]).unwrap_or("");
    let irregular = || {
        bad(format!(
            "a point cloud (irregular x and y): {}",
            crate::formats::hints::XYZ_HINT
        ))
    };
    if feature == "PCL" || child(record3, "ListDimension").is_some() {
        return Err(irregular());
    }
    for axis in ["CX", "CY"] {
        if let Some(t) = text_at(record1, &["Axes", axis, "AxisType"]) {
            if t == "A" {
                return Err(irregular());
            }
        }
    }
    let (nx, ny, layers) = (
        size(root, "SizeX")?,
        size(root, "SizeY")?,
        size(root, "SizeZ")?,
    );
    let increment = |axis: &str| -> Result<f64, Failure> {
        let v = number(record1, &["Axes", axis, "Increment"], Some(1.0))?;
        if v == 0.0 {
            return Err(bad(format!("main.xml: the {axis} axis's Increment is 0")));
        }
        Ok(v.abs())
    };
    let (dx, dy) = (increment("CX")?, increment("CY")?);
    let dz = number(record1, &["Axes", "CZ", "Increment"], Some(1.0))?;
    let points = nx
        .checked_mul(ny)
        .and_then(|n| n.checked_mul(layers))
        .filter(|&n| {
            (n as u64) <= crate::limits::MAX_BYTES
                && 8 * (nx * ny) as u64 <= crate::limits::MAX_BYTES
        })
        .ok_or_else(|| {
            bad(format!(
                "main.xml says {nx} × {ny} × {layers} points: more than a file is read with"
            ))
        })?;
    let layer = nx * ny;
    let mut z = Vec::new();
    let mut notes: Vec<String> = xml_note.into_iter().collect();
    let mut nonfinite = 0;
    if let Some(list) = child(record3, "DataList") {
        let datums = || {
            list.children()
                .filter(|c| c.is_element() && c.tag_name().name() == "Datum")
        };
        let k = datums().count();
        if k != points {
            return Err(bad(format!(
                "main.xml says {nx} × {ny} × {layers} points but its DataList holds {k}"
            )));
        }
        z.reserve_exact(layer);
        for (k, d) in datums().take(layer).enumerate() {
            let t = d.text().unwrap_or("").trim();
            z.push(if t.is_empty() {
                nonfinite += 1;
                f64::NAN
            } else {
                let v = t.parse::<f64>().map_err(|_| {
                    bad(format!("main.xml: Datum {} = '{t}' is not a number", k + 1))
                })?;
                v * dz
            });
        }
    } else {
        let data_link = child(record3, "DataLink")
            .ok_or_else(|| bad("main.xml has neither a DataLink nor a DataList: no heights"))?;
        let ztype = text_at(record1, &["Axes", "CZ", "DataType"]).unwrap_or("D");
        let (width, get, tname) = data_type(ztype)?;
        let path = text_at(data_link, &["PointDataLink"])
            .filter(|p| !p.is_empty())
            .ok_or_else(|| bad("main.xml has no PointDataLink"))?;
        let path = link(&dir, path)?;
        let says = || format!("main.xml's {nx} × {ny} × {layers} points of {tname}");
        let sum = stream(&mut zip, &path, ((points * width) as u64, &says), |piece| {
            // Sized once data.bin's size is checked and its first piece in.
            if z.capacity() == 0 {
                z.reserve_exact(layer);
            }
            let room = layer - z.len();
            z.extend(piece.chunks_exact(width).take(room).map(|b| {
                let raw = get(b);
                if raw.is_finite() {
                    raw * dz
                } else {
                    nonfinite += 1;
                    f64::NAN
                }
            }));
        })?;
        if let Some(r) = text_at(data_link, &["MD5ChecksumPointData"]) {
            check_sum(&path, &sum, r)?;
        }
        if let Some(vpath) = text_at(data_link, &["ValidPointsLink"]).filter(|p| !p.is_empty()) {
            let vpath = link(&dir, vpath)?;
            let need = points.div_ceil(8) as u64;
            let says = || format!("main.xml's {nx} × {ny} × {layers} validity bits");
            let valid = member(
                &mut zip,
                &vpath,
                crate::limits::MAX_BYTES,
                Some((need, &says)),
            )?;
            check_md5(
                &vpath,
                &valid,
                text_at(data_link, &["MD5ChecksumValidPoints"]),
            )?;
            let mut invalid = 0;
            for (i, v) in z.iter_mut().enumerate() {
                if valid[i / 8] >> (i % 8) & 1 == 0 && !v.is_nan() {
                    invalid += 1;
                    *v = f64::NAN;
                }
            }
            if invalid > 0 {
                notes.push(format!(
                    "{invalid} points marked invalid in {vpath} read as undefined"
                ));
            }
        }
    }
    if nonfinite > 0 {
        notes.push(format!(
            "{nonfinite} points NaN, infinite or empty in the file read as undefined"
        ));
    }
    if layers > 1 {
        notes.push(format!("layer 1 of {layers} read"));
    }
    Ok(Grid {
        nx,
        ny,
        lx: nx as f64 * dx,
        ly: if ny == 1 { 0.0 } else { ny as f64 * dy },
        z,
        notes,
        format: "x3p",
        assumed: crate::formats::readers::assumed::Assumed::default(),
    })
}
