//! ISO 25178-71 surface data files, `.sdf`, in both forms the standard
//! gives: `aISO-1.0` (text: `Key = value` lines up to a `*` line, then the
//! values up to the next `*`, `BAD` a point not measured) and `bISO-1.0`
//! (binary, little-endian: a 10-byte manufacturer id, two 12-byte dates,
//! 16-bit `NumPoints` and `NumProfiles`, double `Xscale`, `Yscale`,
//! `Zscale` and `Zresolution`, then 8-bit `Compression`, `DataType` and
//! `CheckType`, and the values). Scales are in metres; the values are
//! profile after profile, `NumPoints` along x each, of `DataType` 0–7
//! (uint8, uint16, uint32, float32, int8, int16, int32, float64); integers
//! of 16 and 32 bits mark a point not measured with their type's minimum
//! (signed) or maximum (unsigned), as Gwyddion reads them.

use super::bin::{values, Bytes, Order};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "ISO 25178-71 .sdf";
pub(crate) const ASCII: &[u8] = b"aISO-1.0";
pub(crate) const BINARY: &[u8] = b"bISO-1.0";

/// The header.
struct Header {
    nx: u64,
    ny: u64,
    dx: f64,
    dy: f64,
    dz: f64,
    ty: u8,
}

/// The value marking a point not measured for data type `ty`.
fn marker(ty: u8) -> Option<f64> {
    match ty {
        1 => Some(u16::MAX as f64),
        2 => Some(u32::MAX as f64),
        5 => Some(i16::MIN as f64),
        6 => Some(i32::MIN as f64),
        _ => None,
    }
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let (h, raw) = if bytes.starts_with(BINARY) {
        binary(&b)?
    } else {
        ascii(&b)?
    };
    for (v, what) in [(h.dx, "Xscale"), (h.dy, "Yscale"), (h.dz, "Zscale")] {
        if !(v.is_finite() && v != 0.0) {
            return Err(b.bad(format!("{what} is {v}")));
        }
    }
    let bad = marker(h.ty);
    let mut undefined = 0;
    let z: Vec<f64> = raw
        .into_iter()
        .map(|v| {
            if v.is_nan() || Some(v) == bad || v.is_infinite() {
                undefined += 1;
                f64::NAN
            } else {
                v * h.dz
            }
        })
        .collect();
    let notes = (undefined > 0)
        .then(|| format!("{undefined} points not measured read as undefined"))
        .into_iter()
        .collect();
    let (nx, ny) = (h.nx as usize, h.ny as usize);
    Ok(Grid {
        nx,
        ny,
        lx: nx as f64 * h.dx.abs(),
        ly: if ny == 1 { 0.0 } else { ny as f64 * h.dy.abs() },
        z,
        notes,
        format: NAME,
        assumed: Default::default(),
    })
}

fn binary(b: &Bytes<'_>) -> Result<(Header, Vec<f64>), Failure> {
    let at = 8 + 10 + 12 + 12;
    let h = Header {
        nx: b.le::<u16>(at, "NumPoints")? as u64,
        ny: b.le::<u16>(at + 2, "NumProfiles")? as u64,
        dx: b.le::<f64>(at + 4, "Xscale")?,
        dy: b.le::<f64>(at + 12, "Yscale")?,
        dz: b.le::<f64>(at + 20, "Zscale")?,
        ty: b.le::<u8>(at + 37, "DataType")?,
    };
    if b.le::<u8>(at + 36, "Compression")? != 0 {
        return Err(b.bad("compressed data: uncompressed files are read"));
    }
    let item = match h.ty {
        0 | 4 => 1,
        1 | 5 => 2,
        2 | 3 | 6 => 4,
        7 => 8,
        t => return Err(b.bad(format!("DataType {t}: 0 to 7 are read"))),
    };
    let raw = b.raster(at + 39, (h.nx, h.ny), item, "the values")?;
    let o = Order::Little;
    let v: Vec<f64> = match h.ty {
        0 => values::<u8>(raw, o).map(f64::from).collect(),
        1 => values::<u16>(raw, o).map(f64::from).collect(),
        2 => values::<u32>(raw, o).map(f64::from).collect(),
        3 => values::<f32>(raw, o).map(f64::from).collect(),
        4 => values::<i8>(raw, o).map(f64::from).collect(),
        5 => values::<i16>(raw, o).map(f64::from).collect(),
        6 => values::<i32>(raw, o).map(f64::from).collect(),
        _ => values::<f64>(raw, o).collect(),
    };
    Ok((h, v))
}

fn ascii(b: &Bytes<'_>) -> Result<(Header, Vec<f64>), Failure> {
    let text: String = b.b.iter().map(|&c| c as char).collect();
    let mut lines = text.lines().skip(1);
    let mut keys = Vec::new();
    for line in lines.by_ref() {
        let line = line.trim();
        if line == "*" {
            break;
        }
        if let Some((k, v)) = line.split_once('=') {
            keys.push((k.trim().to_string(), v.trim().to_string()));
        }
    }
    let get = |k: &str| -> Result<&str, Failure> {
        keys.iter()
            .find(|(key, _)| key == k)
            .map(|(_, v)| v.as_str())
            .ok_or_else(|| b.bad(format!("the header has no '{k}'")))
    };
    let num = |k: &str| -> Result<f64, Failure> {
        let v = get(k)?;
        v.parse()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a number")))
    };
    let count = |k: &str| -> Result<u64, Failure> {
        let v = get(k)?;
        v.parse()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a count")))
    };
    let h = Header {
        nx: count("NumPoints")?,
        ny: count("NumProfiles")?,
        dx: num("Xscale")?,
        dy: num("Yscale")?,
        dz: num("Zscale")?,
        ty: count("DataType")? as u8,
    };
    if get("Compression").is_ok_and(|c| c != "0") {
        return Err(b.bad("compressed data: uncompressed files are read"));
    }
    let want =
        h.nx.checked_mul(h.ny)
            .filter(|&p| p >= 1 && p <= text.len() as u64 / 2);
    let Some(want) = want else {
        return Err(b.bad(format!(
            "{} × {} points: more than the file holds",
            h.nx, h.ny
        )));
    };
    let mut v = Vec::with_capacity(want as usize);
    'rows: for line in lines {
        if line.trim() == "*" {
            break;
        }
        for w in line.split_whitespace() {
            if v.len() as u64 == want {
                break 'rows;
            }
            v.push(if w.eq_ignore_ascii_case("BAD") {
                f64::NAN
            } else {
                w.parse::<f64>()
                    .map_err(|_| b.bad(format!("'{w}' is not a number")))?
            });
        }
    }
    if (v.len() as u64) < want {
        return Err(b.bad(format!(
            "{} values where NumPoints × NumProfiles is {want}: the file is truncated",
            v.len()
        )));
    }
    Ok((h, v))
}
