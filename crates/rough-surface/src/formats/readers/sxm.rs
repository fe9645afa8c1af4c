//! Nanonis `.sxm` (SPECS Nanonis controllers' scans), read to the layout
//! Nanonis documents and Gwyddion reads: a text header of tags — a line
//! `:TAG:`, then its value lines — up to `:SCANIT_END:`; the data start
//! after the bytes 0x1A 0x04. `SCANIT_TYPE` is `FLOAT` with its byte order
//! (`MSBFIRST` or `LSBFIRST`), `SCAN_PIXELS` the points along a line and
//! the lines, `SCAN_RANGE` the sizes in metres, `SCAN_DIR` `up` (the first
//! line stored is the bottom one) or `down`. `DATA_INFO` lists the
//! channels (name, unit, direction `forward`, `backward` or `both`); each
//! is stored in that order, its forward image before its backward one,
//! in its unit. As Gwyddion shows them: a backward image is mirrored back
//! and an upward scan turned upside down, so that every image has its top
//! line first and its left point first. NaN (a scan stopped early) is an
//! undefined point.
//!
//! The topography is the channel `Z`, its forward image unless
//! `--channel` names another; a flat Z (a constant-height scan, the Z
//! controller off) holds no topography and is refused saying so.

use super::bin::{flip_columns, flip_rows, values, Bytes, Order};
use super::chan::{self, Chan};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Nanonis .sxm";
pub(crate) const MAGIC: &[u8] = b":NANONIS_VERSION:";

/// The header's tags and their values (lines joined by newlines).
fn tags(text: &str) -> Vec<(&str, String)> {
    let mut out: Vec<(&str, String)> = Vec::new();
    for line in text.lines() {
        let t = line.trim();
        if t.len() >= 2 && t.starts_with(':') && t.ends_with(':') && !line.starts_with(' ') {
            out.push((&t[1..t.len() - 1], String::new()));
        } else if let Some((_, v)) = out.last_mut() {
            if !v.is_empty() {
                v.push('\n');
            }
            v.push_str(line.trim_end());
        }
    }
    out
}

/// One image stored: its channel's name and unit, backward or not.
struct Image {
    name: String,
    unit: String,
    backward: bool,
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let end = super::bin::find(bytes, b":SCANIT_END:")
        .ok_or_else(|| b.bad("no ':SCANIT_END:' line: the header is cut short"))?;
    let start = super::bin::find(&bytes[end..], b"\x1a\x04")
        .map(|k| end + k + 2)
        .ok_or_else(|| b.bad("no data start marker (0x1A 0x04) after the header"))?;
    let text: String = bytes[..end].iter().map(|&c| c as char).collect();
    let tags = tags(&text);
    let get = |k: &str| tags.iter().find(|(t, _)| *t == k).map(|(_, v)| v.trim());
    let need = |k: &str| get(k).ok_or_else(|| b.bad(format!("the header has no ':{k}:'")));
    let p = super::bin::printable;
    let ty: Vec<&str> = need("SCANIT_TYPE")?.split_whitespace().collect();
    let order = match ty.as_slice() {
        ["FLOAT", "MSBFIRST"] => Order::Big,
        ["FLOAT", "LSBFIRST"] => Order::Little,
        _ => {
            return Err(b.bad(format!(
                "data of type '{}': FLOAT is read",
                p(&ty.join(" "), 40)
            )))
        }
    };
    let two = |k: &str| -> Result<(f64, f64), Failure> {
        let v = need(k)?;
        let n: Vec<f64> = v
            .split_whitespace()
            .filter_map(|s| s.parse::<f64>().ok())
            .collect();
        match n.as_slice() {
            [a, c] if a.is_finite() && c.is_finite() && *a > 0.0 && *c > 0.0 => Ok((*a, *c)),
            _ => Err(b.bad(format!("':{k}:' is '{}', not two numbers > 0", p(v, 60)))),
        }
    };
    let (px, lines) = two("SCAN_PIXELS")?;
    let (lx, ly) = two("SCAN_RANGE")?;
    let (nx, ny) = (px as u64, lines as u64);
    if nx as f64 != px || ny as f64 != lines {
        return Err(b.bad("':SCAN_PIXELS:' are not whole numbers"));
    }
    let up = get("SCAN_DIR") == Some("up");
    // The channels, in the order they are stored.
    let info = need("DATA_INFO")?;
    let mut images = Vec::new();
    for row in info.lines().skip(1).filter(|l| !l.trim().is_empty()) {
        let w: Vec<&str> = row
            .split('\t')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect();
        let [_, name, unit, dir, ..] = w.as_slice() else {
            return Err(b.bad(format!(
                "a DATA_INFO line '{}' of fewer than 4 fields",
                p(row, 60)
            )));
        };
        let dirs: &[bool] = match *dir {
            "both" => &[false, true],
            "forward" => &[false],
            "backward" => &[true],
            d => {
                return Err(b.bad(format!(
                    "the direction '{}' of channel '{}'",
                    p(d, 20),
                    p(name, 40)
                )))
            }
        };
        for &backward in dirs {
            images.push(Image {
                name: name.to_string(),
                unit: unit.to_string(),
                backward,
            });
        }
    }
    if images.is_empty() {
        return Err(b.bad("DATA_INFO lists no channel"));
    }
    // The channels once each, for a message: "Z (m), Current (A)".
    let mut names: Vec<String> = Vec::new();
    for i in &images {
        let n = format!("{} ({})", p(&i.name, 40), p(&i.unit, 10));
        if !names.contains(&n) {
            names.push(n);
        }
    }
    let names = names.join(", ");
    let chans: Vec<Chan> = images
        .iter()
        .map(|i| Chan {
            title: format!(
                "{} ({})",
                i.name,
                if i.backward { "Backward" } else { "Forward" }
            ),
            // SI symbols: A is an ampere here, not an ångström.
            unit: if i.unit == "A" {
                "ampere".into()
            } else {
                i.unit.clone()
            },
        })
        .collect();
    let n = match choice {
        Some(_) => chan::pick(NAME, &chans, choice, false)?,
        None => images
            .iter()
            .position(|i| i.name == "Z" && !i.backward)
            .or_else(|| images.iter().position(|i| i.name == "Z"))
            .ok_or_else(|| {
                b.bad(format!(
                    "no channel 'Z' (the topography): the file holds {names}"
                ))
            })?,
    };
    let each = b.raster(start, (nx, ny), 4, "an image")?.len();
    // Every image the header lists is in the file: one cut short is
    // refused, even where the one read is whole.
    let count = images.len() as u64;
    b.raster(start, (nx, ny * count), 4, &format!("the {count} images"))?;
    let at = start.saturating_add(n.saturating_mul(each));
    let raw = b.raster(at, (nx, ny), 4, &format!("image {n} ({})", chans[n].title))?;
    let mut z: Vec<f64> = values::<f32>(raw, order)
        .map(|v| if v.is_finite() { v as f64 } else { f64::NAN })
        .collect();
    let (nx, ny) = (nx as usize, ny as usize);
    if images[n].backward {
        flip_columns(&mut z, nx);
    }
    if up {
        flip_rows(&mut z, nx);
    }
    let first = z.iter().copied().find(|v| !v.is_nan());
    if images[n].name == "Z" && first.is_some_and(|f| z.iter().all(|&v| v.is_nan() || v == f)) {
        let off = get("Z-Controller>Controller status") == Some("OFF");
        return Err(b.bad(format!(
            "channel '{}' is flat (every point at {:.4e} m){}: the file holds no topography; \
             its channels are {names}",
            chans[n].title,
            first.unwrap_or(0.0),
            if off {
                ", the Z controller off (a constant-height scan)"
            } else {
                ""
            },
        )));
    }
    let notes = chan::note(&chans, n);
    let unit = crate::units::per_metre(&images[n].unit).unwrap_or(1.0);
    z.iter_mut().for_each(|v| *v /= unit);
    let what = "points not scanned (NaN)";
    Ok(Grid::of_file(NAME, (nx, ny), (lx, ly), z, notes, what))
}
