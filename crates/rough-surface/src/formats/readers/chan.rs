//! The channels of a file of several (a Nanoscope file's height, phase and
//! amplitude images, an Igor wave's layers): which one is read and the
//! note that lists the others.

use crate::error::{Failure, Problem};
use crate::units::per_metre;

/// One channel, as people know it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Chan {
    pub title: String,
    /// The unit of its values as the file says it ("nm", "deg", "V"; ""
    /// without one).
    pub unit: String,
}

impl Chan {
    /// Whether its values are heights (a unit of length).
    pub fn heights(&self) -> bool {
        per_metre(&self.unit).is_some()
    }

    fn describe(&self, n: usize) -> String {
        let unit = if self.unit.is_empty() {
            "no unit"
        } else {
            &self.unit
        };
        let p = |s: &str| super::bin::printable(s, 60);
        format!("{n} '{}' ({})", p(&self.title), p(unit))
    }
}

/// `--channel` on a format of one channel.
pub(crate) fn none(format: &str) -> Failure {
    (
        None,
        Problem::Option(format!(
            "--channel applies to files of several channels; a {format} file holds one"
        )),
    )
}

/// The channels for people: "0 'Height' (nm), 1 'Phase' (deg)".
fn list(chans: &[Chan]) -> String {
    chans
        .iter()
        .enumerate()
        .map(|(n, c)| c.describe(n))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The channel `choice` names (its number, from 0 in the file's order, or
/// its title, without regard to case), else the first of heights; with
/// `unitless`, a channel without a unit may be read (its heights' unit
/// then assumed), and is the default when no channel has a unit of length.
pub(crate) fn pick(
    format: &str,
    chans: &[Chan],
    choice: Option<&str>,
    unitless: bool,
) -> Result<usize, Failure> {
    let bad = |s: String| (None, Problem::Format(format!("{format}: {s}")));
    let all = list(chans);
    let readable = |c: &Chan| c.heights() || unitless && c.unit.is_empty();
    let Some(choice) = choice else {
        return chans
            .iter()
            .position(Chan::heights)
            .or_else(|| chans.iter().position(readable))
            .ok_or_else(|| {
                bad(format!(
                    "no channel holds heights (values in a unit of length): {all}"
                ))
            });
    };
    let choice = choice.trim();
    let n = if let Ok(n) = choice.parse::<usize>() {
        if n >= chans.len() {
            return Err(bad(format!("no channel {n}; the channels are {all}")));
        }
        n
    } else {
        let mut titled = chans
            .iter()
            .enumerate()
            .filter(|(_, c)| c.title.trim().eq_ignore_ascii_case(choice));
        let (first, _) = titled.next().ok_or_else(|| {
            bad(format!(
                "no channel titled '{choice}'; the channels are {all}"
            ))
        })?;
        if let Some((m, _)) = titled.next() {
            return Err(bad(format!(
                "channels {first} and {m} are both titled '{choice}': give the number \
                 (--channel {first})"
            )));
        }
        first
    };
    let c = &chans[n];
    if !readable(c) {
        let unit = if c.unit.is_empty() {
            "no unit"
        } else {
            &c.unit
        };
        return Err(bad(format!(
            "channel {} holds values in {unit}, not a length: the channels are {all}",
            c.describe(n)
        )));
    }
    Ok(n)
}

/// "channel 0 'Height' (nm) read; also in the file: 1 'Phase' (deg)
/// (--channel N or TITLE)", for a file of more than one channel; and the
/// warning of [`not_topography`].
pub(crate) fn note(chans: &[Chan], n: usize) -> Vec<String> {
    let mut out = Vec::new();
    if chans.len() > 1 {
        let others: Vec<String> = chans
            .iter()
            .enumerate()
            .filter(|(m, _)| *m != n)
            .map(|(m, c)| c.describe(m))
            .collect();
        out.push(format!(
            "channel {} read; also in the file: {} (--channel N or TITLE)",
            chans[n].describe(n),
            others.join(", ")
        ));
    }
    out.extend(not_topography(chans, n));
    out
}

/// What a channel named so measures, when it is not the surface's
/// heights though its unit may be a length (an AFM's amplitude, error or
/// deformation channels are in m or nm).
fn measures(title: &str) -> Option<&'static str> {
    let t = title.to_lowercase();
    [
        ("amplitude", "the oscillation's amplitude"),
        ("error", "the feedback's error signal"),
        ("deflection", "the cantilever's deflection"),
        ("deformation", "the sample's deformation under the tip"),
        ("phase", "a phase"),
        ("lateral", "a lateral (friction) signal"),
        ("friction", "a friction signal"),
        ("adhesion", "adhesion"),
        ("dissipation", "dissipation"),
        ("stiffness", "stiffness"),
        ("modulus", "a modulus"),
        ("current", "a current"),
        ("frequency", "a frequency shift"),
        ("potential", "a surface potential"),
        ("intensity", "an intensity"),
    ]
    .into_iter()
    .find(|(k, _)| t.contains(k))
    .map(|(_, what)| what)
}

/// A warning where channel `n`, in a unit of length, is by its name not
/// the surface's heights (Asylum's `AmplitudeRetrace` is in m): its Sq,
/// slopes and indices are of that signal, not of a surface.
pub(crate) fn not_topography(chans: &[Chan], n: usize) -> Option<String> {
    let c = &chans[n];
    let what = measures(&c.title).filter(|_| c.heights())?;
    let height = chans
        .iter()
        .enumerate()
        .find(|(_, o)| o.heights() && measures(&o.title).is_none())
        .map(|(m, o)| format!("; the heights are channel {}", o.describe(m)))
        .unwrap_or_default();
    Some(format!(
        "warning: channel {} is {what}, not the surface's heights, though its unit is a \
         length: its Sq, slopes and indices describe no topography{height}",
        c.describe(n)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(title: &str, unit: &str) -> Chan {
        Chan {
            title: title.into(),
            unit: unit.into(),
        }
    }

    #[test]
    fn picks() {
        let chans = [c("Phase", "deg"), c("Height", "nm"), c("Height", "µm")];
        assert_eq!(pick("F", &chans, None, false), Ok(1));
        assert_eq!(pick("F", &chans, Some("2"), false), Ok(2));
        let e = pick("F", &chans, Some("height"), false).unwrap_err().1;
        assert!(e.to_string().contains("both titled 'height'"), "{e}");
        let e = pick("F", &chans, Some("0"), false).unwrap_err().1;
        assert_eq!(
            e.to_string(),
            "F: channel 0 'Phase' (deg) holds values in deg, not a length: the channels \
             are 0 'Phase' (deg), 1 'Height' (nm), 2 'Height' (µm)"
        );
        assert_eq!(
            note(&chans, 1)[0],
            "channel 1 'Height' (nm) read; also in the file: 0 'Phase' (deg), \
             2 'Height' (µm) (--channel N or TITLE)"
        );
        let bare = [c("no name (1)", "")];
        assert_eq!(pick("F", &bare, None, true), Ok(0));
        assert!(pick("F", &bare, None, false).is_err());
        assert!(note(&bare, 0).is_empty());
        let afm = [c("HeightRetrace", "m"), c("AmplitudeRetrace", "m")];
        assert!(note(&afm, 0).len() == 1);
        assert_eq!(
            not_topography(&afm, 1).unwrap(),
            "warning: channel 1 'AmplitudeRetrace' (m) is the oscillation's amplitude, not \
             the surface's heights, though its unit is a length: its Sq, slopes and indices \
             describe no topography; the heights are channel 0 'HeightRetrace' (m)"
        );
    }
}
