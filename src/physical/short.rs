//! Short numbers and lengths for claims, labels and the bench table.

use rough_surface::lengths::si_prefix as prefix;
pub use rough_surface::lengths::{clean, typed_length};

/// Four significant digits, trailing zeros dropped: plain between 1e-3 and
/// 1e4 (`322.3`, `0.02602`), else exponent form (`1.684e4`, `1e-308`).
pub fn short_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.digits$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        let t = format!("{v:.3e}");
        let (m, e) = t.split_once('e').unwrap_or((&t, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        format!("{m}e{e}")
    }
}

/// A length with an SI prefix, four significant digits: "19.82 nm".
pub fn short_length(m: f64) -> String {
    let (k, unit) = prefix(m);
    format!("{} {unit}", short_number(m * k))
}

#[cfg(test)]
mod tests {
    use super::{short_length, short_number};

    #[test]
    fn lengths_take_a_prefix() {
        assert_eq!(short_length(1.9816636488030044e-8), "19.82 nm");
        assert_eq!(short_length(1e-3), "1 mm");
        assert_eq!(short_length(6.283185307179586e-5), "62.83 µm");
        assert_eq!(short_length(7e-10), "700 pm");
        assert_eq!(short_length(0.0), "0 m");
    }

    #[test]
    fn four_digits_trimmed() {
        assert_eq!(short_number(0.55), "0.55");
        assert_eq!(short_number(12.090201005025126), "12.09");
        assert_eq!(short_number(1.998), "1.998");
        assert_eq!(short_number(1e-308), "1e-308");
        assert_eq!(short_number(1.7976931348623157e308), "1.798e308");
        assert_eq!(short_number(2.6023616895101482e-2), "0.02602");
        assert_eq!(short_number(0.0), "0");
        assert_eq!(short_number(16843.2), "1.684e4");
        assert_eq!(short_number(322.31), "322.3");
        assert_eq!(short_number(-5324.4), "-5324");
    }
}
