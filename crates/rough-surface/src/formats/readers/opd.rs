//! Wyko `.opd` (Bruker's Vision software for its white-light
//! interferometers), read to the layout Gwyddion and SurfaceTopography
//! read: two bytes, then a directory of 24-byte entries (a 16-byte name, a
//! 16-bit type, a 32-bit length, 16 bits of attributes; the first entry,
//! `Directory`, gives the directory's own length), then the blocks in the
//! directory's order, each its length long. Heights are an array block
//! (type 3) named `RAW DATA`, `RAW_DATA`, `OPD`, `Raw` or `SAMPLE_DATA`: 16
//! bits of columns, of rows and of item size (1, 2 or 4: bytes, int16 or
//! float32), then the values column after column (x slowest), rows from
//! the bottom. Heights are in units of the `Wavelength` block (nm) over
//! `Mult` (1 when missing); the `Pixel_size` block is in mm, y's times
//! `Aspect`. Values of 32766 and more (int16) or 1e38 and more (float32),
//! and NaN, are points not measured.

use super::bin::{values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Wyko .opd";
/// After the first two bytes.
pub(crate) const MAGIC: &[u8] = b"Directory";

const ENTRY: usize = 24;
const ARRAY: i16 = 3;
const HEIGHTS: [&str; 5] = ["RAW DATA", "RAW_DATA", "OPD", "Raw", "SAMPLE_DATA"];

/// A block of the file: its name, type and where its bytes are.
struct Block {
    name: String,
    ty: i16,
    at: usize,
    len: usize,
}

/// A scalar block's value, read as its type and length say (some files
/// give a type that does not fit the length; the length decides).
fn scalar(b: &Bytes<'_>, k: &Block) -> Option<f64> {
    let what = &k.name;
    match (k.ty, k.len) {
        (6 | 7, 2) => b.le::<i16>(k.at, what).ok().map(f64::from),
        (6, 4) => b.le::<i32>(k.at, what).ok().map(f64::from),
        (7, 4..) => b.le::<f32>(k.at, what).ok().map(f64::from),
        (8, 8..) => b.le::<f64>(k.at, what).ok(),
        (12, 4..) => b.le::<i32>(k.at, what).ok().map(f64::from),
        _ => None,
    }
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let dir_len = b.le::<i32>(2 + 18, "the directory's length")?;
    if dir_len < ENTRY as i32 || !(dir_len as usize).is_multiple_of(ENTRY) {
        return Err(b.bad(format!(
            "the directory's length {dir_len} is not a multiple of {ENTRY} bytes"
        )));
    }
    let entries = dir_len as usize / ENTRY - 1;
    b.slice(2 + ENTRY, entries * ENTRY, "the directory")?;
    let mut blocks = Vec::new();
    let mut at = 2 + ENTRY * (entries + 1);
    for e in 0..entries {
        let p = 2 + ENTRY * (e + 1);
        let name = b.text(p, 16, "a block's name")?;
        let ty = b.le::<i16>(p + 16, "a block's type")?;
        let len = b.le::<i32>(p + 18, "a block's length")?;
        if len <= 0 {
            continue;
        }
        let len = len as usize;
        blocks.push(Block { name, ty, at, len });
        at = at.saturating_add(len);
    }
    if at > bytes.len() {
        return Err(b.bad(format!(
            "the directory lists {at} bytes of blocks where the file holds {}: it is \
             truncated or damaged",
            bytes.len()
        )));
    }
    let find = |n: &str| blocks.iter().find(|k| k.name == n);
    let value = |n: &str| find(n).and_then(|k| scalar(&b, k));
    let wavelength = value("Wavelength")
        .ok_or_else(|| b.bad("no 'Wavelength' block: the heights' scale is unknown"))?;
    let mult = value("Mult").unwrap_or(1.0);
    let aspect = value("Aspect").unwrap_or(1.0);
    let pixel = value("Pixel_size")
        .ok_or_else(|| b.bad("no 'Pixel_size' block: the lateral size is unknown"))?;
    for (v, what) in [
        (wavelength, "Wavelength"),
        (mult, "Mult"),
        (pixel, "Pixel_size"),
        (aspect, "Aspect"),
    ] {
        if !(v.is_finite() && v != 0.0) {
            return Err(b.bad(format!("the '{what}' block is {v}")));
        }
    }
    let arrays: Vec<&Block> = blocks
        .iter()
        .filter(|k| k.ty == ARRAY && HEIGHTS.contains(&k.name.as_str()))
        .collect();
    if arrays.is_empty() {
        return Err(b.bad("no array of heights (a 'RAW DATA', 'OPD' or 'Raw' block)"));
    }
    let chans: Vec<Chan> = arrays
        .iter()
        .map(|k| Chan {
            title: k.name.clone(),
            unit: "nm".into(),
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    let k = arrays[n];
    let nx = b.le::<u16>(k.at, "the array's columns")? as usize;
    let ny = b.le::<u16>(k.at + 2, "the array's rows")? as usize;
    let item = b.le::<u16>(k.at + 4, "the array's item size")? as usize;
    if !matches!(item, 1 | 2 | 4) {
        return Err(b.bad(format!("items of {item} bytes: 1, 2 or 4 are read")));
    }
    let raw = b.raster(k.at + 6, (nx as u64, ny as u64), item, &k.name)?;
    if 6 + raw.len() > k.len {
        return Err(b.bad(format!(
            "'{}' holds {nx} × {ny} points of {item} bytes beyond its block's {} bytes",
            k.name, k.len
        )));
    }
    let scale = wavelength / mult * 1e-9;
    let v: Vec<f64> = match item {
        1 => values::<u8>(raw, Order::Little)
            .map(|v| v as f64 * scale)
            .collect(),
        2 => values::<i16>(raw, Order::Little)
            .map(|v| {
                if v >= 32766 {
                    f64::NAN
                } else {
                    v as f64 * scale
                }
            })
            .collect(),
        _ => values::<f32>(raw, Order::Little)
            .map(|v| {
                if !v.is_finite() || v >= 1e38 {
                    f64::NAN
                } else {
                    v as f64 * scale
                }
            })
            .collect(),
    };
    // Stored column after column, each column from the bottom.
    let mut z = vec![0.0; nx * ny];
    for (i, col) in v.chunks_exact(ny).enumerate() {
        for (jb, &h) in col.iter().enumerate() {
            z[(ny - 1 - jb) * nx + i] = h;
        }
    }
    let mut notes: Vec<String> = chan::note(&chans, n).into_iter().collect();
    let undefined = z.iter().filter(|v| v.is_nan()).count();
    if undefined > 0 {
        notes.push(format!("{undefined} points not measured read as undefined"));
    }
    let dx = pixel.abs() * 1e-3;
    Ok(Grid {
        nx,
        ny,
        lx: nx as f64 * dx,
        ly: if ny == 1 {
            0.0
        } else {
            ny as f64 * dx * aspect.abs()
        },
        z,
        notes,
        format: NAME,
        assumed: Default::default(),
    })
}
