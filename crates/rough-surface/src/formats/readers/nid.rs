//! Nanosurf `.nid` and `.ezd` (easyScan, DriveAFM), read to the layout
//! Gwyddion and SurfaceTopography read: an INI-style text header
//! (`[DataSet]` first, Latin-1, CR LF) up to `#!`, then the data sets one
//! after the other. `[DataSet]`'s `GroupCount` and `GrN-Count` list the
//! sets, `GrN-ChM` naming the section of each present one; a set's
//! section gives `Points` × `Lines`, `SaveBits`, `SaveSign`, `SaveOrder`
//! (`Intel`: little-endian), the lateral ranges `Dim0Range`/`Dim1Range`
//! in `Dim0Unit`/`Dim1Unit`, and the values' `Dim2Range` in `Dim2Unit` from
//! `Dim2Min`: a value is raw × range / 2^bits (signed values shifted by
//! half the range) plus the minimum. Rows are stored from the bottom. A
//! set whose values are lengths is a channel of heights; its title is
//! `Frame (Dim2Name)`.

use super::bin::{flip_rows, values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Nanosurf .nid";
pub(crate) const MAGIC: &[u8] = b"[DataSet]\r\n";

/// The header is looked for in this many bytes.
const MAX_HEADER: usize = 16 << 20;
/// More data sets than this are refused.
const MAX_SETS: u64 = 4096;

type Section = (String, Vec<(String, String)>);

/// One data set, where its data are.
struct Set {
    chan: Chan,
    keys: Vec<(String, String)>,
    at: usize,
    nx: u64,
    ny: u64,
    bits: usize,
}

fn get<'a>(keys: &'a [(String, String)], k: &str) -> Option<&'a str> {
    keys.iter().find(|(key, _)| key == k).map(|(_, v)| v.trim())
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let head = &bytes[..bytes.len().min(MAX_HEADER)];
    let end = head
        .windows(2)
        .position(|w| w == b"#!")
        .ok_or_else(|| b.bad("no '#!' after the header: the data are missing"))?;
    let text: String = head[..end].iter().map(|&c| c as char).collect();
    let mut secs: Vec<Section> = vec![("DataSet".into(), Vec::new())];
    for line in text
        .lines()
        .skip(1)
        .map(str::trim)
        .filter(|l| !l.is_empty())
    {
        if let Some(name) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            secs.push((name.to_string(), Vec::new()));
        } else if let Some((k, v)) = line.split_once('=') {
            secs.last_mut()
                .expect("one section")
                .1
                .push((k.trim().to_string(), v.to_string()));
        }
    }
    let section = |n: &str| secs.iter().find(|(s, _)| s == n).map(|(_, k)| &k[..]);
    let top = section("DataSet").expect("the first section");
    let count = |keys: &[(String, String)], k: &str| -> Result<u64, Failure> {
        let v = get(keys, k).ok_or_else(|| b.bad(format!("no '{k}'")))?;
        v.parse()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a count")))
    };
    let groups = count(top, "GroupCount")?;
    let mut sets = Vec::new();
    let mut at = end + 2;
    let mut listed = 0u64;
    for g in 0..groups {
        let n = count(top, &format!("Gr{g}-Count"))?;
        listed += n;
        if listed > MAX_SETS {
            return Err(b.bad(format!("more than {MAX_SETS} data sets")));
        }
        for c in 0..n {
            let Some(keys) = get(top, &format!("Gr{g}-Ch{c}")).and_then(section) else {
                continue;
            };
            if get(keys, "SaveMode") != Some("Binary") {
                return Err(b.bad("a data set not saved as binary"));
            }
            let (nx, ny) = (count(keys, "Points")?, count(keys, "Lines")?);
            let bits = count(keys, "SaveBits")? as usize;
            if !matches!(bits, 8 | 16 | 32) {
                return Err(b.bad(format!("values of {bits} bits: 8, 16 or 32 are read")));
            }
            let title = format!(
                "{} ({})",
                get(keys, "Frame").unwrap_or(""),
                get(keys, "Dim2Name").unwrap_or("")
            );
            let unit = get(keys, "Dim2Unit").unwrap_or("").to_string();
            let len = nx
                .checked_mul(ny)
                .and_then(|p| p.checked_mul(bits as u64 / 8))
                .filter(|&l| l <= bytes.len() as u64)
                .ok_or_else(|| {
                    b.bad(format!(
                        "a data set of {nx} × {ny} points is larger than the file"
                    ))
                })?;
            sets.push(Set {
                chan: Chan { title, unit },
                keys: keys.to_vec(),
                at,
                nx,
                ny,
                bits,
            });
            at = at.saturating_add(len as usize);
        }
    }
    if sets.is_empty() {
        return Err(b.bad("no data set"));
    }
    if at > bytes.len() {
        return Err(b.bad(format!(
            "the data sets end at byte {at} but the file holds {} bytes: it is truncated \
             or damaged",
            bytes.len()
        )));
    }
    let chans: Vec<Chan> = sets.iter().map(|s| s.chan.clone()).collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    let s = &sets[n];
    let number = |k: &str| -> Result<f64, Failure> {
        let v = get(&s.keys, k).ok_or_else(|| b.bad(format!("the data set has no '{k}'")))?;
        v.parse::<f64>()
            .map_err(|_| b.bad(format!("'{k}' is '{v}', not a number")))
    };
    let metres = |k: &str| -> Result<f64, Failure> {
        let u = get(&s.keys, k).unwrap_or("m");
        per_metre(u)
            .map(|p| 1.0 / p)
            .ok_or_else(|| b.bad(format!("'{k}' is '{u}', not a unit of length")))
    };
    let mz = metres("Dim2Unit")?;
    let (lx, ly) = (
        number("Dim0Range")? * metres("Dim0Unit")?,
        number("Dim1Range")? * metres("Dim1Unit")?,
    );
    let range = number("Dim2Range")?;
    let signed = get(&s.keys, "SaveSign") == Some("Signed");
    let order = if get(&s.keys, "SaveOrder") == Some("Intel") {
        Order::Little
    } else {
        Order::Big
    };
    let step = range / 2f64.powi(s.bits as i32);
    let min = get(&s.keys, "Dim2Min")
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or(0.0);
    let offset = min + if signed { range / 2.0 } else { 0.0 };
    let raw = b.raster(s.at, (s.nx, s.ny), s.bits / 8, "the data set")?;
    let h = |v: f64| (v * step + offset) * mz;
    let mut z: Vec<f64> = match (s.bits, signed) {
        (8, true) => values::<i8>(raw, order).map(|v| h(v as f64)).collect(),
        (8, false) => values::<u8>(raw, order).map(|v| h(v as f64)).collect(),
        (16, true) => values::<i16>(raw, order).map(|v| h(v as f64)).collect(),
        (16, false) => values::<u16>(raw, order).map(|v| h(v as f64)).collect(),
        (_, true) => values::<i32>(raw, order).map(|v| h(v as f64)).collect(),
        (_, false) => values::<u32>(raw, order).map(|v| h(v as f64)).collect(),
    };
    let nx = s.nx as usize;
    flip_rows(&mut z, nx);
    let ny = s.ny as usize;
    for (v, what) in [(lx, "Dim0Range"), (ly, "Dim1Range")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("'{what}' is {v}")));
        }
    }
    Ok(Grid {
        nx,
        ny,
        lx: lx.abs(),
        ly: if ny == 1 { 0.0 } else { ly.abs() },
        z,
        notes: chan::note(&chans, n).into_iter().collect(),
        format: NAME,
        assumed: Default::default(),
    })
}
