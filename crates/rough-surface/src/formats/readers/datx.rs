//! Zygo `.datx` (Mx software's HDF5 files, interferometers such as the
//! NewView and Nexview), read to the layout Gwyddion (`datxfile.c`),
//! SurfaceTopography and prysm read: the dataset `/MetaData` is a table
//! of links (`Source`, `Link`, `Destination`) whose chain from `Root`
//! through `Measurement` and `Surface` to `Path` names the heights'
//! dataset — rows along y, x fastest — with its attributes `Unit` (such
//! as `NanoMeters`), `No Data` (the value of points not measured) and
//! `X Converter`, `Y Converter`, `Z Converter`: compound values of a
//! `Category`, a `BaseUnit` and `Parameters`, whose second is the pixel
//! size in metres for a lateral converter in `Pixels`.

use std::collections::HashMap;

use hdf5_reader::{SliceInfo, SliceInfoElem};

use super::bin::Bytes;
use super::h5::{self, Field};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "Zygo .datx";

/// Links followed at most from `Root`.
const MAX_LINKS: usize = 64;

/// Whether `bytes` are a Zygo .datx: an HDF5 file with `/MetaData` and
/// `/Measurement`.
pub(crate) fn is_datx(bytes: &[u8]) -> bool {
    bytes.starts_with(h5::MAGIC)
        && h5::open(bytes, NAME).is_ok_and(|f| {
            f.root_group()
                .and_then(|g| g.member_names())
                .is_ok_and(|(groups, sets)| {
                    sets.iter().any(|s| s == "MetaData")
                        && groups.iter().any(|g| g == "Measurement")
                })
        })
}

/// Zygo's names of units of length, as the units module reads them.
fn unit(name: &str) -> Option<f64> {
    let u = match name {
        "Meters" => "m",
        "MilliMeters" => "mm",
        "MicroMeters" => "µm",
        "NanoMeters" => "nm",
        "Angstroms" => "Å",
        other => other,
    };
    per_metre(u)
}

fn text<'a>(fields: &'a [(String, Field)], name: &str) -> Option<&'a str> {
    fields.iter().find_map(|(n, v)| match v {
        Field::Text(t) if n == name => Some(t.as_str()),
        _ => None,
    })
}

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let e = h5::bad(NAME);
    let f = h5::open(bytes, NAME)?;
    let meta = f.dataset("/MetaData").map_err(&e)?;
    let rows = meta.shape().first().copied().unwrap_or(0);
    if rows > 1 << 16 {
        return Err(b.bad(format!("'/MetaData' of {rows} links")));
    }
    let raw = meta.read_raw_bytes().map_err(&e)?;
    let resolve = |r: &[u8], n: usize| meta.resolve_vlen_reference_bytes(r, n).ok();
    let table = h5::compound(&raw, meta.dtype(), meta.vlen_reference_size(), &resolve);
    let mut links: HashMap<(String, String), String> = HashMap::new();
    for row in &table {
        if let (Some(s), Some(l), Some(d)) = (
            text(row, "Source"),
            text(row, "Link"),
            text(row, "Destination"),
        ) {
            links.insert((s.to_string(), l.to_string()), d.to_string());
        }
    }
    // Root → Measurement → Surface → Path.
    let mut at = "Root".to_string();
    for (k, step) in ["Measurement", "Surface", "Path"].iter().enumerate() {
        at = links
            .get(&(at.clone(), step.to_string()))
            .cloned()
            .ok_or_else(|| {
                b.bad(format!(
                    "'/MetaData' has no link '{step}' from '{}': no surface named",
                    super::bin::printable(&at, 60)
                ))
            })?;
        if k >= MAX_LINKS {
            break;
        }
    }
    let path = at;
    let shown = super::bin::printable(&path, 80);
    let ds = f.dataset(&path).map_err(&e)?;
    let (ny, nx) = match ds.shape()[..] {
        [ny, nx] => (ny, nx),
        ref s => {
            return Err(b.bad(format!(
                "the surface '{shown}' has the shape {s:?}, not a map"
            )))
        }
    };
    b.raster(0, (nx, ny), 0, "the surface")?;
    let attrs = ds.attributes();
    let z_unit = h5::text(&attrs, "Unit").unwrap_or_default();
    let per = unit(&z_unit).ok_or_else(|| {
        b.bad(format!(
            "the surface is in '{}', not a length: save it in a unit of length (Mx: \
             Surface, Units) or export it as .xyz",
            super::bin::printable(&z_unit, 30)
        ))
    })?;
    let pixel = |which: &str| -> Result<f64, Failure> {
        let name = format!("{which} Converter");
        let c = h5::compound_attr(&ds, &name)
            .ok_or_else(|| b.bad(format!("the surface has no '{name}'")))?;
        let (cat, base) = (text(&c, "Category"), text(&c, "BaseUnit"));
        if cat != Some("LateralCat") || base != Some("Pixels") {
            return Err(b.bad(format!(
                "'{name}' is a {} in {}: a lateral converter in pixels is read",
                cat.unwrap_or("?"),
                base.unwrap_or("?")
            )));
        }
        let p = c.iter().find_map(|(n, v)| match v {
            Field::Numbers(p) if n == "Parameters" => p.get(1).copied(),
            _ => None,
        });
        match p {
            Some(v) if v.is_finite() && v > 0.0 => Ok(v),
            v => Err(b.bad(format!(
                "'{name}' gives the pixel size {}",
                v.map_or("of no value".to_string(), |v| format!("{v} m"))
            ))),
        }
    };
    let (dx, dy) = (pixel("X")?, pixel("Y")?);
    if let Some(c) = h5::compound_attr(&ds, "Z Converter") {
        if let Some(zb) = text(&c, "BaseUnit") {
            if zb != z_unit {
                return Err(b.bad(format!(
                    "two units for the heights: '{}' and '{}'",
                    super::bin::printable(zb, 30),
                    super::bin::printable(&z_unit, 30)
                )));
            }
        }
    }
    let no_data = h5::number(&attrs, "No Data");
    let all = SliceInfo {
        selections: vec![
            SliceInfoElem::Slice {
                start: 0,
                end: ny,
                step: 1,
            },
            SliceInfoElem::Slice {
                start: 0,
                end: nx,
                step: 1,
            },
        ],
    };
    let raw = h5::values(&ds, &all, NAME)?;
    if raw.len() as u64 != nx * ny {
        return Err(b.bad(format!(
            "the surface holds {} values, not {nx} × {ny}",
            raw.len()
        )));
    }
    let z: Vec<f64> = raw
        .into_iter()
        .map(|v| {
            if !v.is_finite() || Some(v) == no_data {
                f64::NAN
            } else {
                v / per
            }
        })
        .collect();
    let (nx, ny) = (nx as usize, ny as usize);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (nx as f64 * dx, ny as f64 * dy),
        z,
        vec![],
        "points of no data",
    ))
}
