//! A least-squares power law through a spectrum, for orientation only (the
//! model never uses it): its Hurst exponent with a standard error and its
//! amplitude over a fit band (by default the self-affine stretch
//! [`crate::spectrum::band`] finds), whether it is self-affine there at all, and the
//! self-affine surface it stands for in the paper's convention, so that it
//! can be drawn as a ghost.
//!
//! The fit is weighted least squares of ln C against ln q, each bin
//! weighted by the number of Fourier modes it averages (the scatter of a
//! bin's ln C falls as 1/√modes; a PSD table's points weigh the same);
//! whether it is a power law at all is judged by the points' plain rms
//! distance from the line, each point as it is drawn. The
//! standard error of H combines the regression's, σ̂/√S_xx/2 with σ̂² the
//! weighted residual sum over n − 2, with the band's: the rms change of H
//! when the band loses one or two points at either end (a choice of band
//! is part of what H depends on). On fourier_synthesis surfaces with a
//! known H the deviations' rms is 1.15 of it (scripts/hurst_check.py).
//!
//! How far the points lie from the line is said twice: weighted by their
//! modes, as the fit sees them, and unweighted, as the spectrum view shows
//! them. A few-mode bin at small q can lie a decade off and barely move the
//! weighted rms (a Zygo MetroPro map over its former default band: 0.077
//! decades weighted, 0.689 unweighted, its first bins 1.0–1.6 decades
//! off); the verdict "not a power law" rests on the unweighted one past
//! [`POOR_DECADES`], and the default band ([`crate::spectrum::band`]) loses the
//! points farthest off its line until it passes.

use std::f64::consts::PI;

use rough_model::Dim;

use crate::spectrum::band::POOR_DECADES;

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
    /// The standard error of H, the regression's and the band's choice's
    /// combined (NaN with fewer than three points).
    pub hurst_se: f64,
    /// The weighted rms distance of the points from the line, in decades
    /// of C (each point weighted by its modes, as the line is fitted).
    pub rms_decades: f64,
    /// The plain rms distance of the points from the line, in decades of C,
    /// every point shown counting the same: what the verdict rests on (the
    /// mode weighting gives the few-mode bins at small q almost no weight,
    /// so a weighted rms of 0.08 decades can hide first bins 1.0–1.6
    /// decades off the line).
    pub rms_decades_unweighted: f64,
}

/// Whether a fit describes a self-affine surface over its band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Verdict {
    /// 0 < H ≤ 1, a straight line to [`POOR_DECADES`], at least
    /// [`MIN_POINTS`] points over at least [`MIN_DECADES`].
    SelfAffine,
    /// H outside (0, 1].
    OutOfRange,
    /// The points stray from the line by more than [`POOR_DECADES`] rms,
    /// unweighted.
    Poor,
    /// Fewer than [`MIN_POINTS`] points, or a band under [`MIN_DECADES`].
    TooShort,
}

/// The narrowest band, decades of q, a fit is judged over.
pub use crate::limits::MIN_FIT_DECADES as MIN_DECADES;
/// Fewest points of a fit that says anything.
pub use crate::limits::MIN_FIT_POINTS as MIN_POINTS;

impl Verdict {
    /// In words, for the screen: `None` for a self-affine fit.
    pub fn words(&self) -> Option<&'static str> {
        match self {
            Verdict::SelfAffine => None,
            Verdict::OutOfRange => Some("H outside (0, 1]: not self-affine over this band"),
            Verdict::Poor => Some("not a power law over this band"),
            Verdict::TooShort => Some("too short a band to tell"),
        }
    }
}

impl PowerLawFit {
    /// Whether the fit is self-affine over its band ([`Verdict`]); a poor
    /// fit is judged by the points as drawn, unweighted.
    pub fn verdict(&self) -> Verdict {
        if self.points < MIN_POINTS || (self.q_hi / self.q_lo).log10() < MIN_DECADES {
            Verdict::TooShort
        } else if !(self.hurst > 0.0 && self.hurst <= 1.0) {
            Verdict::OutOfRange
        } else if self.rms_decades_unweighted > POOR_DECADES {
            Verdict::Poor
        } else {
            Verdict::SelfAffine
        }
    }

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

/// Weighted least squares of (x, y, w) points: (slope, x̄, ȳ, S_xx, the
/// weighted residual sum, Σw); `None` without a spread in x.
fn line(pts: &[(f64, f64, f64)]) -> Option<(f64, f64, f64, f64, f64, f64)> {
    let w: f64 = pts.iter().map(|p| p.2).sum();
    let mx = pts.iter().map(|p| p.2 * p.0).sum::<f64>() / w;
    let my = pts.iter().map(|p| p.2 * p.1).sum::<f64>() / w;
    let sxx: f64 = pts.iter().map(|p| p.2 * (p.0 - mx).powi(2)).sum();
    if pts.len() < 2 || sxx == 0.0 {
        return None;
    }
    let sxy: f64 = pts.iter().map(|p| p.2 * (p.0 - mx) * (p.1 - my)).sum();
    let slope = sxy / sxx;
    let ssr: f64 = pts
        .iter()
        .map(|p| p.2 * (p.1 - my - slope * (p.0 - mx)).powi(2))
        .sum();
    Some((slope, mx, my, sxx, ssr, w))
}

pub(crate) fn fit(
    dim: Dim,
    spectrum: &[(f64, f64)],
    modes: &[f64],
    q_lo: f64,
    q_hi: f64,
    q0: f64,
) -> Option<PowerLawFit> {
    let pts: Vec<(f64, f64, f64)> = spectrum
        .iter()
        .enumerate()
        .filter(|(_, (q, c))| *q >= q_lo && *q <= q_hi && *c > 0.0)
        .map(|(i, (q, c))| {
            (
                q.ln(),
                c.ln(),
                modes.get(i).copied().unwrap_or(1.0).max(1.0),
            )
        })
        .collect();
    let n = pts.len();
    let (slope, mx, my, sxx, ssr, w) = line(&pts)?;
    let regression = if n > 2 {
        (ssr / (n - 2) as f64 / sxx).sqrt() / 2.0
    } else {
        f64::NAN
    };
    // How much H moves when the band loses one or two points at either
    // end: the band's choice is part of the uncertainty.
    let mut moves = Vec::new();
    for k in 1..=2 {
        if n >= MIN_POINTS + k {
            for part in [&pts[k..], &pts[..n - k]] {
                if let Some(l) = line(part) {
                    moves.push(((l.0 - slope) / 2.0).powi(2));
                }
            }
        }
    }
    let band = if moves.is_empty() {
        0.0
    } else {
        (moves.iter().sum::<f64>() / moves.len() as f64).sqrt()
    };
    let hurst_se = (regression * regression + band * band).sqrt();
    let (lo, hi) = (pts[0].0.exp(), pts[n - 1].0.exp());
    let plain = pts
        .iter()
        .map(|p| (p.1 - my - slope * (p.0 - mx)).powi(2))
        .sum::<f64>()
        / n as f64;
    Some(PowerLawFit {
        dim,
        hurst: crate::spectrum::band::hurst(dim, slope),
        slope,
        q0,
        psd_at_q0: (my + slope * (q0.ln() - mx)).exp(),
        q_lo: lo.max(q_lo),
        q_hi: hi.min(q_hi),
        points: n,
        hurst_se,
        rms_decades: (ssr / w).sqrt() / std::f64::consts::LN_10,
        rms_decades_unweighted: plain.sqrt() / std::f64::consts::LN_10,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A power law whose first bins, of one or two modes each, lie 1.0–1.6
    /// decades below it (a form or roll-off the band kept): the weighted
    /// rms hardly sees them, the unweighted one does.
    #[test]
    fn few_mode_bins_off_the_line_make_a_poor_fit() {
        let q0 = 1e5;
        let law = |q: f64| 1e-30 * (q / q0).powf(-3.6);
        let mut spectrum = Vec::new();
        let mut modes = Vec::new();
        for k in 0..25 {
            let q = q0 * 10f64.powf(0.1 * f64::from(k));
            let off = [1.6, 1.3, 1.0].get(k as usize).copied().unwrap_or(0.0);
            spectrum.push((q, law(q) * 10f64.powf(-off)));
            modes.push(if k < 3 {
                1.0 + f64::from(k) / 2.0
            } else {
                50.0 * f64::from(k * k)
            });
        }
        let f = fit(Dim::Areal, &spectrum, &modes, q0, 1e8, q0).unwrap();
        assert!(f.rms_decades < POOR_DECADES, "{f:?}");
        // The three points' squares over 25 points, about the line the
        // weights draw (nearly the law itself).
        let plain = ((1.6f64.powi(2) + 1.3f64.powi(2) + 1.0f64.powi(2)) / 25.0).sqrt();
        assert!(
            (f.rms_decades_unweighted / plain - 1.0).abs() < 0.05,
            "{f:?}"
        );
        assert_eq!(f.verdict(), Verdict::Poor);
        // The same law without them is self-affine, both rms nought.
        let f = fit(Dim::Areal, &spectrum[3..], &modes[3..], q0, 1e8, q0).unwrap();
        assert_eq!(f.verdict(), Verdict::SelfAffine);
        assert!(f.rms_decades_unweighted < 1e-12, "{f:?}");
    }
}
