//! roughtui as a library: the command line, snapshots, presets, the headless
//! commands and the TUI, so that tests and benchmarks reach them. The binary
//! (`src/main.rs`) only parses and dispatches.

pub mod bench;
pub mod cli;
pub mod contact;
pub mod csv_number;
pub mod export;
pub mod figure;
pub mod presets;
pub mod serve;
pub mod snapshot;
pub mod surface;
pub mod tui;

use cli::{Setup, Source};
use rough_model::Axis;
use snapshot::State;

/// The state named by `--preset`, `--load` or `--surface` (fig2 when none
/// is given), with every `--set` applied in order.
pub fn load_source(src: &Source, setup: &Setup) -> anyhow::Result<State> {
    let mut state = if let Some(path) = &src.load {
        snapshot::load_file(path)?
    } else if let Some(path) = &src.surface {
        let options = rough_surface::Options {
            periodic: setup.periodic,
            pixel_size: setup.pixel_size,
            channel: setup.channel.clone(),
            height_unit: setup.height_unit,
        };
        State::measured(surface::SurfaceSource::read(path, options)?)?
    } else {
        presets::load(src.preset.as_deref().unwrap_or("fig2"))?
    };
    if let Some(band) = setup.fit_band {
        state
            .set_fit_band(Some(band))
            .map_err(|e| anyhow::anyhow!("--fit-band: {e}"))?;
    }
    for (axis, text) in &setup.set {
        set(&mut state, *axis, text)
            .map_err(|e| anyhow::anyhow!("--set {}={text}: {e}", figure::axis_arg(*axis)))?;
    }
    Ok(state)
}

/// Sets `axis` to the value typed as `text` (units as the value prompt
/// takes them), checked as the prompt checks it. A caption that described
/// the scene before goes when a parameter other than the swept one changes.
pub fn set(state: &mut State, axis: Axis, text: &str) -> Result<(), String> {
    let r = state.roughness();
    if !r.is_parameter(axis) {
        return Err(rough_model::RoughnessError::NotAParameter(axis).to_string());
    }
    let params = tui::value_input::apply_value(&state.params, axis, text)?;
    let mut next = state.clone();
    next.params = params;
    next.check().map_err(|e| match e {
        snapshot::Invalid::Moments(_) => tui::app::HURST_ONE_ASYMPTOTIC.to_string(),
        e => e.to_string(),
    })?;
    if axis != state.sweep.axis() && params != state.params {
        next.caption = None;
    }
    *state = next;
    Ok(())
}
