//! The one line that says what a file held and how it was treated.

use rough_model::Dim;

use crate::measured::{Kind, Options};
use crate::spectrum::profiles::Direction;

/// A length for people: "12 µm".
fn length(m: f64) -> String {
    let (scale, unit) = [
        (1.0, "m"),
        (1e-3, "mm"),
        (1e-6, "µm"),
        (1e-9, "nm"),
        (1e-12, "pm"),
    ]
    .into_iter()
    .find(|(s, _)| m >= *s * 0.9995)
    .unwrap_or((1e-12, "pm"));
    format!("{:.4} {unit}", m / scale)
        .replace(".0000 ", " ")
        .replace("000 ", " ")
        .replace("00 ", " ")
}

/// The form removed, "plane removed" or "quadratic removed (--detrend
/// curvature)": the flag named where it was given.
fn removed(opts: &Options, line: bool) -> String {
    let words = opts.detrend_mode().words(line);
    match opts.detrend {
        Some(d) => format!("{words} (--detrend {})", d.name()),
        None => words.to_string(),
    }
}

/// The note where `--detrend` chose another form than the default:
/// "quadratic removed before the spectrum and Sq (--detrend curvature; the
/// default removes the plane)".
pub(crate) fn detrend_note(kind: &Kind, opts: &Options) -> Option<String> {
    let mode = opts.detrend?;
    let default = Options {
        detrend: None,
        ..opts.clone()
    }
    .detrend_mode();
    let line = matches!(kind, Kind::Line { .. });
    let rms = if line { "Rq" } else { "Sq" };
    (mode != default && !matches!(kind, Kind::Psd { .. })).then(|| {
        format!(
            "{} before the spectrum and {rms} (--detrend {}; the default removes the {})",
            mode.words(line),
            mode.name(),
            match default {
                crate::heights::detrend::Detrend::Mean => "mean of periodic data",
                _ if line => "line",
                _ => "plane",
            }
        )
    })
}

pub(crate) fn describe(kind: &Kind, opts: &Options, psd: &str) -> String {
    let treat = |line: bool| {
        if opts.periodic {
            format!("periodic, {}", removed(opts, line))
        } else {
            format!("{}, Hann window", removed(opts, line))
        }
    };
    match *kind {
        Kind::Map { nx, ny, lx, ly } => format!(
            "map {nx} × {ny}, {} × {}, {}",
            length(lx),
            length(ly),
            treat(false)
        ),
        Kind::Line { n, l } => format!("line scan of {n} points, {}, {}", length(l), treat(true)),
        Kind::Profiles {
            direction,
            nx,
            ny,
            lx,
            ly,
        } => {
            let d = direction.name();
            let count = if direction == Direction::X { ny } else { nx };
            format!(
                "map {nx} × {ny}, {} × {}, its {count} profiles along {d}, {}",
                length(lx),
                length(ly),
                if opts.periodic {
                    format!("periodic, {}", removed(opts, false))
                } else {
                    format!("{}, Hann window along {d}", removed(opts, false))
                }
            )
        }
        Kind::Psd { dim, points } => format!(
            "{psd}, {points} points, {}",
            match dim {
                Dim::Areal => "isotropic C(q)",
                Dim::Profile => "profile C1D(q)",
            }
        ),
    }
}
