//! One load on a synthesised power-law surface (H = 0.8, ζ = 16, rms slope
//! 0.1, hardness 0.05 E*, p̄ = 0.02 H) at 256² and 512²: the speed targets
//! are 0.5 s and 2 s. scripts/contact_bench.py times Tamaas on the same kind
//! of surface.

use criterion::{criterion_group, criterion_main, Criterion};
use rough_contact::{moments, synthesise, Boundary, Contact, Options, PowerLaw};
use std::f64::consts::PI;

fn surface(n: usize) -> Vec<f64> {
    let law = PowerLaw {
        z: 1.0,
        hurst: 0.8,
        q0: 2.0 * PI,
        q1: 16.0 * 2.0 * PI,
        rolloff: false,
    };
    let h = synthesise(n, 1.0, &law, 1).unwrap();
    let s = moments(&h, n, 1.0).unwrap().rms_slope;
    h.into_iter().map(|v| v * 0.1 / s).collect()
}

fn one_load(c: &mut Criterion) {
    let mut g = c.benchmark_group("contact one load");
    g.sample_size(10);
    for n in [256, 512] {
        let h = surface(n);
        g.bench_function(format!("{n}²"), |b| {
            b.iter(|| {
                let mut c = Contact::new(h.clone(), n, 1.0, 1.0, Boundary::Periodic).unwrap();
                c.solve(0.001, 0.05, &Options::default()).unwrap()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, one_load);
criterion_main!(benches);
