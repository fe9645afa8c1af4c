//! Bruker `.opdx` (Vision64, Dektak XT stylus profilometers and
//! interferometers), read to the layout Gwyddion (`dektakvca.c`) and
//! SurfaceTopography read: the magic `VCA DATA\x01\0\0\x55`, then items,
//! each a name (a 32-bit length and the bytes), a type byte and a value;
//! containers (types 0x7D, 0x46, 0x47: a variable-length size, items up
//! to a terminator 0x7F, two bytes) nest, so every item has a path such as
//! `/1D_Data/Raw/Array`. `/MetaData/DataKind` says a profile (`Surface
//! Profile`: `/MetaData/1D_Channels/Height` names the channels, each with
//! `NumPoints`, `Extent` — the distance from the first point to the last —
//! `DataScale` and the doubles of `Array` after 5 bytes) or a map
//! (`Surface Height`: `/MetaData/2D_Channels/Height` and `PrimaryData2D`,
//! each channel with `Dimension1Points` (y) and `Dimension2Points` (x),
//! their extents, `DataScale` and a float32 `Matrix`, row after row).
//! A height is a value times `DataScale`, in its unit.

use std::collections::BTreeMap;

use super::bin::{values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Bruker .opdx";
pub(crate) const MAGIC: &[u8] = b"VCA DATA\x01\x00\x00\x55";

/// Containers nested deeper than this are refused.
const MAX_DEPTH: usize = 64;
/// Items read at most.
const MAX_ITEMS: usize = 1 << 18;

/// An item's value, as far as the reader needs it.
#[derive(Clone, Debug)]
enum Value {
    Number(f64),
    Text(String),
    Texts(Vec<String>),
    /// A quantity or a unit: its value and symbol.
    Unit(f64, String),
    /// Bytes of the file: where they start and how many.
    Data(usize, usize),
    /// A matrix: rows (y), columns (x), where its bytes are and how many.
    Matrix(u64, u64, usize, usize),
    Other,
}

struct Parser<'a> {
    b: Bytes<'a>,
    pos: usize,
    items: BTreeMap<String, Value>,
}

impl<'a> Parser<'a> {
    fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8], Failure> {
        let s = self.b.slice(self.pos, n, what)?;
        self.pos += n;
        Ok(s)
    }

    fn u8(&mut self, what: &str) -> Result<u8, Failure> {
        Ok(self.take(1, what)?[0])
    }

    fn le<T: super::bin::Num>(&mut self, what: &str) -> Result<T, Failure> {
        let v = self.b.le::<T>(self.pos, what)?;
        self.pos += T::SIZE;
        Ok(v)
    }

    fn name(&mut self, what: &str) -> Result<String, Failure> {
        let n = self.le::<u32>(what)? as usize;
        Ok(String::from_utf8_lossy(self.take(n, what)?).into_owned())
    }

    fn varlen(&mut self, what: &str) -> Result<usize, Failure> {
        Ok(match self.u8(what)? {
            1 => self.u8(what)? as usize,
            2 => self.le::<u16>(what)? as usize,
            4 => self.le::<u32>(what)? as usize,
            n => {
                return Err(self.b.bad(format!(
                    "{what} at byte {} has a size of {n} bytes",
                    self.pos
                )))
            }
        })
    }

    /// Reads the item at `pos`; `false` at a terminator.
    fn item(&mut self, prefix: &str, depth: usize) -> Result<bool, Failure> {
        if depth > MAX_DEPTH {
            return Err(self
                .b
                .bad(format!("containers nested deeper than {MAX_DEPTH} levels")));
        }
        if self.items.len() > MAX_ITEMS {
            return Err(self.b.bad(format!("more than {MAX_ITEMS} items")));
        }
        let name = self.name("an item's name")?;
        let path = super::bin::printable(&format!("{prefix}/{name}"), 200);
        let ty = self.u8("an item's type")?;
        let v = match ty {
            0x7F => return Ok(false),
            0x7D | 0x46 | 0x47 => {
                let len = self.varlen("a container's size")?;
                let end = self.pos.checked_add(len).filter(|&e| e <= self.b.len());
                let end = end.ok_or_else(|| {
                    self.b
                        .bad(format!("container '{path}' runs past the end of the file"))
                })?;
                while self.pos < end && self.item(&path, depth + 1)? {}
                self.pos = end;
                return Ok(true);
            }
            0x01 => Value::Number(self.u8(&path)? as f64),
            0x04 => Value::Number(self.le::<i16>(&path)? as f64),
            0x05 => Value::Number(self.le::<u16>(&path)? as f64),
            0x06 => Value::Number(self.le::<i32>(&path)? as f64),
            0x07 => Value::Number(self.le::<u32>(&path)? as f64),
            0x0A => Value::Number(self.le::<i64>(&path)? as f64),
            0x0B => Value::Number(self.le::<u64>(&path)? as f64),
            0x0C => Value::Number(self.le::<f32>(&path)? as f64),
            0x0D => Value::Number(self.le::<f64>(&path)?),
            0x15 => {
                self.take(9, &path)?;
                Value::Other
            }
            0x12 => {
                let n = self.varlen(&path)?;
                Value::Text(String::from_utf8_lossy(self.take(n, &path)?).into_owned())
            }
            0x13 | 0x18 => {
                let n = self.varlen(&path)?;
                let end = self.pos + n;
                self.b.slice(self.pos, n, &path)?;
                let v = if ty == 0x13 {
                    let value = self.le::<f64>(&path)?;
                    self.name(&path)?;
                    Value::Unit(value, self.name(&path)?)
                } else {
                    self.name(&path)?;
                    let symbol = self.name(&path)?;
                    Value::Unit(self.le::<f64>(&path)?, symbol)
                };
                if self.pos > end {
                    return Err(self.b.bad(format!("'{path}' runs past its size")));
                }
                self.pos = end;
                v
            }
            0x0E | 0x40 | 0x7C => {
                self.name(&path)?;
                let n = self.varlen(&path)?;
                let at = self.pos;
                self.take(n, &path)?;
                Value::Data(at, n)
            }
            0x42 => {
                self.name(&path)?;
                let n = self.varlen(&path)?;
                let end = self.pos + n;
                self.b.slice(self.pos, n, &path)?;
                let mut list = Vec::new();
                while self.pos < end {
                    list.push(self.name(&path)?);
                }
                Value::Texts(list)
            }
            0x00 | 0x45 => {
                self.name(&path)?;
                if ty == 0x00 {
                    self.le::<u32>(&path)?;
                    self.name(&path)?;
                }
                let n = self.varlen(&path)?;
                if n < 8 {
                    return Err(self.b.bad(format!("matrix '{path}' of {n} bytes")));
                }
                let y = self.le::<u32>(&path)? as u64;
                let x = self.le::<u32>(&path)? as u64;
                let at = self.pos;
                self.take(n - 8, &path)?;
                Value::Matrix(y, x, at, n - 8)
            }
            t => {
                return Err(self.b.bad(format!(
                    "item '{path}' at byte {} has the unknown type {t:#04x}",
                    self.pos - 1
                )))
            }
        };
        self.items.insert(path, v);
        Ok(true)
    }
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let mut p = Parser {
        b,
        pos: MAGIC.len(),
        items: BTreeMap::new(),
    };
    while p.pos < bytes.len() && p.item("", 0)? {}
    let items = p.items;
    let get = |k: &str| items.get(k).ok_or_else(|| b.bad(format!("no '{k}'")));
    let number = |k: &str| match get(k)? {
        Value::Number(v) => Ok(*v),
        _ => Err(b.bad(format!("'{k}' is not a number"))),
    };
    let unit = |k: &str| -> Result<(f64, f64), Failure> {
        match get(k)? {
            Value::Unit(v, s) => {
                let s = if s == "um" || s == "~m" {
                    "µm"
                } else {
                    s.as_str()
                };
                let per = per_metre(s)
                    .ok_or_else(|| b.bad(format!("'{k}' is in '{s}', not a unit of length")))?;
                Ok((*v, 1.0 / per))
            }
            _ => Err(b.bad(format!("'{k}' is not a quantity"))),
        }
    };
    let texts = |k: &str| match items.get(k) {
        Some(Value::Texts(t)) => t.clone(),
        _ => Vec::new(),
    };
    let kind = match items.get("/MetaData/DataKind") {
        Some(Value::Text(t)) => t.clone(),
        _ => String::new(),
    };
    let profile = match kind.as_str() {
        "Surface Profile" => true,
        "Surface Height" => false,
        _ if items.keys().any(|k| k.starts_with("/2D_Data/")) => false,
        _ if items.keys().any(|k| k.starts_with("/1D_Data/")) => true,
        k => return Err(b.bad(format!("data of kind '{k}': no profile or map of heights"))),
    };
    let mut names = if profile {
        texts("/MetaData/1D_Channels/Height")
    } else {
        texts("/MetaData/2D_Channels/Height")
    };
    if !profile {
        if let Some(Value::Text(p)) = items.get("/MetaData/PrimaryData2D") {
            names.retain(|n| n != p);
            names.insert(0, p.clone());
        }
        names.retain(|n| items.contains_key(&format!("/2D_Data/{n}/Matrix")));
    }
    if names.is_empty() {
        return Err(b.bad("no channel of heights"));
    }
    let root = if profile { "/1D_Data" } else { "/2D_Data" };
    let chans: Vec<Chan> = names
        .iter()
        .map(|n| Chan {
            title: match items.get(&format!("{root}/{n}/DataKind")) {
                Some(Value::Text(t)) => t.clone(),
                _ => n.clone(),
            },
            unit: match items.get(&format!("{root}/{n}/DataScale")) {
                Some(Value::Unit(_, s)) => s.clone(),
                _ => String::new(),
            },
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    let at = |k: &str| format!("{root}/{}/{k}", names[n]);
    let (scale, mz) = unit(&at("DataScale"))?;
    let size = |extent: f64, points: u64| {
        if points > 1 {
            extent * points as f64 / (points - 1) as f64
        } else {
            extent
        }
    };
    let (nx, ny, lx, ly, z) = if profile {
        let points = number(&at("NumPoints"))? as u64;
        let (extent, mx) = unit(&at("Extent"))?;
        let Value::Data(pos, len) = get(&at("Array"))?.clone() else {
            return Err(b.bad("the profile's 'Array' is not an array"));
        };
        if (len as u64).checked_sub(5) != points.checked_mul(8) {
            return Err(b.bad(format!(
                "the profile's array of {len} bytes does not hold its {points} points"
            )));
        }
        let raw = b.raster(pos + 5, (points, 1), 8, "the profile")?;
        let z = values::<f64>(raw, Order::Little)
            .map(|v| v * scale * mz)
            .collect();
        (points, 1, size(extent, points) * mx, 0.0, z)
    } else {
        let py = number(&at("Dimension1Points"))? as u64;
        let px = number(&at("Dimension2Points"))? as u64;
        let (ey, my) = unit(&at("Dimension1Extent"))?;
        let (ex, mx) = unit(&at("Dimension2Extent"))?;
        let Value::Matrix(y, x, pos, len) = get(&at("Matrix"))?.clone() else {
            return Err(b.bad("the map's 'Matrix' is not a matrix"));
        };
        if (x, y) != (px, py) || Some(len as u64) != x.checked_mul(y).and_then(|p| p.checked_mul(4))
        {
            return Err(b.bad(format!(
                "the matrix of {x} × {y} points and {len} bytes does not fit the map's {px} × {py}"
            )));
        }
        let raw = b.raster(pos, (x, y), 4, "the map")?;
        let z = values::<f32>(raw, Order::Little)
            .map(|v| {
                if v.is_finite() {
                    v as f64 * scale * mz
                } else {
                    f64::NAN
                }
            })
            .collect();
        (x, y, size(ex, x) * mx, size(ey, y) * my, z)
    };
    let (nx, ny) = (nx as usize, ny as usize);
    for (v, what) in [(lx, "x"), (ly, "y")] {
        if !(v.is_finite() && v > 0.0) && (what == "x" || ny > 1) {
            return Err(b.bad(format!("the extent along {what} is {v}")));
        }
    }
    Ok(Grid {
        nx,
        ny,
        lx,
        ly,
        z,
        notes: chan::note(&chans, n).into_iter().collect(),
        format: NAME,
        assumed: Default::default(),
    })
}
