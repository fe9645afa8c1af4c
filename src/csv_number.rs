//! Numbers as the CSV exports print them: the shortest digits that read
//! back to the same double, in exponent form outside 1e-5 ≤ |v| < 1e16
//! (`8.181099614926789e-166`, never 160 zeros), `inf` for infinity.

use std::fmt::Write;

/// Appends `v` to `out` in the CSV number form.
pub fn push(out: &mut String, v: f64) {
    let a = v.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || !a.is_finite() || (1e-5..1e16).contains(&a) {
        write!(out, "{v}")
    } else {
        write!(out, "{v:e}")
    };
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

    #[test]
    fn every_form_reads_back_exactly() {
        let mut x = 1.234567890123e-300f64;
        while x < 1e300 {
            assert_eq!(format(x).parse::<f64>().unwrap(), x);
            x *= 7.77;
        }
    }
}
