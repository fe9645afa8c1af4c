//! The contact view's convergence table (`t`): the chosen load on 4, 8, 16
//! nodes per shortest wavelength × cells of 1, 2, 4 over the pane's seeds,
//! solved through the engine (cached: the plot's own sampling is not solved
//! again; cancelled when the view is left), the smallest grids first, the
//! same areas as `export --view contact-convergence`, pairs beyond the grid
//! named with the reason, a measured map told why not.

mod common;

use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::{Duration, Instant};

use crossterm::event::{KeyCode, KeyModifiers};
use roughtui::contact::engine::Engine;
use roughtui::contact::{Seeds, Spec};
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::theme::Theme;

use common::app::{ch, press, screen};
use common::contact::{settle, to_contact};

fn app_at(zeta: f64, size: (u16, u16), engine: &Arc<Engine>) -> App {
    common::contact::app_at(zeta, size, Theme::colored(), engine)
}

#[test]
fn t_fills_the_convergence_table_through_the_engine() {
    let engine = Engine::new(2);
    // ζ = 4: grids of 32² to 256².
    let mut a = app_at(4.0, (160, 48), &engine);
    to_contact(&mut a);
    settle(&mut a);
    let plot_solves = engine.solves.load(Ordering::Relaxed);
    assert_eq!(plot_solves, 52);
    ch(&mut a, 't');
    assert!(a.contact.table);
    let rows = &a.contact.convergence.rows;
    let pairs: Vec<(u32, u32, usize)> = rows
        .iter()
        .map(|r| (r.per_wavelength, r.cell, *r.grid.as_ref().unwrap()))
        .collect();
    assert_eq!(
        pairs,
        [
            (4, 1, 32),
            (4, 2, 32),
            (4, 4, 64),
            (8, 1, 32),
            (8, 2, 64),
            (8, 4, 128),
            (16, 1, 64),
            (16, 2, 128),
            (16, 4, 256)
        ]
    );
    assert!(rows.iter().all(|r| r.tasks.len() == 4));
    // The plot's own sampling (8 per wavelength, one cell) is in the cache.
    assert!(rows[3].results.iter().all(Option::is_some));
    assert!(a.contact.busy());
    settle(&mut a);
    // 36 less the plot's four, less four more: at ζ = 4 four and eight
    // nodes per wavelength in one cell are both the smallest grid, 32²,
    // one surface solved once.
    assert_eq!(engine.solves.load(Ordering::Relaxed) - plot_solves, 28);
    // The areas as export --view contact-convergence gives them.
    let spec = Spec {
        sampling: a.contact.sampling,
        seeds: Seeds { first: 1, count: 4 },
    };
    let export =
        roughtui::contact::convergence::points(&a.state, &spec, 0.01, &mut |_| {}).unwrap();
    for r in &a.contact.convergence.rows {
        let s = r.stats().unwrap();
        assert_eq!(s.area.n, 4);
        let e = export
            .iter()
            .find(|p| (p.per_wavelength, p.cell) == (r.per_wavelength, r.cell))
            .unwrap();
        let e = e.result.as_ref().unwrap();
        assert_eq!(e.grid, *r.grid.as_ref().unwrap());
        let rel = |x: f64, y: f64| (x - y).abs() / y.abs().max(1e-300);
        assert!(
            rel(s.area.mean, e.area.mean) < 1e-3,
            "{s:?} vs {:?}",
            e.area
        );
        assert!(rel(s.area.sd, e.area.sd) < 2e-2, "{s:?} vs {:?}", e.area);
    }
    let text = screen(&a);
    assert!(
        text.contains("convergence at p̄ = 0.01 H0 · seeds 1–4"),
        "{text}"
    );
    assert!(text.contains("n/λ  K  grid  contact %"), "{text}");
    assert!(text.contains("36 solved"), "{text}");
    // The plot's row is marked.
    let own = text.lines().find(|l| l.contains("◀")).unwrap();
    assert!(own.contains("8  1   32²"), "{own}");
    // [ ] move the table's load; t goes back to the plot.
    ch(&mut a, ']');
    assert!(a.contact.convergence.rows[0].tasks[0].p_over_h() > 0.017);
    ch(&mut a, 't');
    assert!(!a.contact.table);
    assert!(screen(&a).contains("simulation at p̄ = 0.01778 H0"));
}

/// Pairs beyond the grid the simulation solves are named with the reason;
/// leaving the view stops the table's job at its next iteration.
#[test]
fn beyond_the_grid_a_pair_says_why_and_leaving_stops_the_work() {
    let engine = Engine::new(1);
    // ζ = 512: 16 per wavelength in 4 cells would be 32768².
    let mut a = app_at(512.0, (120, 36), &engine);
    to_contact(&mut a);
    ch(&mut a, 't');
    let rows = &a.contact.convergence.rows;
    let why = rows[8].grid.as_ref().unwrap_err();
    assert_eq!(why, "32768² nodes, beyond the 4096² solved");
    assert!(rows[8].tasks.is_empty());
    assert_eq!(*rows[0].grid.as_ref().unwrap(), 2048);
    let text = screen(&a);
    assert!(text.contains("not solved (below)"), "{text}");
    assert!(
        text.contains("16/λ, K 4: not solved: 32768² nodes, beyond the 4096²"),
        "{text}"
    );
    assert!(a.contact.busy());
    std::thread::sleep(Duration::from_millis(200));
    update(&mut a, Message::Tick);
    // t again: the table's job stops at its next iteration (its first
    // 2048² solve, seconds in a debug build, dropped unfinished) and the
    // plot's takes the engine's one core. The surface's synthesis is not
    // interrupted: at ζ = 512 a seed's noise is drawn and transformed on
    // its 4096² reference grid (0.8 s in a release build, 7 s in a debug
    // one, more on a busy machine).
    let first = a.contact.convergence.rows[0].tasks[0];
    ch(&mut a, 't');
    assert!(!a.contact.table && !a.contact.convergence.busy());
    let start = Instant::now();
    while a.contact.progress.queued || a.contact.progress.started.is_none() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "the table's job holds the core"
        );
        std::thread::sleep(Duration::from_millis(10));
        update(&mut a, Message::Tick);
    }
    assert!(engine.get(&first).is_none(), "the table's solve went on");
    ch(&mut a, 't');
    assert!(a.contact.convergence.busy());
    press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    assert!(!a.contact.busy());
    let start = Instant::now();
    while engine.running() > 0 {
        assert!(start.elapsed() < Duration::from_secs(60), "still working");
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// A measured map has one surface on its own grid: `t` says so.
#[test]
fn a_measured_map_has_no_convergence_table() {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/measured_contact/periodic64.txt");
    let opts = rough_surface::Options {
        periodic: true,
        ..Default::default()
    };
    let src = roughtui::surface::SurfaceSource::read(&data, opts).unwrap();
    let state = roughtui::scene::State::measured(src).unwrap();
    let mut a = App::new(state, Theme::colored(), (120, 36));
    a.contact.engine = Engine::new(1);
    to_contact(&mut a);
    ch(&mut a, 't');
    assert!(!a.contact.table);
    let st = a.status.clone().unwrap();
    assert!(st.error, "{}", st.text);
    assert!(
        st.text
            .starts_with("a measured map is one surface on its own grid"),
        "{}",
        st.text
    );
}

/// `t` is named in the contact view's help and, where it fits, its footer.
#[test]
fn the_help_and_the_footer_name_t() {
    let engine = Engine::new(1);
    let mut a = app_at(4.0, (200, 40), &engine);
    to_contact(&mut a);
    let footer = screen(&a).lines().last().unwrap().to_string();
    assert!(footer.contains("t converge"), "{footer}");
    ch(&mut a, '?');
    let mut s = String::new();
    for _ in 0..4 {
        s.push_str(&screen(&a));
        press(&mut a, KeyCode::Right, KeyModifiers::NONE);
    }
    assert!(
        s.contains("t              contact view: convergence table (grids × cells) / the plot"),
        "{s}"
    );
}
