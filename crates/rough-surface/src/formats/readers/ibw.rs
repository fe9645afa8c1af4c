//! Igor Pro binary waves, `.ibw` (Asylum Research's AFMs), version 5, read
//! to WaveMetrics' technical note PTN003 as Gwyddion and SurfaceTopography
//! read them: a 64-byte binary header (version 5 in either byte order,
//! which tells the order; the sizes of the wave, formula, note, extended
//! units and dimension labels), then a 320-byte wave header (the type at
//! 16, the sizes of the four dimensions at 68, their steps at 84 as
//! doubles, the data's and the dimensions' 4-byte units at 148 and 152),
//! the 384 bytes summing to 0 as 16-bit integers; the data follow, x
//! fastest. A wave of three dimensions is a stack of images, the layers
//! channels named by the third dimension's labels; a square one an image;
//! another two-dimensional one a set of profiles (as SurfaceTopography
//! reads it). Asylum's note (`key: value` lines) gives each channel's unit
//! by its name (Height, ZSensor, Deflection, Amplitude: m; Phase: deg;
//! else V, or a `NAMEUnit` entry); rows are stored from the bottom.

use super::bin::{flip_rows, values, Bytes, Num, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::assumed::Assumed;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Igor .ibw";

const HEADERS: usize = 64 + 320;

/// Asylum's channels' units by the start of their names.
const UNITS: [(&str, &str); 11] = [
    ("Height", "m"),
    ("ZSensor", "m"),
    ("Deflection", "m"),
    ("Amplitude", "m"),
    ("Phase", "deg"),
    ("Current", "A"),
    ("Frequency", "Hz"),
    ("Capacitance", "F"),
    ("Potential", "V"),
    ("Count", ""),
    ("QFactor", ""),
];

fn order(b: &[u8]) -> Option<Order> {
    match b.get(..2)? {
        [5, 0] => Some(Order::Little),
        [0, 5] => Some(Order::Big),
        _ => None,
    }
}

/// Version 5 in either order and the headers' checksum.
pub(crate) fn is_ibw(b: &[u8]) -> bool {
    let Some(o) = order(b) else { return false };
    let Some(h) = b.get(..HEADERS) else {
        return false;
    };
    values::<i16>(h, o).fold(0i16, |a, v| a.wrapping_add(v)) == 0
}

/// A 4-byte unit field, in Igor's spelling (`A` is the ampere).
fn unit(b: &Bytes<'_>, at: usize) -> Result<String, Failure> {
    let u = b.text(at, 4, "a unit")?;
    Ok(if u == "um" || u == "~m" {
        "µm".into()
    } else {
        u
    })
}

/// Metres per unit of a length, Igor's way (`A` is no length).
fn length(u: &str) -> Option<f64> {
    (u != "A").then(|| per_metre(u)).flatten().map(|p| 1.0 / p)
}

/// An Asylum channel's unit from its name and the note.
fn asylum(title: &str, note: &[(String, String)]) -> String {
    let mut base = title;
    if let Some(p) = base
        .rfind("Mod")
        .filter(|&p| base[p + 3..].bytes().all(|c| c.is_ascii_digit()))
    {
        base = &base[..p];
    }
    for s in ["Trace", "Retrace"] {
        if let Some(b) = base.strip_suffix(s) {
            base = b;
            break;
        }
    }
    if let Some((_, u)) = note.iter().find(|(k, _)| *k == format!("{base}Unit")) {
        return u.clone();
    }
    let base = base
        .strip_prefix("DAC")
        .or_else(|| base.strip_prefix("Nap"))
        .unwrap_or(base);
    UNITS
        .iter()
        .find(|(p, _)| base.starts_with(p))
        .map_or("V", |(_, u)| u)
        .to_string()
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let o = order(bytes).ok_or_else(|| b.bad("not an Igor binary wave of version 5"))?;
    let size = |at: usize, what: &str| -> Result<usize, Failure> {
        let v = b.num::<i32>(at, o, what)?;
        usize::try_from(v).map_err(|_| b.bad(format!("{what} is {v}")))
    };
    let wave = size(4, "the wave's size")?;
    let formula = size(8, "the formula's size")?;
    let note_len = size(12, "the note's size")?;
    let extended = size(16, "the extended data units' size")?;
    let mut dim_units = 0usize;
    for d in 0..4 {
        dim_units = dim_units.saturating_add(size(20 + 4 * d, "a dimension's units' size")?);
    }
    let labels: Vec<usize> = (0..4)
        .map(|d| size(36 + 4 * d, "a dimension's labels' size"))
        .collect::<Result<_, _>>()?;
    let ty = b.num::<i16>(64 + 16, o, "the data type")?;
    let dims: Vec<u64> = (0..4)
        .map(|d| {
            let n = b.num::<i32>(64 + 68 + 4 * d, o, "a dimension's size")?;
            u64::try_from(n).map_err(|_| b.bad(format!("a dimension of {n} points")))
        })
        .collect::<Result<_, _>>()?;
    let step: Vec<f64> = (0..2)
        .map(|d| b.num::<f64>(64 + 84 + 8 * d, o, "a dimension's step"))
        .collect::<Result<_, _>>()?;
    let data_unit = unit(&b, 64 + 148)?;
    let lateral_unit = unit(&b, 64 + 152)?;
    if ty & 1 != 0 {
        return Err(b.bad("a wave of complex numbers"));
    }
    let item = match ty {
        2 | 0x20 | 0x60 => 4,
        4 => 8,
        8 | 0x48 => 1,
        0x10 | 0x50 => 2,
        t => return Err(b.bad(format!("data of type {t:#x}: a wave of numbers is read"))),
    };
    if dims[3] != 0 {
        return Err(b.bad("a wave of four dimensions"));
    }
    // (points along x, along y, channels, which dimension's labels name them)
    let (nx, ny, count, label_dim) = if dims[2] != 0 {
        (dims[0], dims[1], dims[2], 2)
    } else if dims[1] != 0 && dims[1] == dims[0] {
        (dims[0], dims[1], 1, 2)
    } else if dims[1] != 0 {
        (dims[0], 1, dims[1], 1)
    } else {
        (dims[0], 1, 1, 1)
    };
    let data = b.raster(
        HEADERS,
        (nx.saturating_mul(ny), count.max(1)),
        item,
        "the wave",
    )?;
    if wave < 320 + data.len() {
        return Err(b.bad(format!(
            "the wave's size of {wave} bytes does not hold its {} bytes of data",
            data.len()
        )));
    }
    // The note, then the units and the dimension labels (32 bytes each).
    let note_at = 64usize.saturating_add(wave).saturating_add(formula);
    let note_text = b.slice(note_at, note_len, "the note")?;
    let note: Vec<(String, String)> = note_text
        .split(|&c| c == b'\r' || c == b'\n')
        .filter_map(|l| {
            let l: String = l.iter().map(|&c| c as char).collect();
            let (k, v) = l.split_once(':')?;
            Some((k.trim().to_string(), v.trim().to_string()))
        })
        .collect();
    let mut at = note_at + note_len;
    at = at.saturating_add(extended).saturating_add(dim_units);
    at = at.saturating_add(labels[..label_dim].iter().sum::<usize>());
    let names = b.slice(at, labels[label_dim], "the dimension labels")?;
    let mut titles: Vec<String> = names
        .chunks_exact(32)
        .skip(1)
        .map(super::bin::latin1)
        .take(count as usize)
        .collect();
    let named = titles.len();
    while (titles.len() as u64) < count {
        titles.push(format!("no name ({})", titles.len() - named + 1));
    }
    let chans: Vec<Chan> = titles
        .iter()
        .enumerate()
        .map(|(i, t)| Chan {
            title: t.clone(),
            unit: if !note.is_empty() && i < named {
                asylum(t, &note)
            } else {
                data_unit.clone()
            },
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, true)?;
    let points = (nx * ny) as usize;
    let raw = &data[n * points * item..(n + 1) * points * item];
    let mut z = match ty {
        2 => to_f64::<f32>(raw, o),
        4 => to_f64::<f64>(raw, o),
        8 => to_f64::<i8>(raw, o),
        0x10 => to_f64::<i16>(raw, o),
        0x20 => to_f64::<i32>(raw, o),
        0x48 => to_f64::<u8>(raw, o),
        0x50 => to_f64::<u16>(raw, o),
        _ => to_f64::<u32>(raw, o),
    };
    let (nx, ny) = (nx as usize, ny as usize);
    // Heights in the lateral unit where it is a length, else their own.
    let lateral = length(&lateral_unit);
    let own = length(&chans[n].unit);
    let mut assumed = Assumed::default();
    let mz = match own {
        Some(m) => m,
        None => {
            assumed.height = Some(lateral.map_or(1.0, |m| 1.0 / m));
            lateral.unwrap_or(1.0)
        }
    };
    let mx = match lateral {
        Some(m) => m,
        None if lateral_unit.is_empty() => {
            // Without a lateral unit the heights' unit is the topography's.
            assumed.lateral = Some(own.map_or(1.0, |m| 1.0 / m));
            own.unwrap_or(1.0)
        }
        None => {
            return Err(b.bad(format!(
                "the lateral unit is '{lateral_unit}', not a unit of length"
            )))
        }
    };
    let mut notes: Vec<String> = chan::note(&chans, n).into_iter().collect();
    let mut undefined = 0;
    for v in z.iter_mut() {
        if v.is_finite() {
            *v *= mz;
        } else {
            *v = f64::NAN;
            undefined += 1;
        }
    }
    if undefined > 0 {
        notes.push(format!(
            "{undefined} NaN or infinite values read as undefined"
        ));
    }
    if ny > 1 {
        flip_rows(&mut z, nx);
    }
    let (dx, dy) = (step[0] * mx, step[1] * mx);
    for (v, what) in [(dx, "x"), (dy, "y")] {
        if !(v.is_finite() && v != 0.0) && (what == "x" || ny > 1) {
            return Err(b.bad(format!("the step along {what} is {v}")));
        }
    }
    Ok(Grid {
        nx,
        ny,
        lx: nx as f64 * dx.abs(),
        ly: if ny == 1 { 0.0 } else { ny as f64 * dy.abs() },
        z,
        notes,
        format: NAME,
        assumed,
    })
}

fn to_f64<T: Num>(raw: &[u8], o: Order) -> Vec<f64> {
    values::<T>(raw, o).map(Num::f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn asylum_units() {
        assert_eq!(asylum("HeightRetrace", &[]), "m");
        assert_eq!(asylum("NapPhaseTrace", &[]), "deg");
        assert_eq!(asylum("UserIn0Trace", &[]), "V");
        let note = [("UserIn0Unit".to_string(), "nm".to_string())];
        assert_eq!(asylum("UserIn0Trace", &note), "nm");
        assert_eq!(asylum("UserIn0Mod2", &note), "nm");
        assert!(!is_ibw(b"\x05\0short"));
    }
}
