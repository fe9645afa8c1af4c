//! The spectrum view's data: a measured surface's spectrum (log-binned for
//! maps and lines, the table itself for a PSD table), the least-squares
//! power law over the fit band, and the cutoff q1 = ζ q0.

use std::fmt;

use rough_model::Dim;
use rough_surface::PowerLawFit;

use crate::scene::State;
use crate::surface::fit_amplitude;

/// The spectrum of the state's measured surface at its current cutoff.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectrumSeries {
    /// Areal C^iso (m⁴) or profile C1D (m³), SurfaceTopography's convention.
    pub dim: Dim,
    /// Wavevectors, 1/m, increasing.
    pub q: Vec<f64>,
    pub psd: Vec<f64>,
    /// The fitted power law at each q inside the fit band; `None` outside
    /// it.
    pub fit: Vec<Option<f64>>,
    /// The fit itself, `None` with fewer than two points in the band.
    pub power_law: Option<PowerLawFit>,
    /// The fit's h_rms in the paper's convention (`None` unless 0 < H ≤ 1).
    pub fit_h_rms: Option<f64>,
    /// The data's lower cutoff and the current upper one, 1/m.
    pub q0: f64,
    pub q1: f64,
}

/// The spectrum view asked of a scene without measured data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NotMeasured;

impl fmt::Display for NotMeasured {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(
            "the spectrum view shows a measured surface's data: give one with --surface FILE",
        )
    }
}

impl std::error::Error for NotMeasured {}

impl SpectrumSeries {
    pub fn of(state: &State) -> Result<SpectrumSeries, NotMeasured> {
        let src = state.surface.as_ref().ok_or(NotMeasured)?;
        let q0 = src.q0();
        let q1 = state.params.zeta() * q0;
        let power_law = src.fit();
        let dim = src.dim();
        let data = &src.measured.spectrum;
        let (q, psd): (Vec<f64>, Vec<f64>) = data.iter().copied().unzip();
        let fit = q
            .iter()
            .map(|&x| {
                let f = power_law?;
                let inside = x >= f.q_lo * (1.0 - 1e-12) && x <= f.q_hi * (1.0 + 1e-12);
                inside.then(|| f.psd_at_q0 * (x / q0).powf(f.slope))
            })
            .collect();
        Ok(SpectrumSeries {
            dim,
            q,
            psd,
            fit,
            power_law,
            fit_h_rms: power_law.and_then(|f| fit_amplitude(&f)).map(|a| a.1),
            q0,
            q1,
        })
    }

    /// What the PSD axis shows, with its unit.
    pub fn psd_label(&self) -> &'static str {
        match self.dim {
            Dim::Areal => "C^iso (m⁴)",
            Dim::Profile => "C1D (m³)",
        }
    }

    /// The fitted power law at `q` (anywhere, for drawing its line).
    pub fn fit_at(&self, q: f64) -> Option<f64> {
        let f = self.power_law?;
        Some(f.psd_at_q0 * (q / self.q0).powf(f.slope))
    }
}
