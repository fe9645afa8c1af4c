//! Every way of computing the initial slopes, and its error over the
//! reference grid: the rows of `roughtui bench`. Errors follow
//! [`crate::rel_err`], taken as the max over the three slopes (elastic,
//! plastic, total).

use rough_model::Slopes;

use crate::{forms, rel_err, SlopeRow};

/// The load of the finite-difference row, p̄/H.
pub const FINITE_RHO: f64 = 1e-6;

/// Which reference columns a method is compared with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Against {
    Exact,
    Closed,
}

/// A way of computing (elastic, plastic, total) from ψ ≥ 0.
pub struct Method {
    pub name: &'static str,
    pub terms: String,
    pub against: Against,
    pub f: fn(f64) -> [f64; 3],
}

fn arr(s: Slopes) -> [f64; 3] {
    [s.elastic, s.plastic, s.total]
}

/// Every method uses the same limits at ψ = 0 and ψ = ∞, where 1/ψ is not a
/// number the formulas can take.
#[inline(always)]
fn guarded(psi: f64, f: impl FnOnce(f64) -> [f64; 3]) -> [f64; 3] {
    if psi == 0.0 {
        [f64::INFINITY, 0.0, f64::INFINITY]
    } else if psi == f64::INFINITY {
        [0.0, 1.0, 1.0]
    } else {
        f(psi)
    }
}

/// [`rough_model::exact`].
pub fn shipped_exact(psi: f64) -> [f64; 3] {
    arr(rough_model::exact(psi))
}

/// [`rough_model::closed_form`].
pub fn shipped_closed(psi: f64) -> [f64; 3] {
    arr(rough_model::closed_form(psi))
}

/// [`forms::image`] with `N` terms per sum.
pub fn image<const N: u32>(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(forms::image(psi, N)))
}

/// [`forms::fourier`] with `K` terms per sum.
pub fn fourier<const K: u32>(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(forms::fourier(psi, K)))
}

/// [`forms::closed_naive`].
pub fn closed_naive(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(forms::closed_naive(psi)))
}

/// [`crate::closed_previous::closed_previous`].
pub fn closed_previous(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| arr(crate::closed_previous::closed_previous(psi)))
}

/// Slopes as A(ρ)/ρ at ρ = [`FINITE_RHO`] from the shipped exact areas.
pub fn finite(psi: f64) -> [f64; 3] {
    guarded(psi, |psi| {
        match rough_model::areas::exact_areas(psi, FINITE_RHO) {
            Ok(a) => [
                a.elastic / FINITE_RHO,
                a.plastic / FINITE_RHO,
                a.total / FINITE_RHO,
            ],
            Err(_) => [f64::NAN; 3],
        }
    })
}

/// Every method, in the table's order.
pub fn methods() -> Vec<Method> {
    let series_row = |name, n: u32, f| Method {
        name,
        terms: format!("{n} per sum"),
        against: Against::Exact,
        f,
    };
    vec![
        Method {
            name: "exact (shipped)",
            terms: "5 per sum (Fourier x²<π, image x²≥π)".into(),
            against: Against::Exact,
            f: shipped_exact,
        },
        series_row("image 1", 1, image::<1>),
        series_row("image 2", 2, image::<2>),
        series_row("image 4", 4, image::<4>),
        series_row("image 8", 8, image::<8>),
        series_row("image 64", 64, image::<64>),
        series_row("fourier 8", 8, fourier::<8>),
        series_row("fourier 64", 64, fourier::<64>),
        Method {
            name: "closed, naive (paper's formula, f64)",
            terms: "closed".into(),
            against: Against::Closed,
            f: closed_naive,
        },
        Method {
            name: "closed, previous (double-double, libm erfc, 39-term series)",
            terms: "closed + series at small x".into(),
            against: Against::Closed,
            f: closed_previous,
        },
        Method {
            name: "closed (shipped)",
            terms: "1 exp, erfcx table, fits at small x".into(),
            against: Against::Closed,
            f: shipped_closed,
        },
        Method {
            name: "closed (shipped) model error vs exact",
            terms: "1 exp, erfcx table, fits at small x".into(),
            against: Against::Exact,
            f: shipped_closed,
        },
        Method {
            name: "finite load A(ρ)/ρ, ρ = 1e-6",
            terms: "shipped areas".into(),
            against: Against::Exact,
            f: finite,
        },
    ]
}

/// The error of one method over a grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStat {
    pub max: f64,
    pub worst_psi: f64,
}

/// Max relative error over `reference` and the three slopes; the first ψ
/// where it occurs.
pub fn max_error(m: &Method, reference: &[SlopeRow]) -> ErrorStat {
    let mut st = ErrorStat {
        max: 0.0,
        worst_psi: reference.first().map_or(f64::NAN, |r| r.psi),
    };
    for r in reference {
        let got = (m.f)(r.psi);
        let want = match m.against {
            Against::Exact => r.exact,
            Against::Closed => r.closed,
        };
        for i in 0..3 {
            let e = rel_err(got[i], want[i]);
            if e > st.max {
                st = ErrorStat {
                    max: e,
                    worst_psi: r.psi,
                };
            }
        }
    }
    st
}

/// The longest run of consecutive grid points (sorted by ψ, ψ > 0) where
/// `m` is within `tol`: its first and last ψ, and whether it is the whole
/// grid. `None` when there is no such point.
pub fn accurate_range(m: &Method, reference: &[SlopeRow], tol: f64) -> Option<(f64, f64, bool)> {
    let mut rows: Vec<&SlopeRow> = reference.iter().filter(|r| r.psi > 0.0).collect();
    rows.sort_by(|a, b| a.psi.total_cmp(&b.psi));
    let (mut best, mut start, mut len) = ((0, 0), 0, 0);
    for (i, r) in rows.iter().enumerate() {
        if max_error(m, std::slice::from_ref(*r)).max <= tol {
            if len == 0 {
                start = i;
            }
            len += 1;
            if len > best.1 {
                best = (start, len);
            }
        } else {
            len = 0;
        }
    }
    (best.1 > 0).then(|| {
        (
            rows[best.0].psi,
            rows[best.0 + best.1 - 1].psi,
            best.1 == rows.len(),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{slopes_reference, SLOPES_CSV};

    #[test]
    fn methods_agree_where_they_should() {
        let r = slopes_reference(SLOPES_CSV).unwrap();
        let ms = methods();
        let err = |name: &str| max_error(ms.iter().find(|m| m.name == name).unwrap(), &r).max;
        assert!(err("exact (shipped)") <= 1e-12);
        assert!(err("closed (shipped)") <= 1e-12);
        // The closed form is a different model: ~0.106 vs 0.0288 at ψ = 1.
        assert!(err("closed (shipped) model error vs exact") > 1.0);
        // Finite load tends to the slopes where ψ ≫ ρ.
        for psi in [1.0, 0.1] {
            let want = shipped_exact(psi);
            for (g, w) in finite(psi).iter().zip(want) {
                assert!(rel_err(*g, w) < 1e-6, "ψ = {psi}: {g} vs {w}");
            }
        }
        // Fourier and images agree with the exact method on their own sides.
        let f = fourier::<8>(3.0);
        let e = shipped_exact(3.0);
        let i8 = image::<8>(0.1);
        let e2 = shipped_exact(0.1);
        for k in 0..3 {
            assert!(rel_err(f[k], e[k]) < 1e-13);
            assert!(rel_err(i8[k], e2[k]) < 1e-13);
        }
        let m = ms.iter().find(|m| m.name == "exact (shipped)").unwrap();
        assert_eq!(accurate_range(m, &r, 1e-12).map(|x| x.2), Some(true));
    }
}
