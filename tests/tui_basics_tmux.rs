//! What a class runs into, in a real terminal (tmux): signals restore the
//! terminal, a too-small terminal takes only quit keys, no terminal gets a
//! clear message.

mod common;

use std::process::{Command, Stdio};

use common::tmux::{have_tmux, Pane};

/// SIGHUP (a dropped SSH connection), SIGTERM, SIGINT and SIGQUIT leave the
/// alternate screen, show the cursor and exit with 128 + the signal.
#[test]
fn signals_restore_the_terminal_and_exit_128_plus_n() {
    if !have_tmux() {
        return;
    }
    for (sig, n) in [("HUP", 1), ("TERM", 15), ("INT", 2), ("QUIT", 3)] {
        let dir = tempfile::tempdir().unwrap();
        let p = Pane::start(&format!("sig{n}"), dir.path(), (80, 24), &[], &[]);
        p.wait_text("Readout");
        assert_eq!(p.display("#{alternate_on}"), "1");
        assert_eq!(p.display("#{cursor_flag}"), "0");
        p.signal(sig);
        assert_eq!(p.exit_status(), 128 + n, "SIG{sig}");
        assert_eq!(p.display("#{alternate_on}"), "0", "SIG{sig}");
        assert_eq!(p.display("#{cursor_flag}"), "1", "SIG{sig}");
    }
}

/// Without a terminal on standard input: one clear line and status 2.
#[test]
fn no_terminal_says_so_and_points_to_export() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start_redirected(
        "notty",
        dir.path(),
        (80, 24),
        &["--preset", "fig2"],
        " </dev/null",
    );
    assert_eq!(p.exit_status(), 2);
    let s = p.wait_text("needs a terminal");
    assert!(s.contains("roughtui export"), "{s}");
    assert!(!s.contains("os error"), "{s}");
    assert_eq!(p.display("#{alternate_on}"), "0");
}

/// The same without tmux: output to a pipe.
#[test]
fn output_to_a_pipe_says_it_needs_a_terminal() {
    let o = Command::new(env!("CARGO_BIN_EXE_roughtui"))
        .args(["--preset", "fig2"])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("needs a terminal") && err.contains("`roughtui export`"),
        "{err}"
    );
}

/// While "enlarge the terminal" shows, → changes nothing unseen, and with the
/// save prompt open `q` quits instead of going into the name.
#[test]
fn too_small_takes_only_quit_keys() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start("small", dir.path(), (100, 30), &[], &[]);
    p.wait_text("ζ = 128");
    p.tmux(&["resize-window", "-t", "t", "-x", "40", "-y", "12"]);
    p.wait_text("enlarge the terminal");
    p.keys(&["Right", "Right", "x", "m"]);
    std::thread::sleep(std::time::Duration::from_millis(200));
    p.tmux(&["resize-window", "-t", "t", "-x", "100", "-y", "30"]);
    let s = p.wait_text("Readout");
    assert!(s.contains("ζ = 128") && s.contains("[fig2]"), "{s}");
    assert!(s.contains("ζ 1…1e4"), "{s}");

    p.keys(&["s"]);
    p.wait_text("save as: fig2-");
    p.tmux(&["resize-window", "-t", "t", "-x", "40", "-y", "12"]);
    p.wait_text("enlarge the terminal");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    assert_eq!(p.display("#{alternate_on}"), "0");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

/// Braille cells drawn in each foreground colour (SGR 30–37, 90–97 and
/// 38;5;N; 39 and 0 reset), from a pane captured with its escape sequences.
fn braille_by_colour(raw: &str) -> std::collections::HashMap<u32, usize> {
    let mut counts = std::collections::HashMap::new();
    let mut fg = 39;
    let mut it = raw.chars().peekable();
    while let Some(c) = it.next() {
        if c == '\u{1b}' && it.peek() == Some(&'[') {
            it.next();
            let mut params = String::new();
            for d in it.by_ref() {
                if d.is_ascii_alphabetic() {
                    if d == 'm' {
                        let ps: Vec<u32> =
                            params.split(';').map(|p| p.parse().unwrap_or(0)).collect();
                        let mut i = 0;
                        while i < ps.len() {
                            match ps[i] {
                                0 | 39 => fg = 39,
                                n @ (30..=37 | 90..=97) => fg = n,
                                // 38;5;N: the 256-colour form tmux uses.
                                38 if ps.get(i + 1) == Some(&5) => {
                                    let n = ps.get(i + 2).copied().unwrap_or(0);
                                    fg = if n < 8 { 30 + n } else { 82 + n };
                                    i += 2;
                                }
                                // 38;2;R;G;B: 24-bit, kept apart by value.
                                38 if ps.get(i + 1) == Some(&2) => {
                                    let c = |k: usize| ps.get(i + k).copied().unwrap_or(0);
                                    fg = 1_000_000 + (c(2) << 16) + (c(3) << 8) + c(4);
                                    i += 4;
                                }
                                _ => {}
                            }
                            i += 1;
                        }
                    }
                    break;
                }
                params.push(d);
            }
        } else if ('\u{2801}'..='\u{28FF}').contains(&c) {
            *counts.entry(fg).or_insert(0) += 1;
        }
    }
    counts
}

/// Persson's green curve is drawn where it coincides with the total (fig3)
/// and mostly with it (fig2), and the legend says which curve lies under it
/// where it does: on fig3 everywhere; on fig2 the total leaves Persson's
/// line above ζ ≈ 2000, so both are listed.
#[test]
fn coinciding_curves_stay_visible_and_the_legend_says_so() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (preset, legend, blue) in [
        (
            "fig3",
            "━━ plastic < 1  ━━ Persson = elastic = total here",
            0,
        ),
        ("fig2", "━━ total  ━━ Persson elastic", 20),
    ] {
        let p = Pane::start(preset, dir.path(), (100, 30), &[], &["--preset", preset]);
        let s = p.wait_text("Readout");
        assert!(s.contains(legend), "{preset}:\n{s}");
        if preset == "fig2" {
            assert!(!s.contains("= total here"), "{s}");
        }
        let raw = p.tmux(&["capture-pane", "-e", "-p", "-t", "t"]);
        let counts = braille_by_colour(&String::from_utf8_lossy(&raw.stdout));
        let green = counts.get(&32).copied().unwrap_or(0);
        assert!(green > 30, "{preset}: {green} green cells ({counts:?})");
        // The plastic curve (blue) is its own and visible where it lies in
        // the chart (fig3's, at 1e-33, lies below it and the legend says so).
        // Blue as the palette has it: ANSI 34 or bright 94, xterm's 63
        // (82 + 63 here), or 24-bit #5f5fff.
        let shown: usize = [34, 94, 82 + 63, 1_000_000 + 0x5f5fff]
            .iter()
            .map(|k| counts.get(k).copied().unwrap_or(0))
            .sum();
        assert!(
            shown >= blue && (blue > 0) == (shown > 0),
            "{preset}: {counts:?}"
        );
    }
}

/// `--help` says where the keys are, the smallest terminal and NO_COLOR.
#[test]
fn help_mentions_the_keys_the_minimum_size_and_no_color() {
    let o = Command::new(env!("CARGO_BIN_EXE_roughtui"))
        .arg("--help")
        .output()
        .unwrap();
    assert!(o.status.success());
    let s = String::from_utf8_lossy(&o.stdout);
    for must in ["80×24", "? lists the keys", "NO_COLOR", "roughtui export"] {
        assert!(s.contains(must), "--help lacks {must:?}:\n{s}");
    }
}

/// Bytes for one ζ step (marker and readout move) and one h_rms step
/// (curves redrawn too) on fig2 at 100×30; printed for docs/explorer.md.
#[test]
fn bytes_per_slider_step_at_100x30() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start("bytes", dir.path(), (100, 30), &[], &[]);
    p.wait_text("ζ = 128");
    let zeta = p.bytes_written(|| {
        p.keys(&["Right"]);
        p.wait_text("ζ = 178");
    });
    p.keys(&["k"]);
    let h_rms = p.bytes_written(|| {
        p.keys(&["Right"]);
        p.wait_text("31.6 nm");
    });
    eprintln!("bytes for one step at 100x30: ζ {zeta}, h_rms {h_rms}");
    assert!(zeta > 0 && zeta < 4000 && h_rms > 0 && h_rms < 6000);
}

/// `--load mine.ron` shows the file's name beside the scene's.
#[test]
fn a_loaded_file_shows_its_name() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("mine.ron"), common::GOOD).unwrap();
    let p = Pane::start("load", dir.path(), (100, 30), &[], &["--load", "mine.ron"]);
    let s = p.wait_text("Readout");
    assert!(s.contains("[fig2 · mine.ron]"), "{s}");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}
