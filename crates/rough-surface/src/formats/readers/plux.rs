//! Sensofar `.plux` (SensoSCAN and SensoVIEW, S neox and S lynx
//! profilers), read to the layout SurfaceTopography and surfalize read: a
//! zip holding `index.xml` — its `GENERAL` element gives the points along
//! x and y (`IMAGE_SIZE_X`, `IMAGE_SIZE_Y`) and the pixel sizes in µm
//! (`FOV_X`, `FOV_Y`), each `LAYER_N` element a layer whose heights are
//! the member `FILENAME_Z` — float32 little-endian in µm, row after row,
//! x fastest, NaN where not measured.

use super::bin::{values, Bytes, Order};
use super::chan::{self, Chan};
use super::zipped::Zipped;
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Sensofar .plux";

/// `index.xml` is read up to this size.
const MAX_XML: u64 = 16 << 20;

/// Whether `bytes` are a zip holding `index.xml` and no `main.xml`.
pub(crate) fn is_plux(bytes: &[u8]) -> bool {
    Zipped::probe(bytes).is_some_and(|z| z.has("index.xml") && !z.has("main.xml"))
}

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let mut z = Zipped::open(bytes, NAME)?;
    let xml = z.member("index.xml", MAX_XML)?;
    let xml = String::from_utf8_lossy(&xml);
    let opts = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: 1 << 20,
        ..Default::default()
    };
    let doc = roxmltree::Document::parse_with_options(xml.trim_start_matches('\u{feff}'), opts)
        .map_err(|e| b.bad(format!("index.xml is not XML ({e})")))?;
    let root = doc.root_element();
    let general = root
        .children()
        .find(|n| n.has_tag_name("GENERAL"))
        .ok_or_else(|| b.bad("index.xml has no GENERAL element"))?;
    let value = |k: &str| -> Result<f64, Failure> {
        let t = general
            .children()
            .find(|n| n.has_tag_name(k))
            .and_then(|n| n.text())
            .ok_or_else(|| b.bad(format!("index.xml has no GENERAL/{k}")))?;
        t.trim().parse::<f64>().map_err(|_| {
            b.bad(format!(
                "GENERAL/{k} is '{}', not a number",
                super::bin::printable(t, 40)
            ))
        })
    };
    let count = |k: &str| -> Result<u64, Failure> {
        let v = value(k)?;
        if !(v >= 1.0 && v <= u32::MAX as f64 && v.fract() == 0.0) {
            return Err(b.bad(format!("GENERAL/{k} is {v}, not a count")));
        }
        Ok(v as u64)
    };
    let (nx, ny) = (count("IMAGE_SIZE_X")?, count("IMAGE_SIZE_Y")?);
    let (dx, dy) = (value("FOV_X")?, value("FOV_Y")?);
    for (v, what) in [(dx, "FOV_X"), (dy, "FOV_Y")] {
        if !(v.is_finite() && v > 0.0) {
            return Err(b.bad(format!("the pixel size GENERAL/{what} is {v} µm")));
        }
    }
    let layers: Vec<(String, String)> = root
        .children()
        .filter(|n| n.tag_name().name().starts_with("LAYER_"))
        .filter_map(|n| {
            let file = n
                .children()
                .find(|c| c.has_tag_name("FILENAME_Z"))?
                .text()?
                .trim()
                .to_string();
            Some((n.tag_name().name().to_string(), file))
        })
        .take(1024)
        .collect();
    if layers.is_empty() {
        return Err(b.bad("index.xml names no layer of heights (LAYER_N/FILENAME_Z)"));
    }
    let chans: Vec<Chan> = layers
        .iter()
        .map(|(name, _)| Chan {
            title: name.clone(),
            unit: "µm".into(),
        })
        .collect();
    let n = chan::pick(NAME, &chans, choice, false)?;
    b.raster(0, (nx, ny), 0, "the layer")?;
    let want = nx * ny * 4;
    let raw = z.member(&layers[n].1, crate::limits::MAX_BYTES)?;
    if raw.len() as u64 != want {
        return Err(b.bad(format!(
            "the layer '{}' holds {} bytes where {nx} × {ny} float32 heights take {want}",
            super::bin::printable(&layers[n].1, 60),
            raw.len()
        )));
    }
    let heights: Vec<f64> = values::<f32>(&raw, Order::Little)
        .map(|v| {
            if v.is_finite() {
                v as f64 * 1e-6
            } else {
                f64::NAN
            }
        })
        .collect();
    let notes = chan::note(&chans, n).into_iter().collect();
    let (nx, ny) = (nx as usize, ny as usize);
    Ok(Grid::of_file(
        NAME,
        (nx, ny),
        (nx as f64 * dx * 1e-6, ny as f64 * dy * 1e-6),
        heights,
        notes,
        "points not measured (NaN)",
    ))
}
