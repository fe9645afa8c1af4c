//! Westergaard's wavy contact against the analytic solution
//! (scripts/contact_westergaard.py, mpmath): contact fraction within one
//! grid cell at each of its two edges (|ΔA/A0| ≤ 2/N, the discrete contact
//! being symmetric its node count is odd) at N = 256 … 1024 and converging
//! with N; the pressure profile;
//! the mean pressure exact.

use rough_contact::{Boundary, Contact, Options};
use std::f64::consts::PI;

const D: f64 = 0.01;

struct Row {
    r: f64,
    fraction: f64,
    p: Vec<f64>,
}

fn reference() -> Vec<Row> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/westergaard.csv");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
            Row {
                r: v[0],
                fraction: v[1],
                p: v[2..].to_vec(),
            }
        })
        .collect()
}

fn wavy(n: usize) -> Contact {
    let h: Vec<f64> = (0..n * n)
        .map(|i| D * (2.0 * PI * (i % n) as f64 / n as f64).cos())
        .collect();
    Contact::new(h, n, 1.0, 1.0, Boundary::Periodic).unwrap()
}

#[test]
fn contact_fraction_within_one_cell_and_converging() {
    let rows = reference();
    let p_star = PI * D;
    let opts = Options::default();
    let mut errors = vec![];
    for n in [256, 512, 1024] {
        let mut c = wavy(n);
        let mut worst: f64 = 0.0;
        for row in &rows {
            let r = c.solve(row.r * p_star, f64::INFINITY, &opts).unwrap();
            let err = (r.area - row.fraction).abs();
            println!(
                "N {n} p/p* {}: {:.6} vs {:.6}: {:.2} cells, {} it",
                row.r,
                r.area,
                row.fraction,
                err * n as f64,
                r.iterations
            );
            assert!(
                err <= 2.0 / n as f64,
                "N {n}, p/p* {}: {} vs {}",
                row.r,
                r.area,
                row.fraction
            );
            assert_eq!(r.plastic_area, 0.0);
            let mean = c.pressure().iter().sum::<f64>() / (n * n) as f64;
            assert!((mean / (row.r * p_star) - 1.0).abs() < 1e-12);
            worst = worst.max(err * n as f64);
        }
        errors.push(worst);
    }
    println!("worst error in cells at 256, 512, 1024: {errors:?}");
    // In absolute terms the error falls with the cell size.
    assert!(errors[2] / 1024.0 < errors[0] / 256.0 / 2.0, "{errors:?}");
}

#[test]
fn pressure_profile_matches_westergaard() {
    let n = 256;
    let mut c = wavy(n);
    let p_star = PI * D;
    for row in reference().iter().filter(|r| r.r >= 0.1) {
        c.solve(row.r * p_star, f64::INFINITY, &Options::default())
            .unwrap();
        let line = &c.pressure()[..n];
        let (mut d2, mut t2) = (0.0, 0.0);
        for (a, b) in line.iter().zip(&row.p) {
            d2 += (a - b) * (a - b);
            t2 += b * b;
        }
        let l2 = (d2 / t2).sqrt();
        println!("p/p* {}: relative L2 {l2:.3e}", row.r);
        assert!(l2 < 2e-2, "p/p* {}: relative L2 {l2}", row.r);
        // Every row of the cell carries the same profile.
        let last = &c.pressure()[(n - 1) * n..];
        for (a, b) in line.iter().zip(last) {
            assert!((a - b).abs() <= 1e-12 * p_star);
        }
    }
}
