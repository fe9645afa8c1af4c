//! Numbers as the CSV exports print them: the shortest digits that read
//! back to the same double, in exponent form outside 1e-5 ≤ |v| < 1e16
//! (`8.181099614926789e-166`, never 160 zeros), `inf` for infinity.
//!
//! The digits come from `zmij` (shortest round-trip digits, several times
//! faster than `{}`): a 200 000-point export prints 1.4 million numbers, and
//! their formatting is most of its time. zmij lays the digits out exactly as
//! `{}`/`{:e}` do here except for integers (`128.0` for `128`), whose `.0` is
//! dropped; its digits are the standard formatter's too, except where a
//! double lies exactly halfway between two shortest decimals, which zmij
//! rounds to even (as Python's repr does) and `{}` up.

/// Appends `v` to `out` in the CSV number form.
pub fn push(out: &mut String, v: f64) {
    if !v.is_finite() {
        out.push_str(if v.is_nan() {
            "NaN"
        } else if v > 0.0 {
            "inf"
        } else {
            "-inf"
        });
        return;
    }
    let mut buf = zmij::Buffer::new();
    let s = buf.format_finite(v);
    if v.abs() < 1e16 {
        out.push_str(s.strip_suffix(".0").unwrap_or(s));
    } else {
        // Exponent form with a sign: 1e+16 is written 1e16.
        out.push_str(&s.replacen("e+", "e", 1));
    }
}

/// `v` in the CSV number form.
pub fn format(v: f64) -> String {
    let mut s = String::new();
    push(&mut s, v);
    s
}

#[cfg(test)]
mod tests {
    use super::format;

    #[test]
    fn shortest_digits_plain_inside_exponent_outside() {
        for (v, want) in [
            (0.0, "0"),
            (1.0, "1"),
            (10.0, "10"),
            (0.1, "0.1"),
            (1e-5, "0.00001"),
            (9.999999999999999e-6, "9.999999999999999e-6"),
            (128.0, "128"),
            (9999999999999998.0, "9999999999999998"),
            (1e16, "1e16"),
            (8.181099614926788e-166, "8.181099614926788e-166"),
            (1.7976931348623157e308, "1.7976931348623157e308"),
            (5e-324, "5e-324"),
            (-2e-8, "-2e-8"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
        ] {
            assert_eq!(format(v), want, "{v:e}");
        }
    }

    /// The form `{}` gives inside 1e-5 ≤ |v| < 1e16 and `{:e}` outside: what
    /// the exports printed before the digits came from zmij.
    fn std_form(v: f64) -> String {
        let a = v.abs();
        if a == 0.0 || !a.is_finite() || (1e-5..1e16).contains(&a) {
            format!("{v}")
        } else {
            format!("{v:e}")
        }
    }

    /// `format(v)` is the standard formatter's text, or, where the double
    /// lies exactly halfway between two shortest decimals (…094.25), the
    /// other one (zmij rounds such ties to even, as Python's repr does; the
    /// standard library rounds them up): as short, as close, same layout.
    fn same_as_std(v: f64) -> Result<(), String> {
        let (ours, std) = (format(v), std_form(v));
        if ours == std {
            return Ok(());
        }
        let split = |t: &str| {
            let (m, e) = t.split_once('e').unwrap_or((t, ""));
            (m.to_string(), e.to_string())
        };
        let ((m1, e1), (m2, e2)) = (split(&ours), split(&std));
        let last_digit_apart = m1.len() == m2.len()
            && m1[..m1.len() - 1] == m2[..m2.len() - 1]
            && m1.as_bytes()[m1.len() - 1].abs_diff(m2.as_bytes()[m2.len() - 1]) == 1;
        if e1 == e2 && last_digit_apart && ours.parse::<f64>() == Ok(v) {
            Ok(())
        } else {
            Err(format!("{v:e}: {ours} vs {std}"))
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(20_000))]
        /// Any double, bit pattern by bit pattern.
        #[test]
        fn same_text_as_the_standard_formatter(bits in proptest::prelude::any::<u64>()) {
            let v = f64::from_bits(bits);
            proptest::prop_assume!(!v.is_nan());
            proptest::prop_assert_eq!(same_as_std(v), Ok(()));
        }

        /// Near the layout's edges (1e-5, 1e16) and on integers.
        #[test]
        fn same_text_near_the_edges(
            e in -7i32..18, m in 1.0f64..10.0, ulps in -3i64..3, neg: bool,
        ) {
            let p = 10f64.powi(e);
            for b in [(m * p).round(), p, m * p] {
                let v = f64::from_bits((b.to_bits() as i64 + ulps) as u64);
                let v = if neg { -v } else { v };
                proptest::prop_assert_eq!(same_as_std(v), Ok(()));
            }
        }
    }

    #[test]
    fn every_form_reads_back_exactly() {
        let mut x = 1.234567890123e-300f64;
        while x < 1e300 {
            assert_eq!(format(x).parse::<f64>().unwrap(), x);
            x *= 7.77;
        }
    }
}
