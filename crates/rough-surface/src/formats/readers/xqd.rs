//! Seiko Instruments / SII NanoTechnology (now Hitachi High-Tech) SPM
//! files, `.xqd` (and `.xqb`, `.xqt`, `.xqj`; `.xqp` holds a phase image
//! and `.xqi` a current, told only by the extension), read to the layout
//! Gwyddion reads: the magic `SPIZ000AFM`, `SPIZ000DFM`, `SPIZ000STM` (or
//! `NPXZ000…`), then little-endian fields — the end of the file at byte
//! 0x14 and the start of the data at 0x18 (32 bits), the spacings along x
//! and y in nm at 0x98 and 0xA0 and the height step in nm at 0xA8
//! (doubles), the points along x and y at 0x57A and 0x57C (16 bits) — and
//! from byte 2944 16-bit unsigned heights, row after row. A file of
//! several images (`.xq?x`: each after a header of its own) is read for
//! its first.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Seiko/SII .xqd";

/// Whether `b` starts with one of the format's magics.
pub(crate) fn is_xqd(b: &[u8]) -> bool {
    [
        &b"SPIZ000AFM"[..],
        b"SPIZ000DFM",
        b"SPIZ000STM",
        b"NPXZ000AFM",
        b"NPXZ000DFM",
    ]
    .iter()
    .any(|m| b.starts_with(m))
}

/// Where the heights start.
const HEADER: usize = 2944;

/// A `.xqp` or `.xqi` file: a phase or a current image.
pub(crate) fn not_heights() -> Result<Grid, Failure> {
    Err(Bytes::new(&[], NAME)
        .bad("a phase or current image (.xqp, .xqi): the file holds no heights"))
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let end = b.le::<u32>(0x14, "the end of the file")? as usize;
    let start = b.le::<u32>(0x18, "the start of the data")? as usize;
    if end != b.len() {
        return Err(b.bad(format!(
            "the header says the file ends at byte {end}, but it holds {} bytes: it is \
             truncated or damaged",
            b.len()
        )));
    }
    let nx = b.le::<u16>(0x57a, "the points along x")? as u64;
    let ny = b.le::<u16>(0x57c, "the points along y")? as u64;
    let image = 2 * nx * ny;
    let data = (end as u64).checked_sub(start as u64);
    // One image, or several each after a header of its own.
    let fits = data.is_some_and(|d| {
        image > 0
            && (d == image
                || (d > image && (d + HEADER as u64).is_multiple_of(image + HEADER as u64)))
    });
    if !fits {
        return Err(b.bad(format!(
            "{nx} × {ny} points of 2 bytes do not fill the data from byte {start} to the \
             file's end at {end}: it is damaged"
        )));
    }
    let dx = b.le::<f64>(0x98, "the spacing along x")?;
    let dy = b.le::<f64>(0xa0, "the spacing along y")?;
    let dz = b.le::<f64>(0xa8, "the height step")?;
    for (v, what) in [(dx, "the spacing along x"), (dy, "the spacing along y")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("{what} is {v} nm")));
        }
    }
    if !dz.is_finite() {
        return Err(b.bad(format!("the height step is {dz} nm")));
    }
    let raw = b.raster(HEADER, (nx, ny), 2, "the heights")?;
    let z: Vec<f64> = values::<u16>(raw, Order::Little)
        .map(|v| v as f64 * dz / 1e9)
        .collect();
    let (nx, ny) = (nx as usize, ny as usize);
    let size = (nx as f64 * dx / 1e9, ny as f64 * dy / 1e9);
    let notes: Vec<String> = (data != Some(image))
        .then(|| "the first of the file's images read".to_string())
        .into_iter()
        .collect();
    Ok(Grid::of_file(NAME, (nx, ny), size, z, notes, ""))
}
