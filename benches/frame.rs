//! One frame of the explorer drawn into ratatui's TestBackend at 160×48.
//!
//! TODO(tui): the explorer (`roughtui::tui::app::App`, `impl Widget for &App`)
//! is on branch `tui`, not yet on main. Until it is merged this draws a
//! stand-in of the same size and load: the fig2 scene's four curves, 400
//! points each, as a braille log-log chart. After the merge, replace
//! `stand_in` by
//!     let app = App::new(presets::load("fig2")?, Theme::plain(), (160, 48));
//!     terminal.draw(|f| f.render_widget(&app, f.area()))
//! (the real frame bench is ready in the bench engineer's report).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use ratatui::backend::TestBackend;
use ratatui::symbols::Marker;
use ratatui::widgets::{Axis, Chart, Dataset, GraphType};
use ratatui::Terminal;
use rough_model::{Curves, Scene, SceneSpec};
use roughtui::presets;

fn scene() -> Scene {
    let s = presets::load("fig2").expect("built-in preset");
    Scene::compute(&SceneSpec {
        base: s.params,
        sweep: s.sweep,
        size_effect: s.size_effect,
        model: s.model,
        curves: Curves::ALL,
        points: 400,
    })
    .expect("valid scene")
}

fn stand_in(terminal: &mut Terminal<TestBackend>, s: &Scene) {
    let log = |ys: &[f64]| -> Vec<(f64, f64)> {
        s.x.iter()
            .zip(ys)
            .filter(|(_, y)| y.is_finite() && **y > 0.0)
            .map(|(x, y)| (x.log10(), y.log10()))
            .collect()
    };
    let curves = [
        log(&s.elastic),
        log(&s.plastic),
        log(&s.total),
        log(&s.persson_elastic),
    ];
    terminal
        .draw(|f| {
            let sets = curves
                .iter()
                .map(|c| {
                    Dataset::default()
                        .marker(Marker::Braille)
                        .graph_type(GraphType::Line)
                        .data(c)
                })
                .collect();
            let chart = Chart::new(sets)
                .x_axis(Axis::default().bounds([0.0, 4.0]))
                .y_axis(Axis::default().bounds([-3.0, 1.0]));
            f.render_widget(chart, f.area());
        })
        .expect("draw");
}

fn frame(c: &mut Criterion) {
    let s = scene();
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).expect("terminal");
    c.bench_function("frame 160x48 (stand-in until tui is merged)", |b| {
        b.iter(|| stand_in(&mut terminal, black_box(&s)))
    });
}

criterion_group!(benches, frame);
criterion_main!(benches);
