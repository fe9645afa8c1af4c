//! Values a physicist would accept: each parameter bounded to a stated
//! physical range on the command line and at the value prompt, refusals
//! that fit an 80-column status line with their advice, parameters named as
//! the screen names them, q0 / L settable, and material values in physical
//! units (`--set e=210GPa --set h0=2GPa [--set nu=0.3]`).

mod common;

use common::app::{ch, fig, press, screen, type_text};
use common::cli::{run, stdout};
use crossterm::event::{KeyCode, KeyModifiers};
use rough_model::Axis;
use roughtui::tui::app::{update, App, Message, Mode};

/// The `# name = value` line of an export's scene.
fn scene_value(csv: &str, name: &str) -> String {
    let prefix = format!("# {name} = ");
    let line = csv
        .lines()
        .find_map(|l| l.strip_prefix(&prefix))
        .unwrap_or_else(|| panic!("no {name} in {csv}"));
    line.split_whitespace().next().unwrap().to_string()
}

fn refused(args: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty());
    err.trim_end().to_string()
}

#[test]
fn set_refuses_unphysical_values_with_the_range() {
    for (set, want) in [
        (
            "h0-over-e=2",
            "H0/E = 2 is out of range: H0/E takes 1e-6 … 0.5",
        ),
        (
            "h0-over-e=5",
            "H0/E = 5 is out of range: H0/E takes 1e-6 … 0.5",
        ),
        (
            "h-rms=1m",
            "h_rms = 1m is out of range: h_rms takes 1 pm … 1 mm",
        ),
        (
            "hurst=1e-300",
            "H = 1e-300 is out of range: H takes 0.05 … 1",
        ),
        ("r-star=2m", "R* = 2m is out of range: R* takes 0 … 1 m"),
        ("zeta=1e9", "ζ = 1e9 is out of range: ζ takes 1 … 1e8"),
        (
            "q0=1e12",
            "q0 = 1e12 is out of range: q0 takes 0.63 … 6.3e8 1/m (L = 10 nm … 10 m)",
        ),
        ("l=1nm", "L = 1nm is out of range: L takes 10 nm … 10 m"),
    ] {
        let err = refused(&["export", "--points", "2", "--set", set]);
        assert_eq!(err, format!("roughtui: --set {set}: {want}"));
    }
    // The edges are in.
    for set in [
        "h0-over-e=0.5",
        "hurst=0.05",
        "h-rms=1pm",
        "h-rms=1mm",
        "r-star=1m",
    ] {
        stdout(&["export", "--points", "2", "--set", set]);
    }
    let err = refused(&["export", "--points", "2", "--sweep", "zeta:1:1e9"]);
    assert_eq!(
        err,
        "roughtui: --sweep: ζ = 1e9 is out of range: ζ takes 1 … 1e8"
    );
}

#[test]
fn q0_and_the_longest_wavelength_are_set() {
    let csv = stdout(&["export", "--points", "2", "--set", "q0=2e5"]);
    assert_eq!(scene_value(&csv, "q0"), "200000");
    // L = 2π/q0: 62.83185307179586 µm is the paper's q0 = 1e5 1/m.
    let csv = stdout(&["export", "--points", "2", "--set", "l=31.41592653589793um"]);
    let q0: f64 = scene_value(&csv, "q0").parse().unwrap();
    assert!((q0 / 2e5 - 1.0).abs() < 1e-15, "{q0}");
    // A larger q0 at the same h_rms and H: a smaller m2 at the same ζ.
    let psi = |csv: &str| -> f64 {
        let row = csv.lines().filter(|l| !l.starts_with('#')).nth(2).unwrap();
        row.split(',').nth(1).unwrap().parse().unwrap()
    };
    let base = stdout(&["export", "--points", "2"]);
    assert_ne!(psi(&csv), psi(&base));
}

#[test]
fn material_values_in_physical_units_set_h0_over_e() {
    let h = |args: &[&str]| -> f64 {
        let csv = stdout(&[&["export", "--points", "2"][..], args].concat());
        scene_value(&csv, "h0_over_e").parse().unwrap()
    };
    // E taken as the composite modulus E*.
    let got = h(&["--set", "e=210GPa", "--set", "h0=2GPa"]);
    assert_eq!(got, 2e9 / 210e9);
    // With ν: E* = E/(1 − ν²), so H0/E* = H0 (1 − ν²)/E.
    let got = h(&["--set", "h0=2GPa", "--set", "e=210GPa", "--set", "nu=0.3"]);
    assert!((got / (2.0 * 0.91 / 210.0) - 1.0).abs() < 1e-15, "{got}");
    let got = h(&["--set", "h0=500MPa", "--set", "e=70000MPa"]);
    assert!((got / (5e8 / 7e10) - 1.0).abs() < 1e-15, "{got}");
    let err = refused(&["export", "--set", "e=210GPa"]);
    assert!(err.contains("e and h0 go together"), "{err}");
    let err = refused(&["export", "--set", "e=1GPa", "--set", "h0=2GPa"]);
    assert_eq!(
        err,
        "roughtui: --set: H0/E = 2GPa/1GPa is out of range: H0/E takes 1e-6 … 0.5"
    );
    let err = refused(&["export", "--set", "e=210 psi", "--set", "h0=2GPa"]);
    assert!(
        err.contains("unknown unit \"psi\": use Pa, kPa, MPa or GPa"),
        "{err}"
    );
    let err = refused(&[
        "export", "--set", "nu=0.7", "--set", "e=1GPa", "--set", "h0=2MPa",
    ]);
    assert!(
        err.contains("ν = 0.7 is out of range: ν takes -1 … 0.5"),
        "{err}"
    );
}

#[test]
fn hurst_one_is_set_with_truncated_moments_in_any_order() {
    stdout(&[
        "export",
        "--points",
        "2",
        "--set",
        "hurst=1",
        "--moments",
        "truncated",
    ]);
    let err = refused(&["export", "--points", "2", "--set", "hurst=1"]);
    assert!(err.ends_with("add --moments truncated"), "{err}");
}

/// Opens the value prompt on `axis`, types `text` and presses Enter.
fn type_value(a: &mut App, axis: Axis, text: &str) {
    while a.selected_axis() != axis {
        update(a, Message::SelectNext);
    }
    ch(a, '=');
    if !matches!(a.mode, Mode::Value(..)) {
        update(a, Message::StartValue);
    }
    type_text(a, text);
    press(a, KeyCode::Enter, KeyModifiers::NONE);
}

#[test]
fn the_prompt_refuses_in_80_columns_with_the_advice_intact() {
    for (axis, text, want) in [
        (
            Axis::H0OverE,
            "2",
            "H0/E = 2 is out of range: H0/E takes 1e-6 … 0.5",
        ),
        (
            Axis::HRms,
            "1 m",
            "h_rms = 1 m is out of range: h_rms takes 1 pm … 1 mm",
        ),
        (
            Axis::Hurst,
            "1e-300",
            "H = 1e-300 is out of range: H takes 0.05 … 1",
        ),
        (
            Axis::Hurst,
            "1",
            "H = 1 needs truncated moments (asymptotic m2 is infinite there): press a first",
        ),
    ] {
        let mut a = fig("fig2");
        type_value(&mut a, axis, text);
        let status = a.status.clone().unwrap();
        assert!(status.error);
        assert_eq!(status.text, want);
        assert!(want.chars().count() <= 80, "{want}");
        // Shown whole on an 80-column screen.
        assert!(screen(&a).contains(want), "{}", screen(&a));
    }
}

#[test]
fn the_prompt_takes_set_pairs_for_q0_l_and_material_values() {
    let mut a = fig("fig2");
    type_value(&mut a, Axis::Zeta, "q0=2e5");
    assert_eq!(a.state.params.q0(), 2e5);
    assert!(a.modified);
    type_value(&mut a, Axis::Zeta, "e=210GPa h0=2GPa");
    assert_eq!(a.state.params.h0_over_e(), 2e9 / 210e9);
    type_value(&mut a, Axis::Zeta, "l=10km");
    let status = a.status.clone().unwrap();
    assert!(status.error, "{status:?}");
    assert_eq!(
        status.text,
        "l=10km: unknown unit \"km\": use m, cm, mm, µm (um), nm or pm"
    );
}

#[test]
fn the_readout_shows_q0_and_l_where_there_is_room() {
    let mut a = fig("fig2");
    update(&mut a, Message::Resize(160, 48));
    let s = screen(&a);
    assert!(s.contains("q0    1e5/m     L      62.8 µm"), "{s}");
    type_value(&mut a, Axis::Zeta, "l=1mm");
    assert!(screen(&a).contains("L      1.00 mm"), "{}", screen(&a));
}

/// A length typed on the command line comes back in the unit it was typed
/// in, or the slider's, never as metres with eight zeros.
#[test]
fn typed_lengths_are_echoed_as_typed() {
    for typed in ["50nm", "0.05um", "5e-8"] {
        let err = refused(&[
            "export",
            "--surface",
            "surfaces/example.txt",
            "--pixel-size",
            typed,
        ]);
        assert_eq!(
            err,
            "roughtui: bad surface surfaces/example.txt, line 2: --pixel-size 50 nm does not \
             apply: the file gives its size",
            "{typed}"
        );
    }
    assert_eq!(
        refused(&["export", "--sweep", "h-rms:1nm:2mm"]),
        "roughtui: --sweep: h_rms = 2mm is out of range: h_rms takes 1 pm … 1 mm"
    );
    assert_eq!(
        refused(&["export", "--sweep", "r-star:0.5pm:1.5 m"]),
        "roughtui: --sweep: R* = 1.5 m is out of range: R* takes 0 … 1 m"
    );
    assert_eq!(
        refused(&["export", "--sweep", "zeta:1:1e9"]),
        "roughtui: --sweep: ζ = 1e9 is out of range: ζ takes 1 … 1e8"
    );
    assert!(
        refused(&["export", "--sweep", "zeta:1nm:4"]).contains("ζ takes no unit (\"nm\")"),
        "a unit on an axis without one is refused"
    );
    // The ends of a length sweep take a unit as --set does.
    let csv = stdout(&["export", "--points", "2", "--sweep", "h-rms:1nm:1um"]);
    assert!(
        csv.contains("# sweep = h_rms from 1e-9 to 1e-6, 2 points"),
        "{csv}"
    );
    // At the value prompt: as typed.
    let mut a = fig("fig2");
    type_value(&mut a, Axis::HRms, "2 mm");
    assert!(
        screen(&a).contains("h_rms = 2 mm is out of range: h_rms takes 1 pm … 1 mm"),
        "{}",
        screen(&a)
    );
}
