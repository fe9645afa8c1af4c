//! Digital Surf `.sur` (MountainsMap's native format, written by many
//! instruments), read to its published header: a 512-byte little-endian
//! header after the magic `DIGITAL SURF` — the item size in bits (16 or
//! 32) at byte 98, zmin at 100, the points along x and y at 108 and 112
//! (their product at 116), the spacings along x and y at 120 and 124 and
//! the height step at 128 (float32), 16-byte unit names (the spacings'
//! units at 180 and 196, the heights' at 212), the inversion flag at 290,
//! the comment's and the private zone's sizes at 334 and 336 — then the
//! comment, the private zone and the heights, row after row, x fastest.
//! A file with non-measured points (the flag at 86 is 1) marks them
//! zmin − 2; they are undefined points, which Gwyddion's conversion loses
//! (its constant then counts as heights). Inverted heights (flag 1, 2 or 3)
//! are negated, 2 also mirrored in x and 3 in y.

use super::bin::{flip_columns, flip_rows, values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Digital Surf .sur";
pub(crate) const MAGIC: &[u8] = b"DIGITAL SURF";

/// Old files write the micro sign in an MS-DOS code page (0xE6).
fn unit(b: &Bytes<'_>, pos: usize, what: &str) -> Result<f64, Failure> {
    let u = b.text(pos, 16, what)?;
    let u = if u == "\u{e6}m" { "µm".to_string() } else { u };
    per_metre(&u).map(|p| 1.0 / p).ok_or_else(|| {
        b.bad(format!(
            "{what} is '{u}', not a unit of length (m, mm, µm, nm, Å, pm)"
        ))
    })
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
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
    let (nx, ny) = (nx as usize, ny as usize);
    let dx = b.le::<f32>(120, "the spacing along x")? as f64;
    let dy = b.le::<f32>(124, "the spacing along y")? as f64;
    let step = b.le::<f32>(128, "the height step")? as f64;
    for (v, what) in [(dx, "the spacing along x"), (dy, "the spacing along y")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("{what} is {v}")));
        }
    }
    if !step.is_finite() {
        return Err(b.bad(format!("the height step is {step}")));
    }
    let mx = unit(&b, 180, "the unit of the spacing along x")?;
    let my = unit(&b, 196, "the unit of the spacing along y")?;
    let mz = unit(&b, 212, "the unit of the heights")?;
    let special = b.le::<u16>(86, "the non-measured points' flag")? == 1;
    let inversion = b.le::<u16>(290, "the inversion flag")?;
    let comment = b.le::<u16>(334, "the comment's size")? as usize;
    let private = b.le::<u16>(336, "the private zone's size")? as usize;
    let item = bits as usize / 8;
    let raw = b.raster(
        512 + comment + private,
        (nx as u64, ny as u64),
        item,
        "the heights",
    )?;
    let sign = if matches!(inversion, 1..=3) {
        -1.0
    } else {
        1.0
    };
    let k = sign * step * mz;
    let missing = special.then_some(zmin as i64 - 2);
    let scale = |v: i64| {
        if Some(v) == missing {
            f64::NAN
        } else {
            v as f64 * k
        }
    };
    let mut z: Vec<f64> = if bits == 16 {
        values::<i16>(raw, Order::Little)
            .map(|v| scale(v as i64))
            .collect()
    } else {
        values::<i32>(raw, Order::Little)
            .map(|v| scale(v as i64))
            .collect()
    };
    match inversion {
        2 => flip_columns(&mut z, nx),
        3 => flip_rows(&mut z, nx),
        _ => {}
    }
    let size = (nx as f64 * dx * mx, ny as f64 * dy * my);
    let what = "non-measured points (marked zmin − 2)";
    Ok(Grid::of_file(NAME, (nx, ny), size, z, vec![], what))
}
