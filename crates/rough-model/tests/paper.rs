//! What the paper computed: the closed form of Appendix A on the asymptotic
//! moments of eq. 10, from Z = 1e-8 m^0.4 (h_rms = 19.8166… nm). The claims
//! its text makes about Figures 2–4 (docs/model.md, "The paper's figures") are
//! checked where they happen, to the precision the text gives.

use rough_model::{Axis, Curves, Model, Moments, ParamValues, Params, Scene, SceneSpec, Sweep};

/// h_rms of Z = 1e-8 m^0.4 at q0 = 1e5 1/m, H = 0.8 (docs/model.md).
const H_RMS_PAPER: f64 = 19.816636488030044e-9;

fn scene(h_rms: f64, h0_over_e: f64, size_effect: bool, to: f64) -> Scene {
    let base = Params::new(ParamValues {
        h0_over_e,
        h_rms,
        zeta: 128.0,
        hurst: 0.8,
        r_star: 1e-3,
        q0: 1e5,
    })
    .unwrap();
    Scene::compute(&SceneSpec {
        base,
        sweep: Sweep::new(Axis::Zeta, 1.0, to).unwrap(),
        size_effect,
        model: Model::ClosedForm,
        moments: Moments::Asymptotic,
        roughness: rough_model::Roughness::SelfAffine,
        curves: Curves::ALL,
        points: 4001,
    })
    .unwrap()
}

fn share(s: &Scene, i: usize) -> f64 {
    s.plastic[i] / s.total[i]
}

/// ζ values where the plastic share crosses ½ (linear interpolation in ln ζ
/// between grid points 1/1000 of the sweep apart).
fn half_crossings(s: &Scene) -> Vec<f64> {
    (1..s.x.len())
        .filter(|&i| (share(s, i - 1) - 0.5) * (share(s, i) - 0.5) < 0.0)
        .map(|i| {
            let (a, b) = (share(s, i - 1) - 0.5, share(s, i) - 0.5);
            let (la, lb) = (s.x[i - 1].ln(), s.x[i].ln());
            (la + (lb - la) * a / (a - b)).exp()
        })
        .collect()
}

#[test]
fn curves_start_finite_at_zeta_one() {
    for (h, h0e, se, to) in [
        (H_RMS_PAPER, 1e-2, false, 1e4),
        (H_RMS_PAPER, 1e-2, true, 1e4),
        (6e-7, 1e-3, true, 1e6),
    ] {
        let s = scene(h, h0e, se, to);
        assert!(s.psi[0] > 0.0 && s.total[0].is_finite() && s.elastic[0].is_finite());
    }
}

/// Fig. 2: "the plastic share passes ½ near ζ ≈ 320".
#[test]
fn fig2_plastic_share_passes_half_near_320() {
    let s = scene(H_RMS_PAPER, 1e-2, false, 1e4);
    let c = half_crossings(&s);
    assert_eq!(c.len(), 1, "{c:?}");
    assert!((300.0..340.0).contains(&c[0]), "{c:?}");
    assert!(share(&s, 0) < 1e-4 && share(&s, s.x.len() - 1) > 0.9);
}

/// Fig. 3: "no plastic area anywhere", and the H_y-normalized slope first
/// falls, then rises (its minimum near ζ ≈ 3).
#[test]
fn fig3_no_plastic_area_and_a_minimum_near_3() {
    let s = scene(H_RMS_PAPER, 1e-2, true, 1e4);
    let max = (0..s.x.len()).map(|i| share(&s, i)).fold(0.0, f64::max);
    assert!(max < 1e-4, "{max}");
    let (imin, _) =
        s.total.iter().enumerate().fold(
            (0, f64::INFINITY),
            |m, (i, &v)| if v < m.1 { (i, v) } else { m },
        );
    assert!((2.5..4.0).contains(&s.x[imin]), "{}", s.x[imin]);
    assert!(s.total[0] > s.total[imin] && s.total[s.x.len() - 1] > s.total[imin]);
}

/// Fig. 4: plastic at bulk scale, elastic again at small scales ("about
/// 1e4"; share ½ near ζ ≈ 1.7e4).
#[test]
fn fig4_turns_elastic_again_near_1_7e4() {
    let s = scene(6e-7, 1e-3, true, 1e6);
    assert!(share(&s, 0) > 0.999);
    let c = half_crossings(&s);
    assert_eq!(c.len(), 1, "{c:?}");
    assert!((1.6e4..1.8e4).contains(&c[0]), "{c:?}");
    assert!(share(&s, s.x.len() - 1) < 0.1);
}
