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

fn frame(c: &mut Criterion) {
    let mut g = c.benchmark_group("frame 160x48");
    for preset in ["fig2", "fig4"] {
        let state = presets::load(preset).expect("built-in preset");
        for (name, theme) in [("colored", Theme::colored()), ("plain", Theme::plain())] {
            let app = App::new(state.clone(), theme, SIZE);
            let mut terminal = Terminal::new(TestBackend::new(SIZE.0, SIZE.1)).expect("terminal");
            g.bench_function(format!("draw {preset} {name}"), |b| {
                b.iter(|| {
                    terminal
                        .draw(|f| f.render_widget(black_box(&app), f.area()))
                        .expect("draw");
                })
            });
        }
        // A slider step on a parameter that is not swept: recompute and draw.
        let mut app = App::new(state.clone(), Theme::colored(), SIZE);
        update(&mut app, Message::SelectNext);
        let before = app.recomputes;
        update(
            &mut app,
            Message::Step {
                up: true,
                fine: false,
            },
        );
        assert!(app.recomputes > before, "a step must recompute the curves");
        let mut terminal = Terminal::new(TestBackend::new(SIZE.0, SIZE.1)).expect("terminal");
        let mut up = false;
        g.bench_function(format!("step+draw {preset}"), |b| {
            b.iter(|| {
                update(&mut app, Message::Step { up, fine: false });
                up = !up;
                terminal
                    .draw(|f| f.render_widget(black_box(&app), f.area()))
                    .expect("draw");
            })
        });
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
        let mut terminal = Terminal::new(TestBackend::new(size.0, size.1)).expect("terminal");
        g.bench_function(format!("draw {label}"), |b| {
            b.iter(|| {
                terminal
                    .draw(|f| f.render_widget(black_box(&app), f.area()))
                    .expect("draw");
            })
        });
        update(&mut app, Message::SelectNext);
        let before = app.map.computes();
        let mut up = true;
        g.bench_function(format!("step+draw {label}"), |b| {
            b.iter(|| {
                update(&mut app, Message::Step { up, fine: false });
                up = !up;
                terminal
                    .draw(|f| f.render_widget(black_box(&app), f.area()))
                    .expect("draw");
            })
        });
        assert!(
            app.map.computes() > before + 1,
            "each step recomputes the map"
        );
    }
    g.finish();
}

criterion_group!(benches, frame, map_frame);
criterion_main!(benches);
