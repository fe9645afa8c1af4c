//! Digital Surf `.sur` and `.pro` (MountainsMap's native format, written
//! by many instruments), read to its published header: a 512-byte
//! little-endian header after the magic `DIGITAL SURF` — the number of
//! objects at byte 14, the object type at 18 (1 a profile, 2 a surface …),
//! the item size in bits (16 or 32) at byte 98, zmin at 100, the points
//! along x and y at 108 and 112 (their product at 116), the spacings along
//! x and y at 120 and 124 and the height step at 128 (float32), 16-byte
//! unit names (the spacings' units at 180 and 196, the heights' at 212),
//! the inversion flag at 290, the comment's and the private zone's sizes
//! at 334 and 336 — then the comment, the private zone and the heights,
//! row after row, x fastest. A profile (`.pro`, object type 1) is one row:
//! its y spacing and unit mean nothing. A file with non-measured points
//! (the flag at 86 is 1) marks them zmin − 2; they are undefined points,
//! which Gwyddion's conversion loses (its constant then counts as
//! heights). Inverted heights (flag 1, 2 or 3) are negated, 2 also
//! mirrored in x and 3 in y. The same header starts a compressed file
//! ([`super::surz`]), whose heights are zlib streams.
//!
//! The first object is read: a surface or a profile, or the first layer
//! of a series, or the surface of a surface with an image over it; the
//! objects that hold no heights (images, spectra, force curves) are named
//! in one line.

use super::bin::{flip_columns, flip_rows, values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Digital Surf .sur";
pub(crate) const MAGIC: &[u8] = b"DIGITAL SURF";

/// What a MountainsMap object of type `t` is, when it holds no heights.
fn no_heights(t: i16) -> Option<&'static str> {
    Some(match t {
        3 => "a binary image",
        6 | 9 => "a disc of profiles",
        10 => "an intensity image",
        11 => "an intensity surface",
        12 => "an RGB image",
        14 | 15 => "force curves",
        17 => "a contour profile",
        18 => "a series of RGB images",
        20 => "a spectrum",
        21 => "a hyperspectral map (spectra)",
        _ => return None,
    })
}

/// Old files write the micro sign in an MS-DOS code page (0xE6).
fn unit(b: &Bytes<'_>, pos: usize, what: &str) -> Result<f64, Failure> {
    let u = b.text(pos, 16, what)?;
    let u = if u == "\u{e6}m" { "µm".to_string() } else { u };
    per_metre(&u).map(|p| 1.0 / p).ok_or_else(|| {
        b.bad(if u.is_empty() || u == "a.u." {
            format!("{what} is '{u}', not a length: the values are not heights")
        } else {
            format!("{what} is '{u}', not a unit of length (m, mm, µm, nm, Å, pm)")
        })
    })
}

/// A first object's header, checked: what its heights are and where.
pub(crate) struct Header {
    /// Points along x and y (1 for a profile).
    pub nx: usize,
    pub ny: usize,
    /// Bytes an item.
    pub item: usize,
    /// Where the comment and private zone end: the heights (or, in a
    /// compressed file, their streams) start.
    pub data: usize,
    zmin: i32,
    special: bool,
    inversion: u16,
    /// Metres a step along x and y, and a height step.
    dx: f64,
    dy: f64,
    dz: f64,
    /// How many objects the file holds (at least 1).
    objects: u32,
}

/// The header of the first object of `b` (a file of `format`).
pub(crate) fn header(b: &Bytes<'_>) -> Result<Header, Failure> {
    let kind = b.le::<i16>(18, "the object type")?;
    if let Some(what) = no_heights(kind) {
        return Err(b.bad(format!(
            "{what} (object type {kind}): the file holds no heights (a surface or a \
             profile is read)"
        )));
    }
    let profile = matches!(kind, 1 | 4 | 7);
    let bits = b.le::<u16>(98, "the item size")?;
    if bits != 16 && bits != 32 {
        return Err(b.bad(format!("heights of {bits} bits: 16 or 32 bits are read")));
    }
    let zmin = b.le::<i32>(100, "zmin")?;
    let nx = b.le::<i32>(108, "the points along x")?;
    let ny = b.le::<i32>(112, "the points along y")?;
    let points = b.le::<u32>(116, "the number of points")?;
    if nx < 1 || ny < 1 || (nx as u64) * (ny as u64) != points as u64 {
        return Err(b.bad(format!(
            "the header's {nx} × {ny} points do not make its count of {points}"
        )));
    }
    if profile && ny != 1 {
        return Err(b.bad(format!(
            "a profile (object type {kind}) of {ny} rows: one is read"
        )));
    }
    let dx = b.le::<f32>(120, "the spacing along x")? as f64;
    let dy = b.le::<f32>(124, "the spacing along y")? as f64;
    let step = b.le::<f32>(128, "the height step")? as f64;
    let spacings: &[(f64, &str)] = if profile {
        &[(dx, "the spacing along x")]
    } else {
        &[(dx, "the spacing along x"), (dy, "the spacing along y")]
    };
    for &(v, what) in spacings {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("{what} is {v}")));
        }
    }
    if !step.is_finite() {
        return Err(b.bad(format!("the height step is {step}")));
    }
    let mx = unit(b, 180, "the unit of the spacing along x")?;
    let my = if profile {
        0.0
    } else {
        unit(b, 196, "the unit of the spacing along y")?
    };
    let mz = unit(b, 212, "the unit of the heights")?;
    let comment = b.le::<u16>(334, "the comment's size")? as usize;
    let private = b.le::<u16>(336, "the private zone's size")? as usize;
    Ok(Header {
        nx: nx as usize,
        ny: ny as usize,
        item: bits as usize / 8,
        data: 512 + comment + private,
        zmin,
        special: b.le::<u16>(86, "the non-measured points' flag")? == 1,
        inversion: b.le::<u16>(290, "the inversion flag")?,
        dx: dx * mx,
        dy: dy * my,
        dz: step * mz,
        // Objects after the first, as MountainsMap counts them: objects
        // times channels (an RGB surface is 1 object of 4 channels).
        objects: u32::from(b.le::<u16>(14, "the number of objects")?.max(1))
            * b.le::<i16>(80, "the number of channels")?.clamp(1, 64) as u32,
    })
}

/// The grid of header `h`'s heights `raw` (`h.nx × h.ny` items), for a
/// file of format `name`.
pub(crate) fn grid(name: &'static str, h: &Header, raw: &[u8]) -> Grid {
    let sign = if matches!(h.inversion, 1..=3) {
        -1.0
    } else {
        1.0
    };
    let k = sign * h.dz;
    let missing = h.special.then_some(h.zmin as i64 - 2);
    let scale = |v: i64| {
        if Some(v) == missing {
            f64::NAN
        } else {
            v as f64 * k
        }
    };
    let mut z: Vec<f64> = if h.item == 2 {
        values::<i16>(raw, Order::Little)
            .map(|v| scale(v as i64))
            .collect()
    } else {
        values::<i32>(raw, Order::Little)
            .map(|v| scale(v as i64))
            .collect()
    };
    match h.inversion {
        2 => flip_columns(&mut z, h.nx),
        3 => flip_rows(&mut z, h.nx),
        _ => {}
    }
    let size = (h.nx as f64 * h.dx, h.ny as f64 * h.dy);
    let notes: Vec<String> = (h.objects > 1)
        .then(|| {
            format!(
                "the first of the file's {} objects (channels) read",
                h.objects
            )
        })
        .into_iter()
        .collect();
    let what = "non-measured points (marked zmin − 2)";
    Grid::of_file(name, (h.nx, h.ny), size, z, notes, what)
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let h = header(&b)?;
    let raw = b.raster(h.data, (h.nx as u64, h.ny as u64), h.item, "the heights")?;
    Ok(grid(NAME, &h, raw))
}
