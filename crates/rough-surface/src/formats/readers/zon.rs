//! Keyence `.zon` (VR series one-shot 3D measuring macroscopes), read to
//! the layout SurfaceTopography reads: the magic `KPK0`, the size of a BMP
//! thumbnail and the thumbnail, then a zip whose members are named by
//! UUIDs — an XML calibration (`XYCalibration/MeterPerPixel`,
//! `ZCalibration/MeterPerUnit`), the heights and a validity plane, each
//! plane a 16-byte header (its width, its height, the bytes of a value, the
//! bytes of a row: 32-bit little-endian integers) and rows padded to that
//! size; heights are int32 times `MeterPerUnit`, and a point whose
//! validity byte has one of its two low bits set (out of range, or not to
//! be measured) is undefined. `KPK1` files compress each member with
//! zstd and are not read.

use super::bin::{values, Bytes, Order};
use super::zipped::Zipped;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Keyence .zon";
/// A .zon's first bytes (`KPK1` files are told and refused).
pub(crate) const MAGICS: [&[u8]; 2] = [b"KPK0", b"KPK1"];

const HEIGHTS: &str = "4cdb0c75-5706-48cc-a9a1-adf395d609ae";
const VALID: &str = "9e7ca6dd-0e6a-4d7b-8986-f0a7b773c916";
const CALIBRATION: &str = "686613b8-27b5-4a29-8ffc-438c2780873e";

/// The calibration XML is read up to this size.
const MAX_XML: u64 = 1 << 20;

/// A plane: its width, height and values (`item` bytes each), row after
/// row without the padding.
fn plane<'a>(raw: &'a [u8], item: usize, what: &str) -> Result<(u64, u64, Vec<&'a [u8]>), Failure> {
    let b = Bytes::new(raw, NAME);
    let nx = b.le::<i32>(0, what)?;
    let ny = b.le::<i32>(4, what)?;
    let size = b.le::<i32>(8, what)?;
    let row = b.le::<i32>(12, what)?;
    if nx < 1 || ny < 1 {
        return Err(b.bad(format!("{what} claims {nx} × {ny} points")));
    }
    if size as usize != item {
        return Err(b.bad(format!("{what} has values of {size} bytes, not {item}")));
    }
    let (nx, ny, row) = (nx as u64, ny as u64, row.max(0) as u64);
    if row < nx * item as u64 || row % item as u64 != 0 {
        return Err(b.bad(format!(
            "{what}'s rows of {row} bytes cannot hold {nx} values of {item} bytes"
        )));
    }
    let all = b.raster(16, (row / item as u64, ny), item, what)?;
    let rows = all
        .chunks_exact(row as usize)
        .map(|r| &r[..nx as usize * item])
        .collect();
    Ok((nx, ny, rows))
}

/// The number in the element `inner` inside an element `outer`.
fn calibration(xml: &str, outer: &str, inner: &str) -> Option<f64> {
    let opts = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: 1 << 16,
        ..Default::default()
    };
    let doc = roxmltree::Document::parse_with_options(xml, opts).ok()?;
    let o = doc.descendants().find(|n| n.has_tag_name(outer))?;
    let i = o.children().find(|n| n.has_tag_name(inner))?;
    i.text()?.trim().parse().ok()
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    if bytes.starts_with(b"KPK1") {
        return Err(b.bad(
            "a KPK1 file (its members compressed with zstd) is not read: export it from \
             the VR software as .csv or .x3p",
        ));
    }
    let mut z = Zipped::open(bytes, NAME)?;
    let xml = z.member(CALIBRATION, MAX_XML)?;
    let xml = String::from_utf8_lossy(&xml);
    let xml = xml.trim_start_matches('\u{feff}');
    let get = |outer: &str, inner: &str| -> Result<f64, Failure> {
        match calibration(xml, outer, inner) {
            Some(v) if v.is_finite() && v > 0.0 => Ok(v),
            Some(v) => Err(b.bad(format!("the calibration's {outer}/{inner} is {v}"))),
            None => Err(b.bad(format!("the calibration has no {outer}/{inner}"))),
        }
    };
    let pixel = get("XYCalibration", "MeterPerPixel")?;
    let unit = get("ZCalibration", "MeterPerUnit")?;
    let raw = z.member(HEIGHTS, crate::limits::MAX_BYTES)?;
    let (nx, ny, rows) = plane(&raw, 4, "the heights' plane")?;
    let mut heights: Vec<f64> = rows
        .iter()
        .flat_map(|r| values::<i32>(r, Order::Little))
        .map(|v| v as f64 * unit)
        .collect();
    let mut notes = Vec::new();
    if z.has(VALID) {
        let raw = z.member(VALID, crate::limits::MAX_BYTES)?;
        let (mx, my, rows) = plane(&raw, 1, "the validity plane")?;
        if (mx, my) != (nx, ny) {
            return Err(b.bad(format!(
                "the validity plane of {mx} × {my} points does not fit the heights' {nx} × {ny}"
            )));
        }
        for (h, &v) in heights.iter_mut().zip(rows.concat().iter()) {
            if v & 0x03 != 0 {
                *h = f64::NAN;
            }
        }
    } else {
        notes.push("no validity plane: every point read as measured".to_string());
    }
    let (nx, ny) = (nx as usize, ny as usize);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (nx as f64 * pixel, ny as f64 * pixel),
        heights,
        notes,
        "points not measured (the validity plane)",
    ))
}
