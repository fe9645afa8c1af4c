//! Setting a parameter of the scene as typed (the value prompt, `--set`).

use rough_model::Axis;

use super::{Invalid, State};
use crate::physical;

/// Sets `axis` to the value typed as `text` (units as the value prompt
/// takes them), checked as the prompt checks it. A caption that described
/// the scene before goes when a parameter other than the swept one changes.
pub fn set(state: &mut State, axis: Axis, text: &str) -> Result<(), String> {
    let v = physical::value::parse_value(axis, text)?;
    set_value(state, axis, v, text)
}

/// [`set`] with the value parsed: `typed` is how the refusal shows it.
pub fn set_value(state: &mut State, axis: Axis, v: f64, typed: &str) -> Result<(), String> {
    let r = state.roughness();
    if !r.is_parameter(axis) {
        return Err(rough_model::RoughnessError::NotAParameter(axis).to_string());
    }
    let params = physical::value::apply_number(&state.params, axis, v, typed)?;
    let mut next = state.clone();
    next.params = params;
    next.check().map_err(|e| match e {
        Invalid::Moments(_) => HURST_ONE_SET.to_string(),
        e => e.to_string(),
    })?;
    if axis != state.sweep.axis() && params != state.params {
        next.caption = None;
    }
    *state = next;
    Ok(())
}

/// Why H = 1 is refused with the asymptotic moments, on the command line.
pub const HURST_ONE_SET: &str =
    "H = 1 needs truncated moments (asymptotic m2 is infinite): add --moments truncated";

/// Sets the lower cutoff q0 (1/m) of the paper's power law; a measured
/// surface's q0 is its data's.
pub fn set_q0(state: &mut State, q0: f64) -> Result<(), String> {
    if state.is_measured() {
        return Err("q0 is the data's on a measured surface (2π over its length)".into());
    }
    let mut v = state.params.values();
    v.q0 = q0;
    let params = rough_model::Params::new(v).map_err(|e| e.to_string())?;
    if params != state.params {
        state.params = params;
        state.caption = None;
    }
    Ok(())
}
