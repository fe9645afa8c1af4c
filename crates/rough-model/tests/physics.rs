//! The physics as properties: sums, limits, monotonicity, the two series forms
//! agreeing, and no NaN anywhere in the valid domain.

use proptest::prelude::*;
use rough_model::slopes::SQRT_2_OVER_PI;
use rough_model::{
    closed_form, exact, persson_elastic, Axis, Curves, Model, Moments, ParamValues, Params, Scene,
    SceneSpec, Slopes, Surface, Sweep,
};
use rough_study::{forms, rel_err};

fn no_nan(s: &Slopes) -> bool {
    !(s.elastic.is_nan() || s.plastic.is_nan() || s.total.is_nan())
        && s.elastic >= 0.0
        && s.plastic >= 0.0
        && s.total >= 0.0
}

/// Valid parameters from the decimal exponents of H0/E, h_rms and ζ and
/// the values of H, R* and q0.
fn params(h0: f64, h: f64, z: f64, hurst: f64, r_star: f64, q0: f64) -> Params {
    Params::new(ParamValues {
        h0_over_e: 10f64.powf(h0),
        h_rms: 10f64.powf(h),
        zeta: 10f64.powf(z),
        hurst,
        r_star,
        q0,
    })
    .unwrap()
}

fn moments_of(asymptotic: bool) -> Moments {
    if asymptotic {
        Moments::Asymptotic
    } else {
        Moments::Truncated
    }
}

/// 2000 cases unless PROPTEST_CASES says otherwise.
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000)
}

/// ψ log-uniform over 1e-10 … 1e10.
fn psi() -> impl Strategy<Value = f64> {
    (-10.0f64..10.0).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn elastic_plus_plastic_is_total(p in psi()) {
        for (m, s) in [("exact", exact(p)), ("closed", closed_form(p))] {
            prop_assert!(
                rel_err(s.elastic + s.plastic, s.total) < 4e-16 * 4.0,
                "{m} at psi={p:e}: {s:?}"
            );
        }
    }

    #[test]
    fn exact_slopes_are_monotone_in_psi(a in psi(), f in 1.0f64..1.5) {
        let (s1, s2) = (exact(a), exact(a * f));
        let slack = 1.0 + 1e-14;
        prop_assert!(s2.elastic <= s1.elastic * slack, "elastic at {a:e}: {s1:?} {s2:?}");
        prop_assert!(s2.plastic >= s1.plastic * (2.0 - slack) - 1e-300, "plastic at {a:e}: {s1:?} {s2:?}");
        prop_assert!(s2.total <= s1.total * slack, "total at {a:e}: {s1:?} {s2:?}");
    }

    #[test]
    fn elastic_never_exceeds_persson(p in psi()) {
        // The plastic barrier only removes contact from Persson's elastic solution.
        prop_assert!(exact(p).elastic <= persson_elastic(p) * (1.0 + 1e-14));
        prop_assert!(exact(p).total >= 1.0 - 1e-15);
    }

    #[test]
    fn image_and_fourier_forms_agree_where_both_converge(u in 0.6f64..6.0) {
        // x² = u from well below to well above π: 64 terms converge on both sides.
        let p = 1.0 / u.sqrt();
        let (i, f, e) = (forms::image(p, 64), forms::fourier(p, 64), exact(p));
        // The image elastic sum alternates: it cancels below x² ≈ 1.5.
        let el = if u >= 1.5 { Some((i.elastic, f.elastic, "elastic")) } else { None };
        for (a, b, what) in [(i.total, f.total, "total"), (i.plastic, f.plastic, "plastic")]
            .into_iter()
            .chain(el)
        {
            prop_assert!(rel_err(a, b) < 1e-13, "{what} at x²={u}: image {a:e} fourier {b:e}");
        }
        prop_assert!(rel_err(e.elastic, f.elastic) < 1e-13);
        prop_assert!(rel_err(e.plastic, i.plastic) < 1e-13);
    }

    #[test]
    fn any_nonnegative_psi_gives_no_nan(bits in any::<u64>()) {
        let p = f64::from_bits(bits).abs();
        prop_assume!(!p.is_nan());
        prop_assert!(no_nan(&exact(p)), "exact at {p:e}: {:?}", exact(p));
        prop_assert!(no_nan(&closed_form(p)), "closed at {p:e}: {:?}", closed_form(p));
    }

    #[test]
    fn any_valid_parameters_give_no_nan(
        h0 in -300.0f64..300.0,
        h in -300.0f64..300.0,
        z in 0.0f64..300.0,
        hu in 1e-6f64..=1.0,
        rs in prop_oneof![Just(0.0), (-300.0f64..300.0).prop_map(|e| 10f64.powf(e))],
        q0 in -300.0f64..300.0,
        asymptotic in any::<bool>(),
    ) {
        let moments = moments_of(asymptotic);
        let p = params(h0, h, z, hu, rs, 10f64.powf(q0));
        let s = Surface::of(&p, moments);
        let sp = s.spectrum;
        let ix = s.indices;
        for (name, v) in [
            ("z", sp.z), ("m0", sp.m0), ("m2", sp.m2), ("m4", sp.m4), ("r_s", sp.r_s),
            ("lambda1", sp.lambda1), ("h_rms_actual", sp.h_rms_actual),
            ("rms_slope", sp.rms_slope), ("rms_curvature", sp.rms_curvature),
            ("psi_gw", ix.psi_gw), ("psi_p", ix.psi_p), ("psi_star", ix.psi_star),
            ("hardness_ratio", ix.hardness_ratio),
        ] {
            prop_assert!(!v.is_nan() && v >= 0.0, "{name} = {v} at {p:?}");
        }
        prop_assert!(ix.hardness_ratio >= 1.0);
        prop_assert!(ix.psi_star <= ix.psi_p * (1.0 + 1e-15));
        if let Some(a) = ix.psi_star_asymptotic {
            prop_assert!(!a.is_nan());
        }
        for se in [false, true] {
            for m in [Model::Exact, Model::ClosedForm] {
                let sl = rough_model::slopes(m, ix.psi_in_use(se));
                prop_assert!(no_nan(&sl), "{m:?} se={se} at {p:?}: {sl:?}");
            }
        }
    }
}

#[test]
fn limits_of_small_and_large_psi() {
    for p in [1e-300, 1e-30, 1e-8, 1e-3] {
        for s in [exact(p), closed_form(p)] {
            assert!(
                rel_err(s.elastic * p, SQRT_2_OVER_PI) < 1e-15,
                "{p:e}: {s:?}"
            );
            assert_eq!(s.plastic, 0.0, "{p:e}");
        }
    }
    assert!(rel_err(exact(1e3).plastic, 1.0) < 1e-15 && exact(1e3).elastic == 0.0);
    for p in [1e8, 1e300] {
        for s in [exact(p), closed_form(p)] {
            assert!(
                rel_err(s.plastic, 1.0) < 1e-15 && rel_err(s.total, 1.0) < 1e-15,
                "{p:e}: {s:?}"
            );
            assert!(s.elastic < 1e-8, "{p:e}: {s:?}");
        }
    }
    let zero = exact(0.0);
    assert_eq!(
        (zero.elastic, zero.plastic, zero.total),
        (f64::INFINITY, 0.0, f64::INFINITY)
    );
    let inf = closed_form(f64::INFINITY);
    assert_eq!((inf.elastic, inf.plastic, inf.total), (0.0, 1.0, 1.0));
}

#[test]
fn regime_follows_plastic_share() {
    use rough_model::Regime;
    assert_eq!(exact(0.2).regime(), Regime::Elastic);
    assert_eq!(exact(0.6).regime(), Regime::ElastoPlastic);
    assert_eq!(exact(2.0).regime(), Regime::Plastic);
    assert_eq!(exact(0.0).regime(), Regime::Elastic);
}

fn scene(preset: &str, size_effect: bool, h_rms: f64, h0: f64, to: f64) -> Scene {
    let mut v = Params::paper_fig2().values();
    v.h_rms = h_rms;
    v.h0_over_e = h0;
    let _ = preset;
    Scene::compute(&SceneSpec {
        base: Params::new(v).unwrap(),
        sweep: Sweep::new(Axis::Zeta, 1.0, to).unwrap(),
        size_effect,
        model: Model::Exact,
        moments: Moments::Truncated,
        roughness: rough_model::Roughness::SelfAffine,
        curves: Curves::ALL,
        points: 400,
    })
    .unwrap()
}

#[test]
fn figures_show_the_papers_claims() {
    // fig2: the plastic share grows with ζ past one half.
    let s = scene("fig2", false, 2e-8, 1e-2, 1e4);
    let share = |s: &Scene, i: usize| s.plastic[i] / s.total[i];
    let n = s.x.len();
    assert!(share(&s, n - 1) > 0.5 && share(&s, 1) < 0.01);
    // fig3: with the size effect no plastic area anywhere.
    let s = scene("fig3", true, 2e-8, 1e-2, 1e4);
    assert!((1..n).all(|i| share(&s, i) < 1e-9));
    // fig4: plastic at moderate ζ, elastic again at large ζ.
    let s = scene("fig4", true, 6e-7, 1e-3, 1e6);
    let max = (1..n).map(|i| share(&s, i)).fold(0.0, f64::max);
    assert!(max > 0.9 && share(&s, n - 1) < 0.1);
}

fn axis() -> impl Strategy<Value = (Axis, f64, f64)> {
    prop_oneof![
        (-6.0f64..0.0, 0.1f64..4.0).prop_map(|(a, d)| (
            Axis::H0OverE,
            10f64.powf(a),
            10f64.powf(a + d)
        )),
        (-10.0f64..-4.0, 0.1f64..4.0).prop_map(|(a, d)| (
            Axis::HRms,
            10f64.powf(a),
            10f64.powf(a + d)
        )),
        (0.0f64..6.0, 0.1f64..6.0).prop_map(|(a, d)| (
            Axis::Zeta,
            10f64.powf(a),
            10f64.powf(a + d)
        )),
        (Just(0.0), Just(0.0)).prop_map(|_| (Axis::Zeta, 1.0, 1e10)),
        (0.01f64..0.5, 0.05f64..0.5).prop_map(|(a, d)| (Axis::Hurst, a, (a + d).min(1.0))),
        (-8.0f64..-1.0, 0.1f64..4.0).prop_map(|(a, d)| (
            Axis::RStar,
            10f64.powf(a),
            10f64.powf(a + d)
        )),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() / 10))]

    /// A scene's precomputed sweep gives the values of the pointwise API
    /// (which the reference tests check) at every point.
    #[test]
    fn scenes_agree_with_pointwise_values(
        (ax, from, to) in axis(),
        h0 in -5.0f64..-1.0,
        h in -9.0f64..-6.0,
        z in 0.0f64..5.0,
        hu in 0.05f64..=1.0,
        rs in -6.0f64..-2.0,
        se in any::<bool>(),
        closed in any::<bool>(),
        asymptotic in any::<bool>(),
    ) {
        let moments = moments_of(asymptotic);
        let base = params(h0, h, z, hu, 10f64.powf(rs), 1e5);
        let model = if closed { Model::ClosedForm } else { Model::Exact };
        let spec = SceneSpec {
            base,
            sweep: Sweep::new(ax, from, to).unwrap(),
            size_effect: se,
            model,
            moments,
            roughness: rough_model::Roughness::SelfAffine,
            curves: Curves::ALL,
            points: 37,
        };
        let s = Scene::compute(&spec).unwrap();
        for i in 0..spec.points {
            let p = base.with(ax, s.x[i]).unwrap();
            let (psi, hr) = rough_model::psi_in_use(&p, se, moments);
            let sl = rough_model::slopes(model, psi);
            let close = |a: f64, b: f64| rel_err(a, b) < 1e-13;
            prop_assert!(close(s.psi[i], psi.to_f64()), "psi at {p:?}: {} vs {:?}", s.psi[i], psi);
            prop_assert!(close(s.hardness_ratio[i], hr), "hr at {p:?}");
            prop_assert!(close(s.elastic[i], sl.elastic), "el at {p:?}: {} vs {}", s.elastic[i], sl.elastic);
            prop_assert!(close(s.plastic[i], sl.plastic), "pl at {p:?}: {} vs {}", s.plastic[i], sl.plastic);
            prop_assert!(close(s.total[i], sl.total), "tot at {p:?}");
            prop_assert!(close(s.persson_elastic[i], persson_elastic(psi)), "persson at {p:?}");
        }
    }
}

/// The asymptotic m2 ∝ ζ^(2−2H)/(2−2H) is infinite at H = 1: a documented
/// infinity (fully plastic slopes), never NaN, and refused by `Moments::check`.
#[test]
fn asymptotic_moments_at_hurst_one() {
    let p = Params::new(ParamValues {
        h0_over_e: 1e-2,
        h_rms: 2e-8,
        zeta: 128.0,
        hurst: 1.0,
        r_star: 1e-3,
        q0: 1e5,
    })
    .unwrap();
    let s = Surface::of(&p, Moments::Asymptotic);
    assert_eq!(s.spectrum.m2, f64::INFINITY);
    assert!(s.spectrum.m4.is_finite() && s.spectrum.m4 > 0.0);
    assert_eq!(s.indices.psi_p, f64::INFINITY);
    assert_eq!(s.indices.psi_star, f64::INFINITY);
    for se in [false, true] {
        let sl = rough_model::slopes(Model::Exact, s.indices.psi_in_use(se));
        assert_eq!((sl.elastic, sl.plastic, sl.total), (0.0, 1.0, 1.0));
    }
    let msg = Moments::Asymptotic.check(&p).unwrap_err().to_string();
    assert!(
        msg.contains("hurst = 1") && msg.contains("moments: Truncated"),
        "{msg}"
    );
    assert!(Moments::Truncated.check(&p).is_ok());
    // A Hurst sweep ending at 1 ends on the same limit.
    let scene = Scene::compute(&SceneSpec {
        base: p,
        sweep: Sweep::new(Axis::Hurst, 0.5, 1.0).unwrap(),
        size_effect: false,
        model: Model::ClosedForm,
        moments: Moments::Asymptotic,
        roughness: rough_model::Roughness::SelfAffine,
        curves: Curves::ALL,
        points: 11,
    })
    .unwrap();
    assert_eq!(scene.psi[10], f64::INFINITY);
    assert_eq!((scene.elastic[10], scene.plastic[10]), (0.0, 1.0));
    assert!(scene.psi[..10].iter().all(|v| v.is_finite()));
}

/// At ζ = 1 the asymptotic moments stay finite (the paper's curves start at
/// finite values), while the truncated ones vanish (ψ = 0).
#[test]
fn asymptotic_moments_at_zeta_one() {
    let p = Params::new(ParamValues {
        h0_over_e: 1e-2,
        h_rms: 2e-8,
        zeta: 1.0,
        hurst: 0.8,
        r_star: 1e-3,
        q0: 1e5,
    })
    .unwrap();
    let t = Surface::of(&p, Moments::Truncated);
    let a = Surface::of(&p, Moments::Asymptotic);
    assert_eq!((t.indices.psi_p, t.spectrum.r_s), (0.0, f64::INFINITY));
    assert!(a.indices.psi_p > 0.0 && a.spectrum.r_s.is_finite());
    assert!(a.indices.hardness_ratio > 1.0);
}

/// Sweeps between powers of ten hit the whole decades exactly, so that
/// exported grids read 10, 100 … rather than 10.000000000000002.
#[test]
fn sweeps_between_decades_hit_them_exactly() {
    let s = Sweep::new(Axis::Zeta, 1.0, 1e4).unwrap();
    let v: Vec<f64> = s.points(9).collect();
    assert_eq!(v[0], 1.0);
    assert_eq!(v[2], 10.0);
    assert_eq!(v[4], 100.0);
    assert_eq!(v[6], 1000.0);
    assert_eq!(v[8], 1e4);
    let s = Sweep::new(Axis::H0OverE, 1e-4, 1e-1).unwrap();
    let v: Vec<f64> = s.points(301).collect();
    assert_eq!((v[100], v[200]), (1e-3, 1e-2));
    // Off-decade ends keep the plain log grid.
    let s = Sweep::new(Axis::Zeta, 2.0, 2e4).unwrap();
    assert!((s.at(0.25) / 20.0 - 1.0).abs() < 1e-15);
}

/// Linear grids between short decimals hit those decimals (0.3, not
/// 0.30000000000000004); any other point moves by at most 2 ulp.
#[test]
fn linear_sweeps_hit_short_decimals() {
    let s = Sweep::new(Axis::Hurst, 0.1, 0.9).unwrap();
    let v: Vec<f64> = s.points(9).collect();
    assert_eq!(v, [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]);
    let s = Sweep::new(Axis::Hurst, 0.3, 0.9).unwrap();
    assert_eq!(s.points(41).nth(3), Some(0.345));
}

proptest! {
    #[test]
    fn linear_sweep_points_stay_within_2_ulp_and_in_order(
        a in 0.001f64..0.5, w in 0.001f64..0.5, n in 2usize..500,
    ) {
        let b = a + w;
        let s = Sweep::new(Axis::Hurst, a, b).unwrap();
        let v: Vec<f64> = s.points(n).collect();
        prop_assert_eq!(v[0], a);
        prop_assert_eq!(v[n - 1], b);
        for (i, &x) in v.iter().enumerate() {
            let t = i as f64 / (n - 1) as f64;
            let plain = (a + (b - a) * t).clamp(a, b);
            prop_assert!((x - plain).abs() <= 2.0 * f64::EPSILON * plain, "{} vs {}", x, plain);
            if i > 0 {
                prop_assert!(x >= v[i - 1]);
            }
        }
    }
}
