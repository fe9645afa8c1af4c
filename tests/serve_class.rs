//! A class with real OpenSSH clients: the class code (answered through
//! SSH_ASKPASS) and its limit on wrong codes, the line a full class gets,
//! the console log, the lecturer's class line and list, and a poll that 30
//! students answer before the model does. Names OpenSSH will not send
//! (control characters) come from the russh test client.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use common::codes::{askpass, code_ssh, finish, first_frame};
use common::lecture::{lecturer_key, lecturer_line};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::{have_tmux, BIN};
use rough_model::Axis;

const CODE: &str = "hertz";

#[test]
fn a_class_code_lets_the_room_in_while_one_client_keeps_failing() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let right = askpass(dir.path(), "right", CODE);
    let wrong = askpass(dir.path(), "wrong", "ohm");
    let limits = ["--max-sessions", "100", "--max-per-address", "100"];
    let mut args = vec!["--class-code", CODE];
    args.extend(limits);
    let srv = Arc::new(Server::start(dir.path(), &args));
    assert!(srv.banner.contains("class code: on"), "{}", srv.banner);

    // One client keeps sending the wrong code, from the class's address.
    let stop = Arc::new(AtomicBool::new(false));
    let errors = Arc::new(Mutex::new(Vec::new()));
    let failing = {
        let (srv, stop, errors, wrong) = (
            Arc::clone(&srv),
            Arc::clone(&stop),
            Arc::clone(&errors),
            wrong.clone(),
        );
        std::thread::spawn(move || {
            while !stop.load(Ordering::SeqCst) {
                let o = code_ssh(&srv, "mallory", &wrong, &["-tt"])
                    .stdin(Stdio::null())
                    .output()
                    .unwrap();
                let err = String::from_utf8_lossy(&o.stderr).into_owned();
                errors.lock().unwrap().push((o.status.code(), err));
            }
        })
    };
    srv.wait_log("wrong codes counted", 60, |l| {
        l.contains("refused in the last second: ") && l.contains(" wrong class codes")
    });

    // 60 students with the right code come in meanwhile.
    let t = Instant::now();
    let mut students: Vec<Child> = (0..60)
        .map(|i| {
            code_ssh(&srv, &format!("s{i}"), &right, &["-tt"])
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for s in &mut students {
        first_frame(s);
    }
    let joined = t.elapsed();
    let log = srv.wait_log("60 joins", 30, |l| {
        (0..60).all(|i| l.contains(&format!("join  s{i} from 127.0.0.1")))
    });
    assert!(!log.contains("join  mallory"), "{log}");
    stop.store(true, Ordering::SeqCst);
    failing.join().unwrap();
    for s in &mut students {
        s.stdin.as_mut().unwrap().write_all(b"q").unwrap();
    }
    for s in students {
        let (code, err) = finish(s, 30);
        assert_eq!(code, 0, "{err}");
    }
    let errors = errors.lock().unwrap();
    assert!(errors.iter().all(|(c, _)| *c == Some(255)), "{errors:?}");
    assert!(
        errors
            .iter()
            .any(|(_, e)| e.contains("Permission denied (keyboard-interactive)")),
        "{errors:?}"
    );
    eprintln!(
        "60 students in {joined:?} while {} wrong-code clients ran",
        errors.len()
    );
}

#[test]
fn the_lecturer_needs_no_code_and_nobody_else_is_the_lecturer() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let srv = Server::start(
        dir.path(),
        &[
            "--class-code",
            CODE,
            "--lecturer-keys",
            keys.to_str().unwrap(),
        ],
    );
    // The lecturer: by key, in batch mode (no prompt at all).
    let key = key.to_str().unwrap();
    let mut lect = Command::new("ssh")
        .args(srv.ssh_args("lecturer", &["-tt", "-i", key, "-o", "IdentitiesOnly=yes"]))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    first_frame(&mut lect);
    lect.stdin.as_mut().unwrap().write_all(b"q").unwrap();
    assert_eq!(finish(lect, 20).0, 0);
    // The class code does not make a lecturer.
    let right = askpass(dir.path(), "right", CODE);
    let o = code_ssh(
        &srv,
        "lecturer",
        &right,
        &["-tt", "-o", "IdentitiesOnly=yes"],
    )
    .stdin(Stdio::null())
    .output()
    .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(255), "{err}");
    assert!(err.contains("Permission denied (publickey)"), "{err}");
    // Without the code a student is not asked for a key.
    let o = Command::new("ssh")
        .args(srv.ssh_args("bob", &["-tt"]))
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(255), "{err}");
    assert!(
        err.contains("Permission denied (keyboard-interactive)"),
        "{err}"
    );
}

#[test]
fn a_full_class_gets_a_line_not_a_dropped_connection() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--max-sessions", "2"]);
    let held: Vec<Child> = (0..2)
        .map(|i| {
            let mut c = Command::new("ssh")
                .args(srv.ssh_args(&format!("s{i}"), &["-tt"]))
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            first_frame(&mut c);
            c
        })
        .collect();
    // The late student is let in to be told, on their terminal.
    let o = Command::new("ssh")
        .args(srv.ssh_args("late", &["-tt"]))
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert_eq!(
        out,
        "roughtui: the class is full (2 students): try again later\r\n"
    );
    srv.wait_log("the turn-away line", 20, |l| {
        l.contains("turned away 127.0.0.1: the class is full")
    });
    for mut c in held {
        c.stdin.as_mut().unwrap().write_all(b"q").unwrap();
        assert_eq!(finish(c, 20).0, 0);
    }
    // Per address, the same.
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--max-per-address", "1"]);
    let mut one = Command::new("ssh")
        .args(srv.ssh_args("one", &["-tt"]))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    first_frame(&mut one);
    let o = Command::new("ssh")
        .args(srv.ssh_args("two", &["-tt"]))
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.contains("roughtui: too many sessions from 127.0.0.1 (1): try again later"),
        "{out}"
    );
    one.stdin.as_mut().unwrap().write_all(b"q").unwrap();
    assert_eq!(finish(one, 20).0, 0);
}

#[test]
fn bad_class_codes_on_the_command_line_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| {
        let o = Command::new(BIN)
            .current_dir(dir.path())
            .args(["serve", "--listen", "127.0.0.1:0", "--host-key"])
            .arg(dir.path().join("hk"))
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
            o.stdout.len(),
        )
    };
    let empty = dir.path().join("empty");
    std::fs::write(&empty, "  \n\n").unwrap();
    let (code, err, out) = run(&["--class-code-file", empty.to_str().unwrap()]);
    assert_eq!((code, out), (Some(2), 0), "{err}");
    assert_eq!(
        err,
        format!(
            "roughtui: the class code file {} is empty\n",
            empty.display()
        )
    );
    let missing = dir.path().join("missing");
    let (code, err, _) = run(&["--class-code-file", missing.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.starts_with(&format!(
            "roughtui: cannot read the class code file {}: No such file",
            missing.display()
        )),
        "{err}"
    );
    let (code, err, _) = run(&["--class-code-file", dir.path().to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("cannot read the class code file"), "{err}");
    let binary = dir.path().join("binary");
    std::fs::write(&binary, b"\xff\xfe\x00code").unwrap();
    let (code, err, _) = run(&["--class-code-file", binary.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("valid UTF-8"), "{err}");
    let two = dir.path().join("two");
    std::fs::write(&two, "one\ntwo\n").unwrap();
    let (code, err, _) = run(&["--class-code-file", two.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("more than one line"), "{err}");
    let (code, err, _) = run(&["--class-code", " "]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(err, "roughtui: --class-code: the class code is empty\n");
    let (code, err, _) = run(&["--class-code", "a", "--class-code-file", "f"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("cannot be used with"), "{err}");
    // Nothing was written: no host key either.
    assert!(!dir.path().join("hk").exists());
}

// Multi-threaded: the russh client's connection keeps running while the
// test waits on tmux.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn names_are_shown_escaped_and_cut_and_the_console_logs_the_class() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let env = [("ROUGHTUI_SUMMARY_MS", "500")];
    let srv = Server::start_env(
        dir.path(),
        &["--lecturer-keys", keys.to_str().unwrap()],
        &env,
    );
    let room = Room::new("names", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's class line", 20, |s| {
        s.contains("0 students · 0 following · 0 on their own")
    });
    // 10 kB of name from OpenSSH; control characters from the russh client
    // (OpenSSH refuses to send them).
    let line = srv.ssh_line("LONG", &["-t"]);
    let long = line.replace(
        "'LONG@127.0.0.1'",
        r#"-l "$(head -c 10000 /dev/zero | tr '\0' a)" 127.0.0.1"#,
    );
    assert_ne!(line, long);
    room.open("long", &long);
    room.open("small", &srv.ssh_line("tiny", &["-t"]));
    room.resize("small", (60, 20));
    let (_h, mut ch) = common::client::student(srv.port, "red\x1b[31m\x07\u{202e}x", 100, 30)
        .await
        .unwrap();
    // Its first frame, then its frames are read as they come.
    let first = tokio::time::timeout(Duration::from_secs(20), async {
        loop {
            match ch.wait().await {
                Some(russh::ChannelMsg::Data { .. }) => break true,
                None => break false,
                Some(_) => {}
            }
        }
    });
    assert_eq!(first.await, Ok(true), "no frame for the russh student");
    tokio::spawn(async move { while ch.wait().await.is_some() {} });
    room.wait("lect", "three students", 20, |s| {
        s.contains("3 students · 3 following · 0 on their own · 1 terminal < 80×24")
    });
    room.keys("lect", &["w"]);
    let s = room.wait("lect", "the class list", 20, |s| s.contains("w closes"));
    let cut = format!("{}…", "a".repeat(31));
    assert!(s.contains(&cut), "{s}");
    assert!(!s.contains(&"a".repeat(33)), "{s}");
    assert!(s.contains(r"red\x1b[31m\x07\u{202e}x"), "{s}");
    assert!(
        s.lines()
            .any(|l| l.contains(" tiny ") && l.contains("following") && l.contains("60×20")),
        "{s}"
    );
    assert!(
        s.lines()
            .any(|l| l.contains(&cut) && l.contains("100×30") && l.contains("braille")),
        "{s}"
    );
    // A student's M (the next marker set) shows in the open list.
    room.keys("long", &["M"]);
    room.wait("lect", "the long name's half blocks", 20, |s| {
        s.lines()
            .any(|l| l.contains(&cut) && l.contains("100×30") && l.contains("half"))
    });
    // The console: a line per join with time, name, address, size, marker;
    // a summary each (here shortened) minute; escaped names there too.
    let log = srv.wait_log("a summary", 20, |l| {
        l.contains("class: 3 students, 3 following, 0 on their own, 1 terminal < 80x24")
    });
    assert!(!log.contains('\x1b') && !log.contains('\x07'), "{log:?}");
    let join = log
        .lines()
        .find(|l| l.contains("join  red"))
        .unwrap_or_else(|| panic!("{log}"));
    let (time, rest) = join.split_once(' ').unwrap();
    assert_eq!(time.len(), 8, "{join}");
    assert!(
        time.chars().all(|c| c.is_ascii_digit() || c == ':'),
        "{join}"
    );
    assert_eq!(
        rest,
        r"join  red\x1b[31m\x07\u{202e}x from 127.0.0.1, 100x30, braille"
    );
    assert!(
        log.contains(&format!("join  {cut} from 127.0.0.1, 100x30, braille")),
        "{log}"
    );
    assert!(
        log.contains("join  lecturer (lecturer) from 127.0.0.1"),
        "{log}"
    );
    room.keys("small", &["q"]);
    srv.wait_log("a leave line", 20, |l| {
        l.contains("leave tiny from 127.0.0.1 after ")
    });
    room.wait("lect", "two students", 20, |s| s.contains("2 students"));

    // --quiet: the banner only.
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start_env(dir.path(), &["--quiet"], &env);
    let (_h, mut ch) = common::client::student(srv.port, "quiet", 100, 30)
        .await
        .unwrap();
    let _ = tokio::time::timeout(Duration::from_secs(2), ch.wait()).await;
    tokio::time::sleep(Duration::from_millis(1500)).await;
    assert_eq!(srv.log(), "");
    assert!(!srv.banner.contains("log:"), "{}", srv.banner);
}

/// ζ after `k` coarse steps up from `from` on fig2's sweep.
fn stepped(from: f64, k: usize) -> f64 {
    (0..k).fold(from, |v, _| {
        roughtui::tui::app::step_value(Axis::Zeta, v, (1.0, 1e4), true, false)
    })
}

#[test]
fn thirty_students_predict_then_the_model_answers() {
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
    let room = Room::new("poll", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's explorer", 30, |s| {
        s.contains("Readout")
    });
    let names: Vec<String> = (0..30).map(|i| format!("s{i:02}")).collect();
    for n in &names {
        room.open(n, &srv.ssh_line(n, &["-t"]));
    }
    room.wait_all(&names, "students following", 90, |s| {
        s.contains("following the lecturer")
    });
    room.wait("lect", "30 following", 30, |s| {
        s.contains("30 students · 30 following · 0 on their own")
    });

    // v: every student is asked, the claims line gives way to the question.
    room.keys("lect", &["v"]);
    let asked = room.wait_all(&names, "the question", 60, |s| {
        s.contains("Predict: where does the plastic share pass ½? Move the marker and press Enter")
    });
    assert!(asked.iter().all(|s| !s.contains("Ψ_P reaches 1 at")));
    room.wait("lect", "0/30 answered", 30, |s| {
        s.contains("30 students · 0/30 answered")
    });

    // Student i moves the marker i % 5 steps up from 128 and presses Enter.
    let want: Vec<f64> = (0..30).map(|i| stepped(128.0, i % 5)).collect();
    for (i, n) in names.iter().enumerate() {
        let mut keys = vec!["Right"; i % 5];
        keys.push("Enter");
        room.keys(n, &keys);
    }
    room.wait_all(&names, "answers sent", 60, |s| {
        s.contains("you answered ζ = ")
    });
    let lect = room.wait("lect", "30/30 answered", 30, |s| {
        // In the class line, in place of the claims and on the chart.
        s.contains("30 students · 30/30 answered")
            && s.contains("poll open: 30/30 answered")
            && s.matches("30/30 answered").count() == 3
    });
    // Five answers, six students each: five bars of one height.
    let cols: std::collections::BTreeSet<usize> = lect
        .lines()
        .flat_map(|l| {
            l.chars()
                .enumerate()
                .filter(|(_, c)| *c == '█')
                .map(|(i, _)| i)
        })
        .collect();
    assert_eq!(cols.len(), 5, "{lect}");
    let rows = |col: usize| {
        lect.lines()
            .filter(|l| l.chars().nth(col) == Some('█'))
            .count()
    };
    let heights: Vec<usize> = cols.iter().map(|c| rows(*c)).collect();
    assert!(
        heights.iter().all(|h| *h == heights[0] && *h > 3),
        "{heights:?}\n{lect}"
    );

    // v again: the model's answer reaches everyone, with their own.
    room.keys("lect", &["v"]);
    let truth = roughtui::figure::claims(&roughtui::presets::load("fig2").unwrap())[0].at;
    let shown = roughtui::physical::short_number(truth);
    assert_eq!(shown, "321.5");
    let revealed = room.wait_all(&names, "the reveal", 60, |s| {
        s.contains(&format!("the model: ζ = {shown} · you: "))
    });
    for (i, s) in revealed.iter().enumerate() {
        let mine = roughtui::physical::short_number(want[i]);
        let line = s.lines().find(|l| l.contains("the model:")).unwrap();
        assert!(line.contains(&format!("you: {mine} · ")), "{i}: {line}");
        let off = if want[i] > truth { " high" } else { " low" };
        assert!(line.contains(off), "{i}: {line}");
    }
    room.wait_all(&names, "following again", 30, |s| {
        s.contains("following the lecturer")
    });
    let revealed_line =
        "30 students · 30 following · 0 on their own · revealed ζ = 321.5 (30 answers)";
    room.wait("lect", "the revealed line", 30, |s| {
        s.contains(revealed_line)
    });

    // S: the answers as CSV, a row per answer.
    room.keys("lect", &["S"]);
    let saved = room.wait("lect", "the CSV saved", 30, |s| s.contains("saved "));
    let csvs = |dir: &Path| -> Vec<PathBuf> {
        let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "csv"))
            .collect();
        v.sort();
        v
    };
    let files = csvs(dir.path());
    assert_eq!(files.len(), 1, "{saved}");
    let text = std::fs::read_to_string(&files[0]).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("question,quantity,unit,truth,name,answer,offset,step,time,poll,revealed")
    );
    let mut rows: Vec<(String, f64, f64)> = lines
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            assert_eq!(
                f[..3],
                ["where does the plastic share pass 1/2?", "zeta", ""]
            );
            let (answer, truth): (f64, f64) = (f[5].parse().unwrap(), f[3].parse().unwrap());
            assert_eq!(f[6].parse::<f64>().unwrap(), answer - truth, "{l}");
            (f[4].into(), answer, truth)
        })
        .collect();
    rows.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(rows.len(), 30, "{text}");
    for (i, (name, answer, t)) in rows.iter().enumerate() {
        assert_eq!(name, &names[i]);
        assert_eq!(*answer, want[i], "{name}");
        assert_eq!(*t, truth, "{name}");
    }

    // A student's Enter after the reveal dismisses it: they keep
    // following, and the class is as it was.
    room.keys(&names[0], &["Enter"]);
    room.wait(&names[0], "the reveal dismissed", 20, |s| {
        !s.contains("the model:") && s.contains("following the lecturer")
    });
    // The lecturer moves on: the claims come back for the student who
    // dismissed the result, the others keep theirs; S still saves the
    // same answers.
    room.keys("lect", &["Right"]);
    room.wait(&names[0], "the claims again", 60, |s| {
        s.contains("plastic share passes ½ at ζ = 321.5")
    });
    room.wait_all(&names[1..], "the reveal kept", 60, |s| {
        s.contains("the model: ζ = 321.5")
    });
    room.keys("lect", &["S"]);
    room.wait("lect", "a second CSV", 30, |_| csvs(dir.path()).len() == 2);
    for f in csvs(dir.path()) {
        assert_eq!(std::fs::read_to_string(&f).unwrap(), text);
    }
    assert!(room.capture("lect").contains(revealed_line));
    // The class list, in pages at 30 rows.
    room.keys("lect", &["w"]);
    let list = room.wait("lect", "the class list", 20, |s| s.contains("page 1/2"));
    assert!(list.contains("s00") && list.contains("following"), "{list}");
    room.keys("lect", &["Right"]);
    let page = room.wait("lect", "its second page", 20, |s| s.contains("page 2/2"));
    let rows = page.lines().filter(|l| l.contains("100×30")).count();
    assert_eq!(rows, 3, "{page}");
}

#[test]
fn fig3_polls_its_minimum_and_then_a_value_the_lecturer_types() {
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
            "fig3",
        ],
    );
    let room = Room::new("typed", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer's explorer", 30, |s| {
        s.contains("Readout")
    });
    room.open("ann", &srv.ssh_line("ann", &["-t"]));
    room.wait("ann", "following", 30, |s| {
        s.contains("following the lecturer")
    });
    // fig3 claims the total slope's minimum: v asks where it lies.
    room.keys("lect", &["v"]);
    room.wait("ann", "the minimum's question", 30, |s| {
        s.contains("Predict: where is the total slope smallest? Move the marker and press Enter")
    });
    room.keys("ann", &["Right", "Enter"]);
    room.wait("lect", "1/1 answered", 30, |s| {
        s.contains("1 student · 1/1 answered")
    });
    room.keys("lect", &["v"]);
    let want = roughtui::physical::short_number(stepped(
        roughtui::presets::load("fig3").unwrap().params.zeta(),
        1,
    ));
    // The claim's own number, as the claims line writes it.
    room.wait("ann", "the minimum's reveal", 30, |s| {
        s.contains(&format!("the model: ζ = 3.191 · you: {want} · "))
    });
    // V: the lecturer types the value instead.
    room.keys("lect", &["V"]);
    room.wait("lect", "the truth prompt", 20, |s| {
        s.contains("poll: the true ζ = ")
    });
    room.keys("lect", &["1", "0", "0", "Enter"]);
    room.wait("ann", "the question", 30, |s| {
        s.contains("Predict: which ζ is it? Move the marker and press Enter")
    });
    room.keys("ann", &["Right", "Enter"]);
    room.wait("lect", "1/1 answered", 30, |s| {
        s.contains("1 student · 1/1 answered")
    });
    room.keys("lect", &["v"]);
    room.wait("ann", "the reveal", 30, |s| {
        s.contains(&format!("the model: ζ = 100 · you: {want} · "))
    });
}
