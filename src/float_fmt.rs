//! Fast printing of f64 in exactly the form of Rust's `{}`: the shortest
//! digits that round-trip, in positional notation (no exponent), `inf`,
//! `-inf`, `NaN`. `ryu` finds the digits several times faster than the
//! standard library's Grisu/Dragon path; this module only lays them out.
//! Tested for byte equality with `format!("{}")`.

/// Appends `v` as Rust's `{}` would print it.
pub fn push_f64(out: &mut Vec<u8>, v: f64) {
    if !v.is_finite() {
        out.extend_from_slice(if v.is_nan() {
            b"NaN"
        } else if v > 0.0 {
            b"inf"
        } else {
            b"-inf"
        });
        return;
    }
    if v.is_sign_negative() {
        out.push(b'-');
    }
    let v = v.abs();
    if v == 0.0 {
        out.push(b'0');
        return;
    }
    if may_tie(v) {
        use std::io::Write;
        let _ = write!(out, "{v}");
        return;
    }
    let mut buf = ryu::Buffer::new();
    let s = buf.format_finite(v).as_bytes();
    // ryu prints d.ddde±x or a plain decimal; reduce both to digits·10^exp.
    let (mant, exp) = match s.iter().position(|&c| c == b'e') {
        Some(i) => (&s[..i], parse_exp(&s[i + 1..])),
        None => (s, 0),
    };
    let mut digits = [0u8; 24];
    let mut nd = 0usize;
    let mut point = None;
    for &c in mant {
        if c == b'.' {
            point = Some(nd);
        } else {
            digits[nd] = c;
            nd += 1;
        }
    }
    // Decimal exponent of the position after the first digit group.
    let mut int_len = point.unwrap_or(nd) as i32 + exp;
    // Drop leading zeros (e.g. "0.001") and trailing zeros ("100.0").
    let mut start = 0;
    while start < nd - 1 && digits[start] == b'0' {
        start += 1;
        int_len -= 1;
    }
    let mut end = nd;
    while end > start + 1 && digits[end - 1] == b'0' {
        end -= 1;
    }
    let d = &digits[start..end];
    let n = d.len() as i32;
    if int_len <= 0 {
        out.extend_from_slice(b"0.");
        out.resize(out.len() + (-int_len) as usize, b'0');
        out.extend_from_slice(d);
    } else if int_len >= n {
        out.extend_from_slice(d);
        out.resize(out.len() + (int_len - n) as usize, b'0');
    } else {
        out.extend_from_slice(&d[..int_len as usize]);
        out.push(b'.');
        out.extend_from_slice(&d[int_len as usize..]);
    }
}

/// Whether two shortest candidates could lie equally close to `v` (ryu then
/// rounds half to even, the standard library half up) or one could sit on
/// the round-trip boundary. Both need a decimal of at most 18 digits equal
/// to v or to v ± ulp/2, which only exists for v ≥ 2^52 or for v = m·2^−k
/// (m odd) with m·5^k < 10^18.
fn may_tie(v: f64) -> bool {
    if v >= 4_503_599_627_370_496.0 {
        return true;
    }
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, exp) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), biased - 1075)
    };
    let tz = mant.trailing_zeros() as i32;
    let (m, e) = (mant >> tz, exp + tz);
    if e >= 0 {
        return false;
    }
    let k = -e;
    k <= 26 && u128::from(m) * 5u128.pow(k as u32) < 1_000_000_000_000_000_000
}

fn parse_exp(s: &[u8]) -> i32 {
    let (neg, s) = match s.first() {
        Some(b'-') => (true, &s[1..]),
        _ => (false, s),
    };
    let e = s
        .iter()
        .fold(0i32, |acc, &c| acc * 10 + i32::from(c - b'0'));
    if neg {
        -e
    } else {
        e
    }
}

#[cfg(test)]
mod tests {
    use super::push_f64;
    use proptest::prelude::*;

    fn show(v: f64) -> String {
        let mut out = Vec::new();
        push_f64(&mut out, v);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn matches_std_on_edges() {
        for v in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            100.0,
            1e21,
            1e22,
            1e-7,
            123.456,
            5e-324,
            f64::MAX,
            f64::MIN_POSITIVE,
            2e-8,
            1e16,
            1.5e15,
            9007199254740993.0,
            0.3,
            1e300,
            1e-300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            assert_eq!(show(v), format!("{v}"), "{v:e}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]
        #[test]
        fn matches_std_everywhere(bits in any::<u64>()) {
            let v = f64::from_bits(bits);
            prop_assert_eq!(show(v), format!("{v}"));
        }

        #[test]
        fn matches_std_for_moderate_values(m in -1e6f64..1e6, e in -30i32..30) {
            let v = m * 10f64.powi(e);
            prop_assert_eq!(show(v), format!("{v}"));
        }
    }
}
