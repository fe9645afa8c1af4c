//! Bruker/Digital Instruments Nanoscope files (`.spm`, `.001`, `.di`), read
//! to the format's published description: a text header of `\*Section`
//! lines and `\Key: value` lines (Latin-1, up to `\*File list end`), then
//! the images as little-endian integers. Each `\*Ciao image list` section
//! is a channel: `Samps/line` × `Number of lines` points (row after row, the
//! first row at the bottom), `Scan size` (`300 300 nm`, or one number for a
//! square scan; `~m` is µm; a `Slow axis size` in the scan list overrides
//! the second), `Data offset`, `Data length`, `Bytes/pixel` (from version
//! 9.2 on the integers are 32-bit whatever it says, which then only
//! scales them). A value is `@2:Z scale: V [Sens. Zscan] (0.0029 V/LSB)
//! 192.3 V`: the hard value over 256^bytes-per-pixel, in volts, times the
//! soft scale `@Sens. Zscan: V 13.2 nm/V` of the scanner or scan list
//! gives the height per integer; a channel whose soft scale is no length
//! per volt (phase, amplitude in V) holds no heights.

use super::bin::{flip_rows, values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Nanoscope";

/// From this version on the data are 32-bit integers.
const VERSION_32BIT: u64 = 0x0920_0000;

/// The header is looked for in this many bytes.
const MAX_HEADER: usize = 1 << 20;

const FILE_LIST: [&str; 2] = ["file list", "ec file list"];
const SCANNER: [&str; 2] = ["scanner list", "microscope list"];
const SCAN: [&str; 4] = ["ciao scan list", "afm list", "stm list", "nc afm list"];
const IMAGE: [&str; 5] = [
    "ciao image list",
    "afm image list",
    "stm image list",
    "ncafm image list",
    "image list",
];

/// Whether `b` starts as a Nanoscope file does (force curves and text
/// data too, which [`read`] then refuses by name).
pub(crate) fn is_di(b: &[u8]) -> bool {
    let head = &b[..b.len().min(32)];
    let lower: Vec<u8> = head.iter().map(u8::to_ascii_lowercase).collect();
    [
        &b"\\*file list"[..],
        b"\\*ec file list",
        b"\\*force file list",
        b"?*file list",
    ]
    .iter()
    .any(|m| lower.starts_with(m))
}

type Section = (String, Vec<(String, String)>);

/// The header's sections, names and keys lower case.
fn sections(b: &Bytes<'_>) -> Result<Vec<Section>, Failure> {
    let head = &b.b[..b.len().min(MAX_HEADER)];
    let mut out: Vec<Section> = Vec::new();
    for raw in head.split(|&c| c == b'\n') {
        let line: String = raw.iter().map(|&c| c as char).collect();
        let line = line.trim();
        if line.eq_ignore_ascii_case("\\*file list end") {
            return Ok(out);
        }
        if line.is_empty() {
            continue;
        }
        if let Some(name) = line.strip_prefix("\\*") {
            out.push((name.trim().to_lowercase(), Vec::new()));
        } else if let Some(kv) = line.strip_prefix('\\') {
            let Some((_, keys)) = out.last_mut() else {
                return Err(b.bad("a header entry before the first section"));
            };
            let (k, v) = kv.split_once(": ").unwrap_or((kv, ""));
            keys.push((k.trim().to_lowercase(), v.trim().to_string()));
        } else {
            return Err(b.bad(format!(
                "a header line that does not start with a backslash: '{}'",
                line.chars().take(40).collect::<String>()
            )));
        }
    }
    Err(b.bad("the header has no '\\*File list end' line: it is truncated or damaged"))
}

fn get<'a>(keys: &'a [(String, String)], k: &str) -> Option<&'a str> {
    keys.iter()
        .find(|(key, _)| key == k)
        .map(|(_, v)| v.as_str())
}

/// A `@` value: (its soft scale's name, hard scale, hard value with unit).
fn at_value(v: &str) -> Option<(Option<String>, String)> {
    let rest = v.trim().get(1..)?.trim();
    let (soft, rest) = match rest.strip_prefix('[') {
        Some(r) => {
            let end = r.find(']')?;
            (Some(r[..end].trim().to_string()), r[end + 1..].trim())
        }
        None => (None, rest),
    };
    // The hard scale in parentheses (units may hold parentheses).
    let rest = if rest.starts_with('(') {
        let mut level = 0;
        let end = rest.char_indices().find_map(|(i, c)| {
            match c {
                '(' => level += 1,
                ')' => level -= 1,
                _ => {}
            }
            (level == 0).then_some(i)
        })?;
        rest[end + 1..].trim()
    } else {
        rest
    };
    Some((soft, rest.to_string()))
}

/// "2.91 V" as (2.91, "V").
fn number_unit(s: &str) -> Option<(f64, String)> {
    let mut w = s.split_whitespace();
    let n = w.next()?.parse::<f64>().ok()?;
    Some((n, w.collect::<Vec<_>>().join(" ")))
}

fn length_unit(u: &str) -> String {
    match u.trim() {
        "~m" | "um" | "μm" => "µm".into(),
        u => u.into(),
    }
}

fn volts(u: &str) -> Option<f64> {
    Some(match u {
        "V" => 1.0,
        "mV" => 1e-3,
        "µV" | "uV" | "~V" => 1e-6,
        "nV" => 1e-9,
        "kV" => 1e3,
        _ => return None,
    })
}

/// One image of the file, as its section says it.
struct Image {
    chan: Chan,
    nx: u64,
    ny: u64,
    /// Sizes in metres.
    lx: f64,
    ly: f64,
    offset: usize,
    elsize: usize,
    /// Metres per integer, for a channel of heights.
    scale: Option<f64>,
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    if bytes.starts_with(b"?*") {
        return Err(b.bad("the data are stored as text: files with binary data are read"));
    }
    let head: Vec<u8> = bytes.iter().take(18).map(u8::to_ascii_lowercase).collect();
    if head.starts_with(b"\\*force file list") {
        return Err(b.bad("a file of force curves, not a topography"));
    }
    let secs = sections(&b)?;
    match secs.first() {
        Some((n, _)) if FILE_LIST.contains(&n.as_str()) => {}
        Some((n, _)) if n == "force file list" => {
            return Err(b.bad("a file of force curves, not a topography"))
        }
        _ => return Err(b.bad("the header does not start with the '\\*File list' section")),
    }
    let global = |names: &[&str], k: &str| {
        secs.iter()
            .filter(|(n, _)| names.contains(&n.as_str()))
            .find_map(|(_, keys)| get(keys, k))
    };
    let mode = secs
        .iter()
        .find_map(|(_, keys)| get(keys, "operating mode"));
    let version = global(&FILE_LIST, "version")
        .and_then(|v| u64::from_str_radix(v.trim_start_matches("0x"), 16).ok())
        .unwrap_or(0);
    let context = global(&FILE_LIST, "start context").unwrap_or("");
    if mode == Some("Force") || context == "FOL" {
        return Err(b.bad("a file of force curves, not a topography"));
    }
    if context.ends_with("VAR") && mode != Some("Force Volume") {
        return Err(b.bad("a set of unevenly spaced profiles, not a topography"));
    }
    let global_n = match (
        global(&SCAN, "samps/line").and_then(|v| v.parse::<u64>().ok()),
        global(&SCAN, "lines").and_then(|v| v.parse::<u64>().ok()),
    ) {
        (Some(x), Some(y)) => Some((x, y)),
        _ => None,
    };
    // Newer files give the slow axis's size apart (the scan size's
    // second number may then be wrong), in metres.
    let slow = match (global(&SCAN, "scan size"), global(&SCAN, "slow axis size")) {
        (Some(fast), Some(slow)) => {
            let m = |s: &str| {
                let (v, u) = number_unit(s)?;
                Some(v / per_metre(&length_unit(&u))?)
            };
            m(fast).zip(m(slow))
        }
        _ => None,
    };
    let soft = |name: &str| {
        let key = format!("@{}", name.to_lowercase());
        global(&SCANNER, &key).or_else(|| global(&SCAN, &key))
    };
    let mut images = Vec::new();
    for (k, (_, keys)) in secs
        .iter()
        .filter(|(n, _)| IMAGE.contains(&n.as_str()))
        .enumerate()
    {
        let need =
            |key: &str| get(keys, key).ok_or_else(|| b.bad(format!("image {k} has no '{key}'")));
        let int = |key: &str| -> Result<u64, Failure> {
            need(key)?
                .trim()
                .parse::<u64>()
                .map_err(|_| b.bad(format!("image {k}'s '{key}' is not a count")))
        };
        let title = ["@2:image data", "@3:image data", "@4:image data"]
            .iter()
            .find_map(|key| get(keys, key))
            .and_then(at_value)
            .map(|(soft, hard)| soft.unwrap_or_else(|| hard.trim_matches('"').to_string()))
            .or_else(|| get(keys, "image data").map(String::from))
            .unwrap_or_else(|| format!("image {k}"));
        let (mut nx, mut ny) = (int("samps/line")?, int("number of lines")?);
        let size = need("scan size")?;
        let w: Vec<&str> = size.split_whitespace().collect();
        let num = |s: &str| s.parse::<f64>().ok();
        let (mut sx, mut sy, unit) = match (
            w.first().and_then(|s| num(s)),
            w.get(1).and_then(|s| num(s)),
        ) {
            (Some(x), Some(y)) => (x, y, w[2..].join(" ")),
            (Some(x), None) => (x, x, w[1..].join(" ")),
            _ => return Err(b.bad(format!("image {k}'s scan size '{size}' is not a size"))),
        };
        let per = per_metre(&length_unit(&unit)).ok_or_else(|| {
            b.bad(format!(
                "image {k}'s scan size '{size}' is not in a unit of length"
            ))
        })?;
        sx /= per;
        sy /= per;
        if let Some((fast, s)) = slow {
            (sx, sy) = (fast, s);
        }
        let offset = int("data offset")? as usize;
        let length = int("data length")?;
        let bpp = get(keys, "bytes/pixel").map_or(Ok(2), |_| int("bytes/pixel"))?;
        if bpp != 2 && bpp != 4 {
            return Err(b.bad(format!(
                "image {k} has {bpp} bytes a pixel: 2 or 4 are read"
            )));
        }
        let mut elsize = bpp;
        if version >= VERSION_32BIT && length >= 4 * nx.saturating_mul(ny) {
            elsize = 4;
        }
        // Some files give wrong sizes in the image sections: the scan
        // list's are then right.
        let fits = |x: u64, y: u64| x.saturating_mul(y).saturating_mul(elsize);
        if let Some((gx, gy)) = global_n {
            let want = fits(nx, ny);
            if length != want && (length == fits(gx, gy) || want > length && length >= fits(gx, gy))
            {
                if slow.is_none() {
                    sx *= gx as f64 / nx as f64;
                    sy *= gy as f64 / ny as f64;
                }
                (nx, ny) = (gx, gy);
            } else if slow.is_some() && ny < gy && aspect(keys) {
                // A scan stopped early ("Capture Now").
                sy *= ny as f64 / gy as f64;
            }
        }
        if fits(nx, ny) > length {
            return Err(b.bad(format!(
                "image {k} of {nx} × {ny} points of {elsize} bytes does not fit its data \
                 length of {length} bytes"
            )));
        }
        let (mut unit, mut scale) = (String::new(), None);
        let z = get(keys, "@4:z scale").or_else(|| get(keys, "@2:z scale"));
        if let Some((Some(q), hard)) = z.and_then(at_value) {
            if let Some((hv, hu)) = number_unit(&hard) {
                unit = hu.clone();
                let hard_scale = hv / 256f64.powi(bpp as i32);
                if let Some((sv, su)) = soft(&q)
                    .and_then(at_value)
                    .and_then(|(_, s)| number_unit(&s))
                {
                    if let Some((num, den)) = su.split_once('/') {
                        unit = length_unit(num);
                        let to_soft = volts(&hu).zip(volts(den)).map(|(a, b)| a / b);
                        let to_soft = if hu == den { Some(1.0) } else { to_soft };
                        if let (Some(p), Some(t)) = (per_metre(&unit), to_soft) {
                            scale = Some(hard_scale * t * sv / p);
                        }
                    }
                }
            }
        }
        images.push(Image {
            chan: Chan { title, unit },
            nx,
            ny,
            lx: sx,
            ly: sy,
            offset,
            elsize: elsize as usize,
            scale,
        });
    }
    if images.is_empty() {
        return Err(b.bad("no image section: nothing to read"));
    }
    // Every image in the file, or it was cut short.
    for (k, im) in images.iter().enumerate() {
        let end = (im.offset as u64).saturating_add(im.nx * im.ny * im.elsize as u64);
        if end > bytes.len() as u64 {
            return Err(b.bad(format!(
                "image {k} ends at byte {end} but the file holds {} bytes: it is truncated \
                 or damaged",
                bytes.len()
            )));
        }
    }
    // A channel is heights when its scale is a length (its unit alone may be
    // one without a soft scale to make it so).
    let chans: Vec<Chan> = images
        .iter()
        .map(|i| Chan {
            title: i.chan.title.clone(),
            unit: if i.scale.is_some() || per_metre(&i.chan.unit).is_none() {
                i.chan.unit.clone()
            } else {
                format!("{} (no scale)", i.chan.unit)
            },
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    let im = &images[n];
    let scale = im.scale.expect("a channel of heights has a scale");
    let raw = b.raster(im.offset, (im.nx, im.ny), im.elsize, "the image")?;
    let mut z: Vec<f64> = if im.elsize == 2 {
        values::<i16>(raw, Order::Little)
            .map(|v| v as f64 * scale)
            .collect()
    } else {
        values::<i32>(raw, Order::Little)
            .map(|v| v as f64 * scale)
            .collect()
    };
    let nx = im.nx as usize;
    flip_rows(&mut z, nx);
    let ny = im.ny as usize;
    Ok(Grid {
        nx,
        ny,
        lx: im.lx,
        ly: if ny == 1 { 0.0 } else { im.ly },
        z,
        notes: chan::note(&chans, n).into_iter().collect(),
        format: NAME,
        assumed: Default::default(),
    })
}

/// An image section whose aspect ratio is not 1:1.
fn aspect(keys: &[(String, String)]) -> bool {
    match get(keys, "aspect ratio") {
        None => false,
        Some(a) if a.trim() == "1:1" => false,
        Some(a) => a
            .split(':')
            .next()
            .and_then(|r| r.trim().parse::<f64>().ok())
            .is_some_and(|r| r > 0.0 && r != 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_of_the_header() {
        assert_eq!(
            at_value("V [Sens. Zscan] (0.006713867 V/LSB) 2.910461 V"),
            Some((Some("Sens. Zscan".into()), "2.910461 V".into()))
        );
        assert_eq!(
            at_value("V (0.1 log(Arb)/LSB) 3 log(Arb)"),
            Some((None, "3 log(Arb)".into()))
        );
        assert_eq!(number_unit("13.2 nm/V"), Some((13.2, "nm/V".into())));
        assert!(is_di(b"\\*File list\r\n"));
        assert!(!is_di(b"\\*Files"));
    }
}
