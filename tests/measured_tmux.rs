//! A measured surface in a real terminal (tmux) and over SSH: `--surface`
//! opens the explorer on a PSD table and on a contact.engineering download,
//! ζ steps, Tab reaches the spectrum view; a bad file is one message and
//! status 2; `serve --surface` shows the example height map to students,
//! and the lecturer switches between the presets and it.

mod common;

use std::process::Command;

use common::serve::{have_ssh, Server};
use common::tmux::{braille, have_tmux, Pane};

fn write_table(dir: &std::path::Path) {
    std::fs::write(dir.join("fig2-psd.txt"), common::measured::fig2_psd_text()).unwrap();
}

/// The ζ on the swept slider's line ("▶ ζ    ↔     10000  1…1e4").
fn zeta(screen: &str) -> String {
    let Some(line) = screen.lines().find(|l| l.contains("ζ") && l.contains('↔')) else {
        return String::new();
    };
    let after = line.split('↔').nth(1).unwrap_or("");
    after.split_whitespace().next().unwrap_or("").to_string()
}

#[test]
fn the_explorer_opens_a_surface_steps_zeta_and_shows_its_spectrum() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    write_table(dir.path());
    let p = Pane::start(
        "surface",
        dir.path(),
        (100, 30),
        &[],
        &["--surface", "fig2-psd.txt", "--set", "r-star=0.5mm"],
    );
    // The whole first frame: a capture can come while it is being written.
    let s = p.wait_for("the first screen", |s| {
        s.contains("Readout") && !zeta(s).is_empty() && braille(s) > 50
    });
    assert!(s.contains("[fig2-psd]"), "{s}");
    assert!(s.contains("measured moments"), "{s}");
    assert!(s.contains("√m0 at ζ") && s.contains("H fit"), "{s}");
    assert!(s.contains("500 µm"), "{s}");
    assert!(braille(&s) > 50, "{s}");
    assert_eq!(zeta(&s), "10000");
    p.keys(&["Left"]);
    let s = p.wait_for("ζ stepped", |s| zeta(s) != "10000");
    assert_eq!(zeta(&s), "5623", "{s}");
    p.keys(&["BTab", "BTab"]);
    let s = p.wait_text("C^iso (m⁴) vs q");
    assert!(s.contains("q1 = 5.62e8/m (ζ 5623)"), "{s}");
    assert!(braille(&s) > 20, "{s}");
    // `a` says why it does nothing here; the session goes on.
    p.keys(&["a"]);
    p.wait_text("moments are summed from its data");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    assert_eq!(p.display("#{alternate_on}"), "0");
}

#[test]
fn the_explorer_opens_a_contact_engineering_download() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/crates/rough-surface/tests/data/psd_knee_ce.txt"
        ),
        dir.path().join("knee.txt"),
    )
    .unwrap();
    let p = Pane::start("ce", dir.path(), (100, 30), &[], &["--surface", "knee.txt"]);
    let s = p.wait_text("Readout");
    assert!(
        s.contains("[knee]") && s.contains("measured moments"),
        "{s}"
    );
    assert!(s.contains("isotropic PSD table"), "{s}");
    p.keys(&["BTab", "BTab"]);
    let s = p.wait_text("C^iso (m⁴) vs q");
    assert!(braille(&s) > 20, "{s}");
    // Eq. 13 has no value on measured data.
    assert!(s.contains("Ψ*asy n/a on measured data"), "{s}");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    assert_eq!(p.display("#{alternate_on}"), "0");
}

#[test]
fn a_bad_surface_file_is_one_message_and_status_2() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.txt"), "# q C\n1e5 1e-20\n1e6 NaN\n").unwrap();
    let p = Pane::start(
        "badsurface",
        dir.path(),
        (80, 24),
        &[],
        &["--surface", "bad.txt"],
    );
    assert_eq!(p.exit_status(), 2);
    let s = p.wait_text("roughtui:");
    assert!(
        s.contains("roughtui: bad surface bad.txt, line 3: an undefined PSD value"),
        "{s}"
    );
    assert_eq!(p.display("#{alternate_on}"), "0");
}

#[test]
fn serve_shows_the_surface_and_the_lecturer_switches() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    // The shipped example: a Gwyddion-style height map.
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt"),
        dir.path().join("example.txt"),
    )
    .unwrap();
    let key = dir.path().join("lect");
    let st = Command::new("ssh-keygen")
        .args(["-q", "-t", "ed25519", "-N", "", "-f"])
        .arg(&key)
        .status()
        .unwrap();
    assert!(st.success());
    let keys = dir.path().join("keys");
    std::fs::copy(key.with_extension("pub"), &keys).unwrap();
    let srv = Server::start(
        dir.path(),
        &[
            "--surface",
            "example.txt",
            "--lecturer-keys",
            keys.to_str().unwrap(),
        ],
    );
    let key = key.to_str().unwrap();
    // Wide enough for the lecturer's keys and the surface's in the footer.
    let lect = Pane::start_shell(
        "msrv-lect",
        (120, 30),
        &srv.ssh_line("lecturer", &["-t", "-i", key, "-o", "IdentitiesOnly=yes"]),
    );
    let s = lect.wait_text("Readout");
    assert!(s.contains("[example]") && s.contains("5 surface"), "{s}");
    let stud = Pane::start_shell("msrv-stud", (100, 30), &srv.ssh_line("carol", &["-t"]));
    let s = stud.wait_text("following the lecturer");
    assert!(s.contains("[example]"), "{s}");
    assert!(s.contains("measured moments"), "{s}");
    // A preset, then back to the surface: the class follows.
    lect.keys(&["3"]);
    stud.wait_text("[fig3]");
    lect.keys(&["5"]);
    stud.wait_text("[example]");
    // The spectrum view follows too.
    lect.keys(&["BTab", "BTab"]);
    stud.wait_text("C^iso (m⁴) vs q");
    // A student alone can go back to the surface as well.
    stud.keys(&["2"]);
    stud.wait_text("exploring on your own");
    stud.wait_text("[fig2]");
    stud.keys(&["5"]);
    stud.wait_text("[example]");
    lect.keys(&["q"]);
    assert_eq!(lect.exit_status(), 0);
    stud.keys(&["q"]);
    assert_eq!(stud.exit_status(), 0);
}
