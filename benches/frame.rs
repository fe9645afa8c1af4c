//! One frame of the explorer drawn into ratatui's TestBackend at 160×48:
//! the drawing alone (curves cached), and a slider step (recompute + draw);
//! the same for the regime map view at 160×48 and with a 200×60-cell map
//! (253×70 terminal, 200×120 points).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use roughtui::figure::View;
use roughtui::presets;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

const SIZE: (u16, u16) = (160, 48);

type Group<'a> = criterion::BenchmarkGroup<'a, criterion::measurement::WallTime>;

/// Drawing `app` as it is (nothing recomputed).
fn bench_draw(g: &mut Group, name: String, app: &App) {
    let (w, h) = app.size;
    let mut terminal = Terminal::new(TestBackend::new(w, h)).expect("terminal");
    g.bench_function(name, |b| {
        b.iter(|| {
            terminal
                .draw(|f| f.render_widget(black_box(app), f.area()))
                .expect("draw");
        })
    });
}

const STEP_UP: Message = Message::Step {
    up: true,
    fine: false,
};

/// Steps of the selected slider, down and up in turn (after a first step
/// up), each drawn.
fn bench_step(g: &mut Group, name: String, app: &mut App) {
    let (w, h) = app.size;
    let mut terminal = Terminal::new(TestBackend::new(w, h)).expect("terminal");
    let mut up = false;
    g.bench_function(name, |b| {
        b.iter(|| {
            update(app, Message::Step { up, fine: false });
            up = !up;
            terminal
                .draw(|f| f.render_widget(black_box(&*app), f.area()))
                .expect("draw");
        })
    });
}

fn frame(c: &mut Criterion) {
    let mut g = c.benchmark_group("frame 160x48");
    for preset in ["fig2", "fig4"] {
        let state = presets::load(preset).expect("built-in preset");
        for (name, theme) in [("colored", Theme::colored()), ("plain", Theme::plain())] {
            let app = App::new(state.clone(), theme, SIZE);
            bench_draw(&mut g, format!("draw {preset} {name}"), &app);
        }
        // A slider step on a parameter that is not swept: recompute and draw.
        let mut app = App::new(state.clone(), Theme::colored(), SIZE);
        update(&mut app, Message::SelectNext);
        let before = app.recomputes;
        update(&mut app, STEP_UP);
        assert!(app.recomputes > before, "a step must recompute the curves");
        bench_step(&mut g, format!("step+draw {preset}"), &mut app);
    }
    g.finish();
}

/// The regime map view: drawing the cached map, and a step of a slider that
/// is not swept (the map is recomputed, then drawn).
fn map_frame(c: &mut Criterion) {
    let mut g = c.benchmark_group("map frame");
    for (size, label) in [((160, 48), "160x48"), ((253, 70), "200x60 cells")] {
        let state = presets::load("fig2").expect("built-in preset");
        let mut app = App::new(state, Theme::colored(), size);
        while app.view != View::Map {
            update(&mut app, Message::NextView);
        }
        bench_draw(&mut g, format!("draw {label}"), &app);
        update(&mut app, Message::SelectNext);
        let before = app.map.computes();
        bench_step(&mut g, format!("step+draw {label}"), &mut app);
        assert!(
            app.map.computes() > before + 1,
            "each step recomputes the map"
        );
    }
    g.finish();
}

criterion_group!(benches, frame, map_frame);
criterion_main!(benches);
