//! The binary refuses each kind of bad snapshot, from `export --load` and
//! from the TUI's `--load`, with exit status 2, one line on stderr that names
//! the file and the problem, and nothing on stdout (so no terminal setup).

mod common;

use common::GOOD;
use std::path::Path;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_roughtui");

fn run(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .env("TERM", "dumb")
        .output()
        .unwrap()
}

/// Both entry points refuse `path` with status 2 and a single stderr line
/// naming it and containing every one of `words`.
fn refused(path: &Path, words: &[&str]) {
    let p = path.to_str().unwrap();
    for args in [vec!["export", "--load", p], vec!["--load", p]] {
        let out = run(&args);
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}: stdout {:?}", out.stdout);
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("roughtui: "), "{err}");
        assert!(err.contains(p), "{args:?}: names the file: {err}");
        for w in words {
            assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
        }
    }
}

fn case(bytes: impl AsRef<[u8]>, words: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("bad.ron");
    std::fs::write(&p, bytes).unwrap();
    refused(&p, words);
}

fn with(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from));
    GOOD.replacen(from, to, 1)
}

#[test]
fn missing_file() {
    refused(
        Path::new("/nonexistent/snap.ron"),
        &["cannot read snapshot", "no such file"],
    );
}

#[test]
fn directory() {
    let dir = tempfile::tempdir().unwrap();
    refused(
        dir.path(),
        &["cannot read snapshot", "it is a directory, not a file"],
    );
}

#[test]
fn not_utf8() {
    case(
        b"(version: 1, name: \"\xff\xfe\")",
        &["not UTF-8", "line 1, column 21"],
    );
}

#[test]
fn syntax_error() {
    case(
        with("hurst: 0.8,", "hurst: 0.8 ;"),
        &["line 4, column 68", "expected comma"],
    );
}

#[test]
fn unknown_field() {
    case(
        with("model: Exact,", "model: Exact, colour: 3,"),
        &["line 7", "unknown field `colour`"],
    );
}

#[test]
fn missing_field() {
    case(
        with("    model: Exact,\n", ""),
        &["line 7", "missing field `model`"],
    );
}

#[test]
fn wrong_type() {
    case(
        with("zeta: 128.0", "zeta: true"),
        &["line 4", "params.zeta", "wrong type", "number"],
    );
}

#[test]
fn nan_infinity_out_of_range() {
    case(
        with("zeta: 128.0", "zeta: NaN"),
        &["zeta = NaN", "finite and >= 1"],
    );
    case(
        with("h_rms: 2e-8", "h_rms: inf"),
        &["h_rms = inf", "finite and > 0"],
    );
    case(
        with("hurst: 0.8", "hurst: 2.0"),
        &["hurst = 2", "in (0, 1]"],
    );
}

#[test]
fn unknown_version() {
    case(
        with("version: 1", "version: 3"),
        &["unknown snapshot version 3", "reads version 1"],
    );
}

#[test]
fn unknown_axis_and_model() {
    case(
        with("axis: Zeta", "axis: Zed"),
        &["unknown axis `Zed`", "H0OverE, HRms, Zeta, Hurst, RStar"],
    );
    case(
        with("model: Exact", "model: Best"),
        &["unknown model `Best`", "Exact, ClosedForm"],
    );
}

#[test]
fn empty_and_out_of_domain_sweep() {
    case(
        with("to: 10000.0", "to: 1.0"),
        &["sweep range is empty", "from = 1 must be below to = 1"],
    );
    case(
        with("from: 1.0", "from: 0.1"),
        &["sweep from = 0.1", "domain of zeta", ">= 1"],
    );
}

#[test]
fn too_large() {
    let mut big = GOOD.as_bytes().to_vec();
    big.resize(2 << 20, b' ');
    case(big, &["larger than the 1 MiB", "2097152 bytes"]);
}

#[test]
fn deeply_nested() {
    case(
        "(".repeat(1 << 20),
        &["line 1, column 2", "expected a field name"],
    );
    case(
        with("false", &"{".repeat(1 << 19)),
        &["line 5, column 17", "size_effect", "expected true or false"],
    );
}

#[test]
fn bad_moments_and_captions() {
    let add = |field: &str| with("model: Exact,", &format!("model: Exact, {field},"));
    case(
        add("moments: Paper"),
        &["line 7", "unknown moments `Paper`", "Truncated, Asymptotic"],
    );
    case(
        add("moments: Asymptotic").replace("hurst: 0.8", "hurst: 1.0"),
        &["hurst = 1 needs moments: Truncated", "infinite at H = 1"],
    );
    case(
        add("caption: \"\\u{1b}]0;pwned\\u{7}\""),
        &["caption contains the control character U+001B"],
    );
    case(
        add(&format!("caption: \"{}\"", "x".repeat(301))),
        &["caption is 301 characters long", "at most 300"],
    );
}

#[test]
fn control_characters_in_the_name() {
    case(
        with("\"fig2\"", "\"\\u{1b}]0;pwned\\u{7}\""),
        &["name contains the control character U+001B"],
    );
}

#[test]
fn empty_file() {
    case("", &["the file is empty"]);
}

#[test]
fn unknown_preset_lists_known_ones() {
    for args in [vec!["export", "--preset", "fig7"], vec!["--preset", "fig7"]] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        assert_eq!(
            String::from_utf8(out.stderr).unwrap(),
            "roughtui: unknown preset 'fig7': known presets are fig1, fig2, fig3, fig4, elastic-again\n"
        );
    }
}

#[test]
fn a_saved_snapshot_exports_like_its_preset() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["fig1", "fig2", "fig3", "fig4"] {
        let state = roughtui::presets::load(name).unwrap();
        let p = roughtui::snapshot::save_new(dir.path(), name, &state).unwrap();
        let from_file = run(&["export", "--load", p.to_str().unwrap(), "--points", "7"]);
        let from_preset = run(&["export", "--preset", name, "--points", "7"]);
        assert_eq!(from_file.status.code(), Some(0));
        assert_eq!(from_file.stdout, from_preset.stdout);
        let text = String::from_utf8(from_file.stdout).unwrap();
        assert_eq!(text.lines().filter(|l| !l.starts_with('#')).count(), 8);
    }
}
