//! Validated model inputs.
//!
//! A [`Params`] can only be built through [`Params::new`], which rejects every
//! value outside the domain of `docs/model.md` with a [`ParamError`] that names the
//! field and its valid range. Everything downstream may therefore assume finite,
//! positive inputs.

use std::fmt;

/// The raw, unvalidated inputs, in SI units. Build a [`Params`] from it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(deny_unknown_fields)
)]
pub struct ParamValues {
    /// Macroscopic hardness over composite modulus, H0/E (dimensionless).
    pub h0_over_e: f64,
    /// rms height of the spectrum from q0 to infinity, m.
    pub h_rms: f64,
    /// Magnification ζ = q1/q0.
    pub zeta: f64,
    /// Hurst exponent H.
    pub hurst: f64,
    /// Size-effect length R* of the hardness law, m (0 = no size effect).
    pub r_star: f64,
    /// Lower cutoff wavevector q0, 1/m.
    pub q0: f64,
}

/// One of the five parameters a scene can sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Axis {
    H0OverE,
    HRms,
    Zeta,
    Hurst,
    RStar,
}

impl Axis {
    /// All axes, in slider order.
    pub const ALL: [Axis; 5] = [
        Axis::H0OverE,
        Axis::HRms,
        Axis::Zeta,
        Axis::Hurst,
        Axis::RStar,
    ];

    /// The field name used in snapshots and error messages.
    pub fn field(self) -> &'static str {
        match self {
            Axis::H0OverE => "h0_over_e",
            Axis::HRms => "h_rms",
            Axis::Zeta => "zeta",
            Axis::Hurst => "hurst",
            Axis::RStar => "r_star",
        }
    }

    /// The parameter's symbol for labels: "H0/E", "h_rms", "ζ", "H", "R*".
    pub fn symbol(self) -> &'static str {
        match self {
            Axis::H0OverE => "H0/E",
            Axis::HRms => "h_rms",
            Axis::Zeta => "ζ",
            Axis::Hurst => "H",
            Axis::RStar => "R*",
        }
    }

    /// Whether sweeps along this axis are log-spaced (all but the Hurst exponent).
    pub fn is_log(self) -> bool {
        !matches!(self, Axis::Hurst)
    }

    /// Whether `value` lies in this parameter's valid domain.
    pub fn accepts(self, value: f64) -> bool {
        field_domain(self.field()).accepts(value)
    }

    /// The valid domain in words, e.g. "finite and > 0".
    pub fn domain(self) -> &'static str {
        field_domain(self.field()).text
    }
}

/// Why a parameter set was rejected.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ParamError {
    /// `field` holds `value`, which is outside `valid`.
    OutOfDomain {
        field: &'static str,
        value: f64,
        valid: &'static str,
    },
    /// H = 1 with [`crate::Moments::Asymptotic`], whose m2 ∝ ζ^(2−2H)/(2−2H)
    /// is infinite there.
    HurstOneAsymptotic,
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamError::OutOfDomain {
                field,
                value,
                valid,
            } => write!(
                f,
                "{field} = {} is out of range: it must be {valid}",
                Shown(*value)
            ),
            ParamError::HurstOneAsymptotic => write!(
                f,
                "hurst = 1 needs moments: Truncated: the asymptotic moments (eq. 10) \
                 make m2 = πZq0^(2−2H)ζ^(2−2H)/(2−2H) infinite at H = 1"
            ),
        }
    }
}

impl std::error::Error for ParamError {}

/// A number for a message: as typed for ordinary sizes (0.01, 128), in
/// exponent form for very small or large ones (-2e-8, 1e300) instead of
/// hundreds of digits.
pub(crate) struct Shown(pub f64);

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        if a != 0.0 && a.is_finite() && !(1e-4..1e15).contains(&a) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

#[derive(Clone, Copy)]
struct Domain {
    text: &'static str,
    min: f64,
    min_inclusive: bool,
    max: f64,
}

impl Domain {
    fn accepts(self, v: f64) -> bool {
        v.is_finite()
            && (if self.min_inclusive {
                v >= self.min
            } else {
                v > self.min
            })
            && v <= self.max
    }
}

fn field_domain(field: &str) -> Domain {
    const POSITIVE: Domain = Domain {
        text: "finite and > 0",
        min: 0.0,
        min_inclusive: false,
        max: f64::MAX,
    };
    match field {
        "zeta" => Domain {
            text: "finite and >= 1",
            min: 1.0,
            min_inclusive: true,
            max: f64::MAX,
        },
        "hurst" => Domain {
            text: "in (0, 1]",
            min: 0.0,
            min_inclusive: false,
            max: 1.0,
        },
        "r_star" => Domain {
            text: "finite and >= 0 (0 = no size effect)",
            min: 0.0,
            min_inclusive: true,
            max: f64::MAX,
        },
        _ => POSITIVE,
    }
}

fn check(field: &'static str, value: f64) -> Result<f64, ParamError> {
    let d = field_domain(field);
    if d.accepts(value) {
        Ok(value)
    } else {
        Err(ParamError::OutOfDomain {
            field,
            value,
            valid: d.text,
        })
    }
}

/// A validated, immutable parameter set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params(ParamValues);

impl Params {
    /// Validates every field against the domain table of `docs/model.md`
    /// (fields checked in declaration order; the first failure is reported).
    pub fn new(v: ParamValues) -> Result<Params, ParamError> {
        check("h0_over_e", v.h0_over_e)?;
        check("h_rms", v.h_rms)?;
        check("zeta", v.zeta)?;
        check("hurst", v.hurst)?;
        check("r_star", v.r_star)?;
        check("q0", v.q0)?;
        Ok(Params(v))
    }

    /// The values, for copying into a new, modified set.
    pub fn values(&self) -> ParamValues {
        self.0
    }

    pub fn h0_over_e(&self) -> f64 {
        self.0.h0_over_e
    }
    pub fn h_rms(&self) -> f64 {
        self.0.h_rms
    }
    pub fn zeta(&self) -> f64 {
        self.0.zeta
    }
    pub fn hurst(&self) -> f64 {
        self.0.hurst
    }
    pub fn r_star(&self) -> f64 {
        self.0.r_star
    }
    pub fn q0(&self) -> f64 {
        self.0.q0
    }

    /// The value of the swept parameter `axis`.
    pub fn get(&self, axis: Axis) -> f64 {
        match axis {
            Axis::H0OverE => self.0.h0_over_e,
            Axis::HRms => self.0.h_rms,
            Axis::Zeta => self.0.zeta,
            Axis::Hurst => self.0.hurst,
            Axis::RStar => self.0.r_star,
        }
    }

    /// A copy with `axis` set to `value`, validated.
    pub fn with(&self, axis: Axis, value: f64) -> Result<Params, ParamError> {
        Params::new(self.with_unchecked(axis, value).0)
    }

    /// A copy with `axis` set to `value`, which the caller guarantees lies in
    /// the domain (a point of a validated sweep).
    #[inline(always)]
    pub(crate) fn with_unchecked(&self, axis: Axis, value: f64) -> Params {
        let mut v = self.0;
        match axis {
            Axis::H0OverE => v.h0_over_e = value,
            Axis::HRms => v.h_rms = value,
            Axis::Zeta => v.zeta = value,
            Axis::Hurst => v.hurst = value,
            Axis::RStar => v.r_star = value,
        }
        Params(v)
    }

    /// The paper's Figure 2 set: q0 = 1e5 1/m, H = 0.8, h_rms = 20 nm,
    /// ζ = 128, H0/E = 1e-2, R* = 1 mm.
    pub fn paper_fig2() -> Params {
        Params(ParamValues {
            h0_over_e: 1e-2,
            h_rms: 2e-8,
            zeta: 128.0,
            hurst: 0.8,
            r_star: 1e-3,
            q0: 1e5,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_each_field_by_name() {
        let ok = Params::paper_fig2().values();
        for (field, bad) in [
            ("h0_over_e", 0.0),
            ("h_rms", -1e-9),
            ("zeta", 0.5),
            ("hurst", 0.0),
            ("hurst", 1.5),
            ("r_star", -1e-3),
            ("q0", f64::INFINITY),
            ("h0_over_e", f64::NAN),
        ] {
            let mut v = ok;
            match field {
                "h0_over_e" => v.h0_over_e = bad,
                "h_rms" => v.h_rms = bad,
                "zeta" => v.zeta = bad,
                "hurst" => v.hurst = bad,
                "r_star" => v.r_star = bad,
                _ => v.q0 = bad,
            }
            let e = Params::new(v).unwrap_err();
            let msg = e.to_string();
            assert!(msg.starts_with(field), "{msg}");
            assert!(msg.contains("must be"), "{msg}");
        }
    }

    #[test]
    fn messages_show_numbers_compactly() {
        let mut v = Params::paper_fig2().values();
        v.h_rms = -2e-8;
        let e = Params::new(v).unwrap_err().to_string();
        assert_eq!(
            e,
            "h_rms = -2e-8 is out of range: it must be finite and > 0"
        );
        v.h_rms = 2e-8;
        v.zeta = 0.5;
        let e = Params::new(v).unwrap_err().to_string();
        assert_eq!(e, "zeta = 0.5 is out of range: it must be finite and >= 1");
    }

    #[test]
    fn accepts_domain_edges() {
        let mut v = Params::paper_fig2().values();
        v.zeta = 1.0;
        v.hurst = 1.0;
        v.r_star = 0.0;
        assert!(Params::new(v).is_ok());
    }
}
