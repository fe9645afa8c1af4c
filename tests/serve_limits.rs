//! `roughtui serve` at its limits, with a russh client (window sizes no
//! terminal can have, exit status, connection limits, idle timeout) and
//! with many OpenSSH clients (30 at once, killed clients, a restart).

mod common;

use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use common::client::{self, Client};
use common::serve::{have_ssh, Server};
use russh::ChannelMsg;

async fn student(port: u16, cols: u32, rows: u32) -> Client {
    client::student(port, "carol", cols, rows).await.unwrap()
}

/// Bytes of data until `pred` holds on all received so far (10 s at most).
async fn read_until(
    ch: &mut russh::Channel<russh::client::Msg>,
    pred: impl Fn(&str) -> bool,
) -> String {
    let mut all = Vec::new();
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    loop {
        let Ok(msg) = tokio::time::timeout_at(deadline, ch.wait()).await else {
            panic!(
                "timed out reading the session; it sent: {:?}",
                String::from_utf8_lossy(&all)
            );
        };
        match msg {
            Some(ChannelMsg::Data { data }) => all.extend_from_slice(&data),
            Some(_) => {}
            None => panic!(
                "channel closed early; it sent: {:?}",
                String::from_utf8_lossy(&all)
            ),
        }
        let s = String::from_utf8_lossy(&all).into_owned();
        if pred(&s) {
            return s;
        }
    }
}

/// The exit status the session sends before it closes.
async fn exit_status(ch: &mut russh::Channel<russh::client::Msg>) -> Option<u32> {
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    let mut status = None;
    while let Ok(Some(msg)) = tokio::time::timeout_at(deadline, ch.wait()).await {
        if let ChannelMsg::ExitStatus { exit_status } = msg {
            status = Some(exit_status);
        }
    }
    status
}

#[tokio::test]
async fn window_sizes_no_terminal_has_survive() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    // 10000×10000 is drawn at 500×200.
    let (_h, mut ch) = student(srv.port, 10_000, 10_000).await;
    read_until(&mut ch, |s| s.contains("Readout")).await;
    // 0×0: the explorer asks for a larger terminal, q still quits.
    ch.window_change(0, 0, 0, 0).await.unwrap();
    ch.window_change(u32::MAX, 3, 0, 0).await.unwrap();
    ch.window_change(80, 24, 0, 0).await.unwrap();
    read_until(&mut ch, |s| s.contains("Readout")).await;
    ch.data(&b"q"[..]).await.unwrap();
    assert_eq!(exit_status(&mut ch).await, Some(0));
    // At 0×0 (drawn at 1×1) the frame is the first letter of "enlarge".
    let (_h, mut ch) = student(srv.port, 0, 0).await;
    read_until(&mut ch, |s| s.contains("\x1b[1;1He")).await;
    // Ctrl-C ends the session too; a flood of input is bounded per read.
    ch.data(&vec![b'j'; 64 * 1024][..]).await.unwrap();
    ch.data(&b"\x03"[..]).await.unwrap();
    assert_eq!(exit_status(&mut ch).await, Some(0));
}

#[tokio::test]
async fn idle_sessions_end() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--idle-timeout", "1s"]);
    let (_h, mut ch) = student(srv.port, 80, 24).await;
    read_until(&mut ch, |s| s.contains("Readout")).await;
    let t = Instant::now();
    // Told why, on the normal screen (out of the alternate one, cursor
    // shown, colours reset), under the name the class gave.
    read_until(&mut ch, |s| {
        s.ends_with(
            "\x1b[?1049l\x1b[?25h\x1b[0m\x1b[0m\r\n\
             roughtui: you were carol in the class\r\n\
             roughtui: no key for 1s: the session ended (ssh again to come back)\r\n",
        )
    })
    .await;
    let idle = t.elapsed();
    assert_eq!(exit_status(&mut ch).await, Some(0));
    assert!(
        idle >= Duration::from_millis(800) && idle < Duration::from_secs(5),
        "{idle:?}"
    );
}

#[tokio::test]
async fn students_over_the_limit_are_told_at_login() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--max-sessions", "2"]);
    let (ha, mut a) = student(srv.port, 80, 24).await;
    let _b = student(srv.port, 80, 24).await;
    read_until(&mut a, |s| s.contains("Readout")).await;
    // Connections that have not logged in wait at the gate: over the
    // limit every one still gets SSH spoken (a student among them is told
    // at login that the class is full); the gate closes the longest
    // silent one only when it is full (src/serve/gate.rs).
    let held: Vec<_> = (0..20)
        .map(|_| {
            let mut c = std::net::TcpStream::connect(("127.0.0.1", srv.port)).unwrap();
            c.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
            let mut banner = [0u8; 8];
            c.read_exact(&mut banner).unwrap();
            assert_eq!(&banner, b"SSH-2.0-");
            c
        })
        .collect();
    drop(held);
    // The third student gets no explorer: a line on their terminal, and
    // status 1.
    // (The held connections' places come back as the server notices
    // they are gone.)
    let mut tries = 0;
    let (_he, mut e) = loop {
        match client::student(srv.port, "erin", 80, 24).await {
            Ok(c) => break c,
            Err(_) if tries < 50 => {
                tries += 1;
                tokio::time::sleep(Duration::from_millis(200)).await;
            }
            Err(e) => panic!("erin never got in to be told: {e}"),
        }
    };
    read_until(&mut e, |s| {
        s == "roughtui: the class is full (2 students): try again later\r\n"
    })
    .await;
    assert_eq!(exit_status(&mut e).await, Some(1));
    // A place freed is taken again.
    a.data(&b"q"[..]).await.unwrap();
    assert_eq!(exit_status(&mut a).await, Some(0));
    drop((ha, a));
    tokio::time::sleep(Duration::from_millis(300)).await;
    let (_hd, mut d) = student(srv.port, 80, 24).await;
    read_until(&mut d, |s| s.contains("Readout")).await;
}

#[tokio::test]
async fn a_stalled_client_is_cut_off() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let fds0 = srv.fds();
    // A client that never reads: full redraws fill every buffer on the way.
    let (_h, ch) = student(srv.port, 500, 200).await;
    let t = Instant::now();
    for i in 0..2000u32 {
        let resize = ch.window_change(500 - i % 2, 200, 0, 0);
        if tokio::time::timeout(Duration::from_millis(200), resize)
            .await
            .is_err()
        {
            break;
        }
    }
    // The server lets go of it: its socket closes though the client keeps
    // the connection open.
    let start = Instant::now();
    while srv.fds() > fds0 {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "the stalled client is still held"
        );
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    assert!(
        t.elapsed() >= roughtui::serve::output::STALL,
        "cut before the stall timeout"
    );
}

#[tokio::test]
async fn a_second_channel_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let (h, mut ch) = student(srv.port, 80, 24).await;
    read_until(&mut ch, |s| s.contains("Readout")).await;
    let second = h.channel_open_session().await;
    assert!(second.is_err(), "a second session channel was opened");
    let fwd = h
        .channel_open_direct_tcpip("127.0.0.1", u32::from(srv.port), "127.0.0.1", 1)
        .await;
    assert!(fwd.is_err(), "a direct-tcpip channel was opened");
    // The first session goes on.
    ch.data(&b"q"[..]).await.unwrap();
    assert_eq!(exit_status(&mut ch).await, Some(0));
}

#[tokio::test]
async fn slow_logins_are_cut_off() {
    let dir = tempfile::tempdir().unwrap();
    let env = [("ROUGHTUI_LOGIN_DEADLINE_MS", "500")];
    let srv = Server::start_env(dir.path(), &[], &env);
    let fds0 = srv.fds();
    // A connection that says nothing, and one that logs in but asks for no shell.
    let mut mute = std::net::TcpStream::connect(("127.0.0.1", srv.port)).unwrap();
    let config = std::sync::Arc::new(russh::client::Config::default());
    let mut h = russh::client::connect(config, ("127.0.0.1", srv.port), client::Trusting)
        .await
        .unwrap();
    assert!(h.authenticate_none("dave").await.unwrap().success());
    let t = Instant::now();
    mute.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    let mut got = Vec::new();
    // The server's banner, then the close.
    let _ = mute.read_to_end(&mut got);
    assert!(String::from_utf8_lossy(&got).starts_with("SSH-2.0-"));
    assert!(t.elapsed() < Duration::from_secs(3), "{:?}", t.elapsed());
    let start = Instant::now();
    while srv.fds() > fds0 {
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "a slow login is still held"
        );
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    assert!(h.channel_open_session().await.is_err());
}

#[tokio::test]
async fn auth_attempts_are_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let config = std::sync::Arc::new(russh::client::Config::default());
    let mut h = russh::client::connect(config, ("127.0.0.1", srv.port), client::Trusting)
        .await
        .unwrap();
    let mut tries = 0;
    while let Ok(r) = h.authenticate_password("mallory", "guess").await {
        assert!(!r.success(), "a password was accepted");
        tries += 1;
        assert!(tries <= 20, "the connection stays after {tries} attempts");
    }
    // Six are answered; the seventh, not looked at, ends the connection
    // (the client reports that one as a failure too).
    assert_eq!(tries, roughtui::serve::MAX_AUTH_ATTEMPTS + 1);
}

/// `n` OpenSSH clients with a forced pty on a pipe, each past its first frame.
fn clients(srv: &Server, n: usize) -> Vec<std::process::Child> {
    let mut v: Vec<_> = (0..n)
        .map(|i| {
            Command::new("ssh")
                .args(srv.ssh_args(&format!("s{i}"), &["-tt"]))
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
                .unwrap()
        })
        .collect();
    for c in &mut v {
        let mut out = c.stdout.take().unwrap();
        let mut buf = [0u8; 4096];
        let mut seen = Vec::new();
        // At the 0×0 window of a pipe the frame is drawn at 1×1.
        while !String::from_utf8_lossy(&seen).contains("\x1b[1;1H") {
            let n = out.read(&mut buf).unwrap();
            assert!(n > 0, "a client got no frame");
            seen.extend_from_slice(&buf[..n]);
        }
        // Keep draining in the background so no client stalls.
        std::thread::spawn(move || while out.read(&mut buf).is_ok_and(|n| n > 0) {});
    }
    v
}

fn settle(srv: &Server, what: &str, pred: impl Fn(&Server) -> bool) {
    let start = Instant::now();
    while !pred(srv) {
        assert!(start.elapsed() < Duration::from_secs(15), "{what}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

#[test]
fn thirty_sessions_then_killed_clients_leave_nothing() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let fds0 = srv.fds();
    let threads0 = srv.proc_status("Threads");
    let mut all = clients(&srv, 30);
    assert!(srv.fds() >= fds0 + 30);
    // Half quit with q (status 0), half are killed mid-session.
    for (i, c) in all.iter_mut().enumerate() {
        if i % 2 == 0 {
            c.stdin.as_mut().unwrap().write_all(b"q").unwrap();
        } else {
            c.kill().unwrap();
        }
    }
    for (i, mut c) in all.into_iter().enumerate() {
        let st = c.wait().unwrap();
        if i % 2 == 0 {
            assert_eq!(st.code(), Some(0));
        }
    }
    settle(&srv, "sockets left open", |s| s.fds() <= fds0);
    // A thread tokio started for blocking work stays 10 s idle before it
    // goes: wait for it (settle allows 15 s).
    settle(&srv, "threads left running", |s| {
        s.proc_status("Threads") <= threads0
    });
    // Nothing keeps running: no CPU over a second of quiet.
    let t0 = srv.cpu_ticks();
    std::thread::sleep(Duration::from_secs(1));
    assert!(srv.cpu_ticks() - t0 <= 1, "the server kept working");
}

#[test]
fn a_restart_keeps_the_host_key() {
    let dir = tempfile::tempdir().unwrap();
    let fp = |banner: &str| {
        banner
            .lines()
            .find_map(|l| l.split_once("SHA256:").map(|(_, f)| f.to_string()))
            .unwrap()
    };
    let first = Server::start(dir.path(), &[]);
    assert!(first.banner.contains("(new)"), "{}", first.banner);
    let a = fp(&first.banner);
    drop(first);
    let second = Server::start(dir.path(), &[]);
    assert!(second.banner.contains("(reused)"), "{}", second.banner);
    assert_eq!(fp(&second.banner), a);
}
