//! The contact view without a terminal: Tab reaches it, the solver runs off
//! the UI thread and its results come in through Tick, a change of the
//! scene cancels the job, results are cached and shared between explorers,
//! and the screen (insta) at 80×24 and 120×36, coloured, NO_COLOR and ASCII.
//! Small grids (ζ = 4: 32²) keep the solves fast in a debug build.

mod common;

use std::time::{Duration, Instant};

use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::contact::engine::Engine;
use roughtui::figure::View;
use roughtui::presets;
use roughtui::tui::app::{update, App, Message};
use roughtui::tui::contact::Plot;
use roughtui::tui::glyphs::Glyphs;
use roughtui::tui::theme::Theme;

use common::app::{ch, press, screen};
use common::contact::{app_at, settle, to_contact};

#[test]
fn tab_reaches_the_contact_view_and_its_result_comes_in() {
    let engine = Engine::new(1);
    let mut a = app_at(4.0, (160, 48), Theme::colored(), &engine);
    let mut seen = vec![];
    for _ in 0..5 {
        press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
        seen.push(a.view);
    }
    assert_eq!(
        seen,
        [
            View::Indices,
            View::Map,
            View::Load,
            View::Contact,
            View::Slopes
        ]
    );
    to_contact(&mut a);
    assert!(a.contact.busy() || a.contact.progress.finished);
    settle(&mut a);
    assert_eq!(a.contact.results.len(), 13);
    let s = a.contact.chosen().unwrap().as_ref().unwrap();
    assert_eq!(s.result.p_mean, 0.01 * a.contact.tasks[0].scene.hardness());
    assert_eq!(s.map.len(), 32 * 32);
    assert!(s.result.residual <= 1e-10 * 100.0);
    let text = screen(&a);
    assert!(
        text.contains("simulation at p̄ = 0.01 H0: contact"),
        "{text}"
    );
    // Four surfaces by default, their thirteen loads each.
    assert!(text.contains("simulation 32² · seeds 1–4"), "{text}");
    assert!(text.contains("52 solved"), "{text}");
}

#[test]
fn the_readout_gives_the_simulation_and_the_theory_at_the_chosen_load() {
    let engine = Engine::new(1);
    let mut a = app_at(16.0, (160, 48), Theme::colored(), &engine);
    to_contact(&mut a);
    settle(&mut a);
    let r = a.contact.chosen().unwrap().as_ref().unwrap().result;
    let t = a.contact.theory.at_load.unwrap();
    let (lines, error) =
        roughtui::tui::views::contact::readout(&a.contact, 200, Glyphs::Braille, "H0");
    let line = lines.join("\n");
    assert!(!error);
    use roughtui::tui::views::contact::{pct, pct_pm, share_pct};
    // The mean ± sample standard deviation over the four seeds' areas.
    let areas: Vec<f64> = std::iter::once(&a.contact.results)
        .chain(&a.contact.seed_results)
        .map(|rs| {
            rs[a.contact.load]
                .as_ref()
                .unwrap()
                .as_ref()
                .unwrap()
                .result
                .area
        })
        .collect();
    assert_eq!(areas.len(), 4);
    let mean = areas.iter().sum::<f64>() / 4.0;
    let sd = (areas.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 3.0).sqrt();
    let [st, _, pl] = a.contact.at_load(a.contact.load).unwrap();
    assert_eq!((st.n, st.mean, st.sd), (4, mean, sd));
    assert_eq!(
        line,
        format!(
            "simulation at p̄ = 0.01 H0: contact {} %, {} % plastic · theory: {} %, {} % plastic",
            pct_pm(mean, sd),
            share_pct(pl.mean, mean),
            pct(t.total),
            share_pct(t.plastic, t.total)
        )
    );
    assert!(line.contains(" ± "), "{line}");
    assert_eq!(pct_pm(0.021, 0.001), "2.10 ± 0.10");
    // The numbers of docs/theory-vs-simulation.md (fig2, ζ = 16, seed 1).
    assert_eq!(pct(r.area), "4.46", "{line}");
    assert_eq!(pct(t.total), "2.31", "{line}");
    // ] and [ move the load a quarter decade; the readout follows.
    ch(&mut a, ']');
    assert_eq!(a.contact.load, 5);
    let (lines, _) = roughtui::tui::views::contact::readout(&a.contact, 200, Glyphs::Braille, "H0");
    assert!(
        lines[0].starts_with("simulation at p̄ = 0.01778 H0"),
        "{lines:?}"
    );
    // On an 80-column screen the panel is 46 wide: one line or two, none
    // cut; narrower, two.
    for w in [46, 40] {
        let (lines, _) =
            roughtui::tui::views::contact::readout(&a.contact, w, Glyphs::Braille, "H0");
        for l in &lines {
            // Columns: p̄'s combining macron takes none.
            let cols = l.chars().filter(|c| *c != '\u{304}').count();
            assert!(cols <= w, "{l}");
        }
    }
    let (lines, _) = roughtui::tui::views::contact::readout(&a.contact, 40, Glyphs::Braille, "H0");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].starts_with("p̄ = 0.01778 H0 · sim "), "{lines:?}");
    assert!(lines[1].starts_with("theory: "), "{lines:?}");
    for _ in 0..20 {
        ch(&mut a, '[');
    }
    assert_eq!(a.contact.load, 0);
}

#[test]
fn a_change_of_the_scene_cancels_the_job() {
    let engine = Engine::new(1);
    // 512²: seconds a load in a debug build.
    let mut a = app_at(64.0, (80, 24), Theme::colored(), &engine);
    to_contact(&mut a);
    assert!(a.contact.busy());
    let old = a.contact.tasks.clone();
    std::thread::sleep(Duration::from_millis(300));
    update(&mut a, Message::Tick);
    // Back to ζ = 4 (the ζ slider is selected in fig2).
    a.state.params = a.state.params.with(Axis::Zeta, 4.0).unwrap();
    update(&mut a, Message::Tick);
    assert_ne!(a.contact.tasks, old);
    settle(&mut a);
    let start = Instant::now();
    while engine.running() > 0 {
        assert!(start.elapsed() < Duration::from_secs(10), "not cancelled");
        std::thread::sleep(Duration::from_millis(10));
    }
    let solved_old = old.iter().filter(|t| engine.get(t).is_some()).count();
    assert!(solved_old < 13, "{solved_old} of the old loads solved");
}

/// A grid finer than 256² first shows the same surface sampled on 256²
/// (every second node of 512²), saying so, then its own; leaving the view
/// stops the job (no core stays busy), coming back goes on.
#[test]
fn a_coarse_answer_first_and_leaving_stops_the_work() {
    let engine = Engine::new(1);
    let mut a = app_at(64.0, (120, 36), Theme::colored(), &engine);
    to_contact(&mut a);
    assert_eq!(a.contact.grids(), (Some(512), Some(256)));
    assert_eq!(a.contact.coarse_tasks.len(), 13);
    let start = Instant::now();
    while a.contact.chosen().is_none() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no coarse answer"
        );
        std::thread::sleep(Duration::from_millis(5));
        update(&mut a, Message::Tick);
    }
    assert!(a.contact.chosen_is_coarse());
    let s = a.contact.chosen().unwrap().as_ref().unwrap();
    assert_eq!(s.map.len(), 256 * 256);
    assert!(s.result.area > 0.0 && s.result.residual <= 1e-8);
    let text = screen(&a);
    assert!(
        text.contains("simulation 256² coarse, 512² to come · seeds 1–4"),
        "{text}"
    );
    // Away: the job ends at its next iteration and nothing more is solved.
    press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    assert_ne!(a.view, View::Contact);
    update(&mut a, Message::Tick);
    let start = Instant::now();
    while engine.running() > 0 {
        assert!(start.elapsed() < Duration::from_secs(10), "still working");
        std::thread::sleep(Duration::from_millis(10));
    }
    let solves = engine.solves.load(std::sync::atomic::Ordering::Relaxed);
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(
        engine.solves.load(std::sync::atomic::Ordering::Relaxed),
        solves
    );
    // Back: the job goes on from what the cache holds.
    to_contact(&mut a);
    assert!(a.contact.busy());
    assert!(a.contact.chosen().is_some());
}

#[test]
fn results_are_cached_and_shared_between_explorers() {
    let engine = Engine::new(2);
    let mut a = app_at(4.0, (80, 24), Theme::colored(), &engine);
    let mut b = app_at(4.0, (100, 30), Theme::plain(), &engine);
    to_contact(&mut a);
    to_contact(&mut b);
    settle(&mut a);
    settle(&mut b);
    let solves = engine.solves.load(std::sync::atomic::Ordering::Relaxed);
    assert_eq!(solves, 52, "two explorers on one scene solve it once");
    // Away and back: from the cache, no job.
    a.state.params = a.state.params.with(Axis::Zeta, 2.0).unwrap();
    update(&mut a, Message::Tick);
    settle(&mut a);
    a.state.params = a.state.params.with(Axis::Zeta, 4.0).unwrap();
    update(&mut a, Message::Tick);
    assert!(!a.contact.busy());
    assert_eq!(
        engine.solves.load(std::sync::atomic::Ordering::Relaxed),
        104
    );
    assert!(a.contact.results.iter().all(|r| r.is_some()));
    // Another seed is another surface.
    ch(&mut a, 'r');
    assert_eq!(a.contact.seed, 2);
    assert!(a.contact.busy());
    // The seed is the scene's: the snapshot keeps it, and loads it back.
    assert!(a.modified);
    let ron = a.state.to_ron();
    assert!(ron.contains("seed: 2"), "{ron}");
    let back = roughtui::scene::State::from_ron(&ron).unwrap();
    assert_eq!(back.seed, Some(2));
    assert!(!presets::load("fig2").unwrap().to_ron().contains("seed"));
}

#[test]
fn b_shows_the_plastic_share_against_zeta() {
    let engine = Engine::new(2);
    let mut a = app_at(4.0, (120, 36), Theme::colored(), &engine);
    to_contact(&mut a);
    ch(&mut a, '[');
    ch(&mut a, '[');
    ch(&mut a, '[');
    ch(&mut a, '[');
    // p̄ = 1e-3 H; the job (up to 1024², slow in debug) is cancelled when
    // the test drops the explorer.
    ch(&mut a, 'b');
    assert_eq!(a.contact.plot, Plot::Share);
    assert_eq!(a.contact.tasks.len(), 16);
    assert_eq!(a.contact.theory.curves.len(), 2);
    // The theory without the size effect is never below the one with it
    // (at the same load over H0).
    for (off, on) in a.contact.theory.curves[0]
        .iter()
        .zip(&a.contact.theory.curves[1])
    {
        assert!(off.1 >= on.1 - 1e-12, "{off:?} {on:?}");
    }
    // The load is fixed in H0: the size effect's tasks are lighter over
    // their H_y.
    // At each ζ the sets in turn: H0, then H_y(R_s).
    let off = a.contact.tasks.iter().step_by(2);
    let on = a.contact.tasks.iter().skip(1).step_by(2);
    assert!(off.clone().all(|t| t.p_over_h() == 1e-3));
    assert!(off
        .zip(on.clone())
        .all(|(a, b)| a.scene.same_surface(&b.scene)));
    for t in on {
        let h_y = t.scene.hardness() / 0.01;
        assert!(
            (t.p_over_h() * h_y / 1e-3 - 1.0).abs() < 1e-12,
            "{}",
            t.p_over_h()
        );
    }
    let text = screen(&a);
    assert!(
        text.contains("plastic share vs ζ at p̄ = 0.001 H0"),
        "{text}"
    );
    assert!(text.contains("H0") && text.contains("H_y(R_s)"), "{text}");
    ch(&mut a, 'b');
    assert_eq!(a.contact.plot, Plot::Load);
}

/// `i` plots the initial slopes against ζ: each seed's five light loads at
/// each ζ, the theory's three slopes, the readout at the largest ζ.
#[test]
fn i_shows_the_initial_slopes_against_zeta() {
    use roughtui::contact::{Grid, Sampling};
    let engine = Engine::new(2);
    let mut a = app_at(4.0, (120, 36), Theme::colored(), &engine);
    a.contact.seeds = 1;
    // 64 nodes a side hold ζ = 1 … 16: the slopes' grid is 64² here.
    a.contact.sampling = Sampling {
        cell: 1,
        grid: Grid::Side(64),
        ..Sampling::default()
    };
    to_contact(&mut a);
    ch(&mut a, 'i');
    assert_eq!(a.contact.plot, Plot::Slopes);
    assert_eq!(a.contact.zetas, [1.0, 2.0, 4.0, 8.0, 16.0]);
    assert_eq!(a.contact.tasks.len(), 5 * 5);
    assert_eq!(a.contact.theory.curves.len(), 3);
    settle(&mut a);
    let st = a.contact.slopes_at(4).unwrap();
    assert!(st[2].mean > 0.0 && st[2].n == 1, "{st:?}");
    let text = screen(&a);
    assert!(text.contains("initial slopes vs ζ · seed 1"), "{text}");
    assert!(text.contains("ζ = 16: sim total"), "{text}");
    // p: the slopes' picture (the paper's figure with the points) and the
    // surface's heights.
    let dir = tempfile::tempdir().unwrap();
    a.save_dir = dir.path().to_path_buf();
    ch(&mut a, 'p');
    let st = a.status.clone().unwrap();
    assert!(!st.error && st.text.starts_with("saved "), "{}", st.text);
    let files = common::files_in(dir.path());
    assert_eq!(files.len(), 2, "{files:?}");
    let svg = files.iter().find(|f| f.ends_with(".svg")).unwrap();
    let svg = std::fs::read_to_string(dir.path().join(svg)).unwrap();
    assert!(
        svg.contains("initial slopes against ζ, theory and simulation"),
        "{svg}"
    );
    ch(&mut a, 'b');
    assert_eq!(a.contact.plot, Plot::Share);
    ch(&mut a, 'b');
    assert_eq!(a.contact.plot, Plot::Load);
}

/// `A` gives each contact patch its asperity's hardness: without the size
/// effect the view says to switch it on; with it the scene is solved with
/// a cap per node, the title says so, and `b` compares the bulk's one cap
/// (size effect off) with the hardness per asperity (on).
#[test]
fn a_gives_each_asperity_its_hardness() {
    let engine = Engine::new(1);
    let mut a = app_at(4.0, (160, 48), Theme::colored(), &engine);
    a.contact.seeds = 1;
    to_contact(&mut a);
    ch(&mut a, 'A');
    assert_eq!(
        a.contact.sampling.hardness,
        roughtui::contact::Hardness::Asperity
    );
    let text = screen(&a);
    assert!(
        text.contains("the size effect's, so e switches it on"),
        "{text}"
    );
    assert!(
        text.contains("a hardness per asperity is the size"),
        "{text}"
    );
    ch(&mut a, 'e');
    settle(&mut a);
    let text = screen(&a);
    assert!(
        text.contains("simulation 32² · seed 1 · cell 1 · 8 nodes/λ · H per asperity"),
        "{text}"
    );
    assert!(a.contact.tasks.iter().all(|t| t.scene.local.is_some()));
    let r = a.contact.chosen().unwrap().as_ref().unwrap();
    assert!(r.result.area > 0.0);
    // The readout names the caps in use and the share at them; the load's
    // unit is the theory's H_y(R_s), which no node is capped at.
    let share = roughtui::tui::views::contact::share_pct(r.result.plastic_area, r.result.area);
    assert!(text.contains("caps each asperity's H_y: sim "), "{text}");
    assert!(text.contains(&format!("{share} % at its cap")), "{text}");
    assert!(text.contains("at its asperity's H_y"), "{text}");
    ch(&mut a, 'b');
    // At each ζ: H0 (size effect off), H_y(R_s) (on, one cap), per
    // asperity.
    let ts = &a.contact.tasks;
    assert!(ts.iter().step_by(3).all(|t| t.scene.local.is_none()));
    assert!(ts
        .iter()
        .skip(1)
        .step_by(3)
        .all(|t| t.scene.local.is_none()));
    assert!(ts
        .iter()
        .skip(2)
        .step_by(3)
        .all(|t| t.scene.local.is_some()));
    assert!(screen(&a).contains("per asperity"));
    // A again: per summit, then one cap.
    ch(&mut a, 'A');
    assert_eq!(
        a.contact.sampling.hardness,
        roughtui::contact::Hardness::Summit
    );
    assert!(screen(&a).contains("per summit"));
    ch(&mut a, 'A');
    assert!(a.contact.tasks.iter().all(|t| t.scene.local.is_none()));
    assert!(screen(&a).contains("one hardness cap for every node"));
}

/// `b` averages over the pane's seeds as the load plot does: each point
/// the mean of the seeds' plastic shares, ± one sd drawn, the title and
/// the legend saying how many.
#[test]
fn b_averages_the_plastic_share_over_the_seeds() {
    use roughtui::contact::{Grid, Sampling};
    let engine = Engine::new(2);
    let mut a = app_at(4.0, (120, 36), Theme::colored(), &engine);
    // 64 nodes a side hold ζ = 1 … 16 (five points; fast in a debug build).
    a.contact.sampling = Sampling {
        cell: 1,
        grid: Grid::Side(64),
        ..Sampling::default()
    };
    to_contact(&mut a);
    // p̄ = 0.1 H0: part of the contact at the hardness.
    for _ in 0..4 {
        ch(&mut a, ']');
    }
    ch(&mut a, 'b');
    assert_eq!(a.contact.zetas, [1.0, 2.0, 4.0, 8.0, 16.0]);
    assert_eq!(a.contact.tasks.len(), 10);
    assert_eq!(a.contact.seed_tasks.len(), 3, "four seeds by default");
    let seeds: Vec<u64> = std::iter::once(&a.contact.tasks)
        .chain(&a.contact.seed_tasks)
        .map(|ts| ts[0].scene.seed)
        .collect();
    assert_eq!(seeds, [1, 2, 3, 4]);
    settle(&mut a);
    assert_eq!(a.contact.seeds_in(), 4);
    // At ζ = 16, size effect off: the mean and sample sd of the four
    // seeds' own shares.
    let shares: Vec<f64> = std::iter::once(&a.contact.results)
        .chain(&a.contact.seed_results)
        .map(|rs| {
            // ζ = 16 is the fifth ζ, its first set H0: task 4 × 2 + 0.
            let r = rs[8].as_ref().unwrap().as_ref().unwrap().result;
            r.plastic_area / r.area
        })
        .collect();
    let mean = shares.iter().sum::<f64>() / 4.0;
    let sd = (shares.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 3.0).sqrt();
    let st = a.contact.share_at(0, 4).unwrap();
    assert_eq!(st.n, 4);
    assert!((st.mean - mean).abs() < 1e-15 && (st.sd - sd).abs() < 1e-15);
    assert!(st.sd > 0.0, "four surfaces differ: {shares:?}");
    let text = screen(&a);
    assert!(
        text.contains("plastic share vs ζ at p̄ = 0.1 H0 · seeds 1–4"),
        "{text}"
    );
    // The row over the chart: each set's share at the largest ζ, in
    // numbers (the H0 set's is the mean ± sd just computed).
    let h0 = roughtui::tui::views::contact::share_pm(&st);
    assert!(text.contains(&format!("ζ = 16: H0 {h0} %")), "{text}");
    // R: sixteen seeds, then one, as on the load plot.
    ch(&mut a, 'R');
    assert_eq!(a.contact.seed_tasks.len(), 15);
    ch(&mut a, 'R');
    assert!(a.contact.seed_tasks.is_empty());
    settle(&mut a);
    let text = screen(&a);
    assert!(
        text.contains("plastic share vs ζ at p̄ = 0.1 H0 · seed 1"),
        "{text}"
    );
    assert_eq!(a.contact.share_at(0, 4).unwrap().n, 1);
}

#[test]
fn beyond_the_grid_the_view_says_what_it_resolves() {
    let engine = Engine::new(1);
    let mut a = app_at(1000.0, (120, 36), Theme::colored(), &engine);
    to_contact(&mut a);
    assert!(!a.contact.busy());
    assert!(a.contact.tasks.is_empty());
    let text = screen(&a);
    assert!(text.contains("ζ = 1000 in a cell of 1 longest"), "{text}");
    assert!(text.contains("simulation solves up to 4096"), "{text}");
    assert_eq!(engine.running(), 0);
}

fn snapshot(name: &str, zeta: f64, size: (u16, u16), theme: Theme) {
    let engine = Engine::new(1);
    let mut a = app_at(zeta, size, theme, &engine);
    to_contact(&mut a);
    settle(&mut a);
    // The solve time varies: the title's tail is left out.
    let text: String = screen(&a)
        .lines()
        .map(|l| match l.find(" solved, ") {
            Some(i) => l[..i].to_string(),
            None => l.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    insta::assert_snapshot!(name, text);
}

#[test]
fn snapshots() {
    snapshot("contact_fig2_z8_80x24", 8.0, (80, 24), Theme::colored());
    snapshot("contact_fig2_z8_120x36", 8.0, (120, 36), Theme::colored());
    snapshot("contact_fig2_z8_80x24_plain", 8.0, (80, 24), Theme::plain());
    let ascii = Theme::colored().with_glyphs(Glyphs::Ascii);
    snapshot("contact_fig2_z8_80x24_ascii", 8.0, (80, 24), ascii);
}

#[test]
fn p_saves_the_contact_map_at_the_chosen_load() {
    let engine = Engine::new(1);
    let dir = tempfile::tempdir().unwrap();
    let mut a = app_at(4.0, (80, 24), Theme::colored(), &engine);
    a.save_dir = dir.path().to_path_buf();
    to_contact(&mut a);
    settle(&mut a);
    ch(&mut a, ']');
    ch(&mut a, 'p');
    let st = a.status.clone().unwrap();
    assert!(!st.error && st.text.starts_with("saved "), "{}", st.text);
    // The picture and the surface's heights, as the view solves them.
    let files = common::files_in(dir.path());
    assert_eq!(files.len(), 2, "{files:?}");
    assert!(
        files.iter().all(|f| f.starts_with("fig2-contact")),
        "{files:?}"
    );
    assert!(
        st.text.contains("--surface FILE --periodic reads them"),
        "{}",
        st.text
    );
    let heights = files.iter().find(|f| f.ends_with("-surface.txt")).unwrap();
    let heights = std::fs::read_to_string(dir.path().join(heights)).unwrap();
    assert!(heights.starts_with(
        "# Channel: Height (roughtui synthetic surface of scene \"fig2\", seed 1)\n\
         # Width: 0.00006283185307179586 m\n"
    ));
    assert_eq!(heights.lines().filter(|l| !l.starts_with('#')).count(), 32);
    let svg = files.iter().find(|f| f.ends_with(".svg")).unwrap();
    let svg = std::fs::read_to_string(dir.path().join(svg)).unwrap();
    assert!(
        svg.contains("fig2 — contact map at p̄ = 0.01778 H0") && svg.contains("32×32 nodes, seed 1"),
        "{svg}"
    );
    // b's plot has no picture here: the heights are saved, the status says
    // where to get the picture.
    ch(&mut a, 'b');
    ch(&mut a, 'p');
    let st = a.status.clone().unwrap();
    assert!(
        !st.error && st.text.contains("--view contact-sweep --format svg"),
        "{}",
        st.text
    );
    assert_eq!(common::files_in(dir.path()).len(), 3);
}

/// A measured map's heights are read for the contact view alone: the other
/// views never open its file again (a 4096² map's would take a second and
/// 134 MB on the first screen).
#[test]
fn a_measured_maps_heights_are_read_for_the_contact_view_alone() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("map.txt");
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/measured_contact/periodic64.txt");
    // A byte more than the committed map: no other test's kept heights.
    let mut text = std::fs::read(data).unwrap();
    text.push(b'\n');
    std::fs::write(&path, text).unwrap();
    let opts = rough_surface::Options {
        periodic: true,
        ..Default::default()
    };
    let src = roughtui::surface::SurfaceSource::read(&path, opts).unwrap();
    let state = roughtui::scene::State::measured(src).unwrap();
    // Gone from the disk: a view that read the file again would fail.
    std::fs::remove_file(&path).unwrap();
    let mut a = App::new(state, Theme::colored(), (120, 36));
    a.contact.engine = Engine::new(1);
    for axis in [2, 0] {
        a.selected = axis;
        for up in [true, false, true] {
            update(&mut a, Message::Step { up, fine: false });
            assert!(a.contact.why_not.is_none() && a.contact.tasks.is_empty());
        }
    }
    assert!(!screen(&a).contains("map.txt: cannot"), "{}", screen(&a));
    // The contact view reads it, on a thread of its own: meanwhile the
    // view says so, then why it cannot.
    to_contact(&mut a);
    let why = a.contact.why_not.clone().expect("the view says why not");
    assert!(why.contains("map.txt"), "{why}");
    settle(&mut a);
    let why = a.contact.why_not.clone().expect("the file is gone");
    assert!(why.contains("map.txt") && !why.contains("reading"), "{why}");
    assert!(a.contact.tasks.is_empty());
}

/// While a measured map's heights are read the contact view says so and
/// the explorer goes on: leaving the view stops the waiting (nothing ticks
/// off screen), and coming back after the read solves the map.
#[test]
fn the_contact_view_waits_on_a_slow_file_without_the_explorer() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("slow.txt");
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/measured_contact/periodic64.txt");
    // Two bytes more than the committed map: no other test's kept heights.
    let mut text = std::fs::read(data).unwrap();
    text.extend_from_slice(b"\n\n");
    std::fs::write(&path, &text).unwrap();
    let opts = rough_surface::Options {
        periodic: true,
        ..Default::default()
    };
    let src = roughtui::surface::SurfaceSource::read(&path, opts).unwrap();
    let mut state = roughtui::scene::State::measured(src).unwrap();
    state.params = state.params.with(Axis::Zeta, 4.0).unwrap();
    // The file becomes a pipe: reading it waits until the text is written.
    std::fs::remove_file(&path).unwrap();
    let made = std::process::Command::new("mkfifo")
        .arg(&path)
        .status()
        .unwrap();
    assert!(made.success());
    let mut a = App::new(state, Theme::colored(), (120, 36));
    a.contact.engine = Engine::new(1);
    to_contact(&mut a);
    assert!(a.contact.busy());
    let why = a.contact.why_not.clone().unwrap();
    assert!(
        why.contains("reading the heights of slow.txt for the simulation"),
        "{why}"
    );
    assert!(screen(&a).contains("reading the heights of slow.txt"));
    // The explorer answers meanwhile; off the view nothing waits.
    a.selected = 0;
    update(
        &mut a,
        Message::Step {
            up: true,
            fine: false,
        },
    );
    update(
        &mut a,
        Message::Step {
            up: false,
            fine: false,
        },
    );
    press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    assert_ne!(a.view, View::Contact);
    assert!(!a.contact.busy());
    // The text arrives; back on the view the map is solved.
    let writer = std::thread::spawn(move || std::fs::write(&path, text).unwrap());
    writer.join().unwrap();
    to_contact(&mut a);
    settle(&mut a);
    assert!(a.contact.why_not.is_none(), "{:?}", a.contact.why_not);
    assert!(matches!(a.contact.chosen(), Some(Ok(_))));
}
