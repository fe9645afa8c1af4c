//! Clinger's fast path for the plain decimals height files are made of
//! ("1.2574e+02", "-0.000341", "12"): a mantissa m < 2⁵³ and a power of ten
//! 10^e with |e| ≤ 22 are both exact doubles, so m·10^e (or m/10^−e) in one
//! IEEE operation is the correctly rounded value — the same double std's
//! parser returns (Clinger 1990; std's own first path). Anything else
//! (more digits, larger exponents, `nan`, a typo) goes to std's parser.
//! The saving is std's general machinery per number, which dominates
//! reading a large text map.

/// 10^0 … 10^22, all exact.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The largest mantissa of the fast path, 2⁵³.
const MAX_MANTISSA: u64 = 1 << 53;

/// `field` as the correctly rounded double where the fast path applies.
#[inline]
pub(crate) fn fast(field: &str) -> Option<f64> {
    let b = field.as_bytes();
    let mut i = 0;
    let neg = match b.first()? {
        b'-' => {
            i = 1;
            true
        }
        b'+' => {
            i = 1;
            false
        }
        _ => false,
    };
    let (mut m, mut digits, mut e) = (0u64, 0usize, 0i32);
    while i < b.len() && b[i].is_ascii_digit() {
        m = m * 10 + u64::from(b[i] - b'0');
        if m >= MAX_MANTISSA {
            return None;
        }
        digits += 1;
        i += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            m = m * 10 + u64::from(b[i] - b'0');
            if m >= MAX_MANTISSA {
                return None;
            }
            digits += 1;
            e -= 1;
            i += 1;
        }
    }
    if digits == 0 {
        return None;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        let eneg = match b.get(i) {
            Some(b'-') => {
                i += 1;
                true
            }
            Some(b'+') => {
                i += 1;
                false
            }
            _ => false,
        };
        let (mut x, start) = (0i32, i);
        while i < b.len() && b[i].is_ascii_digit() && i - start < 4 {
            x = x * 10 + i32::from(b[i] - b'0');
            i += 1;
        }
        if i == start {
            return None;
        }
        e += if eneg { -x } else { x };
    }
    if i != b.len() {
        return None;
    }
    let v = m as f64;
    let v = match e {
        0..=22 => v * POW10[e as usize],
        -22..=-1 => v / POW10[(-e) as usize],
        _ => return None,
    };
    Some(if neg { -v } else { v })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn same(s: &str) {
        if let Some(v) = fast(s) {
            let want: f64 = s.parse().unwrap();
            assert_eq!(v.to_bits(), want.to_bits(), "{s}");
        }
    }

    #[test]
    fn plain_decimals_as_std_reads_them() {
        for s in [
            "1.2574e+02",
            "-0.000341",
            "12",
            "0",
            "-0",
            "+3.5",
            "1.",
            ".5",
            "-.5e-3",
            "9007199254740991",
            "9007199254740993",
            "1e22",
            "1e23",
            "123456789012345e-22",
            "4.9406564584124654e-324",
            "1.7976931348623157e308",
            "0.1",
            "0.3",
            "2.2250738585072014e-308",
        ] {
            same(s);
        }
        assert_eq!(fast("1.2574e+02"), Some(125.74));
        for s in [
            "", "-", ".", "e5", "1e", "1e+", "nan", "inf", "1,5", "1.2.3", "1e5x", "0x10",
        ] {
            assert_eq!(fast(s), None, "{s}");
        }
        // Beyond the fast path: left to std.
        assert_eq!(fast("9007199254740993"), None);
        assert_eq!(fast("1e23"), None);
    }

    proptest! {
        #[test]
        fn printed_doubles_read_back(m in -1e12f64..1e12, k in -30i32..30, p in 0usize..17) {
            let v = m * 10f64.powi(k);
            for s in [format!("{v:.p$e}"), format!("{v:.p$}"), format!("{v}"), format!("{v:e}")] {
                same(&s);
            }
        }
    }
}
