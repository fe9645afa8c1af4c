//! A least-squares power law through a spectrum, for orientation only (the
//! model never uses it): its Hurst exponent and amplitude over the band on
//! screen, and the self-affine surface it stands for in the paper's
//! convention, so that it can be drawn as a ghost.

use std::f64::consts::PI;

use rough_model::Dim;

/// C ≈ A q^slope over [q_lo, q_hi], read as a self-affine surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerLawFit {
    /// Areal C^iso or profile C1D.
    pub dim: Dim,
    /// The Hurst exponent: slope = −2(1+H) for areal C^iso, −(1+2H) for a
    /// profile C1D.
    pub hurst: f64,
    /// The fitted log-log slope of the PSD.
    pub slope: f64,
    /// The surface's lower cutoff q0, 1/m (the table's).
    pub q0: f64,
    /// The PSD's fitted value at q0 (the spectrum's own units:
    /// SurfaceTopography's C^iso in m⁴, or C1D in m³).
    pub psd_at_q0: f64,
    /// The band the fit used, 1/m, and how many points lay in it.
    pub q_lo: f64,
    pub q_hi: f64,
    pub points: usize,
}

impl PowerLawFit {
    /// The fitted PSD at `q` (1/m), in the spectrum's own units.
    pub fn psd(&self, q: f64) -> f64 {
        self.psd_at_q0 * (q / self.q0).powf(self.slope)
    }

    /// The amplitude Z (m^(2−2H)) of the paper's isotropic power law
    /// C_Persson(q) = Z q^(−2(1+H)) (m⁴).
    ///
    /// Areal data: SurfaceTopography's C^iso is (2π)² C_Persson, so
    /// Z = A/(2π)² with A = C^iso(q) q^(2(1+H)).
    ///
    /// Profile data: an isotropic surface with C^iso = A q^(−2(1+H)) has
    /// the profile PSD C1D(q) = (1/2π) ∫ dq_y C^iso(√(q² + q_y²))
    /// = A Γ(H+½)/(2√π Γ(1+H)) q^(−(1+2H)) (SurfaceTopography's
    /// normalisations, ⟨h²⟩ = (1/2π)∫ C1D dq = (1/(2π)²)∫ C^iso d²q), so
    /// A = B · 2√π Γ(1+H)/Γ(H+½) with B = C1D(q) q^(1+2H). Valid for
    /// H > −½; `None` otherwise.
    pub fn persson_z(&self) -> Option<f64> {
        let amplitude = self.psd_at_q0 * self.q0.powf(-self.slope);
        let a = match self.dim {
            Dim::Areal => amplitude,
            Dim::Profile => {
                if self.hurst.is_nan() || self.hurst <= -0.5 {
                    return None;
                }
                amplitude * 2.0 * PI.sqrt() * libm::tgamma(1.0 + self.hurst)
                    / libm::tgamma(self.hurst + 0.5)
            }
        };
        let z = a / (2.0 * PI).powi(2);
        (z.is_finite() && z > 0.0).then_some(z)
    }

    /// The rms height of the fitted self-affine surface in the paper's
    /// convention (the power law from q0 to infinity):
    /// h_rms = √(π Z q0^(−2H) / H). `None` unless H > 0.
    pub fn h_rms(&self) -> Option<f64> {
        if self.hurst.is_nan() || self.hurst <= 0.0 {
            return None;
        }
        let z = self.persson_z()?;
        let h = (PI * z * self.q0.powf(-2.0 * self.hurst) / self.hurst).sqrt();
        h.is_finite().then_some(h)
    }
}

pub(crate) fn fit(
    dim: Dim,
    spectrum: &[(f64, f64)],
    q_lo: f64,
    q_hi: f64,
    q0: f64,
) -> Option<PowerLawFit> {
    let pts: Vec<(f64, f64)> = spectrum
        .iter()
        .filter(|(q, c)| *q >= q_lo && *q <= q_hi && *c > 0.0)
        .map(|(q, c)| (q.ln(), c.ln()))
        .collect();
    let n = pts.len();
    if n < 2 {
        return None;
    }
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n as f64;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n as f64;
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx == 0.0 {
        return None;
    }
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let slope = sxy / sxx;
    let hurst = match dim {
        Dim::Areal => -slope / 2.0 - 1.0,
        Dim::Profile => (-slope - 1.0) / 2.0,
    };
    Some(PowerLawFit {
        dim,
        hurst,
        slope,
        q0,
        psd_at_q0: (my + slope * (q0.ln() - mx)).exp(),
        q_lo,
        q_hi,
        points: n,
    })
}
