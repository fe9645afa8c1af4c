//! roughtui as a library: the command line, snapshots, presets, the headless
//! commands and the TUI, so that tests and benchmarks reach them. The binary
//! (`src/main.rs`) only parses and dispatches.

pub mod bench;
pub mod cli;
pub mod contact;
pub mod export;
pub mod figure;
pub mod lesson;
pub mod physical;
pub mod presets;
pub mod serve;
pub mod snapshot;
pub mod surface;
pub mod tui;

use cli::{SetKey, Setup, Source};
use rough_model::Axis;
use snapshot::State;

/// The state named by `--preset`, `--load` or `--surface` (fig2 when none
/// is given), with every `--set` applied in order (material values e, h0
/// and nu together, as H0/E, after the others).
pub fn load_source(src: &Source, setup: &Setup) -> anyhow::Result<State> {
    let mut state = load_base(src, setup)?;
    apply_setup(&mut state, setup)?;
    Ok(state)
}

/// The state named by `--preset`, `--load` or `--surface`, nothing set.
pub fn load_base(src: &Source, setup: &Setup) -> anyhow::Result<State> {
    Ok(if let Some(path) = &src.load {
        snapshot::load_file(path)?
    } else if let Some(path) = &src.surface {
        State::measured(surface::SurfaceSource::read(path, setup.surface_options())?)?
    } else {
        presets::load(src.preset.as_deref().unwrap_or("fig2"))?
    })
}

/// `--fit-band` and every `--set` of `setup` applied to `state`; the
/// refusal names the pair.
pub fn apply_setup(state: &mut State, setup: &Setup) -> anyhow::Result<()> {
    if let Some(band) = setup.fit_band {
        state
            .set_fit_band(Some(band))
            .map_err(|e| anyhow::anyhow!("--fit-band: {e}"))?;
    }
    apply_sets(state, &setup.set).map_err(|(at, e)| match at {
        Some(k) => {
            let (key, text) = &setup.set[k];
            anyhow::anyhow!("--set {}={text}: {e}", key.name())
        }
        None => anyhow::anyhow!("--set: {e}"),
    })
}

/// Applies `sets` in order: parameters, q0 and L at once; the material
/// values (e, h0, nu) gathered and applied last as H0/E = H0/E*. A refusal
/// says which pair (its index) or, for the material values together, none.
pub fn apply_sets(
    state: &mut State,
    sets: &[(SetKey, String)],
) -> Result<(), (Option<usize>, String)> {
    let mut material: [Option<(f64, &str)>; 3] = [None; 3];
    for (k, (key, text)) in sets.iter().enumerate() {
        let at = |e: String| (Some(k), e);
        match *key {
            SetKey::Param(axis) => set(state, axis, text).map_err(at)?,
            SetKey::Q0 => set_q0(state, physical::parse_q0(text).map_err(at)?).map_err(at)?,
            SetKey::L => set_q0(state, physical::parse_l(text).map_err(at)?).map_err(at)?,
            SetKey::E => {
                let v = physical::parse_pressure(text).map_err(at)?;
                physical::check_range("E", physical::MODULUS, v, text).map_err(at)?;
                material[0] = Some((v, text));
            }
            SetKey::H0 => {
                let v = physical::parse_pressure(text).map_err(at)?;
                physical::check_range("H0", physical::HARDNESS, v, text).map_err(at)?;
                material[1] = Some((v, text));
            }
            SetKey::Nu => {
                let v: f64 = text
                    .parse()
                    .map_err(|_| at(format!("\"{text}\" is not a number")))?;
                physical::check_range("ν", physical::POISSON, v, text).map_err(at)?;
                material[2] = Some((v, text));
            }
        }
    }
    match material {
        [None, None, None] => Ok(()),
        [Some((e, et)), Some((h0, ht)), nu] => {
            let ratio = physical::h0_over_e(h0, e, nu.map(|n| n.0));
            let typed = match nu {
                Some((_, nt)) => format!("{ht}·(1 − {nt}²)/{et}"),
                None => format!("{ht}/{et}"),
            };
            physical::check(Axis::H0OverE, ratio, &typed).map_err(|e| (None, e))?;
            set_value(state, Axis::H0OverE, ratio, &typed).map_err(|e| (None, e))
        }
        _ => Err((
            None,
            "e and h0 go together (H0/E = H0 over the composite modulus E*; \
             nu forms E* = E/(1 − ν²) from Young's E)"
                .into(),
        )),
    }
}

/// Sets `axis` to the value typed as `text` (units as the value prompt
/// takes them), checked as the prompt checks it. A caption that described
/// the scene before goes when a parameter other than the swept one changes.
pub fn set(state: &mut State, axis: Axis, text: &str) -> Result<(), String> {
    let v = physical::value::parse_value(axis, text)?;
    set_value(state, axis, v, text)
}

/// [`set`] with the value parsed: `typed` is how the refusal shows it.
fn set_value(state: &mut State, axis: Axis, v: f64, typed: &str) -> Result<(), String> {
    let r = state.roughness();
    if !r.is_parameter(axis) {
        return Err(rough_model::RoughnessError::NotAParameter(axis).to_string());
    }
    let params = physical::value::apply_number(&state.params, axis, v, typed)?;
    let mut next = state.clone();
    next.params = params;
    next.check().map_err(|e| match e {
        snapshot::Invalid::Moments(_) => HURST_ONE_SET.to_string(),
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
