//! Image Metrology `.bcr` and `.bcrf` (the BCR-STM interchange format:
//! SPIP writes it, and instruments of many makers export it), read to
//! Image Metrology's published layout, as Gwyddion and SurfaceTopography
//! read it: a text header of `key = value` lines (`%` and `#` start a
//! comment) of 2048 characters, or of `headersize` characters, in Latin-1
//! or — the `_unicode` formats — UTF-16, then `ypixels` rows of `xpixels`
//! values: 16-bit integers (`bcrstm`) times `bit2nm`, or float32 (`bcrf`),
//! heights in `zunit` (nm when not given); little-endian unless
//! `intelmode = 0`. `xlength` and `ylength` are the sizes, in `xunit` and
//! `yunit` (nm when not given). A void point (32767, or a float above
//! 1.7e38) is an undefined point.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Image Metrology .bcr";
const MAGIC: &str = "fileformat = bcr";

/// The header's text encoding, told by its first bytes.
#[derive(Clone, Copy, PartialEq)]
enum Encoding {
    Latin1,
    /// UTF-16, little-endian unless `true`; the byte-order mark's two
    /// bytes skipped.
    Utf16 {
        big: bool,
        bom: bool,
    },
}

fn encoding(b: &[u8]) -> Option<Encoding> {
    let utf16 = |s: &[u8], big: bool| {
        MAGIC
            .bytes()
            .enumerate()
            .all(|(i, c)| s.get(2 * i..2 * i + 2) == Some(&if big { [0, c] } else { [c, 0] }))
    };
    if b.starts_with(MAGIC.as_bytes()) {
        Some(Encoding::Latin1)
    } else if utf16(b, false) {
        Some(Encoding::Utf16 {
            big: false,
            bom: false,
        })
    } else if b.starts_with(&[0xff, 0xfe]) && utf16(&b[2..], false) {
        Some(Encoding::Utf16 {
            big: false,
            bom: true,
        })
    } else if b.starts_with(&[0xfe, 0xff]) && utf16(&b[2..], true) {
        Some(Encoding::Utf16 {
            big: true,
            bom: true,
        })
    } else {
        None
    }
}

/// Whether `b` is a BCR file.
pub(crate) fn is_bcr(b: &[u8]) -> bool {
    encoding(b).is_some()
}

/// The header's first `chars` characters as text.
fn text(b: &[u8], e: Encoding, chars: usize) -> String {
    match e {
        Encoding::Latin1 => b[..chars.min(b.len())].iter().map(|&c| c as char).collect(),
        Encoding::Utf16 { big, .. } => {
            let units = b.chunks_exact(2).take(chars).map(|c| {
                if big {
                    u16::from_be_bytes([c[0], c[1]])
                } else {
                    u16::from_le_bytes([c[0], c[1]])
                }
            });
            char::decode_utf16(units)
                .map(|c| c.unwrap_or('?'))
                .collect()
        }
    }
}

/// The header's `key = value` lines.
fn pairs(t: &str) -> Vec<(String, String)> {
    t.lines()
        .map(|l| l.trim_matches(|c: char| c == '\0' || c.is_whitespace()))
        .filter(|l| !l.starts_with('%') && !l.starts_with('#'))
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| {
            (
                k.trim().to_string(),
                v.trim_matches(['\0', ' ', '\t']).to_string(),
            )
        })
        .filter(|(k, v)| !k.is_empty() && !v.is_empty())
        .collect()
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let e = encoding(bytes).ok_or_else(|| b.bad("no 'fileformat = bcr…' line"))?;
    let (width, skip) = match e {
        Encoding::Latin1 => (1, 0),
        Encoding::Utf16 { bom, .. } => (2, if bom { 2 } else { 0 }),
    };
    // The header's size is within its first 2048 characters.
    let first = pairs(&text(&bytes[skip..], e, 2048));
    let get = |p: &[(String, String)], k: &str| {
        p.iter()
            .find(|(key, _)| key.eq_ignore_ascii_case(k))
            .map(|(_, v)| v.clone())
    };
    let chars = match get(&first, "headersize") {
        Some(s) => s
            .parse::<usize>()
            .ok()
            .filter(|&n| (64..=1 << 20).contains(&n))
            .ok_or_else(|| b.bad(format!("the header size '{s}' is not a size")))?,
        None => 2048,
    };
    let start = chars * width;
    b.slice(0, start, "the header")?;
    let h = pairs(&text(&bytes[skip..start], e, chars));
    let need = |k: &str| get(&h, k).ok_or_else(|| b.bad(format!("the header has no '{k}'")));
    let format = need("fileformat")?;
    let float = match format.as_str() {
        "bcrstm" | "bcrstm_unicode" => false,
        "bcrf" | "bcrf_unicode" => true,
        f => {
            return Err(b.bad(format!(
                "file format '{}': bcrstm and bcrf are read",
                super::bin::printable(f, 40)
            )))
        }
    };
    if get(&h, "forcecurve").is_some_and(|v| v.trim() != "0") {
        return Err(b.bad("force curves: the file holds no heights"));
    }
    let count = |k: &str| -> Result<u64, Failure> {
        let v = need(k)?;
        v.parse::<u64>().map_err(|_| {
            b.bad(format!(
                "'{k}' is '{}', not a count",
                super::bin::printable(&v, 40)
            ))
        })
    };
    let (nx, ny) = (count("xpixels")?, count("ypixels")?);
    let unit = |k: &str| -> Result<f64, Failure> {
        let u = get(&h, k).unwrap_or_else(|| "nm".into());
        per_metre(&u).ok_or_else(|| {
            b.bad(format!(
                "{k} is '{}', not a unit of length{}",
                super::bin::printable(&u, 20),
                if k == "zunit" {
                    ": the file holds no heights"
                } else {
                    ""
                }
            ))
        })
    };
    let length = |k: &str, u: &str| -> Result<f64, Failure> {
        let v = need(k)?;
        match v.parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 => Ok(x / unit(u)?),
            _ => Err(b.bad(format!(
                "'{k}' is '{}', not a length > 0",
                super::bin::printable(&v, 40)
            ))),
        }
    };
    let (lx, ly) = (length("xlength", "xunit")?, length("ylength", "yunit")?);
    let zper = unit("zunit")?;
    let order = match get(&h, "intelmode").as_deref().map(str::trim) {
        Some("0") => Order::Big,
        _ => Order::Little,
    };
    let scale = if float {
        1.0
    } else {
        match get(&h, "bit2nm") {
            Some(v) => v
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    b.bad(format!(
                        "bit2nm is '{}', not a number",
                        super::bin::printable(&v, 40)
                    ))
                })?,
            None => 1.0,
        }
    };
    let item = if float { 4 } else { 2 };
    let raw = b.raster(start, (nx, ny), item, "the heights")?;
    let z: Vec<f64> = if float {
        values::<f32>(raw, order)
            .map(|v| {
                if v.is_finite() && v <= 1.7e38 {
                    v as f64 / zper
                } else {
                    f64::NAN
                }
            })
            .collect()
    } else {
        values::<i16>(raw, order)
            .map(|v| {
                if v == i16::MAX {
                    f64::NAN
                } else {
                    v as f64 * scale / zper
                }
            })
            .collect()
    };
    let what = "void points (32767, or a float above 1.7e38)";
    Ok(Grid::of_file(
        NAME,
        (nx as usize, ny as usize),
        (lx, ly),
        z,
        vec![],
        what,
    ))
}
