//! The free (non-periodic) boundary against Hertz's sphere
//! (scripts/contact_hertz.py, mpmath): contact radius within one cell,
//! the pressure on the centre row, the load carried exactly.

use rough_contact::{Boundary, Contact, Options};

const N: usize = 128;

#[test]
fn hertz_sphere_on_a_window() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/hertz.csv");
    let dx = 1.0 / N as f64;
    let h: Vec<f64> = (0..N * N)
        .map(|i| {
            let x = ((i % N) as f64 - (N / 2) as f64) * dx;
            let y = ((i / N) as f64 - (N / 2) as f64) * dx;
            -(x * x + y * y) / 2.0
        })
        .collect();
    let mut c = Contact::new(h, N, 1.0, 1.0, Boundary::Free).unwrap();
    let text = std::fs::read_to_string(path).unwrap();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let (p_mean, a, p0) = (v[0], v[1], v[2]);
        let r = c.solve(p_mean, f64::INFINITY, &Options::default()).unwrap();
        let radius = (r.area / std::f64::consts::PI).sqrt();
        let row = &c.pressure()[(N / 2) * N..(N / 2 + 1) * N];
        let (mut d2, mut t2) = (0.0, 0.0);
        for (ours, exact) in row.iter().zip(&v[3..]) {
            d2 += (ours - exact).powi(2);
            t2 += exact * exact;
        }
        let l2 = (d2 / t2).sqrt();
        let peak = row[N / 2];
        println!(
            "a {a}: radius {radius:.5} ({:+.2} cells), p(0) {peak:.5} vs {p0:.5}, row L2 {l2:.2e}, {} it",
            (radius - a) / dx,
            r.iterations
        );
        assert!((radius - a).abs() <= dx, "radius {radius} vs {a}");
        assert!((peak / p0 - 1.0).abs() < 0.01, "p(0) {peak} vs {p0}");
        assert!(l2 < 0.02, "L2 {l2}");
        let mean = c.pressure().iter().sum::<f64>() / (N * N) as f64;
        assert!((mean / p_mean - 1.0).abs() < 1e-12);
    }
}
