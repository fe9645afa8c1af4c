//! Enter in a prompt: the save prompt writes a snapshot named as typed; the
//! value prompt sets the selected parameter, checked by the model; the
//! lecturer's truth prompt hands a poll's typed true value to the server.

use super::app::{App, Hint, Mode};
use crate::physical::print::{fmt_param, fmt_short};
use crate::physical::value;
use crate::snapshot;

/// `KEY=VALUE …` typed at the value prompt: any of `--set`'s keys (q0,
/// l, e and h0 with nu, the parameters), applied together as `--set`
/// applies them. A refusal keeps the prompt open.
fn set_pairs(app: &mut App, text: &str) {
    let pairs: Result<Vec<_>, String> = text
        .split_whitespace()
        .map(|p| crate::cli::parse_set(p).map_err(|e| format!("{p}: {e}")))
        .collect();
    let mut next = app.state.clone();
    let applied = pairs.and_then(|p| {
        crate::cli::setup::apply_sets(&mut next, &p).map_err(|(at, e)| match at {
            Some(k) => format!("{}: {e}", text.split_whitespace().nth(k).unwrap_or("")),
            None => e,
        })
    });
    match applied {
        Ok(()) => {
            app.mode = Mode::Main;
            app.status = None;
            if next != app.state {
                app.state = next;
                app.modified = true;
            }
        }
        // In the explorer's words: the key that helps is `a`.
        Err(e) if e.ends_with(crate::scene::HURST_ONE_SET) => {
            app.set_status(super::app::HURST_ONE_ASYMPTOTIC, true)
        }
        Err(e) => app.set_status(e, true),
    }
}

/// Enter in a prompt: save under the typed name, or set the typed value.
/// A bad name or value keeps the prompt open, with the reason.
pub fn accept(app: &mut App) {
    match &app.mode {
        Mode::Value(_, line) if line.text().contains('=') => set_pairs(app, &line.text()),
        Mode::Value(axis, line) => {
            let (axis, text) = (*axis, line.text());
            if text.trim().is_empty() {
                app.mode = Mode::Main;
                return;
            }
            match value::apply_value(&app.state.params, axis, &text) {
                Ok(p) => {
                    let mut next = app.state.clone();
                    next.params = p;
                    if let Err(e) = next.check() {
                        let text = match e {
                            crate::scene::Invalid::Moments(_) => {
                                super::app::HURST_ONE_ASYMPTOTIC.into()
                            }
                            e => e.to_string(),
                        };
                        app.set_status(text, true);
                        return;
                    }
                    app.mode = Mode::Main;
                    if p != app.state.params {
                        app.state.params = p;
                        app.modified = true;
                    }
                    app.status = None;
                    if Hint::MarkerOffSweep.applies(&app.state) {
                        app.set_hint(Hint::MarkerOffSweep);
                    }
                }
                Err(e) => app.set_status(e, true),
            }
        }
        Mode::Prompt(line) => {
            let stem = line.text();
            let clean = match snapshot::check_stem(&stem) {
                Ok(c) => c.to_string(),
                Err(why) => {
                    // Stay in the prompt so the name can be fixed.
                    app.set_status(format!("cannot save: {why}"), true);
                    return;
                }
            };
            app.mode = Mode::Main;
            // The snapshot is named as typed (the stem, without ".ron"
            // and without the offered time stamp), and records the view.
            let mut named = app.state.clone();
            named.name = snapshot::scene_name(&clean).to_string();
            named.shown = super::ghost::shown(app);
            match snapshot::save_new(&app.save_dir, &stem, &named) {
                Ok(path) => {
                    named.shown = Default::default();
                    app.state = named;
                    app.modified = false;
                    app.file = path.file_name().map(|f| f.to_string_lossy().into_owned());
                    app.set_status(format!("saved {}", path.display()), false);
                }
                Err(e) => app.set_status(format!("{e:#}"), true),
            }
        }
        Mode::Truth(axis, line) => {
            let (axis, text) = (*axis, line.text());
            if text.trim().is_empty() {
                app.mode = Mode::Main;
                return;
            }
            let sweep = app.state.sweep;
            match value::parse_value(axis, &text) {
                Ok(v) if sweep.axis() == axis && (sweep.from()..=sweep.to()).contains(&v) => {
                    app.mode = Mode::Main;
                    app.status = None;
                    app.class.typed = Some((axis, v));
                }
                Ok(v) => app.set_status(
                    format!(
                        "{} = {} is outside the sweep {}…{}: the class answers inside it",
                        axis.symbol(),
                        fmt_param(axis, v),
                        fmt_short(axis, sweep.from()),
                        fmt_short(axis, sweep.to())
                    ),
                    true,
                ),
                Err(e) => app.set_status(e, true),
            }
        }
        Mode::Main | Mode::Help | Mode::Class => {}
    }
}
