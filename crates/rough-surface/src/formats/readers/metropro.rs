//! Zygo MetroPro `.dat`, read to the MetroPro Reference Guide's header
//! (big-endian): the magic (three header formats), the header's size at
//! byte 6 (834, or 4096 for the third format), the intensity data's
//! width, height and buckets at 52–56, the phase data's width and height
//! at 68 and 70, the interferometric scale factor, wavelength and
//! obliquity factor at 164, 168 and 176, the lateral resolution (m per
//! pixel) at 184, the phase resolution at 218 (0, 1, 2: 4096, 32768 or
//! 131072 steps a wave) and the sign at 232. After the header the
//! intensity data (2 bytes a bucket and pixel), then the phase data as
//! 32-bit integers row after row; values from 2147483640 on are points
//! not measured. A height is value × scale factor × obliquity ×
//! wavelength / steps, negated when the sign is set.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Zygo MetroPro .dat";
pub(crate) const MAGICS: [&[u8]; 3] = [
    b"\x88\x1b\x03\x6f",
    b"\x88\x1b\x03\x70",
    b"\x88\x1b\x03\x71",
];

/// Phase data at or above this are not measured.
const INVALID: i32 = 2_147_483_640;

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let third = bytes.starts_with(MAGICS[2]);
    let size = b.be::<u32>(6, "the header's size")? as usize;
    let want = if third { 4096 } else { 834 };
    if size != want {
        return Err(b.bad(format!(
            "a header of {size} bytes where this header format has {want}"
        )));
    }
    let ac = (
        b.be::<u16>(52, "the intensity data's width")? as usize,
        b.be::<u16>(54, "the intensity data's height")? as usize,
        b.be::<u16>(56, "the intensity data's buckets")? as usize,
    );
    let nx = b.be::<u16>(68, "the phase data's width")? as u64;
    let ny = b.be::<u16>(70, "the phase data's height")? as u64;
    let scale_factor = b.be::<f32>(164, "the interferometric scale factor")? as f64;
    let wavelength = b.be::<f32>(168, "the wavelength")? as f64;
    let obliquity = b.be::<f32>(176, "the obliquity factor")? as f64;
    let res = b.be::<f32>(184, "the lateral resolution")? as f64;
    let steps = match b.be::<i16>(218, "the phase resolution")? {
        0 => 4096.0,
        1 => 32768.0,
        2 => 131072.0,
        r => return Err(b.bad(format!("the phase resolution is {r} (0, 1 or 2)"))),
    };
    let sign = if b.be::<i16>(232, "the sign")? != 0 {
        -1.0
    } else {
        1.0
    };
    if !(res.is_finite() && res > 0.0) {
        return Err(b.bad(format!(
            "the lateral resolution is {res} m: the lateral size is unknown"
        )));
    }
    let scale = sign * scale_factor * obliquity * wavelength / steps;
    if !scale.is_finite() {
        return Err(b.bad("the heights' scale is not a number"));
    }
    let start = size + 2 * ac.0 * ac.1 * ac.2;
    if nx == 0 || ny == 0 {
        return Err(b.bad("no phase data: the file holds intensities only"));
    }
    let raw = b.raster(start, (nx, ny), 4, "the phase data")?;
    let z: Vec<f64> = values::<i32>(raw, Order::Big)
        .map(|v| {
            if v >= INVALID {
                f64::NAN
            } else {
                v as f64 * scale
            }
        })
        .collect();
    let (nx, ny) = (nx as usize, ny as usize);
    let size = (nx as f64 * res, ny as f64 * res);
    let what = "points not measured";
    Ok(Grid::of_file(NAME, (nx, ny), size, z, vec![], what))
}
