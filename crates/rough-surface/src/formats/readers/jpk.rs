//! JPK Instruments (Bruker) AFM image scans, `.jpk` and `.jpk-qi-image`:
//! TIFF files read to the tags Gwyddion (`jpkscan.c`) and
//! SurfaceTopography read. The first image is a thumbnail whose tags give
//! the scan: its size in metres along the fast and slow axes (tags 0x8042
//! and 0x8043) and whether it is reflected (0x8045). Every further image
//! is a channel: its name (0x8052, 0x8051 set for a retrace), the
//! calibration slot its values are read in (0x8081), then its slots, one
//! every 0x30 tags from 0x8090: the slot's name, and at +0x12 to +0x15
//! its unit, its scaling type and, for a linear scaling, the multiplier
//! and offset from the stored integers to values in that unit. A channel
//! whose unit is a length holds heights; its first scan line is stored
//! first, at the bottom of the image unless the scan is reflected.

use super::bin::flip_rows;
use super::chan::{self, Chan};
use super::tiffs::Tiff;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "JPK image scan";

/// Calibration slots read at most.
const MAX_SLOTS: usize = 64;

/// Whether `bytes` are a JPK TIFF: its first directory names its scan's
/// size (tag 0x8042).
pub(crate) fn is_jpk(bytes: &[u8]) -> bool {
    (bytes.starts_with(super::tiffs::LITTLE) || bytes.starts_with(super::tiffs::BIG))
        && Tiff::first(bytes).is_some_and(|t| t.ifds[0].contains_key(&0x8042))
}

/// One channel's scaling: its unit, multiplier and offset.
struct Scaling {
    unit: String,
    multiply: f64,
    offset: f64,
}

/// The scaling of image `ifd` in its default slot.
fn scaling(t: &Tiff<'_>, ifd: usize) -> Result<Option<Scaling>, Failure> {
    let Some(slot) = t.text(ifd, 0x8081)? else {
        return Ok(None);
    };
    let slots = (t.number(ifd, 0x8080)?.unwrap_or(0.0) as usize).min(MAX_SLOTS);
    for s in 0..slots {
        let base = 0x8090 + 0x30 * s as u16;
        if t.text(ifd, base)?.as_deref() != Some(slot.as_str()) {
            continue;
        }
        let unit = t.text(ifd, base + 0x12)?.unwrap_or_default();
        let ty = t.text(ifd, base + 0x13)?.unwrap_or_default();
        if ty != "LinearScaling" {
            return Err(t.b.bad(format!(
                "image {ifd}'s slot '{slot}' has the scaling '{ty}': linear scalings are read"
            )));
        }
        let multiply = t.number(ifd, base + 0x14)?.unwrap_or(f64::NAN);
        let offset = t.number(ifd, base + 0x15)?.unwrap_or(0.0);
        return Ok(Some(Scaling {
            unit,
            multiply,
            offset,
        }));
    }
    Err(t.b.bad(format!(
        "image {ifd}'s slot '{slot}' is not among its slots"
    )))
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let t = Tiff::read(bytes, NAME)?;
    t.strips_inside()?;
    let b = t.b;
    let size = |tag: u16, what: &str| -> Result<f64, Failure> {
        let v = t
            .number(0, tag)?
            .ok_or_else(|| b.bad(format!("no {what} (tag {tag:#x})")))?;
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("the {what} is {v} m")));
        }
        Ok(v)
    };
    let (lx, ly) = (
        size(0x8042, "scan length along x")?,
        size(0x8043, "scan length along y")?,
    );
    let reflect = t.number(0, 0x8045)?.unwrap_or(0.0) != 0.0;
    let mut pages = Vec::new();
    let mut chans = Vec::new();
    for ifd in 1..t.ifds.len() {
        let Some(name) = t.text(ifd, 0x8052)? else {
            continue;
        };
        let retrace = t.number(ifd, 0x8051)?.unwrap_or(0.0) != 0.0;
        let s = scaling(&t, ifd)?;
        chans.push(Chan {
            title: match (retrace, name.strip_suffix(')')) {
                (true, Some(open)) => format!("{open}, retrace)"),
                (true, None) => format!("{name} (retrace)"),
                _ => name,
            },
            unit: s.as_ref().map(|s| s.unit.clone()).unwrap_or_default(),
        });
        pages.push((ifd, s));
    }
    if chans.is_empty() {
        return Err(b.bad("no channel: the file holds only its thumbnail"));
    }
    // The topography's channel first, as Gwyddion opens it.
    let mut height = None;
    for (k, (ifd, _)) in pages.iter().enumerate() {
        if height.is_none() && t.text(*ifd, 0x8050)?.as_deref() == Some("height") {
            height = Some(k.to_string());
        }
    }
    let n = chan::pick(NAME, &chans, choice.or(height.as_deref()), false)?;
    let (ifd, s) = &pages[n];
    let s = s.as_ref().expect("a channel of heights has a scaling");
    let per = per_metre(&s.unit).expect("a channel of heights");
    if !(s.multiply.is_finite() && s.offset.is_finite()) {
        return Err(b.bad(format!(
            "channel {n}'s scaling is {} × value + {}",
            s.multiply, s.offset
        )));
    }
    let (nx, ny, raw) = t.image(*ifd)?;
    let mut z: Vec<f64> = raw
        .into_iter()
        .map(|v| (v * s.multiply + s.offset) / per)
        .collect();
    if !reflect {
        flip_rows(&mut z, nx);
    }
    let notes = chan::note(&chans, n).into_iter().collect();
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (lx, ly),
        z,
        notes,
        "undefined points",
    ))
}
