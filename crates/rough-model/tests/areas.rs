//! Finite-load areas against the mpmath references and physical properties.

use proptest::prelude::*;
use rough_model::areas::forms;
use rough_model::{areas, closed_form_areas, exact_areas, slopes, AreaError, Areas, Model};

/// Below this both values count as zero (the functions may underflow there).
const TINY: f64 = 1e-300;

fn rel_err(got: f64, want: f64) -> f64 {
    if got == want || (got.abs() < TINY && want.abs() < TINY) {
        0.0
    } else {
        (got - want).abs() / want.abs().max(TINY)
    }
}

struct Row {
    psi: f64,
    rho: f64,
    want: [f64; 6],
}

fn load(name: &str) -> Vec<Row> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut rows = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') || line.starts_with("psi") {
            continue;
        }
        let v: Vec<f64> = line
            .split(',')
            .map(|s| s.parse().unwrap_or_else(|e| panic!("{path}: {s:?}: {e}")))
            .collect();
        assert_eq!(v.len(), 8, "{path}: {line}");
        rows.push(Row {
            psi: v[0],
            rho: v[1],
            want: [v[2], v[3], v[4], v[5], v[6], v[7]],
        });
    }
    assert!(!rows.is_empty(), "{path}: no rows");
    rows
}

const COLUMNS: [&str; 6] = [
    "exact_elastic",
    "exact_plastic",
    "exact_total",
    "closed_elastic",
    "closed_plastic",
    "closed_total",
];

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
