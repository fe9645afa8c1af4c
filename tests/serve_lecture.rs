//! A lecture that goes right, with real OpenSSH clients in tmux: a poll
//! holds whatever the lecturer does until revealed or cancelled (also
//! across the lecturer's leaving), shows nothing of its answer on any
//! screen while open, says each student's miss plainly at the reveal, and
//! saves a CSV with a row for the students who did not answer.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use std::process::Command;

use common::lecture::{csvs, lecturer_key, lecturer_line, modes};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;
use rough_model::Axis;

/// ζ after `k` coarse steps up from `from` on fig2's sweep.
fn stepped(from: f64, k: usize) -> f64 {
    (0..k).fold(from, |v, _| {
        roughtui::tui::app::step_value(Axis::Zeta, v, (1.0, 1e4), true, false)
    })
}

/// The miss as a reader would say it: the percentage of the larger over
/// the smaller, two digits, "low" or "high".
fn miss(answer: f64, truth: f64) -> String {
    // Per cent of the truth: (1 − answer/truth) low, (answer/truth − 1) high.
    let pc = (answer / truth - 1.0).abs() * 100.0;
    let pc = if pc < 10.0 {
        format!("{pc:.1}")
    } else {
        format!("{pc:.0}")
    };
    format!("{pc} % {}", if answer < truth { "low" } else { "high" })
}

/// Nothing of fig2's answer (ζ = 321.5, "≈ 320" in the caption).
fn assert_clean(screen: &str, who: &str) {
    for d in ["321", "320", "≈"] {
        assert!(!screen.contains(d), "{who} shows {d}:\n{screen}");
    }
}

#[test]
fn a_poll_holds_never_leaks_and_ends_as_the_lecturer_says() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--preset",
            "fig2",
        ],
    );
    let room = Room::new("hold", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's explorer", 30, |s| {
        s.contains("Readout")
    });
    let names = ["ann", "bob", "cat"];
    for n in names {
        room.open(n, &srv.ssh_line(n, &["-t"]));
    }
    // Ann's terminal is wide: the caption shows whole there.
    room.resize("ann", (160, 48));
    room.wait_all(&names, "students following", 60, |s| {
        s.contains("following the lecturer")
    });
    room.wait("ann", "the caption whole", 30, |s| s.contains("≈ 320"));

    // v: nothing of the answer anywhere while the poll is open.
    room.keys("lect", &["v"]);
    room.wait_all(&names, "the question", 30, |s| {
        s.contains("Predict: where does the plastic share pass ½?")
    });
    let lect = room.wait("lect", "the open poll", 30, |s| {
        s.contains("poll open: 0/3 answered · v reveals · C cancels")
    });
    assert_clean(&lect, "the lecturer");
    assert_clean(&room.capture("ann"), "the wide student");
    // Cat reads every help page.
    room.keys("cat", &["?"]);
    let first = room.wait("cat", "the help", 20, |s| s.contains("help 1/"));
    let pages: usize = first
        .split("help 1/")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap();
    for page in 1..=pages {
        let s = room.wait("cat", "a help page", 20, |s| {
            s.contains(&format!("help {page}/{pages}"))
        });
        assert_clean(&s, &format!("help page {page}"));
        room.keys("cat", &["Right"]);
    }
    room.keys("cat", &["Escape"]);
    // The lecturer's help too.
    room.keys("lect", &["?"]);
    room.wait("lect", "the lecturer's help", 20, |s| s.contains("help 1/"));
    for _ in 0..6 {
        assert_clean(&room.capture("lect"), "the lecturer's help");
        room.keys("lect", &["Right"]);
    }
    room.keys("lect", &["Escape"]);
    // Bob walks the marker across the answer: the readout hides the share.
    for k in 1..=3 {
        room.keys("bob", &["Right"]);
        let want = roughtui::physical::print::fmt_param(Axis::Zeta, stepped(128.0, k));
        let s = room.wait("bob", "the marker moved", 20, |s| {
            s.contains(&format!("ζ    ↔ {want:>9}"))
        });
        assert_clean(&s, "the walking student");
        assert!(s.contains("plastic ?  (until the reveal)"), "{s}");
    }
    room.keys("ann", &["Right", "Enter"]);
    room.keys("bob", &["Enter"]);
    room.wait("lect", "two answers", 30, |s| {
        s.contains("poll open: 2/3 answered")
    });

    // Whatever else the lecturer does, the poll holds: a move, a view,
    // the help, a snapshot saved, a picture.
    room.keys("lect", &["Right", "Tab", "?", "Escape", "s"]);
    room.wait("lect", "the save prompt", 20, |s| s.contains("save as:"));
    room.keys("lect", &["Enter"]);
    room.wait("lect", "the snapshot saved", 20, |s| s.contains("saved "));
    room.keys("lect", &["p"]);
    room.wait("lect", "the picture saved", 20, |s| s.contains(".svg"));
    room.keys("lect", &["Tab", "Tab", "Tab", "Tab"]);
    let lect = room.wait("lect", "the poll still open", 20, |s| {
        s.contains("poll open: 2/3 answered")
    });
    assert_clean(&lect, "the lecturer after moving");
    room.wait_all(&names[..2], "still answered", 20, |s| {
        s.contains("you answered ζ = ")
    });
    room.wait("cat", "still asked", 20, |s| s.contains("Predict:"));

    // The lecturer's connection drops and comes back: the poll holds.
    room.keys("lect", &["q"]);
    srv.wait_log("the lecturer's leave", 20, |l| {
        l.contains("leave lecturer (lecturer)")
    });
    room.wait("cat", "still asked", 20, |s| s.contains("Predict:"));
    room.open("lect2", &lecturer_line(&srv, &key));
    room.wait("lect2", "the poll still open", 30, |s| {
        s.contains("poll open: 2/3 answered")
    });

    // v reveals: the miss said plainly, to everyone asked.
    room.keys("lect2", &["v"]);
    let truth = roughtui::figure::claims(&roughtui::presets::load("fig2").unwrap())[0].at;
    let (a, b) = (stepped(128.0, 1), stepped(128.0, 3));
    let short = roughtui::physical::short_number;
    let line = |s: &str| {
        s.lines()
            .find(|l| l.contains("the model:"))
            .unwrap_or("")
            .to_string()
    };
    let ann = room.wait("ann", "ann's reveal", 30, |s| s.contains("the model:"));
    assert!(
        line(&ann).contains(&format!(
            "the model: ζ = 321.5 · you: {} · {} · Enter dismisses",
            short(a),
            miss(a, truth)
        )),
        "{ann}"
    );
    let bob = room.wait("bob", "bob's reveal", 30, |s| s.contains("the model:"));
    assert!(
        line(&bob).contains(&format!(
            "the model: ζ = 321.5 · you: {} · {}",
            short(b),
            miss(b, truth)
        )),
        "{bob}"
    );
    room.wait("cat", "cat's reveal", 30, |s| {
        s.contains("the model: ζ = 321.5 · you did not answer")
    });
    // The reveal stays as the lecturer moves on; Enter dismisses it and
    // the student keeps following.
    room.keys("lect2", &["Left"]);
    room.wait_all(&names, "following again", 30, |s| {
        s.contains("following the lecturer")
    });
    room.wait_all(&names, "the reveal kept", 30, |s| s.contains("the model:"));
    room.keys("ann", &["Enter"]);
    room.wait("ann", "dismissed", 20, |s| {
        !s.contains("the model:") && s.contains("following the lecturer")
    });
    room.keys("lect2", &["Left"]);
    room.wait("lect2", "one on their own? no: all follow", 20, |s| {
        s.contains("3 students · 3 following · 0 on their own · revealed ζ = 321.5 (2 answers)")
    });

    // S: the CSV with the silent student's row.
    room.keys("lect2", &["S"]);
    room.wait("lect2", "the CSV", 20, |_| csvs(dir.path()).len() == 1);
    let text = std::fs::read_to_string(&csvs(dir.path())[0]).unwrap();
    let q = "where does the plastic share pass 1/2?,zeta,";
    // Each answer's time (UTC, to the second) last; no step outside a lesson.
    let mut rows: Vec<String> = text
        .lines()
        .map(|l| {
            // Saved at the reveal: poll 1, revealed.
            let l = l
                .strip_suffix(",1,yes")
                .or_else(|| l.strip_suffix(",poll,revealed"))
                .unwrap_or_else(|| panic!("{l}"));
            let (rest, time) = l.rsplit_once(',').unwrap();
            assert!(
                time.is_empty() || time == "time" || time.ends_with('Z'),
                "{l}"
            );
            let rest = rest.strip_suffix(',').unwrap_or(rest);
            rest.to_string()
        })
        .collect();
    assert_eq!(
        rows.remove(0),
        "question,quantity,unit,truth,name,answer,offset,step"
    );
    rows.sort();
    let num = roughtui::physical::csv_number::format;
    assert_eq!(
        rows,
        [
            format!("{q},{},ann,{},{}", num(truth), num(a), num(a - truth)),
            format!("{q},{},bob,{},{}", num(truth), num(b), num(b - truth)),
            format!("{q},{},cat,no answer,", num(truth)),
        ]
    );

    // A new poll, cancelled: everyone follows again, nothing to save.
    room.keys("lect2", &["v"]);
    room.wait_all(&names, "the next question", 30, |s| s.contains("Predict:"));
    room.keys("lect2", &["C"]);
    room.wait("lect2", "cancelled", 20, |s| {
        s.contains("poll cancelled: its answers are dropped")
    });
    room.wait_all(&names, "told", 30, |s| {
        s.contains("the lecturer cancelled the poll") && !s.contains("Predict:")
    });
    room.wait("lect2", "all following", 30, |s| {
        s.contains("3 students · 3 following · 0 on their own") && !s.contains("revealed")
    });
    room.keys("lect2", &["S"]);
    room.wait("lect2", "nothing to save", 20, |s| {
        s.contains("no poll to save: v starts one")
    });
}

#[test]
fn nobody_is_dropped_without_a_word() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--preset",
            "fig2",
            "--idle-timeout",
            "5s",
            "--max-sessions",
            "3",
        ],
    );
    let room = Room::new("word", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's explorer", 30, |s| {
        s.contains("Readout")
    });
    // Three students: the lecturer took none of their places.
    for n in ["ann", "bob", "cat"] {
        room.open(n, &srv.ssh_line(n, &["-t"]));
    }
    // Cat's terminal is small: the compact screen, not "enlarge".
    room.resize("cat", (44, 11));
    room.wait_all(&["ann", "bob"], "following", 30, |s| {
        s.contains("following the lecturer")
    });
    let cat = room.wait("cat", "the compact screen", 30, |s| {
        s.contains("roughtui [fig2]") && s.contains("ζ = 128")
    });
    assert!(!cat.contains("enlarge the terminal"), "{cat}");
    room.wait("lect", "three students", 30, |s| s.contains("3 students"));
    // A fourth is told on their terminal.
    room.open("dan", &srv.ssh_line("dan", &["-t"]));
    room.wait("dan", "the class is full", 30, |s| {
        s.contains("roughtui: the class is full (3 students): try again later")
    });
    // With the class full the lecturer still gets in (a second session).
    room.open("lect2", &lecturer_line(&srv, &key));
    room.wait("lect2", "the second lecturer session", 30, |s| {
        s.contains("3 students")
    });
    room.keys("lect2", &["q"]);

    // Bob leaves the lecturer to explore: idle 5 s, he is told why.
    room.keys("bob", &["Right"]);
    room.wait("bob", "on his own", 20, |s| {
        s.contains("exploring on your own")
    });
    let bob = room.wait("bob", "the idle line", 30, |s| {
        s.contains("roughtui: no key for 5s: the session ended (ssh again to come back)")
    });
    assert!(!bob.contains("Readout"), "not on the normal screen:\n{bob}");
    assert_eq!(modes(&room, "bob"), (false, true));
    // The lecturer and those following, as long idle, are all still here.
    std::thread::sleep(std::time::Duration::from_secs(2));
    assert!(room.capture("lect").contains("Readout"));
    assert!(room.capture("ann").contains("following the lecturer"));
    // Cat follows and answers on the compact screen.
    room.keys("lect", &["v"]);
    room.wait("cat", "the question", 30, |s| {
        s.contains("Predict: where does the plastic share") && s.contains("⏎ answer")
    });
    room.keys("cat", &["Right", "Enter"]);
    room.wait("cat", "the answer sent", 30, |s| s.contains("you answered"));
    room.wait("lect", "cat's answer", 30, |s| s.contains("1/2 answered"));
    room.keys("lect", &["v"]);
    room.wait("cat", "the reveal", 30, |s| {
        s.contains("the model: ζ = 321.5")
    });
    // The lecturer removes a student from the class list: told why.
    room.keys("lect", &["w"]);
    room.wait("lect", "the class list", 20, |s| s.contains("x removes"));
    // (The list is in the order they came: ann or cat first.)
    room.keys("lect", &["x"]);
    let lect = room.wait("lect", "removed", 20, |s| {
        s.contains(": told so on their terminal")
    });
    let who = if lect.contains("removed ann:") {
        "ann"
    } else {
        "cat"
    };
    assert!(lect.contains(&format!("removed {who}: told so")), "{lect}");
    // cat's terminal is 44 columns wide: the line is wrapped there.
    room.wait(who, "the line", 20, |s| {
        s.split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
            .contains("roughtui: the lecturer removed you from the class")
    });
    assert_eq!(modes(&room, who), (false, true));
    room.wait("lect", "one student left", 20, |s| s.contains("1 student"));
}

#[test]
fn a_clean_goodbye_on_sigterm_and_ctrl_c() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let have_plink = common::tmux::have_tool(
        "plink",
        "ROUGHTUI_REQUIRE_SSH",
        "the PuTTY goodbye (apt-get install putty-tools)",
    );
    for signal in ["TERM", "INT"] {
        let dir = tempfile::tempdir().unwrap();
        let key = lecturer_key(dir.path());
        let keys = key.with_extension("pub");
        let srv = Server::start(
            dir.path(),
            &[
                "--lecturer-keys",
                keys.to_str().unwrap(),
                "--preset",
                "fig2",
            ],
        );
        let room = Room::new(&format!("bye{signal}"), (100, 30));
        room.open("lect", &lecturer_line(&srv, &key));
        room.wait("lect", "the lecturer", 30, |s| s.contains("Readout"));
        let mut names = vec!["ann", "bob"];
        room.open("ann", &srv.ssh_line("ann", &["-t"]));
        room.open(
            "bob",
            &format!("env LANG=C TERM=vt100 {}", srv.ssh_line("bob", &["-t"])),
        );
        if have_plink {
            let fingerprint = srv
                .banner
                .split_whitespace()
                .find(|w| w.starts_with("SHA256:"))
                .unwrap()
                .to_string();
            room.open(
                "pat",
                &format!(
                    "env LANG=C.UTF-8 plink -ssh -batch -t -P {} -hostkey {} pat@127.0.0.1",
                    srv.port,
                    common::tmux::sh_quote(&fingerprint)
                ),
            );
            names.push("pat");
        }
        room.wait_all(&names, "following", 30, |s| s.contains("Readout"));
        // A poll saved, for the summary.
        room.keys("lect", &["v"]);
        room.wait("ann", "the question", 30, |s| s.contains("Predict:"));
        room.keys("ann", &["Enter"]);
        room.keys("lect", &["S"]);
        room.wait("lect", "the CSV", 20, |s| s.contains("saved "));
        for n in ["lect"].iter().chain(&names) {
            assert_eq!(modes(&room, n), (true, false), "{n} before");
        }
        assert!(Command::new("kill")
            .args([&format!("-{signal}"), &srv.pid().to_string()])
            .status()
            .unwrap()
            .success());
        for n in ["lect"].iter().chain(&names) {
            let s = room.wait(n, "the goodbye", 30, |s| {
                s.contains("roughtui: the class has ended")
            });
            assert!(!s.contains("FATAL ERROR"), "{n}:\n{s}");
            // The last screen stays above the goodbye, on the normal
            // screen: the explorer's footer is there.
            let above = s.split("roughtui: the class has ended").next().unwrap();
            assert!(above.contains("q quit"), "{n}:\n{s}");
            assert_eq!(modes(&room, n), (false, true), "{n} after:\n{s}");
        }
        // The poll was still open: its answers are saved too, and said.
        let log = srv.wait_log("the summary", 20, |l| l.contains("poll answers saved in:"));
        let csv = csvs(dir.path());
        assert_eq!(csv.len(), 2, "{log}");
        let students = if have_plink { 3 } else { 2 };
        let open = log
            .split_once("the poll was still open: its 1 answer saved unrevealed in ")
            .map(|(_, rest)| rest.lines().next().unwrap().to_string())
            .unwrap_or_else(|| panic!("{log}"));
        assert!(csv.iter().any(|c| c.display().to_string() == open), "{log}");
        // Its rows say so: poll 1, not revealed.
        let rows = std::fs::read_to_string(&open).unwrap();
        assert!(rows.lines().skip(1).all(|r| r.ends_with(",1,no")), "{rows}");
        let summary = format!(
            "roughtui serve: the class has ended: {students} students came, 1 poll\n\
             poll answers saved in:\n"
        );
        assert!(log.contains(&summary), "{log}");
        for c in &csv {
            assert!(log.contains(&format!("\n  {}\n", c.display())), "{log}");
        }
        let mut child = srv;
        let status = child.child.wait().unwrap();
        assert_eq!(status.code(), Some(0), "{signal}");
    }
}

#[test]
fn the_banner_names_real_addresses_the_same_way_twice() {
    let dir = tempfile::tempdir().unwrap();
    let keys = lecturer_key(dir.path()).with_extension("pub");
    // The machine's addresses as iproute2 lists them: IPv4, not loopback.
    let ip = Command::new("ip")
        .args(["-o", "-4", "addr", "show"])
        .output();
    let Ok(ip) = ip else {
        eprintln!("no ip(8): skipping the banner's addresses");
        return;
    };
    let mut want: Vec<String> = String::from_utf8_lossy(&ip.stdout)
        .lines()
        .filter_map(|l| l.split_whitespace().nth(3))
        .filter_map(|a| a.split('/').next())
        .filter(|a| !a.starts_with("127."))
        .map(String::from)
        .collect();
    want.sort();
    want.dedup();
    let banner = |listen: &str| {
        let mut child = Command::new(common::tmux::BIN)
            .current_dir(dir.path())
            .args(["serve", "--listen", listen, "--host-key"])
            .arg(dir.path().join("hk"))
            .args(["--lecturer-keys", keys.to_str().unwrap()])
            .stdin(std::process::Stdio::null())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let out = std::io::BufReader::new(child.stdout.take().unwrap());
        let mut lines = Vec::new();
        for l in std::io::BufRead::lines(out) {
            let l = l.unwrap();
            let end = l.starts_with("students:");
            lines.push(l);
            if end {
                break;
            }
        }
        let _ = child.kill();
        let _ = child.wait();
        lines
    };
    let b = banner("127.0.0.1:0");
    let port = b[0].rsplit(':').next().unwrap().to_string();
    assert!(
        b.contains(&format!("lecturer: ssh -p {port} lecturer@127.0.0.1")),
        "{b:?}"
    );
    assert_eq!(
        b.last().unwrap(),
        &format!("students: ssh -p {port} 127.0.0.1")
    );
    let b = banner("0.0.0.0:0");
    let port = b[0].rsplit(':').next().unwrap().to_string();
    let host = match want.as_slice() {
        [] => {
            eprintln!("no address but loopback: skipping");
            return;
        }
        [one] => one.clone(),
        many => {
            for a in many {
                assert!(b.contains(&format!("  {a}")), "{a} in {b:?}");
            }
            "HOST".to_string()
        }
    };
    assert!(
        b.contains(&format!("lecturer: ssh -p {port} lecturer@{host}")),
        "{b:?}"
    );
    assert_eq!(
        b.last().unwrap(),
        &format!("students: ssh -p {port} {host}")
    );
}
