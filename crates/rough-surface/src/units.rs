//! Which unit heights are read in, said out loud: a file without a value
//! unit takes its lateral unit (as SurfaceTopography reads it, one unit for
//! the whole topography), `--height-unit` overrides the file, and every
//! choice the file did not make is a note; numbers that look like a unit
//! mistake earn a warning (never a refusal).

use rough_model::MomentTable;

use crate::error::{Failure, Problem};

/// How many of a length unit make a metre (SurfaceTopography's
/// spellings). Values are divided by it: x / 1e6 is the correctly rounded
/// metres of x µm, x · 1e-6 need not be.
pub(crate) fn per_metre(u: &str) -> Option<f64> {
    Some(match u {
        "m" => 1.0,
        "mm" => 1e3,
        "µm" | "μm" | "um" | "~m" | "micron" | "microns" | "micrometre" | "micrometres"
        | "micrometer" | "micrometers" => 1e6,
        "nm" => 1e9,
        "Å" | "A" => 1e10,
        "pm" => 1e12,
        // A unit as a word in any case ("Micrometer" in a Dektak header);
        // symbols keep theirs (mm is not Mm).
        _ if u.chars().count() > 3 && u != u.to_lowercase() => return per_metre(&u.to_lowercase()),
        _ => return None,
    })
}

/// A length unit for heights (`--height-unit`), spelled canonically.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightUnit {
    /// "m", "mm", "µm", "nm", "Å" or "pm".
    pub name: &'static str,
    /// How many of it make a metre: heights are divided by it.
    pub per_metre: f64,
}

impl HeightUnit {
    /// Reads a unit as the headers spell it (`um` and `µm` alike).
    pub fn parse(s: &str) -> Option<HeightUnit> {
        let per = per_metre(s.trim())?;
        Some(HeightUnit {
            name: canonical(per),
            per_metre: per,
        })
    }
}

impl std::fmt::Display for HeightUnit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

/// The canonical spelling of a unit with `per` to the metre.
pub(crate) fn canonical(per: f64) -> &'static str {
    [
        (1.0, "m"),
        (1e3, "mm"),
        (1e6, "µm"),
        (1e9, "nm"),
        (1e10, "Å"),
    ]
    .into_iter()
    .find(|(p, _)| *p == per)
    .map_or("pm", |(_, name)| name)
}

/// Where the heights' unit came from.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Source<'a> {
    /// The file names it (a value unit, a column header): no note.
    File(&'a str, usize),
    /// The file names only a lateral unit (`what` says which: "the
    /// width's unit", "the x column's unit").
    Lateral(&'a str, usize, &'static str),
    /// No unit anywhere: SI metres.
    Nothing,
}

/// The heights' scale (divide by it) and the note that says how they were
/// read, if the file did not say it itself.
pub(crate) fn heights(
    source: Source<'_>,
    given: Option<HeightUnit>,
) -> Result<(f64, Option<String>), Failure> {
    let unit = |u: &str, line: usize| {
        per_metre(u).ok_or_else(|| (Some(line), Problem::UnknownUnit(u.to_string())))
    };
    if let Some(g) = given {
        // Said only where it overrules what the file says.
        let note = match source {
            Source::File(u, line) => {
                let per = unit(u, line)?;
                (per != g.per_metre).then(|| {
                    format!(
                        "heights read in {} (--height-unit; the file says {})",
                        g.name,
                        canonical(per)
                    )
                })
            }
            _ => None,
        };
        return Ok((g.per_metre, note));
    }
    Ok(match source {
        Source::File(u, line) => (unit(u, line)?, None),
        Source::Lateral(u, line, what) => {
            let per = unit(u, line)?;
            (
                per,
                Some(format!(
                    "heights read in {} ({what}; --height-unit to change)",
                    canonical(per)
                )),
            )
        }
        Source::Nothing => (
            1.0,
            Some("heights read in m (the file names no unit; --height-unit to change)".into()),
        ),
    })
}

/// What the plausibility line advises: only what the file lets the user
/// say.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Advice {
    /// The heights' unit (a text map, a file without a height unit).
    Height,
    /// The heights' or the x column's unit (an `x z` line scan).
    HeightOrLateral,
    /// Nothing: the file (of this format) gives its units.
    File(&'static str),
    /// A PSD table's units.
    Table,
}

/// The plausibility line: a warning where the rms slope at the largest ζ
/// is above 10 or below 1e-5, or h_rms is above 1 mm — the marks of heights
/// read in the wrong unit — with the way to say the unit where the file
/// lets one (`advice`).
pub(crate) fn plausibility(table: &MomentTable, advice: Advice) -> Option<String> {
    let m = table.at_zeta(table.zeta_max());
    let (h, slope) = (m.m0.sqrt(), (2.0 * m.m2).sqrt());
    let file;
    let fix = match advice {
        Advice::Height => "--height-unit UNIT to say which",
        Advice::HeightOrLateral => {
            "--height-unit UNIT (the heights) or --lateral-unit UNIT (x) to say which"
        }
        Advice::File(format) => {
            file =
                format!("the {format} file gives its units: check how it was measured or exported");
            &file
        }
        Advice::Table => "check the table's units (q in 1/m, C in m⁴ or m³)",
    };
    let g = |v: f64| {
        format!("{v:.3}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    };
    let e = |v: f64| format!("{v:.2e}");
    if slope > 10.0 {
        Some(format!(
            "warning: rms slope {} at the largest ζ is above 10: heights in a smaller unit \
             than read (µm or nm read as m, nm as µm)? {fix}",
            e(slope)
        ))
    } else if h > 1e-3 {
        Some(format!(
            "warning: h_rms {} mm is above 1 mm: heights in µm or nm read as m? {fix}",
            g(h * 1e3)
        ))
    } else if slope < 1e-5 {
        Some(format!(
            "warning: rms slope {} at the largest ζ is below 1e-5: heights in a larger unit \
             than read (µm read as nm, m as µm), or the lateral size too large? {fix}",
            e(slope)
        ))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_and_notes() {
        let um = HeightUnit::parse("um").unwrap();
        assert_eq!((um.name, um.per_metre), ("µm", 1e6));
        assert!(HeightUnit::parse("furlong").is_none());
        assert_eq!(heights(Source::File("nm", 3), None).unwrap(), (1e9, None));
        let (s, note) = heights(Source::Lateral("um", 2, "the width's unit"), None).unwrap();
        assert_eq!(s, 1e6);
        assert_eq!(
            note.unwrap(),
            "heights read in µm (the width's unit; --height-unit to change)"
        );
        let (s, note) = heights(Source::File("nm", 3), Some(um)).unwrap();
        assert_eq!(s, 1e6);
        assert_eq!(
            note.unwrap(),
            "heights read in µm (--height-unit; the file says nm)"
        );
        assert_eq!(heights(Source::Nothing, None).unwrap().0, 1.0);
        assert_eq!(heights(Source::Nothing, Some(um)).unwrap(), (1e6, None));
        assert_eq!(
            heights(Source::File("V", 4), None).unwrap_err(),
            (Some(4), Problem::UnknownUnit("V".into()))
        );
    }
}
