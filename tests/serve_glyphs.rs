//! What a served student's terminal gets, with real clients: OpenSSH under
//! `LANG=C TERM=vt100` (sending LANG) gets only ASCII bytes on every
//! screen; a UTF-8 client gets braille and the first screen's line on
//! switching; a russh client that sends no window change gets a redraw at
//! its real size after Ctrl-L (the terminal's answer to CSI 18 t, also
//! split across reads); env requests other than LANG / LC_* are refused
//! and the session goes on.
//!
//! The OpenSSH tests are skipped (with a note) when ssh or tmux is missing,
//! unless ROUGHTUI_REQUIRE_SSH / ROUGHTUI_REQUIRE_TMUX are set, as in
//! `.ci/run`.

mod common;

use std::sync::Arc;
use std::time::Duration;

use common::client::Trusting;
use common::serve::{have_ssh, Server};
use common::tmux::{braille, have_tmux, sh_quote, Pane};
use russh::{client, ChannelMsg};

/// Starts `ssh` in a tmux pane after a moment, with everything it writes
/// to the terminal copied to `raw` from its first byte.
fn ssh_pane(name: &str, srv: &Server, env: &str, extra: &[&str], raw: &std::path::Path) -> Pane {
    let cmd = format!("sleep 0.5; env {env} {}", srv.ssh_line("student", extra));
    let p = Pane::start_shell(name, (100, 30), &cmd);
    let copy = format!("cat >> {}", sh_quote(raw.to_str().unwrap()));
    assert!(p
        .tmux(&["pipe-pane", "-o", "-t", "t", &copy])
        .status
        .success());
    p
}

#[test]
fn a_c_locale_vt100_client_gets_only_ascii_on_every_screen() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--preset", "fig4"]);
    let raw = dir.path().join("raw");
    let p = ssh_pane(
        "serve-ascii",
        &srv,
        "LANG=C LC_ALL= LC_CTYPE= TERM=vt100",
        &["-t", "-o", "SendEnv=LANG"],
        &raw,
    );
    let s = p.wait_text("Readout");
    assert!(
        s.contains("ASCII drawing (LANG=C is not UTF-8): M switches"),
        "{s}"
    );
    assert!(s.contains("zeta ~"), "{s}");
    assert!(s.contains("Psi_P"), "{s}");
    // Each view, the help's pages, a prompt and its refusal, the student's
    // snapshot panel, a status line.
    let steps: &[(&[&str], &str)] = &[
        (&["Tab"], "plasticity indices vs zeta"),
        (&["Tab"], "plastic share over zeta x H0/E"),
        (&["Tab"], "A/A0 vs pbar/H_y"),
        (&["Tab"], "lower zeta to"),
        (&["Tab"], "slope H_y*dA/dpbar/A0 vs zeta"),
        (&["?"], "help 1/"),
        (&["Right"], "help 2/"),
        (&["Escape"], "? help | the ~ slider"),
        (&["Up", "Enter"], "units m cm mm um nm pm"),
        (&["2", "p", "c", "Enter"], "unknown unit \"pc\""),
        (
            &["Escape", "s"],
            "-- y copies it to your clipboard (OSC 52) - any other key goes back --",
        ),
        (&["Escape", "p"], "no pictures over SSH"),
    ];
    for (keys, want) in steps {
        p.keys(keys);
        p.wait_text(want);
    }
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
    std::thread::sleep(Duration::from_millis(300));
    let bytes = std::fs::read(&raw).unwrap();
    assert!(bytes.len() > 20_000, "{} bytes", bytes.len());
    let bad: Vec<(usize, u8)> = bytes
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, b)| *b >= 0x80)
        .collect();
    assert!(
        bad.is_empty(),
        "{} bytes not ASCII, first at {:?}",
        bad.len(),
        bad.first()
    );
    // A monochrome terminal: no colour codes either (SGR 30–37, 38;…).
    let text = String::from_utf8_lossy(&bytes);
    assert!(!text.contains("\x1b[38;"), "colour sent to a vt100");
}

#[test]
fn a_utf8_client_gets_braille_and_the_first_line_on_switching() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--preset", "fig2"]);
    let raw = dir.path().join("raw");
    let p = ssh_pane(
        "serve-utf8",
        &srv,
        "LANG=C.UTF-8 LC_ALL= LC_CTYPE=",
        &["-t", "-o", "SendEnv=LANG"],
        &raw,
    );
    let s = p.wait_text("Readout");
    assert!(braille(&s) > 100, "{} braille cells:\n{s}", braille(&s));
    assert!(
        s.contains("chart shows boxes, ? or odd signs: press M"),
        "{s}"
    );
    assert!(s.contains('ζ') && s.contains("Ψ_P"), "{s}");
    // The first key takes the line away; M switches to half blocks.
    p.keys(&["M"]);
    let s = p.wait_for("half blocks", |s| {
        !s.contains("chart shows boxes") && s.contains("drawing in half blocks")
    });
    assert_eq!(braille(&s), 0, "{s}");
    assert!(s.contains('▀') || s.contains('▄'), "{s}");
    assert!(s.contains("zeta"), "{s}");
    p.keys(&["M", "M", "M"]);
    let s = p.wait_text("drawing in braille dots");
    assert!(braille(&s) > 100, "{s}");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}

#[test]
fn without_a_key_the_first_line_goes_after_a_few_seconds() {
    if !(have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let raw = dir.path().join("raw");
    let p = ssh_pane("serve-hint", &srv, "LANG=C.UTF-8", &["-t"], &raw);
    p.wait_text("chart shows boxes, ? or odd signs: press M");
    let start = std::time::Instant::now();
    let wait = Duration::from_secs(15);
    while p.capture().contains("chart shows boxes") {
        assert!(start.elapsed() < wait, "the line stayed");
        std::thread::sleep(Duration::from_millis(100));
    }
    assert!(p.capture().contains("the readout is at the marker"));
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}

type Channel = russh::Channel<client::Msg>;

/// Data from `ch` until `pred` holds on all of it (10 s at most).
async fn read_until(ch: &mut Channel, what: &str, pred: impl Fn(&[u8]) -> bool) -> Vec<u8> {
    let mut all = Vec::new();
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    loop {
        let Ok(msg) = tokio::time::timeout_at(deadline, ch.wait()).await else {
            panic!("no {what}; got {:?}", String::from_utf8_lossy(&all));
        };
        match msg {
            Some(ChannelMsg::Data { data }) => all.extend_from_slice(&data),
            Some(_) => {}
            None => panic!("channel closed before {what}"),
        }
        if pred(&all) {
            return all;
        }
    }
}

/// The largest column a cursor move (`CSI row ; col H`) in `bytes` goes to.
fn widest_move(bytes: &[u8]) -> u32 {
    let s = String::from_utf8_lossy(bytes);
    s.split("\x1b[")
        .filter_map(|p| {
            let end = p.find('H')?;
            let (r, c) = p[..end].split_once(';')?;
            r.parse::<u32>().ok()?;
            c.parse::<u32>().ok()
        })
        .max()
        .unwrap_or(0)
}

fn contains(hay: &[u8], needle: &[u8]) -> bool {
    hay.windows(needle.len()).any(|w| w == needle)
}

async fn connect(port: u16) -> (client::Handle<Trusting>, Channel) {
    let config = Arc::new(client::Config::default());
    let mut h = client::connect(config, ("127.0.0.1", port), Trusting)
        .await
        .unwrap();
    assert!(h.authenticate_none("winnie").await.unwrap().success());
    let ch = h.channel_open_session().await.unwrap();
    (h, ch)
}

#[tokio::test]
async fn ctrl_l_asks_the_size_and_redraws_at_it_without_a_window_change() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    for split in [false, true] {
        let (_h, mut ch) = connect(srv.port).await;
        ch.request_pty(false, "xterm-256color", 80, 24, 0, 0, &[])
            .await
            .unwrap();
        ch.request_shell(false).await.unwrap();
        let first = read_until(&mut ch, "the first frame", |b| contains(b, b"Readout")).await;
        assert!(widest_move(&first) <= 80);
        // The window grew to 120×40, and the client said nothing (as
        // Windows' OpenSSH may not); Ctrl-L asks the terminal.
        ch.data(&b"\x0c"[..]).await.unwrap();
        read_until(&mut ch, "the size question", |b| contains(b, b"\x1b[18t")).await;
        if split {
            ch.data(&b"\x1b"[..]).await.unwrap();
            tokio::time::sleep(Duration::from_millis(100)).await;
            ch.data(&b"[8;40;1"[..]).await.unwrap();
            tokio::time::sleep(Duration::from_millis(100)).await;
            ch.data(&b"20t"[..]).await.unwrap();
        } else {
            ch.data(&b"\x1b[8;40;120t"[..]).await.unwrap();
        }
        let frame = read_until(&mut ch, "a frame 120 wide", |b| widest_move(b) > 100).await;
        assert!(widest_move(&frame) <= 120);
        // The answer was not taken as keys (Esc, '[', '8' …): q still quits
        // and nothing was loaded or typed.
        let s = String::from_utf8_lossy(&frame);
        assert!(!s.contains("loaded fig"), "{s}");
        ch.data(&b"q"[..]).await.unwrap();
        let mut status = None;
        while let Ok(Some(msg)) = tokio::time::timeout(Duration::from_secs(10), ch.wait()).await {
            if let ChannelMsg::ExitStatus { exit_status } = msg {
                status = Some(exit_status);
            }
        }
        assert_eq!(status, Some(0));
    }
}

/// The reply to a request sent with want_reply.
async fn reply(ch: &mut Channel) -> bool {
    loop {
        let msg = tokio::time::timeout(Duration::from_secs(10), ch.wait())
            .await
            .expect("a reply")
            .expect("the channel open");
        match msg {
            ChannelMsg::Success => return true,
            ChannelMsg::Failure => return false,
            _ => {}
        }
    }
}

#[tokio::test]
async fn only_lang_and_lc_variables_are_taken_and_the_session_goes_on() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let (_h, mut ch) = connect(srv.port).await;
    for (name, value, taken) in [
        ("PATH", "/tmp/evil", false),
        ("LD_PRELOAD", "/tmp/evil.so", false),
        ("TERM", "vt100", false),
        ("LANG", "C", true),
        ("LC_MESSAGES", "de_DE.UTF-8", true),
        ("LANG", "C\nx", false),
        ("ROUGHTUI_PANIC_KEY", "j", false),
    ] {
        ch.set_env(true, name, value).await.unwrap();
        assert_eq!(reply(&mut ch).await, taken, "{name}={value:?}");
    }
    ch.request_pty(true, "xterm-256color", 100, 30, 0, 0, &[])
        .await
        .unwrap();
    assert!(reply(&mut ch).await);
    ch.request_shell(true).await.unwrap();
    assert!(reply(&mut ch).await);
    let frame = read_until(&mut ch, "the first frame", |b| contains(b, b"Readout")).await;
    assert!(frame.iter().all(|b| *b < 0x80), "LANG=C: ASCII only");
    assert!(contains(&frame, b"ASCII drawing (LANG=C is not UTF-8)"));
    // After the shell, even LANG is refused.
    ch.set_env(true, "LANG", "C.UTF-8").await.unwrap();
    assert!(!reply(&mut ch).await, "LANG after the shell was taken");
    ch.data(&b"jq"[..]).await.unwrap();
    let mut status = None;
    while let Ok(Some(msg)) = tokio::time::timeout(Duration::from_secs(10), ch.wait()).await {
        if let ChannelMsg::ExitStatus { exit_status } = msg {
            status = Some(exit_status);
        }
    }
    assert_eq!(status, Some(0), "j did not panic, q quit");
}

/// PuTTY's own SSH code (its command-line client, plink 0.78, the release
/// of russh issue 156, "PuTTY sends nothing"): the explorer draws, takes
/// keys and ends with q.
#[test]
fn putty_draws_takes_keys_and_quits() {
    let have_plink = common::tmux::have_tool(
        "plink",
        "ROUGHTUI_REQUIRE_SSH",
        "the PuTTY test (apt-get install putty-tools)",
    );
    if !(have_plink && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &[]);
    let fingerprint = srv
        .banner
        .split_whitespace()
        .find(|w| w.starts_with("SHA256:"))
        .unwrap()
        .to_string();
    let cmd = format!(
        "env LANG=C.UTF-8 plink -ssh -batch -t -P {} -hostkey {} pat@127.0.0.1",
        srv.port,
        sh_quote(&fingerprint)
    );
    let p = Pane::start_shell("serve-putty", (100, 30), &cmd);
    let s = p.wait_text("Readout");
    assert!(braille(&s) > 100, "{s}");
    p.keys(&["Right"]);
    p.wait_text("ζ = 178");
    p.keys(&["q"]);
    assert_eq!(p.exit_status(), 0);
}
