//! Where a scene's moments come from: the paper's self-affine power law or a
//! measured surface's [`MomentTable`].
//!
//! Everything after the moments (hardness, indices, slopes, areas, regime)
//! is the same for both. A measured surface fixes what the power law takes
//! as parameters: its h_rms is √m0 of the data at the cutoff and its Hurst
//! exponent is whatever the data says, so neither may be set or swept, and
//! the magnification runs from 1 to the largest ζ the data holds.

use std::fmt;
use std::ops::{Add, Div};
use std::sync::Arc;

use crate::dd::{Dd, PI};
use crate::indices::{Indices, Surface};
use crate::measured::{MomentTable, ProfileMoments};
use crate::params::{Axis, Params, Shown};
use crate::spectrum::{Moments, Spectrum};
use crate::sweep::Sweep;

/// R_p/R_s of the hardness law times (3/8): R*/(1.2 R_s) = R*·√(m4/π)/0.45.
const RP_COEF: f64 = 0.45;

/// The source of a scene's spectrum moments.
///
/// Cheap to clone (the table sits behind an `Arc`) and to compare (a
/// table compares by fingerprint in O(1)).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Roughness {
    /// The paper's power law C = Z q^(−2(1+H)) from q0 to ζ q0, with h_rms,
    /// H and q0 taken from the [`Params`] and the moments by the
    /// [`Moments`] convention.
    #[default]
    SelfAffine,
    /// A measured surface: m0, m2, m4 at q1 = ζ q0 summed from the data.
    /// The `Moments` convention, eq. 13 (Ψ*asy) and the parameters h_rms,
    /// H and q0 do not apply.
    Measured(Arc<MomentTable>),
}

/// Why a parameter value or sweep does not fit a measured surface.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum RoughnessError {
    /// h_rms or H: measured, not a parameter.
    NotAParameter(Axis),
    /// A magnification beyond the largest the data holds.
    BeyondData { zeta: f64, zeta_max: f64 },
}

impl fmt::Display for RoughnessError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RoughnessError::NotAParameter(Axis::Hurst) => f.write_str(
                "H is not a parameter of a measured surface: the data has its own \
                 (the screen shows a power-law fit over the band q0…q1)",
            ),
            RoughnessError::NotAParameter(a) => write!(
                f,
                "{} is not a parameter of a measured surface: it is the data's √m0 at the cutoff ζ",
                a.symbol()
            ),
            RoughnessError::BeyondData { zeta, zeta_max } => write!(
                f,
                "ζ = {} is beyond the data: this surface's largest ζ is {}",
                Shown(*zeta),
                Shown(*zeta_max)
            ),
        }
    }
}

impl std::error::Error for RoughnessError {}

impl Roughness {
    /// The measured surface's table, if any.
    pub fn table(&self) -> Option<&MomentTable> {
        match self {
            Roughness::SelfAffine => None,
            Roughness::Measured(t) => Some(t),
        }
    }

    pub fn is_measured(&self) -> bool {
        matches!(self, Roughness::Measured(_))
    }

    /// Whether `axis` may be set and swept: all five for the power law;
    /// for a measured surface not h_rms and H, which the data fixes.
    pub fn is_parameter(&self, axis: Axis) -> bool {
        !(self.is_measured() && matches!(axis, Axis::HRms | Axis::Hurst))
    }

    /// The largest magnification: ∞ for the power law, q_max/q0 of the data.
    pub fn zeta_max(&self) -> f64 {
        self.table().map_or(f64::INFINITY, MomentTable::zeta_max)
    }

    /// Whether `p`'s ζ lies within the data (always, for the power law).
    pub fn check(&self, p: &Params) -> Result<(), RoughnessError> {
        let zeta_max = self.zeta_max();
        // Within the rounding of q_max/q0 (a whole ζ_max such as a line's
        // n/2 is taken as the whole number): the table counts q within
        // 1e-12 of q1 as ≤ q1.
        if p.zeta() > zeta_max * (1.0 + 1e-12) {
            return Err(RoughnessError::BeyondData {
                zeta: p.zeta(),
                zeta_max,
            });
        }
        Ok(())
    }

    /// Whether `s` sweeps a parameter of this roughness, within the data.
    pub fn check_sweep(&self, s: &Sweep) -> Result<(), RoughnessError> {
        if !self.is_parameter(s.axis()) {
            return Err(RoughnessError::NotAParameter(s.axis()));
        }
        let zeta_max = self.zeta_max();
        if s.axis() == Axis::Zeta && s.to() > zeta_max * (1.0 + 1e-12) {
            return Err(RoughnessError::BeyondData {
                zeta: s.to(),
                zeta_max,
            });
        }
        Ok(())
    }

    /// The profile moments of a measured surface at `p`'s ζ.
    fn moments_at(table: &MomentTable, p: &Params) -> ProfileMoments {
        table.at_zeta(p.zeta())
    }

    /// Spectrum and indices at `p`: [`Surface::of`] for the power law.
    pub fn surface(&self, p: &Params, moments: Moments) -> Surface {
        match self {
            Roughness::SelfAffine => Surface::of(p, moments),
            Roughness::Measured(t) => {
                let m = Roughness::moments_at(t, p);
                Surface {
                    params: *p,
                    moments,
                    spectrum: spectrum_of(t, p, &m),
                    indices: indices_of(p, &m),
                }
            }
        }
    }

    /// The indices at `p`: [`Indices::of`] for the power law.
    pub fn indices(&self, p: &Params, moments: Moments) -> Indices {
        match self {
            Roughness::SelfAffine => Indices::of(p, moments),
            Roughness::Measured(t) => indices_of(p, &Roughness::moments_at(t, p)),
        }
    }

    /// The index in use (double-double) and the hardness ratio in use at
    /// `p`: [`crate::psi_in_use`] for the power law.
    pub fn psi_in_use(&self, p: &Params, size_effect: bool, moments: Moments) -> (Dd, f64) {
        match self {
            Roughness::SelfAffine => crate::indices::psi_in_use(p, size_effect, moments),
            Roughness::Measured(t) => {
                let (sq, hr) = psi_sq(p, &Roughness::moments_at(t, p), size_effect);
                (sq.sqrt(), hr)
            }
        }
    }
}

/// (H_y/H0)² = 1 + R*/(1.2 R_s) = 1 + R*·√(m4/π)/0.45; 1 at R* = 0 or
/// m4 = 0 (no roughness, R_s = ∞).
fn hardness_sq(r_star: f64, m4: f64) -> Dd {
    if r_star == 0.0 || m4 == 0.0 {
        return Dd::from_f64(1.0);
    }
    Dd::from_f64(m4)
        .div(PI)
        .sqrt()
        .mul_f64(r_star)
        .div(Dd::from_f64(RP_COEF))
        .add(Dd::from_f64(1.0))
}

/// Ψ_P² = m2/(2 (H0/E)²), in double-double.
fn psi_p_sq(p: &Params, m: &ProfileMoments) -> Dd {
    let h0e = p.h0_over_e();
    Dd::from_f64(m.m2).mul_f64(0.5).div(Dd::prod(h0e, h0e))
}

/// ψ² in use and the hardness ratio in use, from the profile moments: the
/// per-point work of a sweep over a measured surface.
#[inline]
pub(crate) fn psi_sq(p: &Params, m: &ProfileMoments, size_effect: bool) -> (Dd, f64) {
    let sp = psi_p_sq(p, m);
    if !size_effect {
        return (sp, 1.0);
    }
    let hy2 = hardness_sq(p.r_star(), m.m4);
    (sp.div(hy2), hy2.sqrt().to_f64())
}

fn indices_of(p: &Params, m: &ProfileMoments) -> Indices {
    let psi_p = psi_p_sq(p, m).sqrt();
    let hy = hardness_sq(p.r_star(), m.m4).sqrt();
    let psi_star = psi_p.div(hy);
    // Ψ_GW = (E/H0)√(√m0/R_s), 1/R_s = √(m4/π)/0.375.
    let psi_gw =
        (m.m0.sqrt() * (m.m4 / std::f64::consts::PI).sqrt() / 0.375).sqrt() / p.h0_over_e();
    Indices::from_parts(psi_gw, psi_p, psi_star, None, hy.to_f64())
}

fn spectrum_of(t: &MomentTable, p: &Params, m: &ProfileMoments) -> Spectrum {
    let r_s = if m.m4 > 0.0 {
        0.375 * (std::f64::consts::PI / m.m4).sqrt()
    } else {
        f64::INFINITY
    };
    Spectrum {
        z: f64::NAN,
        m0: m.m0,
        m2: m.m2,
        m4: m.m4,
        r_s,
        lambda1: std::f64::consts::TAU / (p.zeta() * t.q0()),
        h_rms_actual: m.m0.sqrt(),
        rms_slope: (2.0 * m.m2).sqrt(),
        rms_curvature: (8.0 * m.m4 / 3.0).sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::Dim;
    use crate::params::ParamValues;

    /// fig2's spectrum, Z = 1e-8, H = 0.8, q0 = 1e5, in SurfaceTopography's
    /// convention C = (2π)² Z q^(−2(1+H)), one point per decade to 1e9.
    fn fig2_table() -> MomentTable {
        let q: Vec<f64> = [1e5, 1e6, 1e7, 1e8, 1e9].to_vec();
        let c: Vec<f64> = q
            .iter()
            .map(|&q: &f64| (2.0 * std::f64::consts::PI).powi(2) * 1e-8 * q.powf(-3.6))
            .collect();
        MomentTable::from_psd(Dim::Areal, &q, &c).unwrap()
    }

    fn fig2(zeta: f64, r_star: f64) -> Params {
        Params::new(ParamValues {
            h0_over_e: 1e-2,
            h_rms: 19.816636488030044e-9,
            zeta,
            hurst: 0.8,
            r_star,
            q0: 1e5,
        })
        .unwrap()
    }

    fn rel(a: f64, b: f64) -> f64 {
        if a == b {
            0.0
        } else {
            ((a - b) / b).abs()
        }
    }

    #[test]
    fn a_power_law_table_gives_the_truncated_power_law() {
        let r = Roughness::Measured(Arc::new(fig2_table()));
        for zeta in [1.0, 1.01, 2.0, 128.0, 3000.0, 1e4] {
            for r_star in [0.0, 1e-3] {
                let p = fig2(zeta, r_star);
                let a = Surface::of(&p, Moments::Truncated);
                let b = r.surface(&p, Moments::Truncated);
                let (ia, ib) = (a.indices, b.indices);
                for (name, x, y) in [
                    ("psi_p", ia.psi_p, ib.psi_p),
                    ("psi_star", ia.psi_star, ib.psi_star),
                    ("psi_gw", ia.psi_gw, ib.psi_gw),
                    ("hy", ia.hardness_ratio, ib.hardness_ratio),
                    ("m0", a.spectrum.m0, b.spectrum.m0),
                    ("m4", a.spectrum.m4, b.spectrum.m4),
                    ("r_s", a.spectrum.r_s, b.spectrum.r_s),
                    ("lambda1", a.spectrum.lambda1, b.spectrum.lambda1),
                ] {
                    assert!(rel(y, x) < 1e-13, "{name} ζ {zeta} R* {r_star}: {y} vs {x}");
                }
                assert_eq!(ib.psi_star_asymptotic, None);
                for se in [false, true] {
                    let (pa, ha) = crate::psi_in_use(&p, se, Moments::Truncated);
                    let (pb, hb) = r.psi_in_use(&p, se, Moments::Truncated);
                    assert!(rel(pb.to_f64(), pa.to_f64()) < 1e-13, "ζ {zeta}");
                    assert!(rel(hb, ha) < 1e-13, "ζ {zeta}");
                }
            }
        }
    }

    #[test]
    fn measured_parameters_and_range() {
        let r = Roughness::Measured(Arc::new(fig2_table()));
        assert!(!r.is_parameter(Axis::HRms) && !r.is_parameter(Axis::Hurst));
        assert!(r.is_parameter(Axis::Zeta) && Roughness::SelfAffine.is_parameter(Axis::HRms));
        assert!((r.zeta_max() - 1e4).abs() < 1e-9);
        assert_eq!(
            r.check(&fig2(2e4, 0.0)).unwrap_err().to_string(),
            "ζ = 20000 is beyond the data: this surface's largest ζ is 10000"
        );
        let s = Sweep::new(Axis::Hurst, 0.1, 0.9).unwrap();
        assert!(r
            .check_sweep(&s)
            .unwrap_err()
            .to_string()
            .starts_with("H is not a parameter of a measured surface"));
        let s = Sweep::new(Axis::HRms, 1e-9, 1e-6).unwrap();
        assert!(r
            .check_sweep(&s)
            .unwrap_err()
            .to_string()
            .starts_with("h_rms is not a parameter"));
        assert!(Roughness::SelfAffine.check_sweep(&s).is_ok());
    }
}
