//! The explorer in a real terminal: tmux runs the binary, the test reads the
//! pane, presses keys, resizes, and checks the exit status.
//!
//! Skipped (with a note) when tmux is missing, unless ROUGHTUI_REQUIRE_TMUX
//! is set, as `.ci/run` does after installing tmux.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use common::tmux::{braille, have_tmux, Pane};

#[test]
fn explorer_under_tmux() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start("main", dir.path(), (100, 30), &[], &[]);
    // Waits for the whole first frame (a capture may catch it half drawn).
    let s = p.wait_for("the first frame", |s| {
        s.contains("[fig2]") && braille(s) > 100
    });
    assert!(s.contains("Readout"), "{s}");

    // One coarse slider step: ζ 128 → 10^2.25; count the bytes it costs.
    let bytes = p.bytes_written(|| {
        p.keys(&["Right"]);
        p.wait_text("ζ = 178");
    });
    eprintln!("bytes written for one slider step at 100x30: {bytes}");
    assert!(bytes > 0 && bytes < 4000, "{bytes} bytes for one step");
    // Idle: nothing is written.
    let idle = p.bytes_written(|| std::thread::sleep(Duration::from_millis(700)));
    assert_eq!(idle, 0, "the idle explorer wrote {idle} bytes");

    // Fine step, vi keys, selection.
    p.keys(&["S-Right"]);
    p.wait_text("ζ = 188");
    p.keys(&["h", "H"]);
    p.wait_text("ζ = 168");
    p.keys(&["k", "l"]); // h_rms up from 19.8 nm to 10^-7.5 m
    let s = p.wait_text("31.6 nm");
    assert!(s.contains("[fig2*]"), "{s}");

    for (key, name) in [
        ("3", "[fig3]"),
        ("4", "[fig4]"),
        ("1", "[fig1]"),
        ("2", "[fig2]"),
    ] {
        p.keys(&[key]);
        let s = p.wait_text(name);
        assert!(braille(&s) > 30, "{name}:\n{s}");
    }
    p.keys(&["x"]);
    p.wait_text("H 0.05…1 · ");
    p.keys(&["m"]);
    p.wait_text("· exact ·"); // the presets use the paper's closed form
    p.keys(&["e"]);
    p.wait_text("size effect on");
    p.keys(&["?"]);
    p.wait_text("Esc or ? closes");
    p.keys(&["Escape"]);
    p.wait_for("help closed", |s| !s.contains("Esc or ? closes"));

    // Resize down: a message, not a crash; back up: the explorer again.
    p.tmux(&["resize-window", "-t", "t", "-x", "40", "-y", "12"]);
    p.wait_text("enlarge the terminal");
    p.tmux(&["resize-window", "-t", "t", "-x", "100", "-y", "30"]);
    let s = p.wait_text("Readout");
    assert!(braille(&s) > 30, "{s}");

    // Two saves, two files.
    for n in 1..=2 {
        p.keys(&["s"]);
        p.wait_text("save as: fig2-");
        p.keys(&["Enter"]);
        let start = Instant::now();
        while std::fs::read_dir(dir.path()).unwrap().count() < n {
            assert!(start.elapsed() < Duration::from_secs(10), "save {n}");
            std::thread::sleep(Duration::from_millis(30));
        }
        p.wait_text("saved ");
    }
    let files: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(files.len(), 2, "{files:?}");
    assert!(files
        .iter()
        .all(|f| f.starts_with("fig2-") && f.ends_with(".ron")));

    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    assert_eq!(p.display("#{alternate_on}"), "0");
}

/// A folder where saving fails even for root: without root, a folder made
/// read-only; as root (whom permissions do not stop), /proc, where no file
/// can be created.
fn unwritable_dir() -> (PathBuf, Option<tempfile::TempDir>) {
    let uid = Command::new("id").arg("-u").output().unwrap();
    if String::from_utf8_lossy(&uid.stdout).trim() == "0" {
        return ("/proc".into(), None);
    }
    let d = tempfile::tempdir().unwrap();
    let mut perm = std::fs::metadata(d.path()).unwrap().permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut perm, 0o555);
    std::fs::set_permissions(d.path(), perm).unwrap();
    (d.path().to_path_buf(), Some(d))
}

#[test]
fn failed_save_shows_an_error_and_q_exits_0() {
    if !have_tmux() {
        return;
    }
    let (dir, _keep) = unwritable_dir();
    let p = Pane::start("ro", &dir, (80, 24), &[], &["--preset", "fig3"]);
    p.wait_text("[fig3]");
    p.keys(&["s"]);
    p.wait_text("save as: fig3-");
    p.keys(&["Enter"]);
    let s = p.wait_text("cannot");
    assert!(s.contains(dir.to_str().unwrap()), "{s}");
    // The session goes on.
    p.keys(&["l"]);
    p.wait_text("[fig3*]");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    if let Some(d) = _keep {
        let mut perm = std::fs::metadata(d.path()).unwrap().permissions();
        std::os::unix::fs::PermissionsExt::set_mode(&mut perm, 0o755);
        std::fs::set_permissions(d.path(), perm).unwrap();
    }
}

#[test]
fn panic_restores_the_terminal() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start(
        "panic",
        dir.path(),
        (80, 24),
        &[("ROUGHTUI_PANIC_KEY", "!")],
        &[],
    );
    p.wait_text("Readout");
    assert_eq!(p.display("#{alternate_on}"), "1");
    p.keys(&["!"]);
    assert_eq!(p.exit_status(), 101);
    assert_eq!(p.display("#{alternate_on}"), "0");
    assert_eq!(p.display("#{cursor_flag}"), "1");
    let s = p.wait_text("panicked");
    assert!(s.contains("ROUGHTUI_PANIC_KEY pressed"), "{s}");
}

/// The SGR parameters of colour (foreground, background, 256 and RGB).
fn colour_codes(s: &str) -> Vec<String> {
    let mut found = Vec::new();
    for seq in s.split('\u{1b}').skip(1) {
        let Some(body) = seq.strip_prefix('[') else {
            continue;
        };
        let Some(end) = body.find('m') else { continue };
        let params = &body[..end];
        if params
            .split(';')
            .filter_map(|p| p.parse::<u32>().ok())
            .any(|n| matches!(n, 30..=38 | 40..=48 | 90..=97 | 100..=107))
        {
            found.push(params.to_string());
        }
    }
    found
}

#[test]
fn no_color_draws_without_colour_codes() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let plain = Pane::start("nocolor", dir.path(), (100, 30), &[("NO_COLOR", "1")], &[]);
    let s = plain.wait_text("Readout");
    assert!(s.contains("•• elastic") && s.contains("++ plastic") && s.contains("oo Persson"));
    let raw = plain.tmux(&["capture-pane", "-e", "-p", "-t", "t"]);
    let raw = String::from_utf8_lossy(&raw.stdout);
    assert_eq!(colour_codes(&raw), Vec::<String>::new());
    plain.keys(&["q"]);
    assert_eq!(plain.exit_status(), 0);

    let coloured = Pane::start("color", dir.path(), (100, 30), &[], &[]);
    coloured.wait_text("Readout");
    let raw = coloured.tmux(&["capture-pane", "-e", "-p", "-t", "t"]);
    assert!(!colour_codes(&String::from_utf8_lossy(&raw.stdout)).is_empty());
}

/// The microseconds of each handled event in a `ROUGHTUI_FRAME_LOG` file.
fn frame_times(log: &Path) -> Vec<u64> {
    std::fs::read_to_string(log)
        .unwrap()
        .lines()
        .map(|l| l.parse().unwrap())
        .collect()
}

/// Median and 90th percentile.
fn median_p90(mut us: Vec<u64>) -> (u64, u64) {
    us.sort_unstable();
    (us[us.len() / 2], us[(us.len() * 9) / 10])
}

/// Key → drawn frame at 160×48 from the program's own frame log, in the
/// view `tabs` Tab presses from the slopes: 36 keys cycling a step of the
/// swept slider (twice: the marker moves), a selection, a step of h_rms
/// (twice: what the view shows is recomputed) and a selection back. Returns
/// (median, p90) in µs for the marker steps and for the recomputing steps.
fn key_to_frame(name: &str, tabs: usize, title: &str) -> ((u64, u64), (u64, u64)) {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("frames");
    let p = Pane::start(
        name,
        dir.path(),
        (160, 48),
        &[("ROUGHTUI_FRAME_LOG", log.to_str().unwrap())],
        &[],
    );
    p.wait_text("Readout");
    for _ in 0..tabs {
        p.keys(&["Tab"]);
    }
    p.wait_text(title);
    let keys = ["Right", "Left", "Up", "Right", "Left", "Down"];
    for i in 0..36 {
        p.keys(&[keys[i % 6]]);
        std::thread::sleep(Duration::from_millis(60));
    }
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    let us = frame_times(&log);
    assert_eq!(us.len(), 36 + tabs, "{us:?}");
    let steps = &us[tabs..];
    let pick = |phase: [usize; 2]| -> Vec<u64> {
        (0..steps.len())
            .filter(|i| phase.contains(&(i % 6)))
            .map(|i| steps[i])
            .collect()
    };
    (median_p90(pick([0, 1])), median_p90(pick([3, 4])))
}

#[test]
fn key_to_frame_time_at_160x48() {
    if !have_tmux() {
        return;
    }
    let ((m, m90), (r, r90)) = key_to_frame("timing", 0, "slope H0");
    eprintln!(
        "key to frame at 160x48: median {m} µs (p90 {m90} µs) moving the marker, \
         median {r} µs (p90 {r90} µs) recomputing the curves"
    );
    assert!(r < 100_000, "median {r} µs");
}

/// The contact view, whichever of its answers shows first.
const CONTACT: &str = "the contact view";

/// Tab and Shift-Tab through all five views; the size-effect key redraws the
/// regime map.
#[test]
fn tab_cycles_the_five_views() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let p = Pane::start("views", dir.path(), (80, 24), &[], &[]);
    p.wait_text("slope H0·dA/dp̄/A0 vs ζ");
    for (key, title) in [
        ("Tab", "plasticity indices vs ζ"),
        ("Tab", "plastic share over ζ × H0/E"),
        ("Tab", "A/A0 vs p̄/H0"),
        ("Tab", CONTACT),
        ("Tab", "slope H0·dA/dp̄/A0 vs ζ"),
        ("BTab", CONTACT),
        ("BTab", "A/A0 vs p̄/H0"),
        ("BTab", "plastic share over ζ × H0/E"),
    ] {
        p.keys(&[key]);
        if title == CONTACT {
            // The contact view: its coarse answer first, then the full
            // grid over four seeds (from the cache when it comes back).
            p.wait_for("the contact view", |s| {
                s.contains("simulation 256² coarse") || s.contains("simulation 1024² · seeds 1–4")
            });
        } else {
            p.wait_text(title);
        }
    }
    let s = p.wait_text("Ψ_P=1");
    assert!(s.contains("▀") && s.contains("◆"), "{s}");
    p.keys(&["e"]);
    p.wait_text("Ψ*=1");
    p.keys(&["y"]);
    p.wait_text("plastic share over ζ × h_rms");
    p.keys(&["Tab"]);
    p.wait_text("A/A0 vs p̄/H_y");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}

/// Key → drawn frame in the regime map view at 160×48: steps of the swept
/// slider (the map only moves its point) and of another slider (the map is
/// recomputed).
#[test]
fn key_to_frame_time_in_map_view_at_160x48() {
    if !have_tmux() {
        return;
    }
    let ((m, m90), (r, r90)) = key_to_frame("map-timing", 2, "plastic share over");
    eprintln!(
        "key to frame in map view at 160x48: median {m} µs (p90 {m90} µs) \
         moving the point, median {r} µs (p90 {r90} µs) recomputing the map"
    );
    assert!(r < 1_000_000, "median {r} µs");
}
