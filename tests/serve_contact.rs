//! The contact view in a served class: the lecturer Tabs to it, the
//! students following see the solver's progress and then the same result,
//! and the console says the scene was solved once for all of them.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use common::lecture::{lecturer_key, lecturer_line};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;

#[test]
fn a_class_solves_the_lecturers_contact_scene_once() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    // ζ = 32: a 256² grid, seconds in a debug build.
    let srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--preset",
            "fig2",
            "--set",
            "zeta=32",
        ],
    );
    let room = Room::new("contact", (160, 48));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's explorer", 30, |s| {
        s.contains("Readout")
    });
    let names = ["ada", "bob"];
    for n in names {
        room.open(n, &srv.ssh_line(n, &["-t"]));
    }
    room.wait_all(&names, "students following", 60, |s| {
        s.contains("following the lecturer")
    });
    room.keys("lect", &["Tab", "Tab", "Tab", "Tab"]);
    let all = ["lect", "ada", "bob"];
    room.wait_all(&all, "the contact view", 30, |s| {
        s.contains("simulation 256² · seeds 1–4")
    });
    let done = room.wait_all(&all, "the result", 90, |s| s.contains("52 solved"));
    for s in &done {
        assert!(
            s.contains(
                "contact 2.94 ± 0.40 %, 0.80 ± 0.65 % plastic · theory: 2.01 %, 7.9 % plastic"
            ),
            "{s}"
        );
    }
    let log = srv.wait_log("the job's end", 30, |l| {
        l.contains("contact: 52 solutions on 256² (seed 1)")
    });
    assert_eq!(log.matches("contact: ").count(), 1, "{log}");
    // The lecturer's next load: the students follow, nothing is solved again.
    room.keys("lect", &["]"]);
    room.wait_all(&all, "the next load", 30, |s| {
        s.contains("simulation at p̄ = 0.01778 H0: contact")
    });
    std::thread::sleep(std::time::Duration::from_millis(300));
    assert_eq!(srv.log().matches("contact: ").count(), 1);
}
