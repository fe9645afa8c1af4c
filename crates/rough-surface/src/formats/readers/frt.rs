//! FRT MicroProf `.frt`, read to the layout Gwyddion (`microprof.c`) and
//! SurfaceTopography read: the magic `FRTM_GLIDERV`, the version `1.00`
//! (32-bit block sizes) or `1.01` (64-bit), a 16-bit count of blocks, then
//! the blocks, each a 16-bit tag, its size and its bytes (little-endian).
//! Block 0x66 gives the points along x and y and the bits a pixel (16:
//! unsigned, 32: signed), 0x67 the size along x and y (doubles, metres),
//! 0x6C the height per step (a double after a 32-bit range) and 0x0B the
//! heights, row after row from the bottom; without 0x0B, block 0x7D holds
//! images, each with a type (heights: topography, thickness, sample
//! thickness, AFM), its points, bits and data. A value of 1 marks a point
//! not measured.

use super::bin::{flip_rows, values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "FRT .frt";
pub(crate) const MAGIC: &[u8] = b"FRTM_GLIDERV";

/// Image types (bits) of heights in block 0x7D.
const HEIGHT_TYPES: u32 = 0x0004 | 0x0080 | 0x0800 | 0x1000;

/// A raster of heights: points, bits a pixel and where its values are.
struct Raster {
    nx: u64,
    ny: u64,
    bits: u32,
    at: usize,
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let wide = match b.slice(12, 4, "the version")? {
        b"1.00" => false,
        b"1.01" => true,
        v => {
            return Err(b.bad(format!(
                "version '{}': 1.00 and 1.01 are read",
                super::bin::latin1(v)
            )))
        }
    };
    let count = b.le::<u16>(16, "the number of blocks")?;
    let mut blocks = Vec::new();
    let mut at = 18usize;
    for _ in 0..count {
        let tag = b.le::<u16>(at, "a block's tag")?;
        let (size, head) = if wide {
            (b.le::<u64>(at + 2, "a block's size")?, 10)
        } else {
            (b.le::<u32>(at + 2, "a block's size")? as u64, 6)
        };
        let start = at + head;
        let size = usize::try_from(size)
            .ok()
            .filter(|&s| s <= b.len().saturating_sub(start))
            .ok_or_else(|| {
                b.bad(format!(
                    "block {tag:#06x} at byte {at} claims {size} bytes: more than the file holds"
                ))
            })?;
        blocks.push((tag, start, size));
        at = start + size;
    }
    let block = |t: u16| {
        blocks
            .iter()
            .find(|(tag, _, _)| *tag == t)
            .map(|&(_, s, n)| (s, n))
    };
    let need =
        |t: u16, what: &str| block(t).ok_or_else(|| b.bad(format!("no {what} (block {t:#06x})")));
    let (sizes, _) = need(0x67, "size")?;
    let lx = b.le::<f64>(sizes, "the size along x")?;
    let ly = b.le::<f64>(sizes + 8, "the size along y")?;
    let (scale_at, _) = need(0x6C, "height scale")?;
    let scale = b.le::<f64>(scale_at + 4, "the height scale")?;
    if !scale.is_finite() {
        return Err(b.bad(format!("the height scale is {scale}")));
    }
    let mut rasters = Vec::new();
    let mut chans = Vec::new();
    if let Some((data, len)) = block(0x0B) {
        let (g, _) = need(0x66, "grid")?;
        let r = Raster {
            nx: b.le::<u32>(g, "the points along x")? as u64,
            ny: b.le::<u32>(g + 4, "the points along y")? as u64,
            bits: b.le::<u32>(g + 8, "the bits a pixel")?,
            at: data,
        };
        if r.nx.saturating_mul(r.ny).saturating_mul(r.bits as u64 / 8) > len as u64 {
            return Err(b.bad(format!(
                "{} × {} points of {} bits do not fit the heights' block of {len} bytes",
                r.nx, r.ny, r.bits
            )));
        }
        rasters.push(r);
        chans.push(Chan {
            title: "Topography".into(),
            unit: "m".into(),
        });
    } else if let Some((start, len)) = block(0x7D) {
        let end = start + len;
        let mut at = start + 8;
        while at + 16 <= end {
            let ty = b.le::<u32>(at, "an image's type")?;
            let r = Raster {
                nx: b.le::<u32>(at + 4, "an image's points along x")? as u64,
                ny: b.le::<u32>(at + 8, "an image's points along y")? as u64,
                bits: b.le::<u32>(at + 12, "an image's bits a pixel")?,
                at: at + 16,
            };
            if r.bits != 16 && r.bits != 32 {
                return Err(b.bad(format!("an image of {} bits a pixel", r.bits)));
            }
            let n = b
                .raster(r.at, (r.nx, r.ny), r.bits as usize / 8, "an image")?
                .len();
            at = r.at + n;
            if ty & HEIGHT_TYPES != 0 {
                rasters.push(r);
                chans.push(Chan {
                    title: format!("image {}", chans.len()),
                    unit: "m".into(),
                });
            }
        }
    }
    if rasters.is_empty() {
        return Err(b.bad("no heights (no block 0x000b, no image of heights in 0x007d)"));
    }
    let n = chan::pick(NAME, &chans, choice, false)?;
    let r = &rasters[n];
    let raw = match r.bits {
        16 => b.raster(r.at, (r.nx, r.ny), 2, "the heights")?,
        32 => b.raster(r.at, (r.nx, r.ny), 4, "the heights")?,
        bits => return Err(b.bad(format!("heights of {bits} bits: 16 or 32 are read"))),
    };
    let h = |v: i64| if v == 1 { f64::NAN } else { v as f64 * scale };
    let mut z: Vec<f64> = if r.bits == 16 {
        values::<u16>(raw, Order::Little)
            .map(|v| h(v as i64))
            .collect()
    } else {
        values::<i32>(raw, Order::Little)
            .map(|v| h(v as i64))
            .collect()
    };
    let nx = r.nx as usize;
    flip_rows(&mut z, nx);
    let ny = r.ny as usize;
    for (v, what) in [(lx, "x"), (ly, "y")] {
        if !(v.is_finite() && v != 0.0) {
            return Err(b.bad(format!("the size along {what} is {v}")));
        }
    }
    let notes: Vec<String> = chan::note(&chans, n).into_iter().collect();
    let what = "points not measured (value 1)";
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (lx.abs(), ly.abs()),
        z,
        notes,
        what,
    ))
}
