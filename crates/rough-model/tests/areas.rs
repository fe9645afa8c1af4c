//! Finite-load areas against the mpmath references and physical properties.

use proptest::prelude::*;
use rough_model::areas::forms;
use rough_model::{areas, closed_form_areas, exact_areas, slopes, AreaError, Areas, Model};
use rough_study::{rel_err, Table};

/// Reference rows: ψ, ρ and the six areas in the order of [`COLUMNS`].
struct Row {
    psi: f64,
    rho: f64,
    want: [f64; 6],
}

/// `name` in `rough_study::DATA_DIR`, or an absolute path.
fn load(name: &str) -> Vec<Row> {
    let t = Table::read(name).unwrap_or_else(|e| panic!("{e}"));
    let field = |row: &[Option<f64>], col: &str| {
        t.get(row, col)
            .unwrap_or_else(|| panic!("{name}: empty {col}"))
    };
    t.rows
        .iter()
        .map(|row| Row {
            psi: field(row, "psi"),
            rho: field(row, "rho"),
            want: COLUMNS.map(|c| field(row, c)),
        })
        .collect()
}

/// The six outputs, as the reference tables name them.
const COLUMNS: [&str; 6] = rough_study::MODEL_COLUMNS;

fn check_file(name: &str, tol: f64) {
    let rows = load(name);
    let mut worst = [(0.0f64, 0.0f64, 0.0f64); 6];
    let mut failures = Vec::new();
    for r in &rows {
        let e = exact_areas(r.psi, r.rho).unwrap();
        let c = closed_form_areas(r.psi, r.rho).unwrap();
        let got = [e.elastic, e.plastic, e.total, c.elastic, c.plastic, c.total];
        for i in 0..6 {
            assert!(
                got[i].is_finite(),
                "{name}: {} at psi={}, rho={}: {}",
                COLUMNS[i],
                r.psi,
                r.rho,
                got[i]
            );
            let err = rel_err(got[i], r.want[i]);
            if err > worst[i].0 {
                worst[i] = (err, r.psi, r.rho);
            }
            if err > tol {
                failures.push(format!(
                    "{}: psi={:e} rho={:e}: got {:e}, want {:e}, rel err {:.3e}",
                    COLUMNS[i], r.psi, r.rho, got[i], r.want[i], err
                ));
            }
        }
    }
    for i in 0..6 {
        println!(
            "{name} {:>15}: max rel err {:.3e} at psi={:e} rho={:e}",
            COLUMNS[i], worst[i].0, worst[i].1, worst[i].2
        );
    }
    assert!(
        failures.is_empty(),
        "{name}: {} values off by more than {tol:e}:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn reference_areas_csv() {
    check_file("areas.csv", 1e-12);
}

#[test]
fn reference_areas_extra_csv() {
    check_file("areas_extra.csv", 1e-12);
}

#[test]
fn dispatch_and_double_double_input() {
    use rough_model::Dd;
    for (psi, rho) in [(0.2, 0.3), (0.9, 0.7), (3.0, 1e-5)] {
        assert_eq!(areas(Model::Exact, psi, rho), exact_areas(psi, rho));
        assert_eq!(
            areas(Model::ClosedForm, psi, rho),
            closed_form_areas(psi, rho)
        );
        // A double-double ψ with a zero tail is the same input.
        assert_eq!(exact_areas(Dd::new(psi, 0.0), rho), exact_areas(psi, rho));
    }
}

/// Any further reference file in the same format, by absolute path:
/// `AREAS_REFERENCE=/path/file.csv cargo test --test areas -- --ignored reference_from_env`.
#[test]
#[ignore]
fn reference_from_env() {
    if let Ok(path) = std::env::var("AREAS_REFERENCE") {
        check_file(&path, 1e-12);
    }
}

#[test]
fn limits_and_special_points() {
    for model in [Model::Exact, Model::ClosedForm] {
        for rho in [1e-300, 1e-9, 0.5, 0.999] {
            let z = areas(model, 0.0, rho).unwrap();
            assert_eq!(
                (z.elastic, z.plastic, z.total),
                (1.0, 0.0, 1.0),
                "{model:?} psi=0 rho={rho}"
            );
            let i = areas(model, f64::INFINITY, rho).unwrap();
            assert_eq!(
                (i.elastic, i.plastic, i.total),
                (0.0, rho, rho),
                "{model:?} psi=inf rho={rho}"
            );
        }
        for psi in [0.0, 1e-300, 0.3, 1.0, 1e300, f64::INFINITY] {
            let a = areas(model, psi, 1.0).unwrap();
            assert_eq!(
                (a.elastic, a.plastic, a.total),
                (0.0, 1.0, 1.0),
                "{model:?} rho=1 psi={psi}"
            );
        }
    }
}

#[test]
fn invalid_inputs_are_typed_errors() {
    for rho in [
        0.0,
        -0.0,
        -1e-300,
        1.0 + f64::EPSILON,
        2.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ] {
        for model in [Model::Exact, Model::ClosedForm] {
            let e = areas(model, 0.5, rho).unwrap_err();
            assert!(matches!(e, AreaError::Rho(_)), "{e:?}");
            let msg = e.to_string();
            assert!(msg.contains("rho") && msg.contains("(0, 1]"), "{msg}");
        }
    }
    for psi in [-1e-300, -1.0, f64::NAN, f64::NEG_INFINITY] {
        let e = exact_areas(psi, 0.5).unwrap_err();
        assert!(matches!(e, AreaError::Psi(_)), "{e:?}");
        assert!(e.to_string().contains("psi"), "{e}");
        assert!(closed_form_areas(psi, 0.5).is_err());
    }
}

fn both(psi: f64, rho: f64) -> [(Model, Areas); 2] {
    [
        (Model::Exact, exact_areas(psi, rho).unwrap()),
        (Model::ClosedForm, closed_form_areas(psi, rho).unwrap()),
    ]
}

/// ψ log-uniform over [1e-4, 1e4].
fn psi_strategy() -> impl Strategy<Value = f64> {
    (-4.0f64..4.0).prop_map(|e| 10f64.powf(e))
}

/// ρ in (0, 1], dense near both ends.
fn rho_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-15.0f64..0.0).prop_map(|e| 10f64.powf(e)),
        (-15.0f64..-0.3).prop_map(|e| 1.0 - 10f64.powf(e)),
        (1e-9f64..1.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn parts_add_up_and_stay_in_unit_interval(psi in psi_strategy(), rho in rho_strategy()) {
        for (model, a) in both(psi, rho) {
            for v in [a.elastic, a.plastic, a.total] {
                prop_assert!((0.0..=1.0).contains(&v), "{model:?} psi={psi:e} rho={rho:e}: {a:?}");
            }
            let sum = a.elastic + a.plastic;
            prop_assert!(
                (sum - a.total).abs() <= 4.0 * f64::EPSILON * a.total,
                "{model:?} psi={psi:e} rho={rho:e}: {a:?}"
            );
        }
    }

    #[test]
    fn total_is_monotone_in_load(psi in psi_strategy(), r1 in rho_strategy(), r2 in rho_strategy()) {
        let (lo, hi) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
        let (a, b) = (both(psi, lo), both(psi, hi));
        for i in 0..2 {
            prop_assert!(
                b[i].1.total >= a[i].1.total * (1.0 - 1e-14),
                "{:?} psi={psi:e}: total({lo:e}) = {:e} > total({hi:e}) = {:e}",
                a[i].0, a[i].1.total, b[i].1.total
            );
        }
    }

    #[test]
    fn small_loads_follow_the_initial_slopes(psi in (-3.0f64..3.0).prop_map(|e| 10f64.powf(e))) {
        let rho = 1e-9;
        for (model, a) in both(psi, rho) {
            let s = slopes(model, psi);
            for (name, got, want) in [
                ("elastic", a.elastic / rho, s.elastic),
                ("plastic", a.plastic / rho, s.plastic),
                ("total", a.total / rho, s.total),
            ] {
                if want < 1e-280 {
                    prop_assert!(got < 1e-270, "{model:?} {name} psi={psi:e}: {got:e} vs {want:e}");
                    continue;
                }
                let err = rel_err(got, want);
                prop_assert!(err < 1e-6, "{model:?} {name} psi={psi:e}: A/rho {got:e}, slope {want:e}, rel {err:e}");
            }
        }
    }

    #[test]
    fn elastic_area_is_symmetric_in_load(psi in psi_strategy(), e in -15.0f64..-0.31) {
        // 1 - rho is exact for rho >= 1/2.
        let rho = 1.0 - 10f64.powf(e);
        let r = 1.0 - rho;
        for (i, (model, a)) in both(psi, rho).into_iter().enumerate() {
            let b = both(psi, r)[i].1;
            let err = rel_err(a.elastic, b.elastic);
            prop_assert!(err < 1e-14, "{model:?} psi={psi:e}: A_el({rho}) = {:e}, A_el({r:e}) = {:e}", a.elastic, b.elastic);
        }
    }

    #[test]
    fn image_and_sine_forms_agree(psi in 0.35f64..0.9, rho in rho_strategy()) {
        prop_assume!(rho < 1.0);
        let (ie, ip) = forms::exact_images(psi, rho);
        let (fe, fp) = forms::exact_fourier(psi, rho);
        prop_assert!(rel_err(ie, fe) < 1e-13, "elastic psi={psi} rho={rho:e}: images {ie:e}, sine {fe:e}");
        prop_assert!(rel_err(ip, fp) < 1e-13, "plastic psi={psi} rho={rho:e}: images {ip:e}, sine {fp:e}");
    }

    #[test]
    fn closed_series_and_direct_agree(psi in 1.18f64..1.8, rho in rho_strategy()) {
        prop_assume!(rho < 1.0);
        let s = forms::closed_elastic_series(psi, rho);
        let d = forms::closed_elastic_direct(psi, rho);
        prop_assert!(rel_err(s, d) < 1e-12, "psi={psi} rho={rho:e}: series {s:e}, direct {d:e}");
    }

    #[test]
    fn every_output_is_finite(
        psi in prop_oneof![Just(0.0), Just(f64::INFINITY), Just(f64::MIN_POSITIVE), Just(5e-324), Just(f64::MAX), prop::num::f64::POSITIVE],
        rho in prop_oneof![Just(1.0), Just(5e-324), Just(1.0 - f64::EPSILON / 2.0), prop::num::f64::POSITIVE.prop_filter("<= 1", |r| *r <= 1.0)],
    ) {
        for (model, a) in both(psi, rho) {
            for v in [a.elastic, a.plastic, a.total] {
                prop_assert!(v.is_finite() && (0.0..=1.0).contains(&v), "{model:?} psi={psi:e} rho={rho:e}: {a:?}");
            }
        }
    }
}

/// Rough cost per call; `cargo test --release -p rough-model --test areas -- --ignored --nocapture`.
#[test]
#[ignore]
fn timing() {
    use std::hint::black_box;
    use std::time::Instant;
    let psis: Vec<f64> = (0..64)
        .map(|i| 10f64.powf(-2.0 + 4.0 * i as f64 / 63.0))
        .collect();
    let rhos = [1e-6, 0.01, 0.2, 0.45, 0.6, 0.95];
    for model in [Model::Exact, Model::ClosedForm] {
        let n = 200;
        let t = Instant::now();
        let mut s = 0.0;
        for _ in 0..n {
            for &p in &psis {
                for &r in &rhos {
                    s += areas(model, black_box(p), black_box(r)).unwrap().total;
                }
            }
        }
        let ns = t.elapsed().as_nanos() as f64 / (n * psis.len() * rhos.len()) as f64;
        println!("{model:?}: {ns:.0} ns/call ({s})");
    }
}

#[test]
#[ignore]
fn timing_by_case() {
    use std::hint::black_box;
    use std::time::Instant;
    let cases = [
        ("small psi", 0.05, 0.3),
        ("small psi, tiny rho", 0.05, 1e-6),
        ("small psi, rho>1/2", 0.05, 0.8),
        ("mid psi", 0.4, 0.3),
        ("mid psi rho>1/2", 0.4, 0.8),
        ("psi 0.7", 0.7, 0.3),
        ("psi 1", 1.0, 0.3),
        ("psi 1, rho > 1/2", 1.0, 0.8),
        ("psi 3", 3.0, 0.3),
        ("psi 30", 30.0, 0.3),
        ("psi 30, rho > 1/2", 30.0, 0.8),
    ];
    for model in [Model::Exact, Model::ClosedForm] {
        for (name, p, r) in cases {
            // Best of 50 short runs: the machine may be shared.
            let n = 2000;
            let mut best = f64::INFINITY;
            let mut s = 0.0;
            for _ in 0..50 {
                let t = Instant::now();
                for _ in 0..n {
                    s += areas(model, black_box(p), black_box(r)).unwrap().total;
                }
                best = best.min(t.elapsed().as_nanos() as f64 / n as f64);
            }
            println!("{model:?} {name}: {best:.0} ns ({s:.3})");
        }
    }
}
