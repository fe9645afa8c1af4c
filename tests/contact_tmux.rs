//! The contact view in a real terminal: Tab reaches it, the solver's
//! progress bar shows while it works (the explorer wakes for it with no
//! key pressed), then the result; a change of the scene starts again.

mod common;

use common::tmux::{have_tmux, Pane};

#[test]
fn tab_to_the_contact_view_shows_the_progress_then_the_result() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // ζ = 32: a 256² grid, seconds for the thirteen loads in a debug build.
    let p = Pane::start("contact", dir.path(), (160, 48), &[], &["--set", "zeta=32"]);
    p.wait_text("slope H0·dA/dp̄/A0 vs ζ");
    p.keys(&["Tab", "Tab", "Tab", "Tab"]);
    p.wait_text("simulation 256² · seeds 1–4");
    // R: sixteen surfaces, then one.
    p.keys(&["R"]);
    p.wait_text("16 surfaces: seeds 1–16");
    p.keys(&["R"]);
    p.wait_text("one surface: seed 1");
    let s = p.wait_text("simulation 256² · seed 1 ");
    assert!(s.contains("solving") || s.contains("13 solved"), "{s}");
    // No key pressed from here: the explorer redraws as the solver works.
    let s = p.wait_text("13 solved");
    assert!(
        s.contains(
            "simulation at p̄ = 0.01 H0: contact 2.34 %, 1.5 % plastic · theory: 2.01 %, 7.9 % plastic"
        ),
        "{s}"
    );
    assert!(s.contains("█ elastic █ at H0"), "{s}");
    // The size effect changes the hardness: the job starts again.
    p.keys(&["e"]);
    p.wait_text("solving");
    p.keys(&["]"]);
    p.wait_text("p̄ = 0.01778 H");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}
