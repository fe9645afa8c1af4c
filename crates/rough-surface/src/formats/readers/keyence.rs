//! Keyence VK laser confocal microscopes' files: `.vk4`, and `.vk6` and
//! `.vk7`, which wrap the same `.vk4` bytes in a zip member `Vk4File`
//! behind a prefix of their own (the magic `VK6`/`VK7` and a thumbnail).
//! Read to the layout Gwyddion (`keyence.c`), SurfaceTopography and
//! surfalize read: after the magic `VK4_`, 4 bytes of version and 4 of
//! zeros, a table of 32-bit little-endian offsets from byte 12 — the
//! measurement conditions first, the three height images 7th to 9th (0
//! where absent); in the measurement conditions, the pixel sizes along x
//! and y at bytes 168 and 172 and the height step at 176, all in
//! picometres; each height image a header (its width, height, bits per
//! value 8, 16 or 32, a compression word, its bytes, the palette's range),
//! a 768-byte palette, then its unsigned values, row after row, x
//! fastest. A height is its value times the step.

use super::bin::{values, Bytes, Order};
use super::chan::{self, Chan};
use super::zipped::Zipped;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Keyence .vk4/.vk6/.vk7";
/// A bare .vk4 in messages.
const VK4: &str = "Keyence .vk4";
/// A .vk4's first bytes.
pub(crate) const MAGIC: &[u8] = b"VK4_";
/// The first bytes of a .vk6 and a .vk7.
pub(crate) const WRAPPED: [&[u8]; 2] = [b"VK6", b"VK7"];
/// The .vk4 member of a .vk6 or .vk7.
const MEMBER: &str = "Vk4File";

/// Where the offset table starts.
const TABLE: usize = 12;
/// The height images' places in the offset table.
const HEIGHTS: [usize; 3] = [6, 7, 8];

/// Whether `bytes` are a Keyence VK file read here.
pub(crate) fn is_vk(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC) || WRAPPED.iter().any(|m| bytes.starts_with(m))
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    if bytes.starts_with(MAGIC) {
        return read_vk4(bytes, choice, VK4);
    }
    let which = if bytes.starts_with(b"VK7") {
        "Keyence .vk7"
    } else {
        "Keyence .vk6"
    };
    let mut z = Zipped::open(bytes, which)?;
    if !z.has(MEMBER) {
        return Err(z.bad(format!(
            "no '{MEMBER}' member, which holds the heights: the members are {}",
            super::bin::printable(&z.names().join(", "), 300)
        )));
    }
    let vk4 = z.member(MEMBER, crate::limits::MAX_BYTES)?;
    if !vk4.starts_with(MAGIC) {
        return Err(z.bad(format!("the member '{MEMBER}' is not a .vk4 (no 'VK4_')")));
    }
    read_vk4(&vk4, choice, which)
}

/// The .vk4 bytes `bytes`, named `format` in messages.
fn read_vk4(bytes: &[u8], choice: Option<&str>, format: &'static str) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, format);
    let offset = |k: usize, what: &str| -> Result<usize, Failure> {
        Ok(b.le::<u32>(TABLE + 4 * k, what)? as usize)
    };
    let conditions = offset(0, "the offset of the measurement conditions")?;
    let pm = |at: usize, what: &str| -> Result<f64, Failure> {
        Ok(b.le::<u32>(conditions + at, what)? as f64 * 1e-12)
    };
    let dx = pm(168, "the pixel size along x")?;
    let dy = pm(172, "the pixel size along y")?;
    let step = pm(176, "the height step")?;
    for (v, what) in [
        (dx, "the pixel size along x"),
        (dy, "the pixel size along y"),
        (step, "the height step"),
    ] {
        if v <= 0.0 {
            return Err(b.bad(format!("{what} is 0")));
        }
    }
    let mut images = Vec::new();
    for (k, &slot) in HEIGHTS.iter().enumerate() {
        let at = offset(slot, "the offset of a height image")?;
        if at != 0 || k == 0 {
            images.push(at);
        }
    }
    let chans: Vec<Chan> = (0..images.len())
        .map(|k| Chan {
            title: if k == 0 {
                "Height".to_string()
            } else {
                format!("Height {}", k + 1)
            },
            unit: "pm".into(),
        })
        .collect();
    let n = chan::pick(format, &chans, choice, false)?;
    // Every height image is in the file, read or not: one cut short says
    // the file is.
    for (k, &at) in images.iter().enumerate() {
        image(&b, at, k)?;
    }
    let (nx, ny, bits, raw) = image(&b, images[n], n)?;
    let z: Vec<f64> = match bits {
        8 => values::<u8>(raw, Order::Little)
            .map(|v| v as f64 * step)
            .collect(),
        16 => values::<u16>(raw, Order::Little)
            .map(|v| v as f64 * step)
            .collect(),
        _ => values::<u32>(raw, Order::Little)
            .map(|v| v as f64 * step)
            .collect(),
    };
    let (nx, ny) = (nx as usize, ny as usize);
    let notes = chan::note(&chans, n).into_iter().collect();
    Ok(Grid::of_file(
        format,
        (nx, ny),
        (nx as f64 * dx, ny as f64 * dy),
        z,
        notes,
        "undefined points",
    ))
}

/// Height image `k` at byte `at`: its width, height, bits a value and
/// values' bytes, checked against its header and the file.
fn image<'a>(b: &Bytes<'a>, at: usize, k: usize) -> Result<(u64, u64, u32, &'a [u8]), Failure> {
    let what = format!("height image {}'s header", k + 1);
    let nx = b.le::<u32>(at, &what)? as u64;
    let ny = b.le::<u32>(at + 4, &what)? as u64;
    let bits = b.le::<u32>(at + 8, &what)?;
    let size = b.le::<u32>(at + 16, &what)? as u64;
    if !matches!(bits, 8 | 16 | 32) {
        return Err(b.bad(format!(
            "height image {} has values of {bits} bits: 8, 16 or 32 are read",
            k + 1
        )));
    }
    let item = bits as usize / 8;
    if nx.checked_mul(ny).and_then(|p| p.checked_mul(item as u64)) != Some(size) {
        return Err(b.bad(format!(
            "height image {} of {nx} × {ny} values of {bits} bits does not make its {size} bytes",
            k + 1
        )));
    }
    let raw = b.raster(
        at + 28 + 768,
        (nx, ny),
        item,
        &format!("height image {}", k + 1),
    )?;
    Ok((nx, ny, bits, raw))
}
