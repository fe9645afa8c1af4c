//! What a picture or a CSV shows, in words: the full parameter set of the
//! scene, so that a file found on its own says how to make it again.
//!
//! Two forms of the same facts: [`full_lines`], every number with all the
//! digits that read back to the same double (the CSV's `#` lines and the
//! SVG's `<desc>`), and [`short_lines`], four significant digits with
//! units for the caption line under a picture.

use rough_model::Axis;

use super::{axis_unit, FigureOptions, MapSpec, View};
pub use crate::physical::short_length;
use crate::physical::short_number;
use crate::scene::State;

/// A number as the CSV prints it: the shortest digits that read back.
fn full(v: f64) -> String {
    let mut s = String::new();
    crate::physical::csv_number::push(&mut s, v);
    s
}

/// A parameter's value in the short form: lengths with a unit.
pub fn short_value(axis: Axis, v: f64) -> String {
    match axis_unit(axis) {
        "m" => short_length(v),
        _ => short_number(v),
    }
}

/// The parameter's name for a caption: the symbol the screen shows, the
/// Hurst exponent spelled out so that it is not read as a hardness.
fn caption_symbol(axis: Axis) -> &'static str {
    match axis {
        Axis::Hurst => "Hurst H",
        a => a.symbol(),
    }
}

/// What the parameter is, for the `#` lines.
fn meaning(axis: Axis) -> &'static str {
    match axis {
        Axis::H0OverE => "H0/E: macroscopic hardness over E, the composite modulus E*",
        Axis::HRms => "rms height of the spectrum from q0 up",
        Axis::Zeta => "magnification q1/q0",
        Axis::Hurst => "Hurst exponent",
        Axis::RStar => "size-effect length of the hardness law",
    }
}

fn on_off(b: bool) -> &'static str {
    if b {
        "on"
    } else {
        "off"
    }
}

/// The moments' name: "measured" on a measured surface.
fn moments(state: &State) -> &'static str {
    if state.is_measured() {
        "measured"
    } else {
        state.moments.label()
    }
}

/// What the view spans besides the parameters, in full.
fn span_full(state: &State, view: View, opts: &FigureOptions) -> String {
    let s = &state.sweep;
    let spacing = |a: Axis| {
        if a.is_log() {
            "log-spaced"
        } else {
            "evenly spaced"
        }
    };
    match view {
        View::Slopes | View::Indices => format!(
            "sweep = {} from {} to {}, {} points ({})",
            s.axis().field(),
            full(s.from()),
            full(s.to()),
            opts.points,
            spacing(s.axis())
        ),
        View::Map => match MapSpec::of(state, opts.grid, opts.map_y) {
            Ok(m) => format!(
                "map = {} from {} to {} across, {} from {} to {} up, {} x {} cells",
                m.x.axis().field(),
                full(m.x.from()),
                full(m.x.to()),
                m.y.axis().field(),
                full(m.y.from()),
                full(m.y.to()),
                m.cols,
                m.rows
            ),
            Err(e) => format!("map = none ({e})"),
        },
        View::Load => format!(
            "load = pbar/{} from 0 to 1, {} points, at the parameters above",
            state.hardness_name(),
            opts.points
        ),
        View::Spectrum => match state.surface.as_ref().and_then(|s| s.fit()) {
            Some(f) => format!(
                "spectrum = the data's, with the power law fitted over its fit band \
                 q = {} to {} 1/m ({})",
                full(f.q_lo),
                full(f.q_hi),
                if state.surface.as_ref().is_some_and(|s| s.fit_band.is_some()) {
                    "set"
                } else {
                    "found from the data"
                }
            ),
            None => "spectrum = the data's (no power law fitted)".to_string(),
        },
        View::Contact => "contact = the boundary-element simulation beside the theory".to_string(),
    }
}

/// The scene in full, one fact a line (no comment marks): the scene's name
/// and view, every parameter with all its digits, the sweep or map, model,
/// moments and size effect, and a measured surface's file and SHA-256.
pub fn full_lines(state: &State, view: View, opts: &FigureOptions) -> Vec<String> {
    full_lines_of(state, view.name(), span_full(state, view, opts))
}

/// [`full_lines`] of a picture or table that is not one of the explorer's
/// views (`export --view moments`): `what` names it, `span` says what it
/// spans.
pub fn full_lines_of(state: &State, what: &str, span: String) -> Vec<String> {
    let p = &state.params;
    let mut lines = vec![format!(
        "roughtui {}: scene {:?}, view {what}",
        env!("CARGO_PKG_VERSION"),
        state.name,
    )];
    for axis in Axis::ALL {
        let unit = match axis_unit(axis) {
            "" => String::new(),
            u => format!(" {u}"),
        };
        let marker = if axis == state.sweep.axis() {
            "; the marker"
        } else {
            ""
        };
        lines.push(format!(
            "{} = {}{unit}  ({}{marker})",
            axis.field(),
            full(p.get(axis)),
            meaning(axis)
        ));
    }
    lines.push(format!(
        "q0 = {} 1/m  (longest wavelength L = 2 pi/q0 = {} m)",
        full(p.q0()),
        full(std::f64::consts::TAU / p.q0())
    ));
    lines.push(span);
    lines.push(format!("model = {}", state.model.label()));
    lines.push(format!("moments = {}", moments(state)));
    lines.push(format!("size_effect = {}", on_off(state.size_effect)));
    if let Some(s) = &state.surface {
        lines.push(format!("surface = {}", s.file_name()));
        lines.push(format!("sha256 = {}", s.measured.sha256));
        lines.extend(grid_line(&s.measured.kind));
    }
    lines
}

/// The measured grid and its side lengths, as read: "grid = 192 × 192
/// points over 5e-5 m × 5e-5 m (…)"; a PSD table has none.
fn grid_line(kind: &rough_surface::Kind) -> Option<String> {
    use rough_surface::Kind;
    let map = |nx: usize, ny: usize, lx: f64, ly: f64| {
        format!(
            "grid = {nx} × {ny} points over {} m × {} m  (points along x × along y, sides \
             Lx × Ly; spacing {} m × {} m)",
            full(lx),
            full(ly),
            full(lx / nx as f64),
            full(ly / ny as f64)
        )
    };
    match *kind {
        Kind::Map { nx, ny, lx, ly } | Kind::Profiles { nx, ny, lx, ly, .. } => {
            Some(map(nx, ny, lx, ly))
        }
        Kind::Line { n, l } => Some(format!(
            "grid = {n} points over {} m  (a line scan; spacing {} m)",
            full(l),
            full(l / n as f64)
        )),
        _ => None,
    }
}

/// The scene in short: one line of parameters, one of what is computed
/// and how, and on a measured surface one naming the file and its SHA-256.
pub fn short_lines(state: &State, view: View, opts: &FigureOptions) -> Vec<String> {
    let p = &state.params;
    let swept = state.sweep.axis();
    let range = |a: Axis, from: f64, to: f64| {
        format!(
            "{} {} … {}",
            a.symbol(),
            short_value(a, from),
            short_value(a, to)
        )
    };
    let span = match view {
        View::Slopes | View::Indices => Some(format!(
            "swept {} (marker at {})",
            range(swept, state.sweep.from(), state.sweep.to()),
            short_value(swept, p.get(swept))
        )),
        View::Map => MapSpec::of(state, opts.grid, opts.map_y).ok().map(|m| {
            format!(
                "map {} across, {} up",
                range(m.x.axis(), m.x.from(), m.x.to()),
                range(m.y.axis(), m.y.from(), m.y.to())
            )
        }),
        View::Load | View::Spectrum | View::Contact => None,
    };
    short_lines_of(state, span)
}

/// [`short_lines`] with what the picture spans (`span`) given.
pub fn short_lines_of(state: &State, span: Option<String>) -> Vec<String> {
    let p = &state.params;
    let mut params: Vec<String> = Axis::ALL
        .iter()
        .map(|&a| format!("{} = {}", caption_symbol(a), short_value(a, p.get(a))))
        .collect();
    params.push(format!(
        "q0 = {} 1/m (L = {})",
        short_number(p.q0()),
        short_length(std::f64::consts::TAU / p.q0())
    ));
    let mut how: Vec<String> = span.into_iter().collect();
    how.push(state.model.label().to_string());
    how.push(format!("{} moments", moments(state)));
    how.push(format!("size effect {}", on_off(state.size_effect)));
    let mut lines = vec![params.join(" · "), how.join(" · ")];
    if let Some(s) = &state.surface {
        lines.push(format!(
            "surface {} · SHA-256 {}",
            s.file_name(),
            s.measured.sha256
        ));
    }
    lines
}

/// What each column of `view`'s CSV means, one line: a name says one
/// thing (`h_use_over_h0` is the hardness in use, `hy_over_h0` the
/// size-dependent one whether it is in use or not).
pub fn columns_line(state: &State, view: View) -> Option<String> {
    let (psi, hy) = if state.size_effect {
        ("psi_star, with the size effect on", "H_y/H0")
    } else {
        ("psi_p, with the size effect off", "1")
    };
    let h = state.hardness_name();
    let swept = state.sweep.axis().field();
    Some(match view {
        View::Slopes => format!(
            "columns: {swept} (the swept value); psi = the index in use ({psi}); \
             h_use_over_h0 = the hardness in use over H0 (here {hy}); elastic, plastic, total = \
             the initial slopes {h} dA/(A0 dpbar); persson_elastic = Persson's purely elastic \
             slope sqrt(2/pi)/psi"
        ),
        View::Indices => format!(
            "columns: {swept} (the swept value); psi_gw (Greenwood-Williamson), psi_p (Persson, \
             bulk hardness H0), psi_star (size-dependent hardness H_y), psi_star_asymptotic \
             (eq. 13, empty where undefined); hy_over_h0 = H_y/H0, the size-dependent hardness \
             at lambda1 over H0, whether the size effect is on or off"
        ),
        View::Map => format!(
            "columns: the two parameters; psi = the index in use ({psi}); elastic, plastic, \
             total = the initial slopes {h} dA/(A0 dpbar); plastic_share = plastic/total"
        ),
        View::Load => {
            format!("columns: load = pbar/{h}; elastic, plastic, total = the contact areas A/A0")
        }
        View::Spectrum => "columns: q (1/m); psd = the data's spectrum (C^iso in m^4 of a map, \
                           C1D in m^3 of a profile); fit = the power law fitted over the fit \
                           band (empty outside it)"
            .to_string(),
        View::Contact => return None,
    })
}

/// The scene as CSV comment lines (`# ` before each line of
/// [`full_lines`], then what the columns mean), each ending in a newline.
pub fn csv_comments(state: &State, view: View, opts: &FigureOptions) -> String {
    full_lines(state, view, opts)
        .into_iter()
        .chain(columns_line(state, view))
        .map(|l| format!("# {l}\n"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_parameter_is_named_in_both_forms() {
        let s = crate::presets::load("fig2").unwrap();
        let opts = FigureOptions::default();
        let full = full_lines(&s, View::Slopes, &opts).join("\n");
        for want in [
            "scene \"fig2\", view slopes",
            "h0_over_e = 0.01  (H0/E: macroscopic hardness over E, the composite",
            "hurst = 0.8",
            "r_star = 0.001 m",
            "zeta = 128  (magnification q1/q0; the marker)",
            "q0 = 100000 1/m",
            "sweep = zeta from 1 to 10000, 200 points (log-spaced)",
            "model = closed form",
            "moments = asymptotic",
            "size_effect = off",
        ] {
            assert!(full.contains(want), "{want:?} not in\n{full}");
        }
        let h = s.params.h_rms();
        assert!(full.contains(&format!("h_rms = {} m", super::full(h))));
        let short = short_lines(&s, View::Slopes, &opts).join("\n");
        for want in [
            "H0/E = 0.01",
            "h_rms = 19.82 nm",
            "Hurst H = 0.8",
            "R* = 1 mm",
            "q0 = 1e5 1/m (L = 62.83 µm)",
            "swept ζ 1 … 1e4 (marker at 128)",
            "asymptotic moments",
            "size effect off",
        ] {
            assert!(short.contains(want), "{want:?} not in\n{short}");
        }
    }
}
