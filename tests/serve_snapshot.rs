//! A student takes the scene home, with a real OpenSSH client in tmux: `s`
//! prints the snapshot's RON on the terminal's normal screen, exactly as
//! saved, no border, long lines wrapped by the terminal; what a copy of
//! the pane gets (joined, scrolled back) at 80×24 and 160×48 reads back as
//! the student's scene, `y` puts the same text on the clipboard (OSC 52,
//! here tmux's buffer), and any other key brings the explorer back.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use common::lecture::modes;
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;
use roughtui::scene::State;

/// The RON between the panel's first and last lines in a copy of the
/// whole pane, its wrapped lines joined.
fn copied(room: &Room, name: &str) -> String {
    let t = format!("room:{name}");
    let o = room.tmux(&["capture-pane", "-p", "-J", "-S", "-", "-t", &t]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let start = text.find("-- your snapshot:").expect(&text);
    let body = &text[start..];
    let body = &body[body.find('\n').unwrap() + 1..];
    let end = body.find("-- y copies it").expect(&text);
    body[..end].to_string()
}

#[test]
fn a_student_copies_the_snapshot_whole_at_any_size() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--preset", "fig2"]);
    let room = Room::new("snap", (80, 24));
    assert!(room
        .tmux(&["set-option", "-g", "set-clipboard", "on"])
        .status
        .success());
    for (name, size) in [("small", (80, 24)), ("wide", (160, 48))] {
        room.open(name, &srv.ssh_line(name, &["-t"]));
        room.resize(name, size);
        room.wait(name, "the explorer", 30, |s| s.contains("Readout"));
        // The student's own scene: the exact model, ζ a step up.
        room.keys(name, &["m", "Right"]);
        room.wait(name, "the change", 20, |s| s.contains("ζ    ↔       178"));
        room.keys(name, &["s"]);
        let screen = room.wait(name, "the snapshot", 20, |s| s.contains("-- y copies it"));
        assert!(!screen.contains('┌') && !screen.contains('│'), "{screen}");
        assert_eq!(modes(&room, name), (false, true), "{name}: normal screen");
        let mut want = roughtui::presets::load("fig2").unwrap();
        want.model = want.model.other();
        // The preset's caption described its closed form: it goes with it.
        want.caption = None;
        want.params = want
            .params
            .with(
                rough_model::Axis::Zeta,
                roughtui::tui::app::step_value(
                    rough_model::Axis::Zeta,
                    128.0,
                    (1.0, 1e4),
                    true,
                    false,
                ),
            )
            .unwrap();
        let text = copied(&room, name);
        assert_eq!(text.trim_end(), want.to_ron().trim_end(), "{name}");
        assert_eq!(State::from_ron(&text).unwrap(), want, "{name}");
        // y: the clipboard (tmux's buffer) gets the same text.
        room.keys(name, &["y"]);
        room.wait(name, "copied", 20, |s| {
            s.contains("-- copied to your clipboard")
        });
        let buffer = room.tmux(&["show-buffer"]);
        let clip = String::from_utf8_lossy(&buffer.stdout).into_owned();
        assert_eq!(clip, want.to_ron(), "{name}");
        // Any other key: the explorer again, whole.
        room.keys(name, &["Escape"]);
        room.wait(name, "the explorer again", 20, |s| {
            s.contains("Readout") && !s.contains("-- y copies it")
        });
        assert_eq!(modes(&room, name), (true, false), "{name}: back");
        room.keys(name, &["q"]);
    }
}
