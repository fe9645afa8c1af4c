//! The contact engine's cache as the explorer meets it: a scene's own grid
//! starts each load from the same load's coarse answer (same areas, fewer
//! iterations), and only the drawn seed's maps are kept (a further seed's
//! result has none, and a job that draws it solves it again with one).

use std::sync::Arc;
use std::time::{Duration, Instant};

use rough_model::Axis;
use roughtui::contact::engine::{Engine, Task, Ticket};
use roughtui::contact::scene::SceneKey;
use roughtui::contact::Sampling;
use roughtui::presets;

fn key(zeta: f64, seed: u64) -> SceneKey {
    let mut s = presets::load("fig2").unwrap();
    s.params = s.params.with(Axis::Zeta, zeta).unwrap();
    let sampling = Sampling {
        cell: 1,
        ..Sampling::default()
    };
    SceneKey::with(&s, seed, &sampling).unwrap()
}

fn wait(t: &Ticket) {
    let start = Instant::now();
    while !t.progress().finished {
        assert!(start.elapsed() < Duration::from_secs(300), "solver hung");
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn solve(engine: &Arc<Engine>, tasks: Vec<Task>) {
    let t = engine.request(tasks, 0, Arc::new(|| {}));
    wait(&t);
}

#[test]
fn a_scene_starts_from_its_coarse_answer() {
    // fig2 at ζ = 32: 256², its coarse answer 128².
    let fine = key(32.0, 1);
    let coarse = fine.coarser(128).unwrap();
    assert_eq!((fine.side(), coarse.side()), (256, 128));
    let (f, c) = (Task::new(fine, 0.01), Task::new(coarse, 0.01));
    let warm = Engine::new(1);
    solve(&warm, vec![c, f]);
    let cold = Engine::new(1);
    solve(&cold, vec![f]);
    let got = |e: &Engine, t: &Task| e.get(t).unwrap().unwrap();
    let (w, k, cw) = (got(&warm, &f), got(&cold, &f), got(&warm, &c));
    // The coarse answer keeps its pressure for the start; the fine one not.
    assert_eq!(cw.pressure.as_ref().map(Vec::len), Some(128 * 128));
    assert!(w.pressure.is_none() && k.pressure.is_none());
    // The same contact (the solver's tolerance), in fewer iterations.
    let rel = |a: f64, b: f64| (a - b).abs() / b;
    assert!(
        rel(w.result.area, k.result.area) < 1e-3,
        "{:?} {:?}",
        w.result,
        k.result
    );
    let dp = (w.result.plastic_area - k.result.plastic_area).abs();
    assert!(dp <= 1e-3 * k.result.area, "plastic {dp:e}");
    assert!(
        w.result.iterations < k.result.iterations,
        "from the coarse answer {} iterations, cold {}",
        w.result.iterations,
        k.result.iterations
    );
    // The maps agree but for the nodes at the edge of contact.
    let differ = w.map.iter().zip(&k.map).filter(|(a, b)| a != b).count();
    assert!(differ * 1000 < w.map.len(), "{differ} nodes differ");
}

#[test]
fn only_the_drawn_seeds_maps_are_kept() {
    let engine = Engine::new(1);
    let (one, two) = (Task::new(key(4.0, 1), 0.01), Task::new(key(4.0, 2), 0.01));
    solve(&engine, vec![one, two]);
    let map = |t: &Task| engine.get(t).unwrap().unwrap().map.len();
    assert_eq!((map(&one), map(&two)), (32 * 32, 0));
    assert!(engine.has(&two, false) && !engine.has(&two, true));
    let area = engine.get(&two).unwrap().unwrap().result.area;
    // A job drawing seed 2 solves it again, with its map; seed 1 stays.
    let before = engine.solves.load(std::sync::atomic::Ordering::Relaxed);
    solve(&engine, vec![two, one]);
    let after = engine.solves.load(std::sync::atomic::Ordering::Relaxed);
    assert_eq!(after - before, 1);
    assert_eq!((map(&one), map(&two)), (32 * 32, 32 * 32));
    assert_eq!(engine.get(&two).unwrap().unwrap().result.area, area);
}
