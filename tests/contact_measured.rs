//! The contact simulation of a measured map.
//!
//! - Against Tamaas's `KatoSaturated` (scripts/measured_contact_reference.py
//!   wrote tests/data/measured_contact/): a periodic 64² map from
//!   SurfaceTopography's `fourier_synthesis`, read as a user reads it, at
//!   ζ = 8 and H_use = 0.05 E*: areas within 0.5 % (never finer than one
//!   node), pressures within 1e-6 relative L2.
//! - The CLI on maps written here: a non-square, non-periodic map cropped
//!   to its centred power-of-two square on the free boundary; the map, the
//!   sweep and the refusals of what has no heights on a grid.

mod common;

use common::cli::{run, stdout};
use rough_model::Axis;
use roughtui::contact::Simulation;
use roughtui::scene::State;
use roughtui::surface::SurfaceSource;
use std::path::{Path, PathBuf};

const N: usize = 64;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/measured_contact")
        .join(name)
}

fn reference() -> Vec<[f64; 5]> {
    let text = std::fs::read_to_string(data("cases.csv")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("k,"))
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
            [f[0], f[1], f[2], f[3], f[4]]
        })
        .collect()
}

fn pressure(k: usize) -> Vec<f64> {
    let bytes = std::fs::read(data(&format!("{k}.pressure.f32"))).unwrap();
    assert_eq!(bytes.len(), 4 * N * N);
    bytes
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
        .collect()
}

fn scene() -> State {
    let opts = rough_surface::Options {
        periodic: true,
        ..Default::default()
    };
    let src = SurfaceSource::read(&data("periodic64.txt"), opts).unwrap();
    let mut s = State::measured(src).unwrap();
    s.params = s.params.with(Axis::Zeta, 8.0).unwrap();
    s.params = s.params.with(Axis::H0OverE, 0.05).unwrap();
    s.size_effect = false;
    s
}

#[test]
fn a_periodic_map_agrees_with_tamaas() {
    let state = scene();
    let mut sim = Simulation::of(&state, 1).unwrap();
    assert_eq!(sim.contact.n(), N);
    assert!((sim.hardness - 0.05).abs() < 1e-15, "{}", sim.hardness);
    let how = sim.measured.clone().unwrap();
    assert!(how.starts_with("periodic, measured 64 × 64 map"), "{how}");
    let cases = reference();
    assert_eq!(cases.len(), 3);
    let cell = 1.0 / (N * N) as f64;
    for [k, p_over_h, area, elastic, plastic] in cases {
        let (r, theory) = sim.solve(p_over_h, &mut |_, _| true).unwrap();
        for (what, ours, theirs) in [
            ("area", r.area, area),
            ("elastic", r.elastic_area, elastic),
            ("plastic", r.plastic_area, plastic),
        ] {
            assert!(
                (ours - theirs).abs() <= (0.005 * theirs).max(cell * 1.01),
                "{what} at p/H = {p_over_h}: {ours} vs Tamaas {theirs}"
            );
        }
        let want = pressure(k as usize);
        let got = sim.contact.pressure();
        let (mut d, mut w) = (0.0, 0.0);
        for (a, b) in got.iter().zip(&want) {
            d += (a - b) * (a - b);
            w += b * b;
        }
        let rel = (d / w).sqrt();
        assert!(
            rel < 1e-6,
            "pressure at p/H = {p_over_h}: relative L2 {rel:e}"
        );
        let mean = got.iter().sum::<f64>() / got.len() as f64;
        assert!((mean - p_over_h * 0.05).abs() <= 1e-12 * p_over_h * 0.05);
        // The theory's columns are the model's areas on the map's moments.
        assert!(theory.total > 0.0 && theory.total < 1.0, "{theory:?}");
    }
}

/// A smooth non-periodic map of nx × ny points, 1 nm pixels, heights in nm.
fn write_map(dir: &Path, nx: usize, ny: usize) -> PathBuf {
    let mut text = format!("# Width: {nx} nm\n# Height: {ny} nm\n# Value units: nm\n");
    for j in 0..ny {
        let row: Vec<String> = (0..nx)
            .map(|i| {
                let (x, y) = (i as f64, j as f64);
                let h = 3.0 * (x / 7.0).sin() * (y / 5.0).cos()
                    + 2.0 * ((x + 2.0 * y) / 11.0).sin()
                    + 0.5 * ((3.0 * x - y) / 4.0).cos()
                    + 0.01 * x;
                format!("{h:.6}")
            })
            .collect();
        text.push_str(&row.join("\t"));
        text.push('\n');
    }
    let p = dir.join(format!("map{nx}x{ny}.txt"));
    std::fs::write(&p, text).unwrap();
    p
}

fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

#[test]
fn the_cli_solves_a_non_square_map_on_the_free_boundary() {
    let dir = tempfile::tempdir().unwrap();
    let map = write_map(dir.path(), 80, 72);
    let m = map.to_str().unwrap();
    let csv = stdout(&[
        "export",
        "--view",
        "contact",
        "--surface",
        m,
        "--points",
        "4",
    ]);
    assert!(
        csv.contains(
            "free-boundary (zero-padded 2N × 2N), measured 80 × 72 map cropped to its centred \
             64 × 64"
        ),
        "{csv}"
    );
    let r = rows(&csv);
    assert_eq!(r.len(), 4);
    for row in &r {
        assert_eq!(row.len(), 17);
        // Contact grows with the load; parts add up; the solver converged.
        assert!((row[1] - row[2] - row[3]).abs() < 1e-12);
        assert!(row[6] <= 1e-10, "residual {}", row[6]);
    }
    assert!(r.windows(2).all(|w| w[1][1] > w[0][1]));
    assert_eq!(&r[3][1..4], &[1.0, 0.0, 1.0]);

    // The map at p̄ = 0.01 H: 64 lines of 64 nodes.
    let map_csv = stdout(&["export", "--view", "contact-map", "--surface", m]);
    let grid: Vec<&str> = map_csv.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(grid.len(), 64);
    assert!(grid.iter().all(|l| l.split(',').count() == 64));

    // The sweep runs from the first ζ with a mode on the 64-point square
    // (80/64) to the data's largest (the 80-point side's Nyquist, 40·√2).
    let sweep = stdout(&["export", "--view", "contact-sweep", "--surface", m]);
    let zetas: Vec<f64> = rows(&sweep).iter().map(|r| r[0]).collect();
    assert_eq!(zetas, [2.0, 4.0, 8.0, 16.0, 32.0]);
    refused(
        &[
            "export",
            "--view",
            "contact",
            "--surface",
            m,
            "--set",
            "zeta=1",
        ],
        &["keeps no wavelength shorter", "ζ ≥ 1.250"],
    );
}

/// Exit 2 with each of `words` in the message, nothing on stdout.
fn refused(args: &[&str], words: &[&str]) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty());
    for w in words {
        assert!(err.contains(w), "wants {w:?} in {err}");
    }
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn what_has_no_heights_on_a_grid_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let psd = dir.path().join("psd.txt");
    let mut text = String::from("# q (1/m), C^iso (m^4)\n");
    for e in 5..=9 {
        let q = 10f64.powi(e);
        text.push_str(&format!("{q:e} {:e}\n", 1e-8 * q.powf(-3.6)));
    }
    std::fs::write(&psd, text).unwrap();
    let p = psd.to_str().unwrap();
    for view in ["contact", "contact-sweep", "contact-map"] {
        refused(
            &["export", "--view", view, "--surface", p],
            &["needs heights on a grid", "psd.txt", "a PSD table"],
        );
    }
    let map = write_map(dir.path(), 80, 72);
    let m = map.to_str().unwrap();
    refused(
        &[
            "export",
            "--view",
            "contact",
            "--surface",
            m,
            "--direction",
            "x",
        ],
        &["needs heights on a grid", "a map read as profiles"],
    );
    // Too few points for a solver's square.
    let small = write_map(dir.path(), 20, 40);
    refused(
        &[
            "export",
            "--view",
            "contact",
            "--surface",
            small.to_str().unwrap(),
        ],
        &["20 × 40 points", "at least 32 × 32"],
    );
}

#[test]
fn the_explorer_solves_a_measured_map_in_its_contact_view() {
    use crossterm::event::{KeyCode, KeyModifiers};
    use roughtui::contact::engine::Engine;
    use roughtui::figure::View;
    use roughtui::tui::app::{update, App, Message};
    use roughtui::tui::theme::Theme;
    use std::sync::Arc;
    use std::time::{Duration, Instant};

    let engine = Engine::new(1);
    let mut a = App::new(scene(), Theme::colored(), (160, 48));
    a.contact.engine = Arc::clone(&engine);
    while a.view != View::Contact {
        common::app::press(&mut a, KeyCode::Tab, KeyModifiers::NONE);
    }
    let start = Instant::now();
    while a.contact.busy() {
        assert!(start.elapsed() < Duration::from_secs(120), "solver hung");
        std::thread::sleep(Duration::from_millis(5));
        update(&mut a, Message::Tick);
    }
    assert!(a.contact.why_not.is_none(), "{:?}", a.contact.why_not);
    let s = a.contact.chosen().unwrap().as_ref().unwrap();
    assert_eq!(s.map.len(), N * N);
    // p̄ = 0.01 H: Tamaas's area at that load (the second reference row).
    let area = reference()[1][2];
    assert!((s.result.area - area).abs() <= 1.01 / (N * N) as f64);
    let text = common::app::screen(&a);
    assert!(text.contains("simulation 64² · measured map"), "{text}");
    assert!(
        text.contains("simulation at p̄ = 0.01 H0: contact"),
        "{text}"
    );
    // No seed to change.
    update(&mut a, Message::ContactSeed);
    let st = a.status.clone().unwrap();
    assert!(
        st.text.contains("a measured map has no seed"),
        "{}",
        st.text
    );
    // b: the ζ the map resolves (to 32·√2), with H0 and with H_y.
    update(&mut a, Message::ContactSweep);
    let start = Instant::now();
    loop {
        update(&mut a, Message::Tick);
        if !a.contact.busy() {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(120), "solver hung");
        std::thread::sleep(Duration::from_millis(5));
    }
    assert!(a.contact.why_not.is_none(), "{:?}", a.contact.why_not);
    assert_eq!(a.contact.zetas, [1.0, 2.0, 4.0, 8.0, 16.0, 32.0]);
    assert_eq!(a.contact.results.len(), 12);
    assert!(a.contact.results.iter().all(|r| matches!(r, Some(Ok(_)))));
    assert_eq!(a.contact.theory.curves.len(), 2);
    assert!(a.contact.theory.curves.iter().all(|c| c.len() > 10));
    let text = common::app::screen(&a);
    assert!(text.contains("plastic share vs ζ"), "{text}");
}

#[test]
fn the_cache_key_names_the_file_and_how_it_was_read() {
    use roughtui::contact::scene::SceneKey;
    let (a, b) = (scene(), scene());
    let ka = SceneKey::of(&a, 1).unwrap();
    // Same file, same reading, any seed: one key (the engine shares it).
    assert_eq!(ka, SceneKey::of(&b, 7).unwrap());
    let sha = a.surface.as_ref().unwrap().measured.sha256.clone();
    let id = ka.surface.unwrap();
    let hex: String = id.0.iter().map(|b| format!("{b:02x}")).collect();
    assert_eq!(hex, sha);
    // Read without --periodic: another key (and the free boundary).
    let src = SurfaceSource::read(&data("periodic64.txt"), Default::default()).unwrap();
    let mut c = State::measured(src).unwrap();
    c.params = a.params;
    c.size_effect = false;
    let kc = SceneKey::of(&c, 1).unwrap();
    assert_ne!(ka, kc);
    assert_eq!(ka.surface.unwrap().0, kc.surface.unwrap().0);
    let sim = Simulation::of(&c, 1).unwrap();
    assert!(sim.measured.unwrap().starts_with("free-boundary"));
}

#[test]
fn big_and_odd_maps_are_planned_as_documented() {
    use rough_contact::Boundary;
    use rough_surface::Heights;
    use roughtui::contact::measured::plan;
    let tau = std::f64::consts::TAU;
    let map = |nx: usize, ny: usize, periodic: bool| Heights {
        nx,
        ny,
        lx: nx as f64 * 1e-8,
        ly: ny as f64 * 1e-8,
        periodic,
        z: vec![],
    };
    // A 4096² periodic map: ζ = 16 of its q0 wants 8 × 16 = 128 nodes.
    let h = map(4096, 4096, true);
    let q0 = tau / h.lx;
    let p = plan(&h, 16.0 * q0).unwrap();
    assert_eq!((p.crop, p.n, p.boundary), (4096, 128, Boundary::Periodic));
    // ζ = 200 wants 1600 nodes: beyond the solver's 1024.
    let e = plan(&h, 200.0 * q0).unwrap_err().to_string();
    assert!(e.contains("solves up to 1024"), "{e}");
    // A 3000 × 2000 map: its centred 1024² on the free boundary, the data's
    // own resolution at the largest ζ.
    let h = map(3000, 2000, true);
    let q0 = tau / h.lx;
    let p = plan(&h, 1500.0 * q0).unwrap();
    assert_eq!((p.crop, p.n, p.boundary), (1024, 1024, Boundary::Free));
    assert!((p.length - 1024e-8).abs() < 1e-20);
    // Pixels that are not square.
    let mut h = map(256, 256, false);
    h.ly *= 2.0;
    let e = plan(&h, 1e8).unwrap_err().to_string();
    assert!(e.contains("square pixels"), "{e}");
}

#[test]
fn a_solve_finds_any_loaded_copy_of_the_map() {
    use roughtui::contact::scene::SceneKey;
    // A file of its own (another SHA-256 than the other tests' map).
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("copy.txt");
    let text = std::fs::read_to_string(data("periodic64.txt")).unwrap();
    std::fs::write(&path, format!("# a copy\n{text}")).unwrap();
    let read_file = |path: &Path| {
        let opts = rough_surface::Options {
            periodic: true,
            ..Default::default()
        };
        let mut s = State::measured(SurfaceSource::read(path, opts).unwrap()).unwrap();
        s.params = scene().params;
        s
    };
    let read = || read_file(&path);
    // Exploring keeps no heights; the first solve reads them.
    let first = read();
    assert!(first.surface.as_ref().unwrap().measured.heights.is_none());
    let key = SceneKey::of(&first, 1).unwrap();
    // Two explorers read the same file; the one that read it last leaves.
    let second = read();
    assert_eq!(SceneKey::of(&second, 1).unwrap(), key);
    drop(second);
    assert_eq!(key.build().unwrap().n(), N);
    drop(first);
    // The last surfaces solved stay in memory ...
    assert_eq!(key.build().unwrap().n(), N);
    // ... until as many others were solved.
    for k in 0..roughtui::contact::measured::KEPT {
        let other = dir.path().join(format!("other{k}.txt"));
        std::fs::write(&other, format!("# another copy {k}\n{text}")).unwrap();
        let s = read_file(&other);
        SceneKey::of(&s, 1).unwrap();
    }
    let e = key.build().err().unwrap().to_string();
    assert!(e.contains("no longer loaded"), "{e}");
}

#[test]
fn a_map_changed_since_it_was_read_is_named_not_solved() {
    use roughtui::contact::scene::SceneKey;
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("changed.txt");
    let text = std::fs::read_to_string(data("periodic64.txt")).unwrap();
    std::fs::write(&path, format!("# before\n{text}")).unwrap();
    let opts = rough_surface::Options {
        periodic: true,
        ..Default::default()
    };
    let mut s = State::measured(SurfaceSource::read(&path, opts).unwrap()).unwrap();
    s.params = scene().params;
    std::fs::write(&path, format!("# after\n{text}")).unwrap();
    let e = SceneKey::of(&s, 1).err().unwrap().to_string();
    assert!(e.contains("changed since it was read"), "{e}");
    // The file is left as it is.
    assert!(std::fs::read_to_string(&path)
        .unwrap()
        .starts_with("# after"));
}
