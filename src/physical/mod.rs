//! The ground floor: physical values as people type and read them, used by
//! every layer above (the scene, snapshots, pictures, export, the
//! simulation, the terminal) and using none of them.
//!
//! - [`value`]: what the value prompt and `--set` accept for a parameter
//!   (lengths with units);
//! - [`print`]: numbers, lengths, shares and parameters for the screen;
//! - [`short_number`]: four significant digits for claims, labels and tables;
//! - [`csv_number`]: numbers for CSV, every digit;
//! - [`ascii`]: text in ASCII, every symbol by its name (Psi_P, zeta);
//! - this module: each parameter's physical range, and the material values
//!   (pressures, q0, L) in physical units.
//!
//! The values a physicist would accept: each parameter's physical range,
//! narrower than the model's mathematical domain (which takes H0/E = 5 or
//! H = 1e-300 and computes something meaningless), and the material values
//! `--set` and the value prompt take in physical units.
//!
//! The ranges bound what is typed (the value prompt, `--set`, `--sweep`);
//! snapshots keep the model's domain, so that files written before still
//! load. Every refusal names the parameter as the screen shows it and
//! states the range, in at most 80 characters.

pub mod ascii;
pub mod csv_number;
pub mod print;
mod short;
pub mod value;

use rough_model::Axis;

pub use short::{clean, short_length, short_number, typed_length};
use value::parse_value;

/// A closed range of accepted values with its words.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub lo: f64,
    pub hi: f64,
    /// The range as a refusal states it: "0.05 … 1".
    pub text: &'static str,
}

impl Range {
    pub fn accepts(self, v: f64) -> bool {
        v.is_finite() && v >= self.lo && v <= self.hi
    }
}

/// Each swept parameter's physical range:
/// - H0/E 1e-6 … 0.5: a hardness above half the modulus is no metal,
///   ceramic or polymer (diamond: H/E ≈ 0.1); below 1e-6 nothing is hard;
/// - h_rms 1 pm … 1 mm: from atomic flatness to the coarsest machined
///   surfaces;
/// - ζ 1 … 1e8: eight decades of magnification (62.8 µm down to below
///   an atom at the paper's q0);
/// - H 0.05 … 1: measured Hurst exponents lie in 0.3 … 1, and the
///   power law's moments lose meaning as H → 0;
/// - R* 0 … 1 m: 0 is no size effect, the paper's is 1 mm.
pub fn range(axis: Axis) -> Range {
    match axis {
        Axis::H0OverE => Range {
            lo: 1e-6,
            hi: 0.5,
            text: "1e-6 … 0.5",
        },
        Axis::HRms => Range {
            lo: 1e-12,
            hi: 1e-3,
            text: "1 pm … 1 mm",
        },
        Axis::Zeta => Range {
            lo: 1.0,
            hi: 1e8,
            text: "1 … 1e8",
        },
        Axis::Hurst => Range {
            lo: 0.05,
            hi: 1.0,
            text: "0.05 … 1",
        },
        Axis::RStar => Range {
            lo: 0.0,
            hi: 1.0,
            text: "0 … 1 m",
        },
    }
}

/// q0, 1/m: the longest wavelength L = 2π/q0 from 10 nm to 10 m.
pub const Q0: Range = Range {
    lo: std::f64::consts::TAU / 10.0,
    hi: std::f64::consts::TAU / 1e-8,
    text: "0.63 … 6.3e8 1/m (L = 10 nm … 10 m)",
};

/// The composite modulus E, Pa: soft rubber to diamond.
pub const MODULUS: Range = Range {
    lo: 1e5,
    hi: 2e12,
    text: "0.1 MPa … 2000 GPa",
};

/// The macroscopic hardness H0, Pa.
pub const HARDNESS: Range = Range {
    lo: 1e5,
    hi: 2e11,
    text: "0.1 MPa … 200 GPa",
};

/// Poisson's ratio ν (thermodynamic bounds: −1 … 0.5).
pub const POISSON: Range = Range {
    lo: -1.0,
    hi: 0.5,
    text: "-1 … 0.5",
};

/// `value` (typed as `typed`) against `axis`'s range; the refusal names
/// the parameter as the screen does.
pub fn check(axis: Axis, value: f64, typed: &str) -> Result<f64, String> {
    check_range(axis.symbol(), range(axis), value, typed)
}

/// `value` (typed as `typed`) against `r`; the refusal names `name`.
pub fn check_range(name: &str, r: Range, value: f64, typed: &str) -> Result<f64, String> {
    if r.accepts(value) {
        Ok(value)
    } else {
        Err(format!(
            "{name} = {} is out of range: {name} takes {}",
            typed.trim(),
            r.text
        ))
    }
}

/// The pressure units `--set e=…` and `--set h0=…` take, with their power
/// of ten in pascals; a bare number is in pascals.
pub const PRESSURE_UNITS: &[(&str, i32)] = &[("Pa", 0), ("kPa", 3), ("MPa", 6), ("GPa", 9)];

/// A pressure typed with an optional unit (`210GPa`, `2 GPa`, `5e8`).
pub fn parse_pressure(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let split = t
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_alphabetic())
        .last()
        .map_or(t.len(), |(i, _)| i);
    let (number, unit) = (t[..split].trim_end(), &t[split..]);
    let power = if unit.is_empty() {
        0
    } else {
        PRESSURE_UNITS
            .iter()
            .find(|(u, _)| *u == unit)
            .map(|(_, p)| *p)
            .ok_or_else(|| format!("unknown unit \"{unit}\": use Pa, kPa, MPa or GPa"))?
    };
    let v: f64 = number
        .parse()
        .map_err(|_| format!("\"{number}\" is not a number"))?;
    let v = v * 10f64.powi(power);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("\"{t}\" is not a finite pressure"))
    }
}

/// q0 typed as a wavevector in 1/m (`1e5`, `1e5 1/m`, `1e5/m`), within
/// [`Q0`].
pub fn parse_q0(text: &str) -> Result<f64, String> {
    let v = parse_q0_number(text)?;
    check_range("q0", Q0, v, text)
}

/// q0's number, not yet checked against its range.
pub fn parse_q0_number(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let number = t
        .strip_suffix("1/m")
        .or_else(|| t.strip_suffix("/m"))
        .unwrap_or(t)
        .trim();
    let v: f64 = number
        .parse()
        .map_err(|_| format!("\"{t}\" is not a wavevector (a number in 1/m)"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("\"{t}\" is not a finite wavevector"))
    }
}

/// L = 2π/q0 typed as a length (`62.8um`); the q0 it gives.
pub fn parse_l(text: &str) -> Result<f64, String> {
    let l = parse_value(Axis::HRms, text)?;
    let q0 = std::f64::consts::TAU / l;
    if l > 0.0 && Q0.accepts(q0) {
        Ok(q0)
    } else {
        Err(format!(
            "L = {} is out of range: L takes 10 nm … 10 m",
            text.trim()
        ))
    }
}

/// H0/E from material values: H0 over the composite modulus, which is E
/// itself without ν (E given as the composite modulus), or E* = E/(1 − ν²)
/// with it (one elastic body against a rigid flat, the reduction the
/// paper's half-space contact uses).
pub fn h0_over_e(h0: f64, e: f64, nu: Option<f64>) -> f64 {
    match nu {
        Some(nu) => h0 * (1.0 - nu * nu) / e,
        None => h0 / e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_state_the_range_in_80_columns() {
        for (axis, v, typed, want) in [
            (
                Axis::H0OverE,
                2.0,
                "2",
                "H0/E = 2 is out of range: H0/E takes 1e-6 … 0.5",
            ),
            (
                Axis::HRms,
                1.0,
                "1 m",
                "h_rms = 1 m is out of range: h_rms takes 1 pm … 1 mm",
            ),
            (
                Axis::Hurst,
                1e-300,
                "1e-300",
                "H = 1e-300 is out of range: H takes 0.05 … 1",
            ),
            (
                Axis::RStar,
                2.0,
                "2m",
                "R* = 2m is out of range: R* takes 0 … 1 m",
            ),
            (
                Axis::Zeta,
                1e9,
                "1e9",
                "ζ = 1e9 is out of range: ζ takes 1 … 1e8",
            ),
        ] {
            let e = check(axis, v, typed).unwrap_err();
            assert_eq!(e, want);
            assert!(e.chars().count() <= 80, "{e}");
        }
        assert_eq!(check(Axis::H0OverE, 0.5, "0.5"), Ok(0.5));
        assert_eq!(check(Axis::RStar, 0.0, "0"), Ok(0.0));
        assert!(check(Axis::Hurst, f64::NAN, "nan").is_err());
    }

    #[test]
    fn material_values_in_physical_units() {
        assert_eq!(parse_pressure("210GPa"), Ok(210e9));
        assert_eq!(parse_pressure(" 2 GPa "), Ok(2e9));
        assert_eq!(parse_pressure("500MPa"), Ok(5e8));
        assert_eq!(parse_pressure("5e8"), Ok(5e8));
        assert_eq!(
            parse_pressure("2 psi").unwrap_err(),
            "unknown unit \"psi\": use Pa, kPa, MPa or GPa"
        );
        assert_eq!(h0_over_e(2e9, 210e9, None), 2e9 / 210e9);
        assert_eq!(h0_over_e(2e9, 210e9, Some(0.3)), 2e9 * 0.91 / 210e9);
    }

    #[test]
    fn q0_as_a_wavevector_or_a_wavelength() {
        assert_eq!(parse_q0("1e5"), Ok(1e5));
        assert_eq!(parse_q0("1e5 1/m"), Ok(1e5));
        assert_eq!(parse_q0("2e4/m"), Ok(2e4));
        let q = parse_l("62.83185307179586um").unwrap();
        assert!((q / 1e5 - 1.0).abs() < 1e-15, "{q}");
        let e = parse_q0("1e12").unwrap_err();
        assert_eq!(
            e,
            "q0 = 1e12 is out of range: q0 takes 0.63 … 6.3e8 1/m (L = 10 nm … 10 m)"
        );
        assert!(e.chars().count() <= 80);
        assert_eq!(
            parse_l("100 m").unwrap_err(),
            "L = 100 m is out of range: L takes 10 nm … 10 m"
        );
    }
}
