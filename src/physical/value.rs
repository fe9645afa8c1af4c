//! What the value prompt accepts: a number, for lengths with an optional
//! unit (`25nm`, `2 mm`, `1e-3`, `0.5 µm`); a bare number is in metres. The
//! model's own range check decides whether the value may be used.

use rough_model::{Axis, ParamError, Params};

/// The length units the prompt knows, with their power of ten in metres.
/// The unit goes into the decimal exponent before the one rounding to
/// binary, so 0.1 µm is the double nearest 1e-7, as if typed `0.1e-6`.
pub const LENGTH_UNITS: &[(&str, i32)] = &[
    ("m", 0),
    ("cm", -2),
    ("mm", -3),
    ("µm", -6),
    // U+03BC, the Greek letter, which some keyboards type for the micro sign.
    ("μm", -6),
    ("um", -6),
    ("nm", -9),
    ("pm", -12),
];

/// Whether values of `axis` are lengths (and take units).
pub fn is_length(axis: Axis) -> bool {
    matches!(axis, Axis::HRms | Axis::RStar)
}

/// The value typed for `axis`, in the model's units (metres for lengths).
pub fn parse_value(axis: Axis, text: &str) -> Result<f64, String> {
    let t = text.trim();
    // The unit is the trailing run of letters (and µ), after the number.
    let split = t
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_alphabetic())
        .last()
        .map_or(t.len(), |(i, _)| i);
    let (number, unit) = (t[..split].trim_end(), &t[split..]);
    if number.is_empty() {
        return Err(if t.is_empty() {
            "type a number".into()
        } else {
            format!("\"{t}\" is not a number")
        });
    }
    let v: f64 = number
        .parse()
        .map_err(|_| format!("\"{number}\" is not a number"))?;
    if !v.is_finite() {
        return Err(format!("\"{number}\" is not a finite number"));
    }
    if unit.is_empty() {
        return Ok(v);
    }
    if !is_length(axis) {
        return Err(format!("{} takes no unit (\"{unit}\")", axis.symbol()));
    }
    let Some((_, power)) = LENGTH_UNITS.iter().find(|(u, _)| *u == unit) else {
        return Err(format!(
            "unknown unit \"{unit}\": use m, cm, mm, µm (um), nm or pm"
        ));
    };
    let (mantissa, exp) = match number.find(['e', 'E']) {
        Some(i) => (&number[..i], number[i + 1..].parse::<i32>().unwrap_or(0)),
        None => (number, 0),
    };
    let scaled: f64 = format!("{mantissa}e{}", exp.saturating_add(*power))
        .parse()
        .map_err(|_| format!("\"{number}\" is not a number"))?;
    if scaled.is_finite() {
        Ok(scaled)
    } else {
        Err(format!("\"{t}\" is not a finite length"))
    }
}

/// `params` with `axis` set to the typed value, or why not: the value's
/// physical range ([`crate::physical::range`]), then the model's domain.
pub fn apply_value(params: &Params, axis: Axis, text: &str) -> Result<Params, String> {
    let v = parse_value(axis, text)?;
    apply_number(params, axis, v, text)
}

/// [`apply_value`] with the value parsed; `text` is how it was typed.
pub fn apply_number(params: &Params, axis: Axis, v: f64, text: &str) -> Result<Params, String> {
    crate::physical::check(axis, v, text)?;
    params.with(axis, v).map_err(|e| match e {
        // In the prompt's words: its symbol and the value as typed.
        ParamError::OutOfDomain { valid, .. } => format!(
            "{} = {} is out of range: it must be {valid}",
            axis.symbol(),
            text.trim()
        ),
        e => e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_units() {
        // Exactly the double nearest the decimal value.
        let ok = |axis, s: &str, want: f64| assert_eq!(parse_value(axis, s), Ok(want), "{s}");
        ok(Axis::HRms, "25nm", 25e-9);
        ok(Axis::HRms, " 25 nm ", 25e-9);
        ok(Axis::RStar, "2 mm", 2e-3);
        ok(Axis::RStar, "1e-3", 1e-3);
        ok(Axis::HRms, "0.5µm", 0.5e-6);
        ok(Axis::HRms, "0.5μm", 0.5e-6);
        ok(Axis::HRms, "0.5um", 0.5e-6);
        ok(Axis::HRms, "0.1 µm", 1e-7);
        ok(Axis::HRms, "19.816636488030044nm", 1.9816636488030044e-8);
        ok(Axis::HRms, "2e1nm", 2e-8);
        ok(Axis::HRms, "3 cm", 3e-2);
        ok(Axis::HRms, "700pm", 7e-10);
        ok(Axis::HRms, "1 m", 1.0);
        ok(Axis::Zeta, "300", 300.0);
        ok(Axis::Zeta, "1e4", 1e4);
        ok(Axis::Hurst, ".7", 0.7);
    }

    #[test]
    fn refusals_name_the_problem() {
        let err = |axis, s: &str| parse_value(axis, s).unwrap_err();
        assert_eq!(err(Axis::Zeta, ""), "type a number");
        assert_eq!(err(Axis::Zeta, "abc"), "\"abc\" is not a number");
        assert_eq!(err(Axis::Zeta, "inf"), "\"inf\" is not a number");
        assert_eq!(err(Axis::Zeta, "1e999"), "\"1e999\" is not a finite number");
        assert_eq!(err(Axis::Zeta, "1,5"), "\"1,5\" is not a number");
        assert_eq!(err(Axis::Zeta, "30 nm"), "ζ takes no unit (\"nm\")");
        assert_eq!(
            err(Axis::HRms, "3 ft"),
            "unknown unit \"ft\": use m, cm, mm, µm (um), nm or pm"
        );
    }

    #[test]
    fn the_model_checks_the_range() {
        let p = Params::paper_fig2();
        let q = apply_value(&p, Axis::HRms, "25nm").unwrap();
        assert_eq!(q.get(Axis::HRms), 25e-9);
        let e = apply_value(&p, Axis::Hurst, "1.5").unwrap_err();
        assert_eq!(e, "H = 1.5 is out of range: H takes 0.05 … 1");
        let e = apply_value(&p, Axis::HRms, " -2 nm").unwrap_err();
        assert_eq!(e, "h_rms = -2 nm is out of range: h_rms takes 1 pm … 1 mm");
        let e = apply_value(&p, Axis::H0OverE, "5").unwrap_err();
        assert_eq!(e, "H0/E = 5 is out of range: H0/E takes 1e-6 … 0.5");
    }
}
