//! Instruments' files on the command line: an x3p and a .gwy channel chosen
//! with `--channel` give the spectrum of the same heights as text, the
//! channel is recorded in a snapshot, and every file not read exits 2 with
//! one line saying what it looks like and what to do.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use common::cli::{noted, BIN};
use roughtui::scene::State;
use roughtui::snapshot::{load_file, save_new};
use roughtui::surface::SurfaceSource;

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/formats")
        .join(name)
        .to_str()
        .unwrap()
        .to_string()
}

/// Exit 2, nothing on stdout, and each of `words` in the message.
fn refused(args: &[&str], words: &[&str]) {
    let out = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
}

/// The spectrum view's CSV rows.
fn spectrum(args: &[&str]) -> Vec<Vec<f64>> {
    let mut a = vec!["export", "--view", "spectrum", "--set", "zeta=4"];
    a.extend_from_slice(args);
    // The notes (the channel read, the units) are comment lines.
    noted(&a)
        .0
        .lines()
        .skip(1)
        .map(|l| l.split(',').filter_map(|f| f.parse().ok()).collect())
        .collect()
}

fn close(a: &[Vec<f64>], b: &[Vec<f64>]) {
    assert_eq!(a.len(), b.len());
    for (r, s) in a.iter().zip(b) {
        assert_eq!(r.len(), s.len());
        for (x, y) in r.iter().zip(s) {
            assert!((x - y).abs() <= 1e-12 * y.abs(), "{x} vs {y}");
        }
    }
}

#[test]
fn x3p_and_gwy_channels_export_as_their_text() {
    let (x3p, txt) = (data("sur_d.x3p"), data("sur_d.txt"));
    close(
        &spectrum(&["--surface", &x3p]),
        &spectrum(&["--surface", &txt]),
    );
    let (gwy, txt) = (data("three.gwy"), data("three_3.txt"));
    close(
        &spectrum(&["--surface", &gwy, "--channel", "Height (retrace)"]),
        &spectrum(&["--surface", &txt]),
    );
}

#[test]
fn files_not_read_exit_2_with_a_way_forward() {
    let d = tempfile::tempdir().unwrap();
    let write = |name: &str, b: &[u8]| -> String {
        let p: PathBuf = d.path().join(name);
        std::fs::write(&p, b).unwrap();
        p.to_str().unwrap().to_string()
    };
    let nc = write("scan.nc", b"CDF\x01\0\0\0\0");
    refused(
        &["export", "--surface", &nc],
        &[
            "bad surface",
            "scan.nc",
            "looks like a NetCDF file",
            "open it in Gwyddion and save it as .gwy or .x3p",
        ],
    );
    // A Zygo .datx is read: one cut short is named as one.
    let datx = write("scan.datx", b"\x89HDF\r\n\x1a\n\0\0\0\0");
    refused(
        &["export", "--surface", &datx],
        &["scan.datx", "Zygo .datx: its HDF5 structure cannot be read"],
    );
    let npy = write("h.npy", b"\x93NUMPY\x01\x00v\x00{'descr': '<f8'}");
    refused(
        &["export", "--surface", &npy],
        &["NumPy .npy", "numpy.savetxt"],
    );
    let x3p = std::fs::read(data("sur_d.x3p")).unwrap();
    let cut = write("cut.x3p", &x3p[..x3p.len() / 2]);
    refused(
        &["export", "--surface", &cut],
        &["cut.x3p", "x3p: not a readable zip archive"],
    );
    let gwy = data("three.gwy");
    refused(
        &["export", "--surface", &gwy, "--channel", "Phase"],
        &["channel 2 'Phase' (deg) holds values in deg, not a length"],
    );
    let txt = data("sur_d.txt");
    refused(
        &["export", "--surface", &txt, "--channel", "1"],
        &["--channel applies to files of several channels"],
    );
}

#[test]
fn the_channel_is_recorded_in_a_snapshot() {
    let d = tempfile::tempdir().unwrap();
    let gwy = d.path().join("three.gwy");
    std::fs::copy(data("three.gwy"), &gwy).unwrap();
    let opts = rough_surface::Options {
        channel: Some("3".to_string()),
        ..Default::default()
    };
    let s = State::measured(SurfaceSource::read(&gwy, opts.clone()).unwrap()).unwrap();
    let p = save_new(d.path(), "retrace", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(text.contains("channel: Some(\"3\")"), "{text}");
    let back = load_file(&p).unwrap();
    assert_eq!(back, s);
    assert_eq!(back.surface.unwrap().options, opts);
}
