//! Park Systems AFM images (`.tiff`, XEI and SmartScan): TIFF files whose
//! picture is a false-colour rendering, the measurement kept in tags of
//! Park's own, read to the layout Gwyddion (`psia.c`) and
//! SurfaceTopography read: tag 50432 the magic 0x0E031301, 50433 the
//! version (1 or 2), 50434 the data, 50435 a little-endian header — the
//! image type at byte 0 (0 a map, 1 a line profile, 2 spectroscopy: the
//! force curves are then in tags 50438 and 50439, and the data is the map
//! they were taken on), the channel's name (32 UTF-16 characters) at 4,
//! the points along x and y at 100 and 104, the scan's size in µm along x
//! and y at 140 and 148, the data's gain, scale and offset at 220, 228
//! and 236 and its unit (8 UTF-16 characters, µm when empty) at 244, and
//! in version 2 the values' type at 348 (0 int16, 1 int32, 2 float32;
//! version 1 stores int16). A height is gain × (scale × value + offset)
//! in that unit; rows are stored from the bottom.

use super::bin::{flip_rows, values, Bytes, Order};
use super::tiffs::Tiff;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Park Systems TIFF";

const MAGIC: f64 = 235_082_497.0; // 0x0E031301
const TAG_MAGIC: u16 = 50432;
const TAG_VERSION: u16 = 50433;
const TAG_DATA: u16 = 50434;
const TAG_HEADER: u16 = 50435;

/// Whether `bytes` are a Park Systems TIFF (its magic tag).
pub(crate) fn is_park(bytes: &[u8]) -> bool {
    (bytes.starts_with(super::tiffs::LITTLE) || bytes.starts_with(super::tiffs::BIG))
        && Tiff::read(bytes, NAME)
            .is_ok_and(|t| t.number(0, TAG_MAGIC).is_ok_and(|m| m == Some(MAGIC)))
}

/// A UTF-16 text field of `chars` characters at `at`.
fn utf16(h: &Bytes<'_>, at: usize, chars: usize, what: &str) -> Result<String, Failure> {
    let raw = h.slice(at, 2 * chars, what)?;
    let units = raw
        .chunks_exact(2)
        .map(|c| u16::from_le_bytes([c[0], c[1]]))
        .take_while(|&u| u != 0);
    Ok(char::decode_utf16(units)
        .map(|c| c.unwrap_or('?'))
        .collect::<String>()
        .trim()
        .to_string())
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let t = Tiff::read(bytes, NAME)?;
    t.strips_inside()?;
    let b = t.b;
    let version = t.number(0, TAG_VERSION)?.unwrap_or(0.0) as u32;
    if !matches!(version, 0x0100_0001 | 0x0100_0002) {
        return Err(b.bad(format!("version {version:#x}: versions 1 and 2 are read")));
    }
    let header = t
        .bytes(0, TAG_HEADER)?
        .ok_or_else(|| b.bad("no header (tag 50435)"))?;
    let h = Bytes::new(header, NAME);
    let kind = h.le::<u32>(0, "the image type")?;
    let source = utf16(&h, 4, 32, "the channel's name")?;
    let nx = h.le::<u32>(100, "the points along x")? as u64;
    let ny = h.le::<u32>(104, "the points along y")? as u64;
    let lx = h.le::<f64>(140, "the scan size along x")?;
    let ly = h.le::<f64>(148, "the scan size along y")?;
    let gain = h.le::<f64>(220, "the data gain")?;
    let scale = match h.le::<f64>(228, "the data scale")? {
        0.0 => 1.0,
        s => s,
    };
    let offset = h.le::<f64>(236, "the data offset")?;
    let unit = match utf16(&h, 244, 8, "the data unit")?.as_str() {
        "" | "um" => "µm".to_string(),
        u => u.to_string(),
    };
    let ty = if version == 0x0100_0002 {
        h.le::<u32>(348, "the values' type")?
    } else {
        0
    };
    let mut notes = Vec::new();
    match kind {
        0 => {}
        2 => notes.push(format!(
            "a spectroscopy file: its force curves are not read; the map read is the \
             '{source}' image they were taken on"
        )),
        1 => return Err(b.bad("a line profile image (type 1): maps are read")),
        k => return Err(b.bad(format!("image type {k}: maps (type 0) are read"))),
    }
    let Some(per) = per_metre(&unit) else {
        return Err(b.bad(format!(
            "the '{source}' image holds values in '{}', not heights (a length)",
            super::bin::printable(&unit, 20)
        )));
    };
    for (v, what) in [(lx, "x"), (ly, "y")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("the scan size along {what} is {v} µm")));
        }
    }
    if !(gain.is_finite() && scale.is_finite() && offset.is_finite()) {
        return Err(b.bad(format!(
            "the data's gain, scale and offset are {gain}, {scale} and {offset}"
        )));
    }
    let item = match ty {
        0 => 2,
        1 | 2 => 4,
        t => return Err(b.bad(format!("values of type {t}: 0, 1 and 2 are read"))),
    };
    let data = t
        .bytes(0, TAG_DATA)?
        .ok_or_else(|| b.bad("no data (tag 50434)"))?;
    let d = Bytes::new(data, NAME);
    let raw = d.raster(0, (nx, ny), item, "the data")?;
    let k = gain / per;
    let h = |v: f64| k * (scale * v + offset);
    let mut z: Vec<f64> = match ty {
        0 => values::<i16>(raw, Order::Little)
            .map(|v| h(v.into()))
            .collect(),
        1 => values::<i32>(raw, Order::Little)
            .map(|v| h(v.into()))
            .collect(),
        _ => values::<f32>(raw, Order::Little)
            .map(|v| if v.is_finite() { h(v.into()) } else { f64::NAN })
            .collect(),
    };
    let (nx, ny) = (nx as usize, ny as usize);
    flip_rows(&mut z, nx);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (lx * 1e-6, ly * 1e-6),
        z,
        notes,
        "points stored as NaN",
    ))
}
