//! Short numbers and lengths for claims, labels and the bench table.

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

/// `v` as the shortest decimal of at most 9 significant digits within
/// 1e-14 of it (relative: a few roundings), else `v` itself: a ratio that
/// is whole in exact arithmetic (a line's largest ζ = n/2,
/// 96.00000000000001 after the rounding of q_max/q0) is 96, and an
/// irrational one (a map's √2 · 48 = 67.88225099390857) stays (the chance
/// that it lies that close to a short decimal is some 1e-5).
pub fn clean(v: f64) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    (1..=9)
        .filter_map(|digits| format!("{v:.*e}", digits - 1).parse::<f64>().ok())
        .find(|r| ((r - v) / v).abs() <= 1e-14)
        .unwrap_or(v)
}

/// A length with an SI prefix, four significant digits: "19.82 nm".
pub fn short_length(m: f64) -> String {
    let (k, unit) = prefix(m);
    format!("{} {unit}", short_number(m * k))
}

/// A length typed on the command line, echoed back with an SI prefix and
/// the digits it was typed with (the shortest decimal of the scaled value,
/// [`clean`]): `5e-8` (typed `50nm` or `0.05um`) is "50 nm", not
/// "0.00000005 m".
pub fn typed_length(m: f64) -> String {
    let (k, unit) = prefix(m);
    format!("{} {unit}", clean(m * k))
}

/// The SI prefix a length is shown in: its factor from metres and its unit.
fn prefix(m: f64) -> (f64, &'static str) {
    let a = m.abs();
    if a == 0.0 || !a.is_finite() {
        (1.0, "m")
    } else if a < 1e-9 {
        (1e12, "pm")
    } else if a < 1e-6 {
        (1e9, "nm")
    } else if a < 1e-3 {
        (1e6, "µm")
    } else if a < 1.0 {
        (1e3, "mm")
    } else {
        (1.0, "m")
    }
}

#[cfg(test)]
mod tests {
    use super::{clean, short_length, short_number, typed_length};

    #[test]
    fn clean_numbers_are_the_nearest_short_ones() {
        assert_eq!(clean(96.00000000000001), 96.0);
        assert_eq!(clean(95.99999999999999), 96.0);
        assert_eq!(clean(512.0000000000001), 512.0);
        // A map's largest ζ, √2 · 96, is no short decimal: kept.
        assert_eq!(clean(135.76450198781714), 135.76450198781714);
        assert_eq!(clean(67.88225099390857), 67.88225099390857);
        assert_eq!(clean(0.1 + 0.2), 0.3);
        assert_eq!(clean(0.0), 0.0);
    }

    #[test]
    fn lengths_take_a_prefix() {
        assert_eq!(short_length(1.9816636488030044e-8), "19.82 nm");
        assert_eq!(short_length(1e-3), "1 mm");
        assert_eq!(short_length(6.283185307179586e-5), "62.83 µm");
        assert_eq!(short_length(7e-10), "700 pm");
        assert_eq!(short_length(0.0), "0 m");
    }

    #[test]
    fn typed_lengths_keep_their_digits() {
        assert_eq!(typed_length(5e-8), "50 nm");
        assert_eq!(typed_length(0.05e-6), "50 nm");
        assert_eq!(typed_length(1.2345678e-7), "123.45678 nm");
        assert_eq!(typed_length(2.5e-6), "2.5 µm");
        assert_eq!(typed_length(7e-10), "700 pm");
        assert_eq!(typed_length(3.0), "3 m");
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
