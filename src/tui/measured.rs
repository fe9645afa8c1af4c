//! The explorer on a measured surface: what the data fixes is shown, not
//! set (h_rms and H), ζ ends at the data's largest, the moments convention
//! does not apply, `5` returns to the surface after a preset, and `g` pins
//! the power law fitted over the band as well as the curves.

use rough_model::{Axis, Moments, Sweep};

use super::app::{default_range, App};
use super::ghost::{Ghost, GhostKind};
use super::plots::compute_plot;
use super::status::Hint;
use crate::figure::View;
use crate::scene::fitted_params;

/// What `a` says on a measured surface.
pub const MOMENTS_DO_NOT_APPLY: &str =
    "a: a measured surface's moments are summed from its data, up to q1 = ζ q0";

/// The slider after (or before) `from` that is a parameter of the scene.
pub fn next_selectable(app: &App, from: usize, forward: bool) -> usize {
    let n = Axis::ALL.len();
    let r = app.state.roughness();
    let mut i = from % n;
    for _ in 0..n {
        i = if forward {
            (i + 1) % n
        } else {
            (i + n - 1) % n
        };
        if r.is_parameter(Axis::ALL[i]) {
            return i;
        }
    }
    from % n
}

/// Keeps the selection on a parameter of the scene (a surface loaded with
/// h_rms selected moves on to ζ… the next one).
pub fn fix_selection(app: &mut App) {
    if !app.state.roughness().is_parameter(app.selected_axis()) {
        app.selected = next_selectable(app, app.selected, true);
    }
}

/// Refuses changing `axis` when the data fixes it: true if refused (the
/// status says why).
pub fn refuse_fixed(app: &mut App, axis: Axis) -> bool {
    if app.state.roughness().is_parameter(axis) {
        return false;
    }
    app.set_status(fixed_text(axis), true);
    true
}

/// Why the data fixes `axis`, within an 80-column status line (the model's
/// [`RoughnessError::NotAParameter`] says it at more length).
pub fn fixed_text(axis: Axis) -> String {
    match axis {
        Axis::Hurst => {
            "H is the data's on a measured surface: H fit shows a power law over q0…q1".into()
        }
        a => format!(
            "{} is the data's on a measured surface: its √m0 up to the cutoff ζ",
            a.symbol()
        ),
    }
}

/// The default range of `axis` in the current scene: ζ up to the data's
/// largest on a measured surface.
pub fn range(app: &App, axis: Axis) -> (f64, f64) {
    let (lo, hi) = default_range(axis);
    if axis == Axis::Zeta {
        let top = crate::physical::clean(app.state.roughness().zeta_max());
        return (lo, hi.min(top));
    }
    (lo, hi)
}

/// `x`: sweep the next parameter of the scene over its range.
pub fn cycle_sweep(app: &mut App) {
    let cur = app.state.sweep.axis();
    let i = Axis::ALL.iter().position(|a| *a == cur).unwrap_or(0);
    let r = app.state.roughness();
    let axis = (1..=Axis::ALL.len())
        .map(|k| Axis::ALL[(i + k) % Axis::ALL.len()])
        .find(|a| r.is_parameter(*a))
        .unwrap_or(cur);
    let (lo, hi) = range(app, axis);
    match Sweep::new(axis, lo, hi) {
        Ok(s) => {
            app.state.sweep = s;
            app.modified = true;
            let hint = Hint::RStarNeedsSizeEffect;
            if hint.applies(&app.state) {
                app.set_hint(hint);
            }
        }
        Err(e) => app.set_status(e.to_string(), true),
    }
}

/// The surface's notes (units assumed, repairs, warnings) on the status
/// row, a warning shown as one; nothing when there are none.
pub fn show_notes(app: &mut App) {
    let Some(src) = app.state.surface.as_ref() else {
        return;
    };
    let notes = src.notes();
    if notes.is_empty() {
        return;
    }
    let warning = notes.iter().any(|n| n.starts_with("warning:"));
    // Warnings first, then the shorter notes, so that a status row too
    // short for all of them drops the longest notes rather than a warning
    // (the side panel shows them all).
    let (mut first, mut rest): (Vec<&String>, Vec<&String>) =
        notes.iter().partition(|n| n.starts_with("warning:"));
    rest.sort_by_key(|n| n.chars().count());
    first.extend(rest);
    let text: Vec<&str> = first.iter().map(|n| n.as_str()).collect();
    app.set_status(text.join(" · "), warning);
}

/// `[ ]` `{ }`: moves an end of the fit band to the neighbouring point of
/// the spectrum, keeping at least [`rough_surface::MIN_FIT_POINTS`] points
/// in the band.
pub fn move_fit_band(app: &mut App, upper: bool, up: bool) {
    let Some(src) = app.state.surface.as_ref() else {
        app.set_status(
            "the fit band is a measured surface's: 5 or --surface FILE",
            true,
        );
        return;
    };
    let qs: Vec<f64> = src.measured.spectrum.iter().map(|p| p.0).collect();
    let Some((lo, hi)) = src.fit_band() else {
        app.set_status("no fit band: the spectrum has too few points", true);
        return;
    };
    // The band's ends as indices of the spectrum's points.
    let at = |q: f64| qs.partition_point(|&x| x < q * (1.0 - 1e-9));
    let (mut i, mut j) = (at(lo), at(hi).min(qs.len() - 1));
    let min = rough_surface::MIN_FIT_POINTS - 1;
    let moved = match (upper, up) {
        (false, false) => i.checked_sub(1).map(|k| i = k),
        (false, true) => (i + 1 + min <= j).then(|| i += 1),
        (true, false) => (j >= i + 1 + min).then(|| j -= 1),
        (true, true) => (j + 1 < qs.len()).then(|| j += 1),
    };
    if moved.is_none() {
        app.set_status(
            format!(
                "the fit band cannot move that way: it keeps {} points inside the data",
                min + 1
            ),
            true,
        );
        return;
    }
    if let Err(e) = app.state.set_fit_band(Some((qs[i], qs[j]))) {
        app.set_status(e, true);
        return;
    }
    app.modified = true;
    say_fit(app, "b: the band found from the data");
}

/// `b`: the fit band found from the data again.
pub fn auto_fit_band(app: &mut App) {
    if let Err(e) = app.state.set_fit_band(None) {
        app.set_status(e, true);
        return;
    }
    app.modified = true;
    say_fit(app, "found from the data");
}

/// The status row after the fit band changed: the band and H over it.
fn say_fit(app: &mut App, how: &str) {
    let Some(f) = app.state.surface.as_ref().and_then(|s| s.fit()) else {
        app.set_status("no power law fits the band", true);
        return;
    };
    let h = match f.verdict().words() {
        None => format!("H {}", super::views::hurst_se(&f)),
        Some(w) => format!("H {:.2}: {w}", f.hurst),
    };
    app.set_status(
        format!("fit band {:.2e}…{:.2e} /m ({how}): {h}", f.q_lo, f.q_hi),
        false,
    );
}

/// `5`: back to the measured surface the session started on.
pub fn load_surface(app: &mut App) {
    match app.home.clone() {
        Some(s) => {
            let name = s.name.clone();
            app.load_state(s);
            app.set_status(format!("loaded {name} (measured surface)"), false);
            show_notes(app);
        }
        None => app.set_status(
            "no measured surface in this session: start with --surface FILE",
            true,
        ),
    }
}

/// `g`: on the slopes view, pin the curves as a ghost or clear it; on a
/// measured surface first the power law fitted over [q0, q1] (the
/// self-affine scene with the fit's H and h_rms, truncated moments), then
/// the curves themselves, then nothing.
pub fn toggle_ghost(app: &mut App) {
    let measured = app.state.is_measured();
    let was = app.ghost.take().map(|g| g.kind);
    if app.view != View::Slopes {
        if was.is_some() {
            app.set_status("ghost cleared", false);
        } else {
            app.set_status("g pins the slopes view's curves: Tab to it", false);
        }
        return;
    }
    match (measured, was) {
        (true, None) => pin_fit(app),
        (false, None) | (true, Some(GhostKind::Fit)) => {
            app.ghost = Some(Ghost {
                plot: app.plot.clone(),
                state: app.state.clone(),
                kind: GhostKind::Curves,
            });
            // The status row shows what the ghost is.
            app.status = None;
        }
        (_, Some(_)) => app.set_status("ghost cleared", false),
    }
}

fn pin_fit(app: &mut App) {
    let params = match fitted_params(&app.state) {
        Ok(p) => p,
        Err(e) => {
            app.set_status(format!("no fit to pin: {e}"), true);
            return;
        }
    };
    let mut fit = app.state.clone();
    fit.surface = None;
    fit.caption = None;
    fit.moments = Moments::Truncated;
    fit.params = params;
    let spec = fit.scene_spec(rough_model::Curves::ALL, app.plot.points.max(2));
    app.ghost = Some(Ghost {
        plot: compute_plot(&spec),
        state: fit,
        kind: GhostKind::Fit,
    });
    app.status = None;
}
