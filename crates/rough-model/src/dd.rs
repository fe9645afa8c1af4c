//! A minimal double-double ("unevaluated sum of two f64") arithmetic.
//!
//! Only what the model needs: the slopes take exponentials of arguments up to
//! ~1400, so a relative error δ in ψ² becomes ~1400·δ in the result. Carrying
//! ψ² and the exponent arguments as `hi + lo` keeps that error at the level of
//! the few transcendental calls instead of every rounding on the way.

/// `hi + lo` with |lo| ≤ ulp(hi)/2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

impl Dd {
    pub const fn new(hi: f64, lo: f64) -> Dd {
        Dd { hi, lo }
    }

    pub fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The exact product of two doubles (error-free while it neither
    /// overflows nor underflows).
    #[inline(always)]
    pub fn prod(a: f64, b: f64) -> Dd {
        let hi = a * b;
        if !hi.is_finite() {
            return Dd::from_f64(hi);
        }
        Dd::norm(hi, prod_err(a, b, hi))
    }

    /// The exact sum of two doubles.
    #[inline(always)]
    pub fn sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        if !s.is_finite() {
            return Dd::from_f64(s);
        }
        let bb = s - a;
        let e = (a - (s - bb)) + (b - bb);
        Dd { hi: s, lo: e }
    }

    #[inline(always)]
    fn norm(hi: f64, lo: f64) -> Dd {
        let s = hi + lo;
        if !s.is_finite() {
            return Dd::from_f64(s);
        }
        Dd {
            hi: s,
            lo: lo - (s - hi),
        }
    }
}

impl std::ops::Mul for Dd {
    type Output = Dd;
    #[inline(always)]
    fn mul(self, o: Dd) -> Dd {
        let p = Dd::prod(self.hi, o.hi);
        if !p.hi.is_finite() || p.hi == 0.0 {
            return Dd::from_f64(p.hi);
        }
        Dd::norm(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }
}

impl std::ops::Add for Dd {
    type Output = Dd;
    #[inline(always)]
    fn add(self, o: Dd) -> Dd {
        let s = Dd::sum(self.hi, o.hi);
        if !s.hi.is_finite() {
            return s;
        }
        Dd::norm(s.hi, s.lo + self.lo + o.lo)
    }
}

impl std::ops::Div for Dd {
    type Output = Dd;
    #[inline(always)]
    fn div(self, o: Dd) -> Dd {
        let q = self.hi / o.hi;
        if !q.is_finite() || q == 0.0 {
            return Dd::from_f64(q);
        }
        // One correction step: r = self - q*o, q += r/o.
        let p = Dd::prod(q, o.hi);
        let r = (self.hi - p.hi - p.lo + self.lo - q * o.lo) / o.hi;
        Dd::norm(q, r)
    }
}

impl Dd {
    #[inline(always)]
    pub fn mul_f64(self, b: f64) -> Dd {
        self * Dd::from_f64(b)
    }

    #[inline(always)]
    pub fn recip(self) -> Dd {
        Dd::from_f64(1.0) / self
    }

    /// √self to about 2^-100 relative (one Newton step on the f64 root).
    #[inline(always)]
    pub fn sqrt(self) -> Dd {
        if self.hi <= 0.0 || !self.hi.is_finite() {
            return Dd::from_f64(self.hi.sqrt());
        }
        let s = self.hi.sqrt();
        let p = Dd::prod(s, s);
        let r = (self.hi - p.hi - p.lo + self.lo) / (2.0 * s);
        Dd::norm(s, r)
    }

    /// e^(-self) for self ≥ 0, to the accuracy of `f64::exp` however large
    /// `self.hi` is: exp(-hi-lo) = exp(-hi)·(1 - lo) since |lo| < 1e-13 here.
    #[inline(always)]
    pub fn exp_neg(self) -> f64 {
        let e = (-self.hi).exp();
        e - e * self.lo
    }

    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// erfc(z) where z² = `self` is known to double-double precision: the
    /// rounding of z, amplified ~2z² by erfc's Gaussian tail, is taken out by
    /// erfc(z) = erfc(z_f)·e^(−(z² − z_f²)) (erfcx is well-conditioned).
    /// 0 beyond z² = 760 (underflow) and for NaN.
    #[inline(always)]
    pub fn erfc_of_sqrt(self) -> f64 {
        if self.hi.is_nan() || self.hi >= 760.0 {
            return 0.0;
        }
        let zf = self.hi.sqrt();
        // |d| ≤ ulp(z²) < 2e-13 here, so e^(−d) = 1 − d to 1e-26.
        let d = (self + Dd::prod(-zf, zf)).to_f64();
        libm::erfc(zf) * (1.0 - d)
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Dd {
        Dd::from_f64(x)
    }
}

/// a·b − p exactly, for p = fl(a·b). A hardware instruction where the
/// caller is compiled with the `fma` feature (see `scene`), a libm call
/// otherwise.
#[inline(always)]
fn prod_err(a: f64, b: f64, p: f64) -> f64 {
    a.mul_add(b, -p)
}

/// π as a double-double.
pub const PI: Dd = Dd::new(std::f64::consts::PI, 1.2246467991473532e-16);

/// π²/2 as a double-double.
pub const PI2_HALF: Dd = Dd::new(4.934802200544679, 3.1326477543698557e-16);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_products_and_sums() {
        // (1 + 2^-30)² = 1 + 2^-29 + 2^-60 exactly.
        let a = 1.0 + 2f64.powi(-30);
        let p = Dd::prod(a, a);
        assert_eq!((p.hi, p.lo), (1.0 + 2f64.powi(-29), 2f64.powi(-60)));
        let s = Dd::sum(1.0, 1e-20);
        assert_eq!((s.hi, s.lo), (1.0, 1e-20));
    }

    #[test]
    fn division_and_sqrt_round_trip() {
        let a = Dd::new(2.0, 1e-17);
        let r = (a / Dd::from_f64(3.0)).mul_f64(3.0);
        assert!((r.hi - 2.0).abs() == 0.0 && (r.lo - 1e-17).abs() < 1e-31);
        let q = Dd::from_f64(2.0).sqrt();
        let back = q * q;
        assert_eq!(back.hi, 2.0);
        assert!(back.lo.abs() < 1e-30);
    }

    /// x = m·2^e exactly, m odd (0 as (0, 0)); x finite.
    fn parts(x: f64) -> (i128, i32) {
        if x == 0.0 {
            return (0, 0);
        }
        let bits = x.to_bits();
        let field = ((bits >> 52) & 0x7ff) as i32;
        let frac = bits & ((1 << 52) - 1);
        let (mut m, mut e) = if field == 0 {
            (frac as i128, -1074)
        } else {
            ((frac | 1 << 52) as i128, field - 1075)
        };
        let tz = m.trailing_zeros();
        m >>= tz;
        e += tz as i32;
        (if x < 0.0 { -m } else { m }, e)
    }

    /// The exact sum of `xs` as m·2^e, m odd (or 0); `None` if it does not
    /// fit in i128 (the strategies below keep it well inside).
    fn exact_sum(xs: &[f64]) -> Option<(i128, i32)> {
        let ps: Vec<(i128, i32)> = xs.iter().map(|&x| parts(x)).filter(|p| p.0 != 0).collect();
        let Some(lsb) = ps.iter().map(|p| p.1).min() else {
            return Some((0, 0));
        };
        let mut m: i128 = 0;
        for (pm, pe) in ps {
            let shift = u32::try_from(pe - lsb).ok().filter(|&s| s < 127)?;
            m = m.checked_add(pm.checked_mul(1i128 << shift)?)?;
        }
        if m == 0 {
            return Some((0, 0));
        }
        let tz = m.trailing_zeros();
        Some((m >> tz, lsb + tz as i32))
    }

    /// A finite double with exponent `e` (unbiased, normal range), fraction
    /// `frac` and sign `neg`.
    fn double(neg: bool, e: i32, frac: u64) -> f64 {
        f64::from_bits((neg as u64) << 63 | ((e + 1023) as u64) << 52 | frac)
    }

    /// Fractions with all 52 bits random, or only the top few (values with
    /// short mantissas, whose sums are often exact).
    fn fraction() -> impl Strategy<Value = u64> {
        prop_oneof![0u64..1 << 52, (0u64..1 << 8).prop_map(|f| f << 44)]
    }

    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        /// Dd::sum is error-free: a + b = hi + lo exactly, hi = fl(a + b).
        #[test]
        fn sum_is_exact(
            na: bool, nb: bool, ea in -900i32..900, d in -60i32..60,
            fa in fraction(), fb in fraction(),
        ) {
            let (a, b) = (double(na, ea, fa), double(nb, (ea + d).clamp(-1022, 1023), fb));
            let s = Dd::sum(a, b);
            prop_assert_eq!(s.hi, a + b);
            prop_assert_eq!(s.hi + s.lo, s.hi, "lo within half an ulp of hi");
            let want = exact_sum(&[a, b]).unwrap();
            prop_assert_eq!(exact_sum(&[s.hi, s.lo]).unwrap(), want, "{:e} + {:e} -> {:?}", a, b, s);
        }

        /// Dd::prod is error-free where the product neither overflows nor
        /// underflows: a·b = hi + lo exactly, hi = fl(a·b).
        #[test]
        fn product_is_exact(
            na: bool, nb: bool, ea in -450i32..450, eb in -450i32..450,
            fa in fraction(), fb in fraction(),
        ) {
            let (a, b) = (double(na, ea, fa), double(nb, eb, fb));
            let p = Dd::prod(a, b);
            prop_assert_eq!(p.hi, a * b);
            prop_assert_eq!(p.hi + p.lo, p.hi, "lo within half an ulp of hi");
            let ((ma, xa), (mb, xb)) = (parts(a), parts(b));
            let want = (ma * mb, xa + xb); // odd × odd is odd
            prop_assert_eq!(exact_sum(&[p.hi, p.lo]).unwrap(), want, "{:e} * {:e} -> {:?}", a, b, p);
        }
    }
}
