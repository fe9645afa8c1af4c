//! The one line that says what a file held and how it was treated.

use rough_model::Dim;

use crate::measured::{Direction, Kind, Options};

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

pub(crate) fn describe(kind: &Kind, opts: &Options, psd: &str) -> String {
    let treat = |what: &str| {
        if opts.periodic {
            "periodic, mean removed".to_string()
        } else {
            format!("{what} removed, Hann window")
        }
    };
    match *kind {
        Kind::Map { nx, ny, lx, ly } => format!(
            "map {nx} × {ny}, {} × {}, {}",
            length(lx),
            length(ly),
            treat("plane")
        ),
        Kind::Line { n, l } => format!("line scan of {n} points, {}, {}", length(l), treat("line")),
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
                    "periodic, mean removed".to_string()
                } else {
                    format!("plane removed, Hann window along {d}")
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
