//! WSxM `.stp`, `.top` (and any other image file WSxM writes: Nanotec
//! Electronica's and WSxM Solutions' software, and the instruments that
//! save in it), read to the layout Gwyddion and SurfaceTopography read: a
//! Latin-1 text header — the line `WSxM file copyright …`, `SxM Image
//! file`, `Image header size: N`, then `[Section]`s of `key: value` lines
//! up to `[Header end]` — and, at byte N, `Number of rows` ×
//! `Number of columns` values of `Image Data Type` (`short` or `integer`:
//! 16 bits; `float`, `double`), little-endian. `X Amplitude` and
//! `Y Amplitude` (`[Control]`, with their units; a missing y amplitude is
//! the x one) are the sizes. Floating-point values are heights in the
//! unit of `Z Amplitude` (`[General Info]`); integers span it, from the
//! smallest to the largest stored. The image is stored rotated by half a
//! turn from how WSxM, Gwyddion and SurfaceTopography show it, and is read
//! turned back. A value that is not finite is an undefined point.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "WSxM";
pub(crate) const MAGIC: &[u8] = b"WSxM file copyright";

/// "59.7449 nm" as (59.7449, "nm"); `a.u.` and other units as they are.
fn amount(s: &str) -> Option<(f64, &str)> {
    let s = s.trim();
    let end = s.find(char::is_whitespace).unwrap_or(s.len());
    let n = s[..end].parse::<f64>().ok()?;
    Some((n, s[end..].trim()))
}

/// The header's `key: value` lines by section ("General Info", "Number
/// of rows").
struct Header(Vec<(String, String, String)>);

impl Header {
    fn parse(text: &str) -> Result<Header, String> {
        let mut section = String::new();
        let mut out = Vec::new();
        let mut ended = false;
        for line in text.lines().map(str::trim) {
            if let Some(s) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
                section = s.trim().to_string();
                if section == "Header end" {
                    ended = true;
                    break;
                }
            } else if let Some((k, v)) = line.split_once(':') {
                if !section.is_empty() {
                    out.push((section.clone(), k.trim().to_string(), v.trim().to_string()));
                }
            }
        }
        if !ended {
            return Err("the header has no '[Header end]' line: it is cut short".into());
        }
        Ok(Header(out))
    }

    fn get(&self, section: &str, key: &str) -> Option<&str> {
        self.0
            .iter()
            .find(|(s, k, _)| s == section && k.eq_ignore_ascii_case(key))
            .map(|(_, _, v)| v.as_str())
    }
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    // The first three lines: the copyright, what the file is, the size
    // of the header.
    let head = &bytes[..bytes.len().min(512)];
    let text: String = head.iter().map(|&c| c as char).collect();
    let mut lines = text.lines().map(str::trim);
    lines.next();
    let kind = lines.next().unwrap_or("").to_string();
    if kind != "SxM Image file" {
        return Err(b.bad(format!(
            "a WSxM '{}', not an image: the file holds no heights",
            super::bin::printable(&kind, 60)
        )));
    }
    let size = lines
        .next()
        .and_then(|l| l.strip_prefix("Image header size:"))
        .and_then(|n| n.trim().parse::<usize>().ok())
        .ok_or_else(|| b.bad("no 'Image header size:' on the third line"))?;
    let raw = b.slice(0, size, "the header")?;
    let text: String = raw.iter().map(|&c| c as char).collect();
    let h = Header::parse(&text).map_err(|e| b.bad(e))?;
    let need = |s: &str, k: &str| {
        h.get(s, k)
            .ok_or_else(|| b.bad(format!("the header has no '{k}' in [{s}]")))
    };
    let count = |k: &str| -> Result<u64, Failure> {
        need("General Info", k)?
            .parse::<u64>()
            .map_err(|_| b.bad(format!("'{k}' is not a count")))
    };
    let (rows, cols) = (count("Number of rows")?, count("Number of columns")?);
    let ty = need("General Info", "Image Data Type")?;
    let (item, float) = match ty {
        "short" | "integer" => (2, false),
        "float" => (4, true),
        "double" => (8, true),
        t => {
            return Err(b.bad(format!(
                "data of type '{}': short, integer, float and double are read",
                super::bin::printable(t, 40)
            )))
        }
    };
    let channel = h
        .get("General Info", "Acquisition channel")
        .unwrap_or("unnamed");
    let channel = super::bin::printable(channel, 60);
    let zamp = need("General Info", "Z Amplitude")?;
    let (zrange, zunit) = amount(zamp).ok_or_else(|| {
        b.bad(format!(
            "the Z amplitude '{}' is not a number and a unit",
            super::bin::printable(zamp, 40)
        ))
    })?;
    let zper = per_metre(zunit).ok_or_else(|| {
        b.bad(format!(
            "the channel '{channel}' is in '{}', not a length: the file holds no heights",
            super::bin::printable(zunit, 20)
        ))
    })?;
    let side = |k: &str| -> Result<f64, Failure> {
        let v = h
            .get("Control", k)
            .or_else(|| h.get("Control", "X Amplitude"));
        let v = v.ok_or_else(|| b.bad("the header has no 'X Amplitude' in [Control]"))?;
        match amount(v) {
            Some((n, u)) if n.is_finite() && n > 0.0 => per_metre(u)
                .map(|p| n / p)
                .ok_or_else(|| b.bad(format!("the {k}'s unit '{u}' is not a length"))),
            _ => Err(b.bad(format!(
                "the {k} '{}' is not a length > 0",
                super::bin::printable(v, 40)
            ))),
        }
    };
    let (lx, ly) = (side("X Amplitude")?, side("Y Amplitude")?);
    if !(zrange.is_finite() && zrange >= 0.0) {
        return Err(b.bad(format!("the Z amplitude is {zrange}")));
    }
    let data = b.raster(size, (cols, rows), item, "the image")?;
    let mut z: Vec<f64> = match item {
        2 => values::<i16>(data, Order::Little).map(f64::from).collect(),
        4 => values::<f32>(data, Order::Little).map(f64::from).collect(),
        _ => values::<f64>(data, Order::Little).collect(),
    };
    let mut notes = Vec::new();
    if float {
        z.iter_mut()
            .for_each(|v| *v = if v.is_finite() { *v / zper } else { f64::NAN });
    } else {
        // Integers span the Z amplitude from the smallest to the largest.
        let (lo, hi) = z
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, c), &v| (a.min(v), c.max(v)));
        let k = if hi > lo {
            zrange / (hi - lo) / zper
        } else {
            0.0
        };
        z.iter_mut().for_each(|v| *v *= k);
    }
    // Stored turned by half a turn: read back.
    z.reverse();
    if channel != "Topography" && channel != "unnamed" {
        notes.push(format!("channel '{channel}' read as heights ({zunit})"));
    }
    let (nx, ny) = (cols as usize, rows as usize);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (lx, ly),
        z,
        notes,
        "values that are not numbers",
    ))
}
