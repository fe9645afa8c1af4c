//! Lengths said back to the user with an SI prefix and the digits they
//! were typed with: `--pixel-size 50nm` is echoed as "50 nm", not
//! "0.00000005 m" (the explorer's messages and the readers' alike).

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

/// A length typed on the command line, echoed back with an SI prefix and
/// the digits it was typed with (the shortest decimal of the scaled value,
/// [`clean`]): `5e-8` (typed `50nm` or `0.05um`) is "50 nm", not
/// "0.00000005 m".
pub fn typed_length(m: f64) -> String {
    let (k, unit) = si_prefix(m);
    format!("{} {unit}", clean(m * k))
}

/// The SI prefix a length is shown in: its factor from metres and its unit.
pub fn si_prefix(m: f64) -> (f64, &'static str) {
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
    use super::{clean, typed_length};

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
    fn typed_lengths_keep_their_digits() {
        assert_eq!(typed_length(5e-8), "50 nm");
        assert_eq!(typed_length(0.05e-6), "50 nm");
        assert_eq!(typed_length(1.2345678e-7), "123.45678 nm");
        assert_eq!(typed_length(2.5e-6), "2.5 µm");
        assert_eq!(typed_length(7e-10), "700 pm");
        assert_eq!(typed_length(3.0), "3 m");
        // What a reader refuses is said as given.
        assert_eq!(typed_length(-2e-9), "-2 nm");
        assert_eq!(typed_length(f64::INFINITY), "inf m");
    }
}
