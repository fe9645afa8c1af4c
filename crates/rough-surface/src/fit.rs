//! A least-squares power law through a spectrum, for orientation only (the
//! model never uses it): its Hurst exponent and amplitude over the band on
//! screen.

use rough_model::Dim;

/// C ≈ A q^slope over [q_lo, q_hi], read as a self-affine surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerLawFit {
    /// The Hurst exponent: slope = −2(1+H) for areal C^iso, −(1+2H) for a
    /// profile C1D.
    pub hurst: f64,
    /// The fitted log-log slope of the PSD.
    pub slope: f64,
    /// The PSD's fitted value at q0 (the spectrum's own units).
    pub psd_at_q0: f64,
    /// The band the fit used, 1/m, and how many points lay in it.
    pub q_lo: f64,
    pub q_hi: f64,
    pub points: usize,
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
        hurst,
        slope,
        psd_at_q0: (my + slope * (q0.ln() - mx)).exp(),
        q_lo,
        q_hi,
        points: n,
    })
}
