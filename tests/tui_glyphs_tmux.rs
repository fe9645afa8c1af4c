//! The glyph sets in a real terminal (tmux): the explorer under a C locale
//! draws ASCII only and says why, `--marker` chooses and refuses, Ctrl-L
//! repaints the whole screen, and the bytes a ζ step costs in braille and
//! in ASCII at 100×30.

mod common;

use std::process::Command;
use std::time::Duration;

use common::tmux::{braille, have_tmux, sh_quote, Pane, BIN};

/// The bytes of one coarse ζ step (128 → 178) at 100×30 with `env`.
fn step_bytes(name: &str, env: &[(&str, &str)], zeta: &str) -> u64 {
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start(name, dir.path(), (100, 30), env, &[]);
    p.wait_text("Readout");
    let want = format!("{zeta} = 178");
    let bytes = p.bytes_written(|| {
        p.keys(&["Right"]);
        p.wait_text(&want);
    });
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    bytes
}

#[test]
fn a_c_locale_draws_ascii_and_says_why() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let raw = dir.path().join("raw");
    let cmd = format!(
        "sleep 0.5; cd {} && env LANG=C LC_ALL= LC_CTYPE= {}",
        sh_quote(dir.path().to_str().unwrap()),
        sh_quote(BIN)
    );
    let p = Pane::start_shell("ascii-local", (100, 30), &cmd);
    let copy = format!("cat >> {}", sh_quote(raw.to_str().unwrap()));
    assert!(p
        .tmux(&["pipe-pane", "-o", "-t", "t", &copy])
        .status
        .success());
    let s = p.wait_text("Readout");
    assert!(
        s.contains("drawing in ASCII (LANG=C is not UTF-8) | M switches"),
        "{s}"
    );
    assert_eq!(braille(&s), 0);
    for (keys, want) in [
        (&["Tab"][..], "plasticity indices vs zeta"),
        (&["Tab"], "plastic share over zeta x H0/E"),
        (&["Tab"], "A/A0 vs pbar/H0"),
        (&["?"], "help 1/"),
    ] {
        p.keys(keys);
        p.wait_text(want);
    }
    p.keys(&["Escape"]);
    p.wait_for("the help closed", |s| !s.contains("help 1/"));
    p.keys(&["Up", "Enter"]);
    p.wait_text("units m cm mm um nm pm");
    p.keys(&["Escape"]);
    p.wait_for("the prompt closed", |s| !s.contains("units m cm"));
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    std::thread::sleep(Duration::from_millis(300));
    let bytes = std::fs::read(&raw).unwrap();
    assert!(bytes.len() > 10_000, "{} bytes", bytes.len());
    let bad = bytes.iter().filter(|b| **b >= 0x80).count();
    assert_eq!(bad, 0, "{bad} bytes not ASCII");
}

#[test]
fn marker_chooses_the_set_and_refuses_what_it_does_not_know() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start(
        "marker-half",
        dir.path(),
        (100, 30),
        &[],
        &["--marker", "half"],
    );
    let s = p.wait_text("Readout");
    assert_eq!(braille(&s), 0, "{s}");
    assert!(s.contains('▀') || s.contains('▄'), "{s}");
    // Chosen on the command line: no reason in the status line.
    assert!(!s.contains("drawing in"), "{s}");
    p.keys(&["M"]);
    p.wait_text("drawing in blocks");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);

    for args in [&["--marker", "foo"][..], &["serve", "--marker", "foo"]] {
        let out = Command::new(BIN).args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("invalid value 'foo' for '--marker <SET>'")
                && err.contains("[possible values: braille, half, block, ascii]"),
            "{err}"
        );
    }
}

#[test]
fn ctrl_l_repaints_the_whole_screen() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start("ctrl-l", dir.path(), (100, 30), &[], &[]);
    p.wait_for("the first frame", |s| braille(s) > 100);
    let idle = p.bytes_written(|| std::thread::sleep(Duration::from_millis(300)));
    assert_eq!(idle, 0);
    let bytes = p.bytes_written(|| p.keys(&["C-l"]));
    assert!(bytes > 3000, "{bytes} bytes for a full repaint");
    let s = p.wait_for("the frame again", |s| braille(s) > 100);
    assert!(s.contains("Readout") && s.contains("[fig2]"), "{s}");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}

#[test]
fn bytes_per_zeta_step_in_braille_and_ascii() {
    if !have_tmux() {
        return;
    }
    let braille = step_bytes("step-braille", &[], "ζ");
    let ascii = step_bytes("step-ascii", &[("LANG", "C"), ("LC_ALL", "")], "zeta");
    eprintln!("bytes for one zeta step at 100x30: braille {braille}, ASCII {ascii}");
    // A step redraws the marker, the readout and a few chart cells: its
    // bytes are mostly escape sequences, so the two sets cost about the
    // same (ASCII's one byte a cell against braille's three saves little);
    // ASCII never costs more than 2 % over braille.
    assert!(
        ascii > 0 && ascii <= braille + braille / 50,
        "ASCII {ascii}, braille {braille}"
    );
}
