//! Units an instrument's file does not give (an Igor wave without units,
//! a .gwy channel whose values carry none), read as the text reader reads
//! a header without them: heights in the lateral unit, no unit anywhere
//! metres, each said in a note; `--height-unit` and `--lateral-unit` say
//! what they are, and are refused where the file gives its units.

use crate::error::{Failure, Problem};
use crate::measured::Options;
use crate::units::canonical;

/// What a binary reader assumed; `None` where the file gave the unit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Assumed {
    /// The file gives no unit for the heights: they were read in the unit
    /// of this many per metre (the lateral unit's, else 1: metres).
    pub height: Option<f64>,
    /// The file gives no lateral unit: sizes were read in the unit of this
    /// many per metre (1: metres).
    pub lateral: Option<f64>,
}

/// Rescales heights `z` and sizes `lx`, `ly` read by a reader of `format`
/// that assumed `a` to what `opts` say; the notes that say what was read.
pub(crate) fn apply(
    a: Assumed,
    format: &str,
    z: &mut [f64],
    (lx, ly): (&mut f64, &mut f64),
    opts: &Options,
) -> Result<Vec<String>, Failure> {
    let refuse = |what: &str, u: &dyn std::fmt::Display, which: &str| {
        Err((
            None,
            Problem::Option(format!(
                "--{what}-unit {u} applies to a file that does not give its {which} unit: \
                 this {format} file gives it"
            )),
        ))
    };
    let mut notes = Vec::new();
    // The lateral unit said (or assumed), per metre.
    let lateral = match (a.lateral, opts.lateral_unit) {
        (None, Some(u)) => return refuse("lateral", &u, "lateral"),
        (None, None) => None,
        (Some(per), Some(u)) => {
            *lx = *lx * per / u.per_metre;
            *ly = *ly * per / u.per_metre;
            notes.push(format!(
                "sizes read in {u} (--lateral-unit; the file gives no unit)"
            ));
            Some(u.per_metre)
        }
        (Some(per), None) => {
            notes.push(format!(
                "sizes read in {} (the file names no unit; --lateral-unit to change)",
                canonical(per)
            ));
            Some(per)
        }
    };
    match (a.height, opts.height_unit) {
        (None, Some(u)) => return refuse("height", &u, "height"),
        (None, None) => {}
        (Some(per), Some(u)) => {
            z.iter_mut().for_each(|v| *v = *v * per / u.per_metre);
            notes.push(format!(
                "heights read in {u} (--height-unit; the file gives no unit)"
            ));
        }
        (Some(per), None) => {
            // Heights without a unit take the lateral unit, as
            // SurfaceTopography reads one unit for a topography.
            let to = lateral.unwrap_or(per);
            if to != per {
                z.iter_mut().for_each(|v| *v = *v * per / to);
            }
            let why = if a.lateral.is_some() && opts.lateral_unit.is_none() {
                "the file names no unit"
            } else {
                "the sizes' unit"
            };
            notes.push(format!(
                "heights read in {} ({why}; --height-unit to change)",
                canonical(to)
            ));
        }
    }
    Ok(notes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::HeightUnit;

    #[test]
    fn units_said_or_refused() {
        let mut z = vec![1.0, 2.0];
        let (mut lx, mut ly) = (10.0, 20.0);
        let none = Assumed {
            height: Some(1.0),
            lateral: Some(1.0),
        };
        let opts = Options {
            lateral_unit: HeightUnit::parse("um"),
            ..Options::default()
        };
        let notes = apply(none, "Igor .ibw", &mut z, (&mut lx, &mut ly), &opts).unwrap();
        assert_eq!((lx, ly), (10e-6, 20e-6));
        assert_eq!(z, [1e-6, 2e-6]);
        assert_eq!(
            notes,
            [
                "sizes read in µm (--lateral-unit; the file gives no unit)",
                "heights read in µm (the sizes' unit; --height-unit to change)"
            ]
        );
        let opts = Options {
            height_unit: HeightUnit::parse("nm"),
            ..Options::default()
        };
        let mut z = vec![1.0];
        let given = Assumed {
            height: None,
            lateral: None,
        };
        let e = apply(
            given,
            "Digital Surf .sur",
            &mut z,
            (&mut lx, &mut ly),
            &opts,
        )
        .unwrap_err()
        .1
        .to_string();
        assert_eq!(
            e,
            "--height-unit nm applies to a file that does not give its height unit: \
             this Digital Surf .sur file gives it"
        );
        let only_z = Assumed {
            height: Some(1e6),
            lateral: None,
        };
        let notes = apply(only_z, "f", &mut z, (&mut lx, &mut ly), &opts).unwrap();
        // 1 m read as µm is 1e6 µm: 1e6 nm.
        assert_eq!(z, [1e6 / 1e9]);
        assert_eq!(
            notes,
            ["heights read in nm (--height-unit; the file gives no unit)"]
        );
    }
}
