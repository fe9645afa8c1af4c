//! Lessons with real OpenSSH clients in tmux: `serve --lesson` steps the
//! class through lessons/paper.ron (n / N, "step 3/8 · title" on every
//! screen, a step's poll asked without its answer, one CSV of all its
//! polls), `F` pulls every student back, `o` loads a scene for everyone;
//! `roughtui --lesson` rehearses alone and a bad lesson is refused.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use std::path::Path;
use std::process::Command;

use common::lecture::{csvs, lecturer_key, lecturer_line};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;

#[test]
fn a_lesson_steps_polls_into_one_csv_and_everyone_follows() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let paper = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
    let srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--lesson",
            paper.to_str().unwrap(),
        ],
    );
    let room = Room::new("lesson", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.open("ann", &srv.ssh_line("ann", &["-t"]));
    room.open("bob", &srv.ssh_line("bob", &["-t"]));
    let all = ["lect", "ann", "bob"];
    room.wait_all(&all, "step 1", 30, |s| {
        s.contains("step 1/8 · The claim: realistic hardness is elastic")
    });
    // The lecturer's footer and help name the lecturer's keys.
    let lect = room.capture("lect");
    assert!(
        lect.contains("v V poll") && lect.contains("n N step"),
        "{lect}"
    );
    room.keys("lect", &["?"]);
    let help = room.wait("lect", "the help", 20, |s| s.contains("help 1/"));
    for k in [" v ", " V ", " C ", " F ", " S ", " n N "] {
        assert!(help.contains(k), "{k}:\n{help}");
    }
    room.keys("lect", &["Escape"]);
    room.wait("lect", "the help closed", 20, |s| !s.contains("help 1/"));
    let claim = |fig: &str, i: usize| {
        roughtui::figure::claims(&roughtui::presets::load(fig).unwrap())[i].at
    };
    // Three polls: fig1's share, fig2's share, and fig3's: does the
    // share pass ½ at all with the size effect? Nowhere (the paper: the
    // plastic area is zero over the whole range); ann answers with `0`.
    let nowhere = roughtui::class::NOWHERE;
    let polls = [
        (
            2,
            "where does the plastic share fall below ½?",
            claim("fig1", 0),
        ),
        (3, "where does the plastic share pass ½?", claim("fig2", 0)),
        (
            5,
            "where does the plastic share pass ½ now (if anywhere)?",
            nowhere,
        ),
    ];
    // The step before each poll hides its claims (and the readout's
    // values at the marker) on every screen.
    let hidden = "(this step's claims show after the lesson's next poll)";
    let before = |step: usize| {
        let screens = room.wait_all(&all, "the step before a poll", 30, |s| {
            s.contains(&format!("step {step}/8 · "))
        });
        for s in screens {
            assert!(s.contains("Ψ_P    ?"), "{s}");
            // (Bob has not dismissed the last reveal: it stands in.)
            assert!(s.contains(hidden) || s.contains("the model"), "{s}");
        }
    };
    before(1);
    let mut at = 1;
    for (step, question, truth) in polls {
        while at < step {
            room.keys("lect", &["n"]);
            at += 1;
            if at + 1 == step {
                before(at);
            }
        }
        let screens = room.wait_all(&all, "the step", 30, |s| {
            s.contains(&format!("step {step}/8 · "))
        });
        // Before the poll opens no screen gives its answer away.
        let shown = if truth == nowhere {
            "nowhere".to_string()
        } else {
            roughtui::physical::short_number(truth)
        };
        for (i, s) in screens.iter().enumerate() {
            assert!(!s.contains(&shown), "{shown}:\n{s}");
            // (Bob has not dismissed the last reveal: it stays.)
            if i < 2 {
                assert!(s.contains(&format!("this step asks: {question}")), "{s}");
            }
        }
        room.keys("lect", &["v"]);
        room.wait_all(&["ann", "bob"], "the question", 30, |s| {
            s.contains(&format!("Predict: {question}"))
        });
        room.keys("ann", &[if truth == nowhere { "0" } else { "Enter" }]);
        room.wait("lect", "ann's answer", 30, |s| s.contains("1/2 answered"));
        room.keys("lect", &["v"]);
        let lect = room.wait("lect", "the reveal", 30, |s| s.contains("answers added to"));
        assert!(lect.contains("paper-polls-"), "{lect}");
        room.wait("bob", "the reveal", 30, |s| {
            s.contains("you did not answer")
        });
        room.wait("ann", "the model's answer", 30, |s| {
            let said = if truth == nowhere {
                "the model: nowhere in the sweep · you: nowhere · right".to_string()
            } else {
                format!(" = {shown} · you: ")
            };
            s.contains("the model: ") && s.contains(&said)
        });
        room.keys("ann", &["Enter"]);
    }
    let files = csvs(dir.path());
    assert_eq!(files.len(), 1, "one CSV for the lesson: {files:?}");
    let text = std::fs::read_to_string(&files[0]).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(
        text.lines().next(),
        Some("question,quantity,unit,truth,name,answer,offset,step,time,poll,revealed")
    );
    assert_eq!(rows.len(), 6, "{text}");
    for (i, (step, question, truth)) in polls.iter().enumerate() {
        let q = question.replace('½', "1/2");
        for r in &rows[2 * i..2 * i + 2] {
            assert_eq!(r[0], q, "{text}");
            if *truth == nowhere {
                assert_eq!(r[3], "nowhere", "{text}");
            } else {
                assert_eq!(r[3].parse::<f64>().unwrap(), *truth, "{text}");
            }
            assert_eq!(r[7], step.to_string(), "{text}");
        }
        assert_eq!(rows[2 * i][4], "ann");
        assert!(rows[2 * i][8].ends_with('Z'), "{text}");
        assert_eq!(rows[2 * i + 1][4..6], ["bob", "no answer"]);
        for r in &rows[2 * i..2 * i + 2] {
            assert_eq!(r[9..], [(i + 1).to_string().as_str(), "yes"], "{text}");
        }
    }
    assert_eq!(rows[4][5], "nowhere", "{text}");
    // N goes back; F pulls a student exploring alone back.
    room.keys("lect", &["N"]);
    room.wait_all(&all, "step 4", 30, |s| {
        s.contains("step 4/8 · The index behind it")
    });
    room.keys("bob", &["m"]);
    room.wait("bob", "on his own", 20, |s| {
        s.contains("exploring on your own")
    });
    room.keys("lect", &["F"]);
    room.wait("bob", "called back", 20, |s| {
        s.contains("the lecturer asked everyone to follow: following again")
    });
    room.wait("lect", "all following", 20, |s| {
        s.contains("2 following · 0 on their own")
    });
}

#[test]
fn a_lesson_is_rehearsed_alone_and_a_bad_one_is_refused() {
    if !have_tmux() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let paper = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
    let p = common::tmux::Pane::start(
        "rehearse",
        dir.path(),
        (100, 30),
        &[],
        &["--lesson", paper.to_str().unwrap()],
    );
    p.wait_text("step 1/8 · The claim: realistic hardness is elastic");
    p.keys(&["n"]);
    let s = p.wait_text("step 2/8 · Poll: where does fig. 1 turn plastic?");
    assert!(
        s.contains("v opens this step's poll · n next step · N back"),
        "{s}"
    );
    // Nothing of the answer before the poll: fig1's share passes ½ at
    // E/H0 = 120.2.
    assert!(
        s.contains("this step asks: where does the plastic share fall below ½?"),
        "{s}"
    );
    assert!(!s.contains("120.2"), "{s}");
    for _ in 0..10 {
        p.keys(&["n"]);
    }
    p.wait_text("the lesson's last step: N goes back");
    p.keys(&["N"]);
    p.wait_text("step 7/8 · Rougher and softer");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    // A bad lesson: exit 2 and where the problem is.
    let bad = dir.path().join("bad.ron");
    std::fs::write(
        &bad,
        "(title: \"t\", steps: [(title: \"a\", scene: Preset(\"fig9\"))])",
    )
    .unwrap();
    let o = Command::new(common::tmux::BIN)
        .args(["--lesson", bad.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with(&format!("roughtui: the lesson {}, step 1: ", bad.display())),
        "{err}"
    );
}

#[test]
fn o_loads_a_preset_or_a_snapshot_for_everyone() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    // A snapshot in the lecturer's folder: fig3 with the exact model.
    let mut mine = roughtui::presets::load("fig3").unwrap();
    mine.name = "mine".into();
    mine.model = rough_model::Model::Exact;
    std::fs::write(dir.path().join("mine.ron"), mine.to_ron()).unwrap();
    let srv = Server::start(dir.path(), &["--lecturer-keys", keys.to_str().unwrap()]);
    let room = Room::new("open", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer", 30, |s| s.contains("Readout"));
    room.open("ann", &srv.ssh_line("ann", &["-t"]));
    room.wait("ann", "following", 30, |s| {
        s.contains("following the lecturer")
    });
    room.keys("lect", &["o"]);
    let list = room.wait("lect", "the list", 20, |s| s.contains("load a scene"));
    for e in ["preset fig1", "preset fig4", "mine.ron"] {
        assert!(list.contains(e), "{e}:\n{list}");
    }
    room.keys("lect", &["Down", "Down", "Down", "Enter"]);
    room.wait("ann", "fig4", 30, |s| s.contains("roughtui [fig4]"));
    room.keys("lect", &["o", "Up", "Enter"]);
    room.wait("ann", "the snapshot", 30, |s| {
        s.contains("roughtui [mine.ron]") && s.contains("· exact ·")
    });
    // Esc closes the list without loading.
    room.keys("lect", &["o", "Escape", "Right"]);
    room.wait("ann", "still mine", 30, |s| s.contains("[mine.ron*]"));
    // A lesson in the folder is listed as a lesson (a file that is neither
    // a snapshot nor a lesson is not listed); picking it leads the class
    // from its first step, `o` leaves the lesson (the step line says so)
    // and `n` returns to the step.
    let paper = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
    let text = std::fs::read_to_string(paper).unwrap();
    std::fs::write(dir.path().join("paper.ron"), text).unwrap();
    std::fs::write(dir.path().join("junk.ron"), "(not: a scene)").unwrap();
    room.keys("lect", &["o"]);
    let list = room.wait("lect", "the list", 20, |s| s.contains("load a scene"));
    assert!(
        list.contains("lesson paper.ron: Is rough contact elastic?"),
        "{list}"
    );
    assert!(
        !list.contains("junk.ron") && !list.contains(" paper.ron\n"),
        "{list}"
    );
    // The presets, then junk is left out, mine.ron, then the lesson.
    room.keys("lect", &["Up", "Enter"]);
    room.wait_all(&["lect", "ann"], "the lesson", 30, |s| {
        s.contains("step 1/8 · The claim: realistic hardness is elastic")
    });
    room.keys("lect", &["n", "o", "Enter"]);
    room.wait_all(&["lect", "ann"], "left the lesson", 30, |s| {
        s.contains("left the lesson at step 2/8 for fig1 · n returns")
    });
    room.keys("lect", &["n"]);
    room.wait_all(&["lect", "ann"], "back", 30, |s| {
        s.contains("step 2/8 · Poll: where does fig. 1 turn plastic?")
    });
}

/// The class ends with a lesson's first poll open (no CSV made yet): its
/// answers go to the lesson's CSV all the same, marked unrevealed.
#[test]
fn a_lesson_poll_still_open_at_the_end_goes_to_the_lessons_csv() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let paper = Path::new(env!("CARGO_MANIFEST_DIR")).join("lessons/paper.ron");
    let mut srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--lesson",
            paper.to_str().unwrap(),
        ],
    );
    let room = Room::new("lessonopen", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.open("ann", &srv.ssh_line("ann", &["-t"]));
    room.wait_all(&["lect", "ann"], "step 1", 30, |s| s.contains("step 1/8"));
    room.keys("lect", &["n"]);
    room.wait("ann", "step 2", 30, |s| s.contains("step 2/8"));
    room.keys("lect", &["v"]);
    room.wait("ann", "the question", 30, |s| s.contains("Predict:"));
    room.keys("ann", &["Enter"]);
    room.wait("lect", "ann's answer", 30, |s| s.contains("1/1 answered"));
    assert!(Command::new("kill")
        .args(["-TERM", &srv.pid().to_string()])
        .status()
        .unwrap()
        .success());
    let log = srv.wait_log("the summary", 20, |l| l.contains("poll answers saved in:"));
    let _ = srv.child.wait();
    let files = csvs(dir.path());
    assert_eq!(files.len(), 1, "{files:?}\n{log}");
    let name = files[0].file_name().unwrap().to_string_lossy().into_owned();
    assert!(name.starts_with("paper-polls-"), "{name}");
    assert!(
        log.contains(&format!(
            "its 1 answer saved unrevealed in {}",
            files[0].display()
        )),
        "{log}"
    );
    let text = std::fs::read_to_string(&files[0]).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows.len(), 2, "{text}");
    // ann's answer at step 2, poll 1, not revealed.
    let f: Vec<&str> = rows[1].split(',').collect();
    assert_eq!((f[4], f[7], f[9], f[10]), ("ann", "2", "1", "no"), "{text}");
}
