//! JPK Instruments (Bruker) scans saved as HDF5, `.h5-jpk`, read to the
//! layout AFMReader reads: the root's attribute `file-format-info` is
//! `JPK SCAN`; a group `Measurement_000` gives the grid
//! (`position-pattern.grid.ilength` points along the fast axis x,
//! `jlength` along y) and its size (`ulength`, `vlength`, in
//! `position-pattern.grid.unit.unit`); each group `Channel_NNN` in it is a
//! channel (`channel.fancy-name`, `retrace`), its dataset (the one that is
//! not `thumbnail`) integers of shape (points, frames) — a frame a column,
//! a point a row, x fastest — and its attributes `net-encoder.scaling.*`
//! the multiplier, offset and unit from the integers to values. A channel
//! in a unit of length holds heights; the first frame is read (a
//! time series' others are named in a note).

use hdf5_reader::group::Group;
use hdf5_reader::{SliceInfo, SliceInfoElem};

use super::bin::{flip_rows, Bytes};
use super::chan::{self, Chan};
use super::h5;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

pub(crate) const NAME: &str = "JPK .h5-jpk";

/// Whether `bytes` are a JPK HDF5 scan.
pub(crate) fn is_h5jpk(bytes: &[u8]) -> bool {
    bytes.starts_with(h5::MAGIC)
        && h5::open(bytes, NAME).is_ok_and(|f| {
            f.root_group()
                .and_then(|g| g.attributes())
                .is_ok_and(|a| h5::text(&a, "file-format-info").as_deref() == Some("JPK SCAN"))
        })
}

/// One channel: its group, its dataset's name and its scaling.
struct Channel {
    group: Group,
    dataset: String,
    multiply: f64,
    offset: f64,
    /// `height` or `measuredHeight` for the topography's channels.
    name: String,
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let e = h5::bad(NAME);
    let f = h5::open(bytes, NAME)?;
    let root = f.root_group().map_err(&e)?;
    let (groups, _) = root.member_names().map_err(&e)?;
    let mut measurements: Vec<&String> = groups
        .iter()
        .filter(|n| n.starts_with("Measurement_"))
        .collect();
    measurements.sort();
    let Some(&first) = measurements.first() else {
        return Err(b.bad("no group 'Measurement_…': no scan"));
    };
    let m = root.group(first).map_err(&e)?;
    let attrs = m.attributes().map_err(&e)?;
    let count = |k: &str| -> Result<u64, Failure> {
        let v = h5::number(&attrs, k).ok_or_else(|| b.bad(format!("no '{k}'")))?;
        if !(v >= 1.0 && v <= u32::MAX as f64 && v.fract() == 0.0) {
            return Err(b.bad(format!("'{k}' is {v}, not a count")));
        }
        Ok(v as u64)
    };
    let nx = count("position-pattern.grid.ilength")?;
    let ny = count("position-pattern.grid.jlength")?;
    let unit = h5::text(&attrs, "position-pattern.grid.unit.unit").unwrap_or_else(|| "m".into());
    let per = per_metre(&unit)
        .ok_or_else(|| b.bad(format!("the grid's unit is '{unit}', not a length")))?;
    let size = |k: &str| -> Result<f64, Failure> {
        let v = h5::number(&attrs, k).ok_or_else(|| b.bad(format!("no '{k}'")))?;
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("'{k}' is {v}")));
        }
        Ok(v / per)
    };
    let (lx, ly) = (
        size("position-pattern.grid.ulength")?,
        size("position-pattern.grid.vlength")?,
    );
    let (mut names, _) = m.member_names().map_err(&e)?;
    names.retain(|n| n.starts_with("Channel_"));
    names.sort();
    let mut chans = Vec::new();
    let mut channels = Vec::new();
    for n in names.iter().take(1024) {
        let g = m.group(n).map_err(&e)?;
        let a = g.attributes().map_err(&e)?;
        let fancy = h5::text(&a, "channel.fancy-name").unwrap_or_else(|| n.clone());
        let retrace = h5::text(&a, "retrace").as_deref() == Some("true");
        let (_, sets) = g.member_names().map_err(&e)?;
        let Some(dataset) = sets.into_iter().find(|s| s != "thumbnail") else {
            continue;
        };
        chans.push(Chan {
            title: if retrace {
                format!("{fancy} (retrace)")
            } else {
                fancy
            },
            unit: h5::text(&a, "net-encoder.scaling.unit.unit").unwrap_or_default(),
        });
        channels.push(Channel {
            group: g,
            dataset,
            multiply: h5::number(&a, "net-encoder.scaling.multiplier").unwrap_or(f64::NAN),
            offset: h5::number(&a, "net-encoder.scaling.offset").unwrap_or(0.0),
            name: h5::text(&a, "channel.name").unwrap_or_default(),
        });
    }
    if chans.is_empty() {
        return Err(b.bad("no channel"));
    }
    // The topography's channel first, as AFMReader reads it.
    let height = channels.iter().position(|c| c.name == "height");
    let first = height.map(|h| h.to_string());
    let n = chan::pick(NAME, &chans, choice.or(first.as_deref()), false)?;
    let c = &channels[n];
    let per = per_metre(&chans[n].unit).expect("a channel of heights");
    if !(c.multiply.is_finite() && c.offset.is_finite()) {
        return Err(b.bad(format!(
            "channel {n}'s scaling is {} × value + {}",
            c.multiply, c.offset
        )));
    }
    let ds = c.group.dataset(&c.dataset).map_err(&e)?;
    let shape = ds.shape().to_vec();
    let points = nx * ny;
    let frames = match shape[..] {
        [p, f] if p == points && f >= 1 => f,
        [p] if p == points => 1,
        _ => {
            return Err(b.bad(format!(
                "the dataset of channel {n} has the shape {shape:?}, not {points} points \
                 ({nx} × {ny}) by frames"
            )))
        }
    };
    b.raster(0, (nx, ny), 0, "the scan")?;
    let mut sel = vec![SliceInfoElem::Slice {
        start: 0,
        end: points,
        step: 1,
    }];
    if shape.len() == 2 {
        sel.push(SliceInfoElem::Index(0));
    }
    let raw = h5::values(&ds, &SliceInfo { selections: sel }, NAME)?;
    if raw.len() as u64 != points {
        return Err(b.bad(format!(
            "channel {n} holds {} values, not {points}",
            raw.len()
        )));
    }
    let mut z: Vec<f64> = raw
        .into_iter()
        .map(|v| (v * c.multiply + c.offset) / per)
        .collect();
    let nx = nx as usize;
    flip_rows(&mut z, nx);
    let mut notes: Vec<String> = chan::note(&chans, n).into_iter().collect();
    if frames > 1 {
        notes.push(format!("a series of {frames} frames: the first is read"));
    }
    Ok(Grid::of_file(
        NAME,
        (nx, ny as usize),
        (lx, ly),
        z,
        notes,
        "undefined points",
    ))
}
