//! `roughtui serve` with the real OpenSSH client: the explorer in a tmux pane
//! over ssh (chart, keys, resize, the snapshot panel, quit), following the
//! lecturer, every refused request, many and killed clients, a restart.
//!
//! Skipped (with a note) when ssh or tmux is missing, unless
//! ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in `.ci/run`.

mod common;

use std::io::Write;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use common::serve::{have_ssh, Server};
use common::tmux::{braille, have_tmux, Pane};

fn ready() -> bool {
    have_ssh() && have_tmux()
}

/// The ζ on the swept slider's line ("▶ ζ    ↔       128  1…1e4").
fn zeta(screen: &str) -> String {
    let Some(line) = screen.lines().find(|l| l.contains("ζ") && l.contains('↔')) else {
        return String::new();
    };
    let after = line.split('↔').nth(1).unwrap_or("");
    after.split_whitespace().next().unwrap_or("").to_string()
}

/// An ssh with a forced pty whose stdin is a pipe: the server sees a 0×0
/// window; stdout and stderr are kept.
fn piped_ssh(srv: &Server, user: &str, extra: &[&str]) -> Child {
    let mut args = vec!["-tt"];
    args.extend(extra);
    Command::new("ssh")
        .args(srv.ssh_args(user, &args))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Waits (10 s at most) for `child` to end; its status code and stderr.
fn finish(mut child: Child) -> (i32, String) {
    let start = Instant::now();
    loop {
        if let Some(st) = child.try_wait().unwrap() {
            let out = child.wait_with_output().unwrap();
            return (
                st.code().unwrap_or(-1),
                String::from_utf8_lossy(&out.stderr).into_owned(),
            );
        }
        if start.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            panic!("ssh did not end");
        }
        std::thread::sleep(Duration::from_millis(30));
    }
}

fn lecturer_key(dir: &std::path::Path, name: &str) -> std::path::PathBuf {
    let key = dir.join(name);
    let st = Command::new("ssh-keygen")
        .args(["-q", "-t", "ed25519", "-N", "", "-f"])
        .arg(&key)
        .status()
        .unwrap();
    assert!(st.success());
    key
}

#[test]
fn student_explores_over_ssh() {
    if !ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--preset", "fig2"]);
    assert!(srv.banner.contains("SHA256:"), "{}", srv.banner);
    assert!(
        srv.banner
            .contains(&format!("students: ssh -p {} 127.0.0.1", srv.port)),
        "{}",
        srv.banner
    );
    let p = Pane::start_shell("serve-student", (100, 30), &srv.ssh_line("alice", &["-t"]));
    let s = p.wait_text("Readout");
    assert!(s.contains("[fig2]"), "{s}");
    // Without --lecturer-keys there is nobody to follow: no f in the footer.
    assert!(!s.contains("f follow"), "{s}");
    assert!(braille(&s) > 100, "{} braille cells:\n{s}", braille(&s));
    assert_eq!(zeta(&s), "128");
    p.keys(&["Right"]);
    let s = p.wait_for("ζ stepped", |s| zeta(s) != "128");
    assert_eq!(zeta(&s), "178", "{s}");
    p.keys(&["S-Left", "Tab", "BTab"]);
    let s = p.wait_for("fine step", |s| zeta(s) != "178");
    assert_eq!(zeta(&s), "168", "{s}");
    // A resize redraws at the new width.
    p.tmux(&["resize-window", "-t", "t", "-x", "140", "-y", "40"]);
    p.wait_for("wider frame", |s| {
        s.lines().any(|l| l.trim_end().chars().count() > 120)
    });
    // s shows the snapshot to copy; nothing is written on the server.
    p.keys(&["s"]);
    let s = p.wait_text("-- your snapshot:");
    assert!(s.contains("version: 1"), "{s}");
    p.keys(&["Escape"]);
    p.wait_for("panel closed", |s| !s.contains("-- your snapshot:"));
    p.keys(&["p"]);
    p.wait_text("no pictures over SSH");
    let files: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(files, ["host_key"]);
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}

#[test]
fn students_follow_the_lecturer_until_they_explore() {
    if !ready() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path(), "lect");
    let keys = dir.path().join("keys");
    std::fs::copy(key.with_extension("pub"), &keys).unwrap();
    let srv = Server::start(dir.path(), &["--lecturer-keys", keys.to_str().unwrap()]);
    let key = key.to_str().unwrap();
    let lect = Pane::start_shell(
        "serve-lect",
        (100, 30),
        &srv.ssh_line("lecturer", &["-t", "-i", key, "-o", "IdentitiesOnly=yes"]),
    );
    lect.wait_text("Readout");
    let stud = Pane::start_shell("serve-stud", (100, 30), &srv.ssh_line("bob", &["-t"]));
    stud.wait_text("Readout");
    stud.wait_text("following the lecturer");
    // The student's help and footer name f; the lecturer's do not.
    assert!(stud.capture().contains("f follow"));
    stud.keys(&["?"]);
    stud.wait_text("follow the lecturer again");
    stud.keys(&["Escape"]);
    stud.wait_for("help closed", |s| !s.contains("Esc or ? closes"));
    assert!(!lect.capture().contains("f follow"));
    lect.keys(&["Right"]);
    lect.wait_for("lecturer moved", |s| zeta(s) == "178");
    stud.wait_for("student follows", |s| zeta(s) == "178");
    // The view follows too.
    lect.keys(&["Tab"]);
    stud.wait_text("plasticity indices vs ζ");
    lect.keys(&["BTab"]);
    stud.wait_for("back to slopes", |s| !s.contains("plasticity indices vs ζ"));
    // The student's first edit detaches.
    stud.keys(&["Right"]);
    stud.wait_text("exploring on your own — f to follow");
    stud.wait_for("student moved", |s| zeta(s) == "316");
    lect.keys(&["Left", "Left"]);
    let l = zeta(&lect.wait_for("lecturer moved back", |s| zeta(s) == "56.2"));
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(zeta(&stud.capture()), "316");
    // f follows again.
    stud.keys(&["f"]);
    stud.wait_for("student caught up", |s| zeta(s) == l);
    // The lecturer leaves: the student keeps the scene, alone.
    lect.keys(&["q"]);
    assert_eq!(lect.exit_status(), 0);
    stud.wait_text("no lecturer connected");
    // The lecturer comes back where they left, and the student follows.
    let lect = Pane::start_shell(
        "serve-lect2",
        (100, 30),
        &srv.ssh_line("lecturer", &["-t", "-i", key, "-o", "IdentitiesOnly=yes"]),
    );
    let s = lect.wait_text("Readout");
    assert_eq!(zeta(&s), l, "{s}");
    stud.wait_text("following the lecturer");
    assert_eq!(zeta(&stud.capture()), l);
    lect.keys(&["q"]);
    assert_eq!(lect.exit_status(), 0);
    stud.keys(&["C-c"]);
    assert_eq!(stud.exit_status(), 0);
}

#[test]
fn a_wrong_lecturer_key_is_refused() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let good = lecturer_key(dir.path(), "good");
    let bad = lecturer_key(dir.path(), "bad");
    let keys = dir.path().join("keys");
    std::fs::copy(good.with_extension("pub"), &keys).unwrap();
    let srv = Server::start(dir.path(), &["--lecturer-keys", keys.to_str().unwrap()]);
    let bad = bad.to_str().unwrap();
    let child = piped_ssh(&srv, "lecturer", &["-i", bad, "-o", "IdentitiesOnly=yes"]);
    let (code, err) = finish(child);
    assert_eq!(code, 255, "{err}");
    assert!(err.contains("Permission denied"), "{err}");
}

#[test]
fn everything_but_the_explorer_is_refused() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let run = |extra: &[&str], cmd: &[&str]| {
        let mut args = srv.ssh_args("eve", extra);
        args.extend(cmd.iter().map(|s| s.to_string()));
        let o = Command::new("ssh")
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let (code, err) = run(&[], &["cat", "/etc/passwd"]);
    assert_eq!(code, Some(255));
    assert!(err.contains("exec request failed"), "{err}");
    let (code, err) = run(&["-s"], &["sftp"]);
    assert_eq!(code, Some(255));
    assert!(err.contains("subsystem request failed"), "{err}");
    let (code, err) = run(&["-T"], &[]);
    assert_eq!(code, Some(255));
    assert!(err.contains("shell request failed"), "{err}");
    let (code, err) = run(
        &[
            "-N",
            "-o",
            "ExitOnForwardFailure=yes",
            "-R",
            "0:127.0.0.1:9",
        ],
        &[],
    );
    assert_eq!(code, Some(255));
    assert!(err.contains("forwarding failed"), "{err}");

    // -L: the listener is the client's; a connection through it is refused
    // by the server (no bytes come back).
    let lport = std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let spec = format!("{lport}:127.0.0.1:{}", srv.port);
    let mut fwd = Command::new("ssh")
        .args(srv.ssh_args("eve", &["-N", "-L", &spec]))
        .stdin(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let mut got = Vec::new();
    loop {
        if let Ok(mut c) = std::net::TcpStream::connect(("127.0.0.1", lport)) {
            use std::io::Read;
            c.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
            let _ = c.read_to_end(&mut got);
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "no -L listener");
        std::thread::sleep(Duration::from_millis(50));
    }
    let _ = fwd.kill();
    let err = String::from_utf8_lossy(&fwd.wait_with_output().unwrap().stderr).into_owned();
    // Through an open forward the server's own banner would come back.
    assert!(got.is_empty(), "bytes came through -L: {got:?} ({err})");

    // X11, agent and env requests are refused; the explorer itself still
    // runs (here at the 0×0 window of a pipe) and q ends it with status 0.
    let mut child = Command::new("ssh")
        .args(srv.ssh_args("eve", &["-tt", "-Y", "-A", "-o", "SetEnv=ROUGH=1"]))
        .env("DISPLAY", ":7")
        .env("SSH_AUTH_SOCK", dir.path().join("agent"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(800));
    child.stdin.as_mut().unwrap().write_all(b"q").unwrap();
    let (code, err) = finish(child);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("X11 forwarding request failed"), "{err}");
}
