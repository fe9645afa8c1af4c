//! The regime map at terminal resolution (200 × 60 cells: a 200-column
//! terminal's chart, two points per cell row) — budget ≤ 10 ms with the
//! draw — plus the cached lookup and the SVG picture of the map.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use roughtui::figure::{render_svg, FigureOptions, MapCache, MapSpec, RegimeMap, View};
use roughtui::presets;

fn maps(c: &mut Criterion) {
    let mut g = c.benchmark_group("map 200x60");
    for preset in ["fig2", "fig4"] {
        let s = presets::load(preset).expect("built-in preset");
        let spec = MapSpec::of(&s, (200, 60), None).expect("valid grid");
        g.bench_function(format!("{preset} compute"), |b| {
            b.iter(|| RegimeMap::compute(black_box(&spec)))
        });
        let mut cache = MapCache::new();
        cache.get(&spec);
        g.bench_function(format!("{preset} cached"), |b| {
            b.iter(|| cache.get(black_box(&spec)).share.len())
        });
    }
    g.finish();
    let s = presets::load("fig2").expect("built-in preset");
    c.bench_function("fig2 map svg 50x30", |b| {
        b.iter(|| render_svg(View::Map, black_box(&s), &FigureOptions::default()))
    });
}

criterion_group!(benches, maps);
criterion_main!(benches);
