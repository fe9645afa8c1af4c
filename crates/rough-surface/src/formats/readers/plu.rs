//! Sensofar `.plu` (and `.apx`), which has no magic of its own (told by
//! its extension), read to the layout Sensofar's software writes and
//! Gwyddion and SurfaceTopography read: a 128-byte date, a time and a
//! 256-byte comment; the calibration at byte 388 (rows and columns as
//! 32-bit integers, then float32 µm per pixel along x at 404 and y at
//! 408); the measurement type at 428 (3: a topography); 40 bytes of scan
//! settings; at 489 the number of layers and at 492 of images per layer;
//! from 500 each layer: its rows and columns, the heights (float32 in µm,
//! row after row, x fastest; 1000001 marks a point not measured), its
//! minimum and maximum, then its images (three bytes a pixel).

use super::bin::{values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Sensofar .plu";

/// The date a Sensofar file starts with and its measurement type, where
/// `b` looks like one: printable text up to a NUL in its first 128 bytes
/// and a type of 0–6 (image, profile, profiles, topography, coordinates,
/// thickness, custom) at byte 428 — or a file cut short before it (`None`:
/// the reader then says so). The format has no magic: this tells a `.plu`
/// renamed, or a file named `.plu` that is none.
pub(crate) fn looks_like(b: &[u8]) -> Option<(String, Option<u32>)> {
    let head = &b[..b.len().min(128)];
    let end = head.iter().position(|&c| c == 0)?;
    let date = &head[..end];
    if date.len() < 8 || !date.iter().all(|&c| (0x20..0x7f).contains(&c)) {
        return None;
    }
    let date = String::from_utf8_lossy(date).into_owned();
    match b.get(428..432) {
        None => Some((date, None)),
        Some(t) => {
            let ty = u32::from_le_bytes(t.try_into().expect("4 bytes"));
            (ty <= 6).then_some((date, Some(ty)))
        }
    }
}

/// Why `b`, named `.plu`, is not a Sensofar file ([`looks_like`] says it
/// is none).
pub(crate) fn why_not(b: &[u8]) -> String {
    let head = &b[..b.len().min(128)];
    let date = head
        .iter()
        .position(|&c| c == 0)
        .is_some_and(|n| n >= 8 && head[..n].iter().all(|&c| (0x20..0x7f).contains(&c)));
    let ty = b
        .get(428..432)
        .map(|t| u32::from_le_bytes(t.try_into().expect("4 bytes")));
    match (date, ty) {
        (false, None) => "no date at its start, where Sensofar writes one".into(),
        (false, Some(t)) if t <= 6 => "no date at its start, where Sensofar writes one".into(),
        (false, Some(t)) => format!(
            "no date at its start, and a measurement type of {t} at byte 428, where Sensofar's are 0–6"
        ),
        (true, None) => "a date, but no measurement type".into(),
        (true, Some(t)) => format!("a measurement type of {t} at byte 428, where Sensofar's are 0–6"),
    }
}

/// A point not measured.
const UNDEFINED: f32 = 1_000_001.0;

/// Where layer data start.
const LAYERS: usize = 500;

/// A layer: its size and where its heights are.
struct Layer {
    nx: u64,
    ny: u64,
    at: usize,
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let ty = b.le::<u32>(428, "the measurement type")?;
    if ty != 3 {
        return Err(b.bad(format!(
            "measurement type {ty}: a topography (type 3) is read{}",
            if ty == 1 { ", this is a profile" } else { "" }
        )));
    }
    let dx = b.le::<f32>(404, "the pixel size along x")? as f64;
    let dy = b.le::<f32>(408, "the pixel size along y")? as f64;
    for (v, what) in [(dx, "x"), (dy, "y")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("the pixel size along {what} is {v} µm")));
        }
    }
    let count = b.le::<u8>(489, "the number of layers")? as usize;
    let images = b.le::<u8>(492, "the number of images")? as u64;
    if count == 0 {
        return Err(b.bad("no layer of heights"));
    }
    let mut layers = Vec::with_capacity(count);
    let mut at = LAYERS;
    for k in 0..count {
        let what = format!("layer {k}'s size");
        let ny = b.le::<u32>(at, &what)? as u64;
        let nx = b.le::<u32>(at + 4, &what)? as u64;
        let raw = b.raster(at + 8, (nx, ny), 4, &format!("layer {k}"))?;
        layers.push(Layer { nx, ny, at: at + 8 });
        // The minimum and maximum, then the images (their size is checked
        // only when another layer follows).
        at = at + 8 + raw.len() + 8;
        if k + 1 < count {
            let skip = 3 * nx * ny * images;
            at = at
                .checked_add(skip as usize)
                .filter(|&a| a <= bytes.len())
                .ok_or_else(|| b.bad(format!("layer {k}'s images run past the end of the file")))?;
        }
    }
    let chans: Vec<Chan> = (0..count)
        .map(|k| Chan {
            title: format!("layer{k}"),
            unit: "µm".into(),
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    let l = &layers[n];
    let raw = b.raster(l.at, (l.nx, l.ny), 4, "the heights")?;
    let z: Vec<f64> = values::<f32>(raw, Order::Little)
        .map(|v| {
            if v == UNDEFINED || !v.is_finite() {
                f64::NAN
            } else {
                v as f64 * 1e-6
            }
        })
        .collect();
    let notes: Vec<String> = chan::note(&chans, n).into_iter().collect();
    let (nx, ny) = (l.nx as usize, l.ny as usize);
    let size = (nx as f64 * dx * 1e-6, ny as f64 * dy * 1e-6);
    let what = "points not measured (1000001)";
    Ok(Grid::of_file(NAME, (nx, ny), size, z, notes, what))
}
