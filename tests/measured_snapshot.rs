//! Snapshots of a measured surface: the file recorded by its path relative
//! to the snapshot and its SHA-256 (and how it was read), loaded back
//! exactly; a missing, refused or changed file says which and why, and no
//! file of the user's is ever changed.

mod common;

use std::path::{Path, PathBuf};

use roughtui::scene::State;
use roughtui::snapshot::{load_file, save_new};
use roughtui::surface::SurfaceSource;
use roughtui::tui::app::App;
use roughtui::tui::theme::Theme;

/// fig2's spectrum as a PSD table (see measured_cli.rs).
fn fig2_table(dir: &Path) -> PathBuf {
    let mut text = String::from("# fig2's power law: q (1/m), C^iso (m^4)\n");
    for e in 5..=9 {
        let q = 10f64.powi(e);
        let c = (2.0 * std::f64::consts::PI).powi(2) * 1e-8 * q.powf(-3.6);
        text.push_str(&format!("{q:e} {c:e}\n"));
    }
    let p = dir.join("fig2-psd.txt");
    std::fs::write(&p, text).unwrap();
    p
}

fn surface_state(path: &Path, options: rough_surface::Options) -> State {
    State::measured(SurfaceSource::read(path, options).unwrap()).unwrap()
}

#[test]
fn a_surface_snapshot_loads_back_exactly() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let mut s = surface_state(&t, Default::default());
    roughtui::scene::set(&mut s, rough_model::Axis::H0OverE, "0.003").unwrap();
    roughtui::scene::set(&mut s, rough_model::Axis::Zeta, "300").unwrap();
    let p = save_new(d.path(), "mine", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    let sha = &s.surface.as_ref().unwrap().measured.sha256;
    assert!(
        text.contains(&format!(
            "    surface: (path: \"fig2-psd.txt\", sha256: \"{sha}\"),\n"
        )),
        "{text}"
    );
    assert_eq!(load_file(&p).unwrap(), s);
    // From another folder the path goes up; any working folder loads it.
    let sub = d.path().join("lectures").join("week 3");
    std::fs::create_dir_all(&sub).unwrap();
    let p = save_new(&sub, "mine", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains("path: \"../../fig2-psd.txt\""), "{text}");
    assert_eq!(load_file(&p).unwrap(), s);
    assert_eq!(
        State::from_bytes_in(text.as_bytes(), Some(&sub)).unwrap(),
        s
    );
}

#[test]
fn how_it_was_read_is_recorded() {
    // A header-less height matrix (SurfaceTopography's fourier_synthesis,
    // rough-surface's test data): read with a pixel size, as periodic.
    let d = tempfile::tempdir().unwrap();
    let t = d.path().join("map_pixel.txt");
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/rough-surface/tests/data/map_pixel.txt"),
        &t,
    )
    .unwrap();
    let opts = rough_surface::Options {
        periodic: true,
        pixel_size: Some(5e-8),
        ..Default::default()
    };
    let s = surface_state(&t, opts.clone());
    let p = save_new(d.path(), "read", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(
        text.contains(", periodic: true, pixel_size: 5e-8),"),
        "{text}"
    );
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    assert_eq!(back.surface.unwrap().options, opts);
}

#[test]
fn the_direction_and_the_measurement_are_recorded() {
    let d = tempfile::tempdir().unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/rough-surface/tests/data");
    // A lay (scripts/direction_reference.py) read along y.
    let t = d.path().join("map_lay.txt");
    std::fs::copy(data.join("map_lay.txt"), &t).unwrap();
    let opts = rough_surface::Options {
        direction: Some(rough_surface::Direction::Y),
        ..Default::default()
    };
    let s = surface_state(&t, opts.clone());
    let p = save_new(d.path(), "lay", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains(", direction: y),"), "{text}");
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    assert_eq!(back.surface.unwrap().options, opts);
    // The second measurement of a contact.engineering download.
    let mut ce = String::new();
    for (name, k) in [("steel", 1.0), ("glass", 3.0)] {
        ce.push_str(&format!(
            "# Topography: {name}\n# q/π × 2D PSD\n# Columns: Wavevector (1/m), PSD (m³)\n"
        ));
        for e in 5..=9 {
            let q = 10f64.powi(e);
            ce.push_str(&format!("{q:e} {:e}\n", k * 1e-20 * (q / 1e5).powf(-2.6)));
        }
    }
    let t = d.path().join("download.txt");
    std::fs::write(&t, ce).unwrap();
    let opts = rough_surface::Options {
        series: Some("glass".into()),
        ..Default::default()
    };
    let s = surface_state(&t, opts.clone());
    assert!(s
        .caption
        .as_deref()
        .unwrap()
        .contains("(measurement 'glass')"));
    let p = save_new(d.path(), "glass", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains(", series: \"glass\"),"), "{text}");
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    assert_eq!(back.surface.unwrap().options, opts);
}

#[test]
fn the_height_unit_and_the_fit_band_are_recorded() {
    let d = tempfile::tempdir().unwrap();
    let t = d.path().join("map.txt");
    let mut text = String::from("# Width: 4 um\n# Height: 4 um\n");
    for j in 0..8 {
        let row: Vec<String> = (0..8)
            .map(|i| format!("{}", ((i * 7 + j * 13) % 11) as f64 + 0.1 * (i * j) as f64))
            .collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    std::fs::write(&t, text).unwrap();
    let opts = rough_surface::Options {
        height_unit: rough_surface::HeightUnit::parse("nm"),
        ..Default::default()
    };
    let mut s = surface_state(&t, opts.clone());
    s.set_fit_band(Some((2e6, 1e7))).unwrap();
    let p = save_new(d.path(), "units", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(
        text.contains(", height_unit: \"nm\", fit_band: (2000000.0, 10000000.0)),"),
        "{text}"
    );
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    let src = back.surface.unwrap();
    assert_eq!(src.options, opts);
    assert_eq!(src.fit_band, Some((2e6, 1e7)));
    // A unit the snapshot cannot read names itself.
    let bad = text.replace("height_unit: \"nm\"", "height_unit: \"furlong\"");
    let e = State::from_bytes_in(bad.as_bytes(), Some(d.path())).unwrap_err();
    assert!(
        e.to_string().contains("\"furlong\" is not a length unit"),
        "{e}"
    );
}

#[test]
fn old_snapshots_stay_byte_for_byte() {
    let s = State::from_ron(common::GOOD).unwrap();
    assert!(s.surface.is_none());
    let text = s.to_ron();
    assert!(!text.contains("surface"), "{text}");
    assert_eq!(State::from_ron(&text).unwrap().to_ron(), text);
    for (name, preset) in roughtui::presets::PRESETS {
        let s = State::from_ron(preset).unwrap();
        assert_eq!(s.surface, None, "{name}");
        assert!(!s.to_ron().contains("surface"), "{name}");
    }
}

/// The snapshot's bytes before and after a refused or warned load.
fn unchanged(p: &Path, before: &[u8]) {
    assert_eq!(std::fs::read(p).unwrap(), before, "{}", p.display());
}

#[test]
fn a_missing_surface_file_names_both_files() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let p = save_new(d.path(), "lost", &surface_state(&t, Default::default())).unwrap();
    let before = std::fs::read(&p).unwrap();
    std::fs::remove_file(&t).unwrap();
    let e = load_file(&p).unwrap_err().to_string();
    assert!(e.starts_with("bad snapshot "), "{e}");
    assert!(
        e.contains("lost.ron: its surface file fig2-psd.txt is missing"),
        "{e}"
    );
    assert!(e.contains(&format!("(looked for {})", t.display())), "{e}");
    unchanged(&p, &before);
}

#[test]
fn a_refused_surface_file_says_where_and_why() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let p = save_new(d.path(), "bad", &surface_state(&t, Default::default())).unwrap();
    let before = std::fs::read(&p).unwrap();
    std::fs::write(&t, "# q C\n1e5 1e-20\n1e6 -3\n1e7 1e-30\n1e8 1e-34\n").unwrap();
    let e = load_file(&p).unwrap_err().to_string();
    assert!(e.contains("bad.ron: its surface: bad surface"), "{e}");
    assert!(
        e.contains("fig2-psd.txt, line 3: PSD value -3 at point 2"),
        "{e}"
    );
    unchanged(&p, &before);
}

#[test]
fn a_changed_surface_file_is_shown_as_it_is_now_and_said_so() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let s = surface_state(&t, Default::default());
    let p = save_new(d.path(), "then", &s).unwrap();
    let before = std::fs::read(&p).unwrap();
    let old_sha = s.surface.as_ref().unwrap().measured.sha256.clone();
    // Twice the PSD: the same shape, another file.
    let text = std::fs::read_to_string(&t).unwrap();
    let doubled: String = text
        .lines()
        .map(|l| match l.split_once(' ') {
            Some((q, c)) if !l.starts_with('#') => {
                format!("{q} {:e}\n", 2.0 * c.parse::<f64>().unwrap())
            }
            _ => format!("{l}\n"),
        })
        .collect();
    std::fs::write(&t, doubled).unwrap();
    let now = load_file(&p).unwrap();
    let w = now.surface_warning().unwrap();
    assert!(
        w.starts_with("surface fig2-psd.txt changed since the snapshot was saved"),
        "{w}"
    );
    assert!(
        w.contains(&format!("SHA-256 {}… then", &old_sha[..12])),
        "{w}"
    );
    assert!(w.ends_with("showing it as it is now"), "{w}");
    // The data as it is now: Ψ_P grows by √2.
    let r = now.roughness().indices(&now.params, now.moments).psi_p
        / s.roughness().indices(&s.params, s.moments).psi_p;
    assert!((r - 2f64.sqrt()).abs() < 1e-12, "{r}");
    unchanged(&p, &before);
    // The explorer opens on it with the warning on the status line.
    let app = App::new(now.clone(), Theme::plain(), (80, 24));
    let status = app.status.as_ref().unwrap();
    assert!(status.error && status.text == w, "{:?}", app.status);
    // Saving records the file as it is now, under a new name.
    let again = save_new(d.path(), "then", &now).unwrap();
    assert_ne!(again, p);
    let back = load_file(&again).unwrap();
    assert_eq!(back.surface_warning(), None);
    unchanged(&p, &before);
}

#[test]
fn what_a_surface_snapshot_may_not_hold() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let s = surface_state(&t, Default::default());
    let good = s.to_ron_in(Some(d.path()));
    let p = d.path().join("case.ron");
    let refused = |text: String, want: &str| {
        std::fs::write(&p, text).unwrap();
        let e = load_file(&p).unwrap_err().to_string();
        assert!(e.contains(want), "wants {want:?} in {e}");
    };
    refused(
        good.replace(
            "sweep: (axis: Zeta, from: 1.0, to: 10000.0)",
            "sweep: (axis: Hurst, from: 0.1, to: 0.9)",
        ),
        "H is not a parameter of a measured surface",
    );
    refused(
        good.replace("zeta: 10000.0", "zeta: 20000.0"),
        "ζ = 20000 is beyond the data: this surface's largest ζ is 10000",
    );
    refused(
        good.replace("\"),\n)", "\", pixel_size: -1.0),\n)"),
        "surface.pixel_size = -1 is out of range",
    );
    refused(
        good.replace("sha256:", "colour: 1, sha256:"),
        "surface: unknown field `colour`: expected one of path, sha256, periodic, pixel_size",
    );
    refused(
        good.replace("surface: (", "surface: Some("),
        "surface: wrong type, expected a group `(…)` with the fields path, sha256",
    );
}
