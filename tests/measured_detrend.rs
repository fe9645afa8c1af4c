//! `--detrend none|mean|plane|curvature` as a user meets it: in export,
//! the explorer's and serve's command lines and `--help`; its numbers are
//! SurfaceTopography's (`scripts/detrend_reference.py`); the note, the
//! summary and snapshots name it, a snapshot without it reads the plane;
//! what it does not apply to is refused on one line, status 2.

mod common;

use std::path::{Path, PathBuf};

use common::cli::{noted, run};
use roughtui::scene::State;
use roughtui::snapshot::{load_file, save_new};
use roughtui::surface::SurfaceSource;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data")
        .join(name)
}

/// The reference row of `file` under `mode`: rms height, rms slope.
fn reference(file: &str, mode: &str) -> (f64, f64) {
    let text = std::fs::read_to_string(data("detrend_reference.txt")).unwrap();
    let w: Vec<&str> = text
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .find(|w| w[0] == file && w[2] == mode)
        .unwrap();
    (w[3].parse().unwrap(), w[4].parse().unwrap())
}

#[test]
fn export_removes_the_form_asked_and_says_so() {
    let map = data("map_windowed.txt");
    let map = map.to_str().unwrap();
    for mode in ["none", "mean", "plane", "curvature"] {
        let args = [
            "export",
            "--surface",
            map,
            "--view",
            "moments",
            "--points",
            "2",
            "--detrend",
            mode,
        ];
        let (_, notes) = noted(&args);
        let text = String::from_utf8(run(&args).stdout).unwrap();
        let sq = text.lines().find(|l| l.starts_with("# Sq = ")).unwrap();
        let num = |after: &str, end: &str| -> f64 {
            let t = &sq[sq.find(after).unwrap() + after.len()..];
            t[..t.find(end).unwrap()].parse().unwrap()
        };
        let (h, s) = reference("map_windowed.txt", mode);
        let (gh, gs) = (num("Sq = ", " m,"), num("Sdq = ", " ("));
        assert!(((gh - h) / h).abs() < 1e-11, "{mode}: Sq {gh} vs {h}");
        assert!(((gs - s) / s).abs() < 1e-11, "{mode}: Sdq {gs} vs {s}");
        let said = notes.iter().any(|n| n.contains("(--detrend "));
        assert_eq!(said, mode != "plane", "{mode}: {notes:?}");
    }
    let (_, notes) = noted(&[
        "export",
        "--surface",
        map,
        "--view",
        "moments",
        "--detrend",
        "curvature",
    ]);
    assert!(
        notes.contains(
            &"quadratic removed before the spectrum and Sq (--detrend curvature; the default \
              removes the plane)"
                .to_string()
        ),
        "{notes:?}"
    );
}

#[test]
fn what_it_does_not_apply_to_is_refused_on_one_line() {
    let refused = |args: &[&str], words: &str| {
        let out = run(args);
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(words), "{args:?}: wants {words:?} in {err}");
    };
    let map = data("map_periodic.txt");
    let map = map.to_str().unwrap();
    refused(
        &[
            "export",
            "--surface",
            map,
            "--periodic",
            "--detrend",
            "plane",
        ],
        "--detrend plane removes a tilt, which would leave a periodic surface no longer periodic",
    );
    let psd = data("psd_knee.txt");
    refused(
        &[
            "export",
            "--surface",
            psd.to_str().unwrap(),
            "--detrend",
            "mean",
        ],
        "--detrend mean does not apply to a PSD table: it holds no heights",
    );
    refused(
        &["export", "--surface", map, "--detrend", "tilt"],
        "invalid value 'tilt' for '--detrend <MODE>'; [possible values: none, mean, plane, \
         curvature]",
    );
    refused(
        &["export", "--preset", "fig2", "--detrend", "mean"],
        "applies to --surface FILE, not to a preset: it has no surface",
    );
    // Named in every command's help.
    for cmd in [&["--help"][..], &["export", "--help"], &["serve", "--help"]] {
        let out = run(cmd);
        let help = String::from_utf8(out.stdout).unwrap();
        assert!(help.contains("--detrend <MODE>"), "{cmd:?}");
    }
}

#[test]
fn snapshots_record_it_and_read_the_plane_without_it() {
    let d = tempfile::tempdir().unwrap();
    let t = d.path().join("map_odd.txt");
    std::fs::copy(data("map_odd.txt"), &t).unwrap();
    let opts = rough_surface::Options {
        detrend: Some(rough_surface::Detrend::Curvature),
        ..Default::default()
    };
    let s = State::measured(SurfaceSource::read(&t, opts.clone()).unwrap()).unwrap();
    let p = save_new(d.path(), "form", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains(", detrend: curvature),"), "{text}");
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    assert_eq!(back.surface.as_ref().unwrap().options, opts);
    let r = back.surface.unwrap().measured.real.unwrap();
    let (h, _) = reference("map_odd.txt", "curvature");
    assert!(((r.rms_height - h) / h).abs() < 1e-11);
    // Without the field: the plane, as before the option existed.
    let old = text.replace(", detrend: curvature", "");
    let old = State::from_bytes_in(old.as_bytes(), Some(d.path())).unwrap();
    let src = old.surface.unwrap();
    assert_eq!(src.options.detrend, None);
    let (h, _) = reference("map_odd.txt", "plane");
    let r = src.measured.real.unwrap();
    assert!(((r.rms_height - h) / h).abs() < 1e-11);
    assert!(!save_text(&d, &src).contains("detrend"));
    // A mode the snapshot does not know names the ones it does.
    let bad = text.replace("detrend: curvature", "detrend: tilt");
    let e = State::from_bytes_in(bad.as_bytes(), Some(d.path())).unwrap_err();
    assert!(e.to_string().contains("none"), "{e}");
}

/// A snapshot of `src`'s scene, as saved.
fn save_text(d: &tempfile::TempDir, src: &SurfaceSource) -> String {
    let s = State::measured(src.clone()).unwrap();
    std::fs::read_to_string(save_new(d.path(), "plain", &s).unwrap()).unwrap()
}
