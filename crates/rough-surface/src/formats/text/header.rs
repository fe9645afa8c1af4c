//! The header of a text matrix, as Gwyddion's ASCII export and
//! SurfaceTopography (`IO/Text.py`, `to_matrix`) write it:
//!
//! ```text
//! # Channel: Height
//! # Width: 12 µm
//! # Height: 8 µm
//! # Value units: nm
//! ```
//!
//! Labels are read in every language Gwyddion translates them to (the list
//! SurfaceTopography accepts), with `:`, `=` or a full-width colon; also
//! SurfaceTopography's `x-length`, `y-length`, `x-unit`, `y-unit`, `z-unit`
//! and Gwyddion's XYZ export's `Lateral units`. Units as SurfaceTopography
//! resolves them: a size without a unit takes the lateral unit, then the
//! value unit; with no unit anywhere, SI metres.

use crate::error::{Failure, Problem};
use crate::units::Source;

const WIDTH: &[&str] = &[
    "Width",
    "x-length",
    "Šířka",
    "Breite",
    "Anchura",
    "Largeur",
    "Larghezza",
    "幅",
    "폭",
    "Largura",
    "Ширина",
];
const HEIGHT: &[&str] = &[
    "Height",
    "y-length",
    "Výška",
    "Höhe",
    "Altura",
    "Hauteur",
    "Altezza",
    "高さ",
    "높이",
    "Высота",
];
const VALUE_UNITS: &[&str] = &[
    "Value units",
    "z-unit",
    "Jednotky hodnot",
    "Einheiten",
    "Unités",
    "unità valore",
    "値の単位",
    "값 단위",
    "Unidades de valor",
    "Единицы измерения",
];
const CHANNEL: &[&str] = &[
    "Channel",
    "Kanál",
    "Kanal",
    "Canal",
    "Canale",
    "チャネル",
    "채널",
    "Канал",
];
const X_UNIT: &[&str] = &["x-unit", "Lateral units"];
const Y_UNIT: &[&str] = &["y-unit"];

/// A size as written, with the line it is on.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Size {
    pub value: f64,
    pub unit: Option<String>,
    pub line: usize,
}

/// What a header says.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Header {
    pub width: Option<Size>,
    pub height: Option<Size>,
    pub value_unit: Option<(String, usize)>,
    pub x_unit: Option<(String, usize)>,
    pub y_unit: Option<(String, usize)>,
    /// Lines of `Channel:` labels.
    pub channels: Vec<usize>,
}

/// The value after `label` and a separator, if `text` starts so.
fn labelled<'a>(text: &'a str, labels: &[&str]) -> Option<&'a str> {
    labels.iter().find_map(|l| {
        let rest = text.strip_prefix(l)?.trim_start();
        let rest = rest
            .strip_prefix(':')
            .or_else(|| rest.strip_prefix('='))
            .or_else(|| rest.strip_prefix('：'))?;
        Some(rest.trim())
    })
}

/// The number at the start of `s` and the rest (its unit).
fn number_and_unit(s: &str) -> Option<(f64, &str)> {
    let end = s
        .char_indices()
        .find(|&(i, c)| {
            !(c.is_ascii_digit()
                || c == '.'
                || ((c == '+' || c == '-')
                    && (i == 0 || matches!(s.as_bytes()[i - 1], b'e' | b'E')))
                || ((c == 'e' || c == 'E')
                    && s[i + 1..]
                        .starts_with(|d: char| d.is_ascii_digit() || d == '-' || d == '+')))
        })
        .map_or(s.len(), |(i, _)| i);
    let v = s[..end].parse::<f64>().ok()?;
    Some((v, s[end..].trim()))
}

fn first_word(s: &str) -> String {
    s.split_whitespace().next().unwrap_or("").to_string()
}

impl Header {
    /// Whether rows of `cols` numbers under this header are a height
    /// matrix (else a two-column table).
    pub fn is_matrix(&self, cols: usize) -> bool {
        self.has_size() || cols != 2
    }

    /// Reads the labels this module knows from header and comment lines;
    /// other lines are left alone.
    pub fn read(lines: &[(usize, &str)]) -> Result<Header, Failure> {
        let mut h = Header::default();
        for &(line, text) in lines {
            let size = |v: &str| -> Result<Size, Failure> {
                let (value, unit) = number_and_unit(v).ok_or_else(|| {
                    (
                        Some(line),
                        Problem::BadHeader(format!("'{text}': no size to read")),
                    )
                })?;
                if !(value.is_finite() && value > 0.0) {
                    return Err((
                        Some(line),
                        Problem::BadHeader(format!("'{text}': a size must be > 0")),
                    ));
                }
                Ok(Size {
                    value,
                    unit: (!unit.is_empty()).then(|| unit.to_string()),
                    line,
                })
            };
            if let Some(v) = labelled(text, WIDTH) {
                h.width = Some(size(v)?);
            } else if let Some(v) = labelled(text, HEIGHT) {
                h.height = Some(size(v)?);
            } else if let Some(v) = labelled(text, VALUE_UNITS) {
                h.value_unit = Some((first_word(v), line));
            } else if let Some(v) = labelled(text, X_UNIT) {
                h.x_unit = Some((first_word(v), line));
            } else if let Some(v) = labelled(text, Y_UNIT) {
                h.y_unit = Some((first_word(v), line));
            } else if labelled(text, CHANNEL).is_some() {
                h.channels.push(line);
            }
        }
        Ok(h)
    }

    /// Whether the header gives a matrix's size.
    pub fn has_size(&self) -> bool {
        self.width.is_some() || self.height.is_some()
    }

    /// Whether any label was read.
    pub fn is_empty(&self) -> bool {
        *self == Header::default()
    }

    /// Where the heights' unit comes from: the value unit, else the
    /// lateral unit (the width's own, the x unit, the y size's own), else
    /// nowhere (metres).
    pub fn height_source(&self) -> Source<'_> {
        if let Some((u, line)) = &self.value_unit {
            return Source::File(u, *line);
        }
        fn size(s: &Option<Size>) -> Option<(&str, usize)> {
            s.as_ref().and_then(|s| Some((s.unit.as_deref()?, s.line)))
        }
        if let Some((u, line)) = size(&self.width) {
            return Source::Lateral(u, line, "the width's unit");
        }
        if let Some((u, line)) = &self.x_unit {
            return Source::Lateral(u, *line, "the lateral unit");
        }
        if let Some((u, line)) = size(&self.height) {
            return Source::Lateral(u, line, "the y size's unit");
        }
        Source::Nothing
    }

    /// The width and height in metres, resolved as SurfaceTopography does:
    /// a size's own unit, else the axis unit (`x-unit`; y falls back to
    /// x's), else the value unit, else metres.
    pub fn sizes(&self) -> Result<(Option<f64>, Option<f64>), Failure> {
        let axis_x = self.x_unit.as_ref();
        let axis_y = self.y_unit.as_ref().or(axis_x);
        let fallback = |axis: Option<&(String, usize)>| -> Result<f64, Failure> {
            match axis.or(self.value_unit.as_ref()) {
                Some((u, line)) => unit(u, *line),
                None => Ok(1.0),
            }
        };
        let metres = |s: &Option<Size>, axis| -> Result<Option<f64>, Failure> {
            let Some(s) = s else { return Ok(None) };
            let scale = match &s.unit {
                Some(u) => unit(u, s.line)?,
                None => fallback(axis)?,
            };
            Ok(Some(s.value / scale))
        };
        Ok((metres(&self.width, axis_x)?, metres(&self.height, axis_y)?))
    }
}

fn unit(u: &str, line: usize) -> Result<f64, Failure> {
    crate::units::per_metre(u).ok_or_else(|| (Some(line), Problem::UnknownUnit(u.to_string())))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gwyddion_and_surfacetopography_headers() {
        let h = Header::read(&[
            (1, "Channel: Height"),
            (2, "Width: 12.000 µm"),
            (3, "Height = 8 um"),
            (4, "Value units: nm"),
        ])
        .unwrap();
        assert_eq!(h.channels, vec![1]);
        assert_eq!(h.sizes().unwrap(), (Some(12e-6), Some(8e-6)));
        assert_eq!(h.height_source(), Source::File("nm", 4));
        // SurfaceTopography's to_matrix: sizes in the value unit.
        let h = Header::read(&[
            (1, "Width: 2.5"),
            (2, "Height: 1e3"),
            (3, "Value units: nm"),
        ])
        .unwrap();
        assert_eq!(h.sizes().unwrap(), (Some(2.5e-9), Some(1e-6)));
        // Translated labels and the full-width colon.
        let h = Header::read(&[(1, "Breite: 3 mm"), (2, "高さ： 2 mm")]).unwrap();
        assert_eq!(h.sizes().unwrap(), (Some(3e-3), Some(2e-3)));
        // No unit anywhere: metres.
        let h = Header::read(&[(1, "Width: 1e-5")]).unwrap();
        assert_eq!(h.sizes().unwrap(), (Some(1e-5), None));
    }

    #[test]
    fn bad_headers_name_their_line() {
        let h = Header::read(&[(3, "Width: 12 furlongs")]).unwrap();
        assert_eq!(
            h.sizes().unwrap_err(),
            (Some(3), Problem::UnknownUnit("furlongs".into()))
        );
        assert!(matches!(
            Header::read(&[(2, "Width: wide")]).unwrap_err(),
            (Some(2), Problem::BadHeader(_))
        ));
        // Heights without a value unit take the width's.
        let h = Header::read(&[(2, "Width: 5 um"), (3, "Height: 3.75 um")]).unwrap();
        assert_eq!(
            h.height_source(),
            Source::Lateral("um", 2, "the width's unit")
        );
        // "Height distribution" is not a Height label.
        assert!(Header::read(&[(1, "Height distribution")])
            .unwrap()
            .is_empty());
    }
}
