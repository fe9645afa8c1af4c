//! Alicona Imaging `.al3d` (InfiniteFocus focus-variation microscopes),
//! read to the layout Gwyddion and SurfaceTopography read: the magic
//! `AliconaImaging\0\r\n`, then tags of a 20-byte key and a 30-byte value
//! (text, NUL-padded) ended by CR LF — `Version`, `TagCount`, then that many
//! more (`Cols`, `Rows`, `PixelSizeXMeter`, `PixelSizeYMeter`,
//! `DepthImageOffset`, `InvalidPixelValue` …) — and a 256-byte comment. The
//! depth image at `DepthImageOffset` is float32 in metres, row after row,
//! each row padded to a multiple of 8 bytes; NaN and the invalid value
//! (within 1.5e-7 of it, relative) are points not measured.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Alicona .al3d";
pub(crate) const MAGIC: &[u8] = b"AliconaImaging\0\r\n";

const TAG: usize = 52;

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let tag = |k: usize| -> Result<(String, String), Failure> {
        let at = MAGIC.len() + k * TAG;
        let key = b.text(at, 20, "a tag's key")?;
        let value = b.text(at + 20, 30, "a tag's value")?;
        if b.slice(at + 50, 2, "a tag's end")? != b"\r\n" {
            return Err(b.bad(format!("tag {k} at byte {at} does not end with CR LF")));
        }
        Ok((key, value))
    };
    let (k0, _) = tag(0)?;
    let (k1, count) = tag(1)?;
    if k0 != "Version" || k1 != "TagCount" {
        return Err(b.bad("the first tags are not 'Version' and 'TagCount'"));
    }
    let count: usize = count
        .parse()
        .map_err(|_| b.bad(format!("'TagCount' is '{count}', not a count")))?;
    // Each tag takes 52 bytes of the file.
    if count > b.len() / TAG {
        return Err(b.bad(format!(
            "'TagCount' claims {count} tags: more than the file holds"
        )));
    }
    let tags: Vec<(String, String)> = (0..count).map(|k| tag(k + 2)).collect::<Result<_, _>>()?;
    let get = |k: &str| {
        tags.iter()
            .find(|(key, _)| key == k)
            .map(|(_, v)| v.as_str())
            .ok_or_else(|| b.bad(format!("no '{k}' tag")))
    };
    let count_of = |k: &str| -> Result<u64, Failure> {
        let v = get(k)?;
        v.parse()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a count")))
    };
    let number = |k: &str| -> Result<f64, Failure> {
        let v = get(k)?;
        v.parse::<f64>()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a number")))
    };
    let (nx, ny) = (count_of("Cols")?, count_of("Rows")?);
    let (dx, dy) = (number("PixelSizeXMeter")?, number("PixelSizeYMeter")?);
    for (v, what) in [(dx, "PixelSizeXMeter"), (dy, "PixelSizeYMeter")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("'{what}' is {v}")));
        }
    }
    let invalid = get("InvalidPixelValue")
        .ok()
        .and_then(|v| v.parse::<f64>().ok())
        .filter(|v| !v.is_nan());
    let offset = count_of("DepthImageOffset")? as usize;
    // Rows padded to a multiple of 8 bytes.
    let row = (nx * 4).div_ceil(8) * 8 / 4;
    let raw = b.raster(offset, (row, ny), 4, "the depth image")?;
    let z: Vec<f64> = raw
        .chunks_exact(row as usize * 4)
        .flat_map(|r| values::<f32>(&r[..nx as usize * 4], Order::Little))
        .map(|v| {
            let v = v as f64;
            let bad = v.is_nan() || invalid.is_some_and(|i| (v - i).abs() < 1.5e-7 * i.abs());
            if bad || v.is_infinite() {
                f64::NAN
            } else {
                v
            }
        })
        .collect();
    let (nx, ny) = (nx as usize, ny as usize);
    let size = (nx as f64 * dx, ny as f64 * dy);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        size,
        z,
        vec![],
        "invalid points",
    ))
}
