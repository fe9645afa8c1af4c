//! A whole scene at chart resolution: 4 curves × 400 points (budget ≤ 50 µs).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use rough_model::{Curves, Model, Scene, SceneSpec};
use roughtui::presets;

fn spec(preset: &str, model: Model) -> SceneSpec {
    let s = presets::load(preset).expect("built-in preset");
    SceneSpec {
        model,
        ..s.scene_spec(Curves::ALL, 400)
    }
}

fn scenes(c: &mut Criterion) {
    let mut g = c.benchmark_group("scene 4x400");
    for (name, preset, model) in [
        ("fig2 exact", "fig2", Model::Exact),
        ("fig2 closed form", "fig2", Model::ClosedForm),
        ("fig4 exact, size effect", "fig4", Model::Exact),
    ] {
        let sp = spec(preset, model);
        g.bench_function(name, |b| b.iter(|| Scene::compute(black_box(&sp))));
    }
    g.finish();
}

fn slopes(c: &mut Criterion) {
    let grid: Vec<f64> = (0..400)
        .map(|i| 10f64.powf(-8.0 + 16.0 * i as f64 / 399.0))
        .collect();
    c.bench_function("exact slopes, 400 psi from 1e-8 to 1e8", |b| {
        b.iter(|| {
            for &p in &grid {
                black_box(rough_model::exact(black_box(p)));
            }
        })
    });
}

criterion_group!(benches, scenes, slopes);
criterion_main!(benches);
