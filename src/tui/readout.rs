//! What the readout shows at the current parameters: spectrum, indices,
//! slopes of both models and, on a measured surface, the power law fitted
//! over the band on screen.

use rough_model::{persson_elastic, slopes, Slopes, Surface};
use rough_surface::PowerLawFit;

use crate::scene::State;
use crate::surface::fit_amplitude;

/// Everything the readout shows, at the current parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Readout {
    pub surface: Surface,
    /// The index in use (Ψ_P or Ψ*).
    pub psi: f64,
    pub slopes: Slopes,
    /// The other model's slopes at the same ψ.
    pub other: Slopes,
    pub persson: f64,
    /// On a measured surface: the least-squares power law over the fit band.
    pub fit: Option<Fit>,
}

/// A power law fitted over the band on screen, for orientation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    pub fit: PowerLawFit,
    /// The fit's h_rms in the paper's convention (`None` unless 0 < H ≤ 1).
    pub h_rms: Option<f64>,
}

impl Readout {
    pub fn of(state: &State) -> Readout {
        let surface = state.roughness().surface(&state.params, state.moments);
        let psi = surface.indices.psi_in_use(state.size_effect);
        let fit = state.surface.as_ref().and_then(|src| {
            let fit = src.fit()?;
            Some(Fit {
                fit,
                h_rms: fit_amplitude(&fit).map(|a| a.1),
            })
        });
        Readout {
            surface,
            psi: psi.to_f64(),
            slopes: slopes(state.model, psi),
            other: slopes(state.model.other(), psi),
            persson: persson_elastic(psi),
            fit,
        }
    }
}
