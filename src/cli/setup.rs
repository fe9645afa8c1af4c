//! The scene a command line names: `--preset`, `--load` or `--surface`,
//! then `--fit-band` and every `--set`.

use rough_model::Axis;

use super::{SetKey, Setup, Source};
use crate::scene::{self, State};
use crate::{physical, presets, snapshot, surface};

/// The state named by `--preset`, `--load` or `--surface` (fig2 when none
/// is given), with every `--set` applied in order (material values e, h0
/// and nu together, as H0/E, after the others).
pub fn load_source(src: &Source, setup: &Setup) -> anyhow::Result<State> {
    let mut state = load_base(src, setup)?;
    apply_setup(&mut state, setup)?;
    Ok(state)
}

/// The state named by `--preset`, `--load` or `--surface`, nothing set.
/// How to read a surface (`--detrend`, `--periodic`, …) is refused without
/// `--surface`: a preset has none, a snapshot records how its own is read.
pub fn load_base(src: &Source, setup: &Setup) -> anyhow::Result<State> {
    if src.surface.is_none() && setup.surface_options() != Default::default() {
        let given = if src.load.is_some() {
            "--load: a snapshot records how its surface is read"
        } else {
            "a preset: it has no surface"
        };
        anyhow::bail!(
            "how to read a surface (--periodic, --pixel-size, --series, --direction, \
             --channel, --height-unit, --lateral-unit, --max-undefined, --detrend) applies \
             to --surface FILE, not to {given}"
        );
    }
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
            SetKey::Param(axis) => scene::set(state, axis, text).map_err(at)?,
            SetKey::Q0 => {
                scene::set_q0(state, physical::parse_q0(text).map_err(at)?).map_err(at)?
            }
            SetKey::L => scene::set_q0(state, physical::parse_l(text).map_err(at)?).map_err(at)?,
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
            scene::set_value(state, Axis::H0OverE, ratio, &typed).map_err(|e| (None, e))
        }
        _ => Err((
            None,
            "e and h0 go together (H0/E = H0 over the composite modulus E*; \
             nu forms E* = E/(1 − ν²) from Young's E)"
                .into(),
        )),
    }
}
