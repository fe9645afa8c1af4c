//! A measured surface's scene: the one a surface opens on, its fit band,
//! and the power law fitted to it.

use std::sync::Arc;

use rough_model::{Axis, Dim, Model, MomentTable, Moments, ParamValues, Params, Sweep};
use rough_surface::{Kind, Measured, Options};

use super::{State, MAX_CAPTION_CHARS, MAX_NAME_CHARS};
use crate::surface::{fit_amplitude, fixed_values, printable, SurfaceSource};

/// The self-affine parameters of the power law fitted over `state`'s band:
/// the fit's H and h_rms, the data's q0, the state's H0/E, ζ and R*.
pub fn fitted_params(state: &State) -> Result<Params, String> {
    let src = state
        .surface
        .as_ref()
        .ok_or("no measured surface: the fit is of one")?;
    let fit = src
        .fit()
        .ok_or("fewer than two spectrum points in the fit band: no power-law fit")?;
    let (_, h_rms) = fit_amplitude(&fit).ok_or_else(|| {
        format!(
            "the fit's H = {:.3} is outside (0, 1]: no self-affine power law to compare",
            fit.hurst
        )
    })?;
    Params::new(ParamValues {
        h_rms,
        hurst: fit.hurst,
        q0: src.q0(),
        ..state.params.values()
    })
    .map_err(|e| e.to_string())
}

impl State {
    /// Sets the measured surface's Hurst fit band (`None`: the one found
    /// from the data) and the H the scene records with it.
    pub fn set_fit_band(&mut self, band: Option<(f64, f64)>) -> Result<(), String> {
        let src = self
            .surface
            .as_mut()
            .ok_or("the fit band is a measured surface's: give one with --surface FILE")?;
        src.fit_band = band;
        let values = fixed_values(src, self.params.values());
        self.params = Params::new(values).map_err(|e| e.to_string())?;
        Ok(())
    }

    /// The scene a surface opens on: the paper's material (H0/E = 0.01,
    /// R* = 1 mm, size effect on), the sweep over ζ from 1 to the largest ζ
    /// the data allows and the marker there, the exact model (the data
    /// deserve the exact solution; the paper's closed form is a key away).
    pub fn measured(src: SurfaceSource) -> anyhow::Result<State> {
        // A whole ratio as it is (a line's or a map's profiles' n/2: 96,
        // not 96.00000000000001); the table counts q within 1e-12 of q1
        // as ≤ q1, so the last wavevector stays in.
        let zeta_max = crate::physical::clean(src.zeta_max());
        if !(zeta_max > 1.0 && zeta_max.is_finite()) {
            anyhow::bail!(
                "surface {}: its spectrum spans no band (largest ζ {zeta_max}): \
                 nothing to sweep",
                src.path.display()
            );
        }
        let values = fixed_values(
            &src,
            ParamValues {
                h0_over_e: 1e-2,
                h_rms: 1e-8,
                zeta: zeta_max,
                hurst: 0.8,
                r_star: 1e-3,
                q0: 1.0,
            },
        );
        let params = Params::new(values)?;
        let caption = printable(
            &format!(
                "{}: {}, q0 = {} /m, ζ up to {}; the paper's material H0/E = 0.01, R* = 1 mm.",
                src.file_name(),
                src.describe(),
                crate::physical::short_number(src.q0()),
                crate::physical::short_number(zeta_max)
            ),
            MAX_CAPTION_CHARS,
        );
        let state = State {
            name: src.stem().chars().take(MAX_NAME_CHARS).collect(),
            caption: Some(caption),
            params,
            size_effect: true,
            sweep: Sweep::new(Axis::Zeta, 1.0, zeta_max)?,
            model: Model::Exact,
            moments: Moments::Truncated,
            surface: Some(src),
            seed: None,
            shown: Default::default(),
        };
        state.check()?;
        Ok(state)
    }
}

/// A synthetic n × n map's scene (benchmarks and tests): its spectrum every FFT wavevector of a 10 µm
/// square but the mean, with a power-law term (H = 0.8), tabulated as a
/// map's would be.
pub fn synthetic(n: usize) -> anyhow::Result<State> {
    let l = 1e-5;
    let dq = std::f64::consts::TAU / l;
    let half = (n / 2) as i64;
    let mut terms = Vec::with_capacity(n * n);
    for i in -half..(n as i64 - half) {
        for j in -half..(n as i64 - half) {
            if i == 0 && j == 0 {
                continue;
            }
            let q = dq * ((i * i + j * j) as f64).sqrt();
            terms.push((q, 1e-28 * (q / dq).powf(-3.6)));
        }
    }
    let spectrum: Vec<(f64, f64)> = (1..=half)
        .map(|k| (k as f64 * dq, 1e-28 * (k as f64).powf(-3.6) * l * l))
        .collect();
    let table = MomentTable::from_discrete(Dim::Areal, dq, terms)?;
    let measured = Measured {
        kind: Kind::Map {
            nx: n,
            ny: n,
            lx: l,
            ly: l,
        },
        table: Arc::new(table),
        sha256: "0".repeat(64),
        summary: format!("synthetic map {n} × {n}"),
        notes: Vec::new(),
        measurement: None,
        slopes: None,
        real: None,
        band: Measured::find_band(Dim::Areal, &spectrum, &[]),
        modes: Vec::new(),
        heights: None,
        spectrum,
    };
    State::measured(SurfaceSource {
        path: std::path::PathBuf::from(format!("synthetic-{n}x{n}.txt")),
        options: Options::default(),
        measured: Arc::new(measured),
        recorded_sha256: None,
        fit_band: None,
    })
}
