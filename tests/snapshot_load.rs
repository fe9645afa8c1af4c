//! Every kind of bad snapshot is refused by `load_file` with one message that
//! names the file and the problem; harmless variations are accepted.

mod common;

use common::GOOD;
use std::path::{Path, PathBuf};

use rough_model::Moments;
use roughtui::scene::State;
use roughtui::snapshot::{load_file, read_file, LoadProblem, SnapshotError, MAX_BYTES};

fn write(dir: &Path, bytes: &[u8]) -> PathBuf {
    let p = dir.join("case.ron");
    std::fs::write(&p, bytes).unwrap();
    p
}

/// The exact message for `bytes` saved as `case.ron`, with the folder shown as `DIR`.
fn message(bytes: &[u8]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), bytes);
    let e = load_file(&p).unwrap_err().to_string();
    e.replace(&dir.path().display().to_string(), "DIR")
}

fn with(from: &str, to: &str) -> Vec<u8> {
    assert!(GOOD.contains(from), "{from}");
    GOOD.replacen(from, to, 1).into_bytes()
}

#[test]
fn the_good_snapshot_loads_with_its_values() {
    let s = State::from_ron(GOOD).unwrap();
    assert_eq!(s.name, "fig2");
    assert_eq!(s.params.zeta(), 128.0);
    assert_eq!(s.params.h_rms(), 2e-8);
    assert_eq!(s.sweep.to(), 10000.0);
    assert!(!s.size_effect);
    // Fields added later are optional: a file without them has their defaults.
    assert_eq!(s.caption, None);
    assert_eq!(s.moments, Moments::Truncated);
}

#[test]
fn the_optional_fields_load_in_any_place() {
    let s = State::from_bytes(&with(
        "    size_effect",
        "    moments: Asymptotic,\n    caption: \"Figure 2: slopes against ζ, \\\"Ψ*\\\"\",\n    size_effect",
    ))
    .unwrap();
    assert_eq!(s.moments, Moments::Asymptotic);
    assert_eq!(
        s.caption.as_deref(),
        Some("Figure 2: slopes against ζ, \"Ψ*\"")
    );
    let longest = "é".repeat(300);
    let s = State::from_bytes(&with(
        "model: Exact,",
        &format!("model: Exact, caption: \"{longest}\","),
    ))
    .unwrap();
    assert_eq!(s.caption, Some(longest));
}

#[test]
fn missing_file() {
    assert_eq!(
        load_file(Path::new("/nonexistent/dir/x.ron"))
            .unwrap_err()
            .to_string(),
        "cannot read snapshot /nonexistent/dir/x.ron: no such file"
    );
}

#[test]
fn a_directory_is_not_a_snapshot() {
    let dir = tempfile::tempdir().unwrap();
    let e = read_file(dir.path()).unwrap_err();
    assert!(matches!(e.problem, LoadProblem::IsDir));
    assert_eq!(
        e.to_string(),
        format!(
            "cannot read snapshot {}: it is a directory, not a file",
            dir.path().display()
        )
    );
}

#[test]
fn unreadable_file() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), GOOD.as_bytes());
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o000)).unwrap();
    if std::fs::read(&p).is_ok() {
        return; // running as root: permissions do not apply
    }
    assert_eq!(
        load_file(&p).unwrap_err().to_string(),
        format!("cannot read snapshot {}: permission denied", p.display())
    );
}

#[test]
fn not_utf8() {
    let mut b = with("\"fig2\"", "\"fi?2\"");
    let at = b.iter().position(|&c| c == b'?').unwrap();
    b[at] = 0xff;
    assert_eq!(
        message(&b),
        "bad snapshot DIR/case.ron: not UTF-8 text: invalid byte at line 3, column 14"
    );
}

#[test]
fn syntax_error_has_line_and_column() {
    assert_eq!(
        message(&with("hurst: 0.8,", "hurst: 0.8,,")),
        "bad snapshot DIR/case.ron: line 4, column 68: params: expected a field name"
    );
    assert_eq!(
        message(&with("model: Exact,\n)", "model: Exact,\n")),
        "bad snapshot DIR/case.ron: line 7, column 18: the file ends in the middle of the snapshot"
    );
    assert_eq!(
        message(format!("{GOOD} junk").as_bytes()),
        "bad snapshot DIR/case.ron: line 8, column 2: unexpected text after the snapshot's closing `)`"
    );
}

#[test]
fn empty_file() {
    assert_eq!(
        message(b" \n"),
        "bad snapshot DIR/case.ron: the file is empty: a snapshot starts with `(version: 1, …`"
    );
}

#[test]
fn unknown_field() {
    assert_eq!(
        message(&with("model: Exact,", "model: Exact, colour: 3,")),
        "bad snapshot DIR/case.ron: line 7, column 19: unknown field `colour` in the snapshot: \
         expected one of version, name, caption, params, size_effect, sweep, model, moments, surface, seed, view, map_y, ghost"
    );
    assert_eq!(
        message(&with("q0: 100000.0", "q0: 100000.0, e: 1.0")),
        "bad snapshot DIR/case.ron: line 4, column 98: params: unknown field `e`: \
         expected one of h0_over_e, h_rms, zeta, hurst, r_star, q0"
    );
}

#[test]
fn missing_field() {
    assert_eq!(
        message(&with("    size_effect: false,\n", "")),
        "bad snapshot DIR/case.ron: line 7, column 1: missing field `size_effect` in the snapshot"
    );
    assert_eq!(
        message(&with(", to: 10000.0", "")),
        "bad snapshot DIR/case.ron: line 6, column 34: sweep: missing field `to`"
    );
}

#[test]
fn duplicated_field() {
    assert_eq!(
        message(&with("zeta: 128.0,", "zeta: 128.0, zeta: 3.0,")),
        "bad snapshot DIR/case.ron: line 4, column 57: params: field `zeta` appears twice"
    );
}

#[test]
fn wrong_type_names_the_field() {
    assert_eq!(
        message(&with("zeta: 128.0", "zeta: \"big\"")),
        "bad snapshot DIR/case.ron: line 4, column 49: params.zeta: wrong type, \
         expected a number such as 0.01 or 2e-8"
    );
    assert_eq!(
        message(&with("size_effect: false", "size_effect: 0")),
        "bad snapshot DIR/case.ron: line 5, column 17: size_effect: wrong type, expected true or false"
    );
    assert_eq!(
        message(&with("\"fig2\"", "2")),
        "bad snapshot DIR/case.ron: line 3, column 10: name: wrong type, expected text in double quotes"
    );
    assert_eq!(
        message(&with("(axis: Zeta, from: 1.0, to: 10000.0)", "[1.0, 2.0]")),
        "bad snapshot DIR/case.ron: line 6, column 12: sweep: wrong type, \
         expected a group `(…)` with the fields axis, from, to"
    );
    assert_eq!(
        message(&with("version: 1", "version: \"1\"")),
        "bad snapshot DIR/case.ron: line 2, column 13: version: wrong type, expected a whole number"
    );
}

#[test]
fn nan_infinity_and_out_of_range_name_the_field_and_range() {
    for (from, to, want) in [
        ("zeta: 128.0", "zeta: NaN", "params: zeta = NaN is out of range: it must be finite and >= 1"),
        ("h_rms: 2e-8", "h_rms: inf", "params: h_rms = inf is out of range: it must be finite and > 0"),
        ("q0: 100000.0", "q0: -inf", "params: q0 = -inf is out of range: it must be finite and > 0"),
        ("hurst: 0.8", "hurst: 1.5", "params: hurst = 1.5 is out of range: it must be in (0, 1]"),
        ("zeta: 128.0", "zeta: 1e999", "params: zeta = inf is out of range: it must be finite and >= 1"),
        (
            "r_star: 0.001",
            "r_star: -1e-3",
            "params: r_star = -0.001 is out of range: it must be finite and >= 0 (0 = no size effect)",
        ),
        ("h0_over_e: 0.01", "h0_over_e: 0", "params: h0_over_e = 0 is out of range: it must be finite and > 0"),
    ] {
        assert_eq!(message(&with(from, to)), format!("bad snapshot DIR/case.ron: {want}"));
    }
}

#[test]
fn unknown_version() {
    assert_eq!(
        message(&with("version: 1", "version: 2")),
        "bad snapshot DIR/case.ron: line 2, column 14: unknown snapshot version 2: this build reads version 1"
    );
    assert_eq!(
        message(&with("version: 1", "version: -1")),
        "bad snapshot DIR/case.ron: line 2, column 15: unknown snapshot version -1: this build reads version 1"
    );
    assert_eq!(
        message(&with("version: 1", "version: 99999999999999999999999")),
        "bad snapshot DIR/case.ron: line 2, column 14: unknown snapshot version: this build reads version 1"
    );
}

#[test]
fn unknown_axis_or_model() {
    assert_eq!(
        message(&with("axis: Zeta", "axis: Eta")),
        "bad snapshot DIR/case.ron: line 6, column 19: sweep.axis: unknown axis `Eta`: \
         expected one of H0OverE, HRms, Zeta, Hurst, RStar"
    );
    assert_eq!(
        message(&with("model: Exact", "model: Approx")),
        "bad snapshot DIR/case.ron: line 7, column 12: model: unknown model `Approx`: \
         expected one of Exact, ClosedForm"
    );
    assert_eq!(
        message(&with("model: Exact", "model: \"Exact\"")),
        "bad snapshot DIR/case.ron: line 7, column 12: model: wrong type, expected one of Exact, ClosedForm"
    );
}

#[test]
fn empty_or_out_of_domain_sweep() {
    assert_eq!(
        message(&with("from: 1.0, to: 10000.0", "from: 10.0, to: 10.0")),
        "bad snapshot DIR/case.ron: sweep range is empty: from = 10 must be below to = 10"
    );
    assert_eq!(
        message(&with("from: 1.0, to: 10000.0", "from: 100.0, to: 10.0")),
        "bad snapshot DIR/case.ron: sweep range is empty: from = 100 must be below to = 10"
    );
    assert_eq!(
        message(&with("from: 1.0", "from: 0.5")),
        "bad snapshot DIR/case.ron: sweep from = 0.5 is outside the domain of zeta: it must be finite and >= 1"
    );
    assert_eq!(
        message(&with("to: 10000.0", "to: inf")),
        "bad snapshot DIR/case.ron: sweep to = inf is outside the domain of zeta: it must be finite and >= 1"
    );
    // A zero outside the axis's domain names the domain, not the log rule.
    assert_eq!(
        message(&with("from: 1.0", "from: 0.0")),
        "bad snapshot DIR/case.ron: sweep from = 0 is outside the domain of zeta: it must be finite and >= 1"
    );
    assert_eq!(
        message(&with("axis: Zeta, from: 1.0", "axis: RStar, from: 0.0")),
        "bad snapshot DIR/case.ron: sweep from = 0 is outside the domain of r_star: \
         it must be finite and > 0 (the sweep is log-spaced)"
    );
}

#[test]
fn too_large_is_refused_before_parsing() {
    let mut big = GOOD.as_bytes().to_vec();
    big.resize(MAX_BYTES as usize + 1, b' ');
    assert_eq!(
        message(&big),
        "bad snapshot DIR/case.ron: the file is larger than the 1 MiB (1048576 bytes) limit \
         for a snapshot (1048577 bytes)"
    );
    // Exactly the limit is fine (trailing blanks are allowed).
    big.truncate(MAX_BYTES as usize);
    let dir = tempfile::tempdir().unwrap();
    assert!(load_file(&write(dir.path(), &big)).is_ok());
}

#[test]
fn endless_devices_are_cut_off_at_the_limit() {
    let e = read_file(Path::new("/dev/zero")).unwrap_err();
    assert!(matches!(
        e.problem,
        LoadProblem::Snapshot(SnapshotError::TooLarge { bytes: None })
    ));
    assert_eq!(
        e.to_string(),
        "bad snapshot /dev/zero: the file is larger than the 1 MiB (1048576 bytes) limit for a snapshot"
    );
}

#[test]
fn deep_nesting_is_refused_without_overflowing_the_stack() {
    // 100k brackets in a ~1 MiB file, at the top and inside fields, on a small
    // stack so that any recursion would show.
    // The schema nests two deep, so the first bracket it does not allow is
    // refused where it stands, by what was expected there.
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (
            "(".repeat(100_000).into_bytes(),
            "line 1, column 2: expected a field name",
        ),
        (
            "[".repeat(1_000_000).into_bytes(),
            "line 1, column 1: a snapshot is a group `(…)` with the fields \
             version, name, caption, params, size_effect, sweep, model, moments, surface, seed, view, map_y, ghost",
        ),
        (
            with("Exact", &"Exact(".repeat(100_000)),
            "line 7, column 17: expected comma",
        ),
        (
            with("\"fig2\"", &"Some(".repeat(100_000)),
            "line 3, column 10: name: wrong type, expected text in double quotes",
        ),
        (
            with("false", &"{".repeat(100_000)),
            "line 5, column 17: size_effect: wrong type, expected true or false",
        ),
        (
            with(
                "model: Exact,",
                &format!("model: Exact, caption: {}", "Some(".repeat(100_000)),
            ),
            "line 7, column 27: caption: wrong type, expected text in double quotes",
        ),
        (
            format!("{}{GOOD}", "/*".repeat(300_000)).into_bytes(),
            "line 1, column 600001: unclosed block comment",
        ),
    ];
    std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(move || {
            for (bytes, want) in cases {
                assert_eq!(
                    message(&bytes),
                    format!("bad snapshot DIR/case.ron: {want}")
                );
            }
        })
        .unwrap()
        .join()
        .unwrap();
}

#[test]
fn hostile_names_are_refused() {
    assert_eq!(
        message(&with("\"fig2\"", "\"a\\u{1b}[2Jb\"")),
        "bad snapshot DIR/case.ron: name contains the control character U+001B: it must be printable text"
    );
    assert_eq!(
        message(&with("\"fig2\"", "\"two\\nlines\"")),
        "bad snapshot DIR/case.ron: name contains the control character U+000A: it must be printable text"
    );
    let long = format!("\"{}\"", "é".repeat(65));
    assert_eq!(
        message(&with("\"fig2\"", &long)),
        "bad snapshot DIR/case.ron: name is 65 characters long: it must be at most 64"
    );
    // A long string is refused by length, not by parsing trouble.
    let huge = format!("\"{}\"", "x".repeat(900_000));
    assert_eq!(
        message(&with("\"fig2\"", &huge)),
        "bad snapshot DIR/case.ron: name is 900000 characters long: it must be at most 64"
    );
}

#[test]
fn hostile_captions_are_refused() {
    let caption = |text: &str| with("model: Exact,", &format!("model: Exact, caption: {text},"));
    assert_eq!(
        message(&caption("\"a\\u{1b}[2Jb\"")),
        "bad snapshot DIR/case.ron: caption contains the control character U+001B: it must be printable text"
    );
    assert_eq!(
        message(&caption("\"two\\nlines\"")),
        "bad snapshot DIR/case.ron: caption contains the control character U+000A: it must be printable text"
    );
    assert_eq!(
        message(&caption(&format!("\"{}\"", "é".repeat(301)))),
        "bad snapshot DIR/case.ron: caption is 301 characters long: it must be at most 300"
    );
    assert_eq!(
        message(&caption("Some(\"x\")")),
        "bad snapshot DIR/case.ron: line 7, column 27: caption: wrong type, expected text in double quotes"
    );
    assert_eq!(
        message(&caption("\"x\", caption: \"y\"")),
        "bad snapshot DIR/case.ron: line 7, column 33: field `caption` appears twice in the snapshot"
    );
}

#[test]
fn unknown_or_impossible_moments() {
    let moments = |m: &str| with("model: Exact,", &format!("model: Exact, moments: {m},"));
    assert_eq!(
        message(&moments("Exactish")),
        "bad snapshot DIR/case.ron: line 7, column 28: moments: unknown moments `Exactish`: \
         expected one of Truncated, Asymptotic"
    );
    assert_eq!(
        message(&moments("\"Asymptotic\"")),
        "bad snapshot DIR/case.ron: line 7, column 28: moments: wrong type, \
         expected one of Truncated, Asymptotic"
    );
    // The asymptotic m2 is infinite at H = 1: the message names both fields.
    for hurst in ["1.0", "1"] {
        let text = String::from_utf8(moments("Asymptotic")).unwrap();
        assert_eq!(
            message(
                text.replace("hurst: 0.8", &format!("hurst: {hurst}"))
                    .as_bytes()
            ),
            "bad snapshot DIR/case.ron: hurst = 1 needs moments: Truncated: the asymptotic \
             moments (eq. 10) make m2 = πZq0^(2−2H)ζ^(2−2H)/(2−2H) infinite at H = 1"
        );
    }
    // H = 1 with the default (truncated) moments is fine.
    assert!(State::from_ron(&GOOD.replace("hurst: 0.8", "hurst: 1.0")).is_ok());
}

#[test]
fn lenient_forms_are_accepted() {
    let plain = State::from_ron(GOOD).unwrap();
    for text in [
        GOOD.replace("zeta: 128.0", "zeta: 128"),
        format!("\u{feff}{GOOD}"),
        format!("// saved for the class\n{GOOD}/* end */\n"),
        GOOD.replace("    name: \"fig2\",\n", "")
            .replace("model: Exact,", "model: Exact, name: \"fig2\""),
        GOOD.replace("\r\n", "\n").replace('\n', "\r\n"),
        format!("SnapshotFile{GOOD}"),
    ] {
        assert_eq!(State::from_ron(&text), Ok(plain.clone()), "{text}");
    }
    let named = State::from_ron(&GOOD.replace("\"fig2\"", "r#\"Ψ* \"quoted\"\"#")).unwrap();
    assert_eq!(named.name, "Ψ* \"quoted\"");
}

#[test]
fn unknown_preset_lists_the_known_ones() {
    assert_eq!(
        roughtui::presets::load("fig5").unwrap_err().to_string(),
        "unknown preset 'fig5': known presets are fig1, fig2, fig3, fig4, elastic-again"
    );
}
