//! Admission that keeps a class joinable, on loopback (one address, as a
//! campus behind its NAT): with 200 idle connections open on each port,
//! and after 200 wrong class codes from that address, a student's join
//! over the web and over SSH shows its first screen within 2 s. The
//! console counts the refusals as they happen, a line a second, and the
//! goodbye counts the students who came, not the connections.

mod common;

use std::io::Write;
use std::net::TcpStream;
use std::path::Path;
use std::process::Stdio;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use common::browser::web_port;
use common::codes::{askpass, code_ssh, finish, first_frame};
use common::serve::{have_ssh, Server};
use tokio_tungstenite::tungstenite::{self, Message};

const CODE: &str = "granite";

/// A web join with `code`: the time to its first screen (a frame of the
/// terminal), or the close frame's code and reason.
fn web_join(port: u16, name: &str, code: &str) -> Result<Duration, (u16, String)> {
    let t = Instant::now();
    let url = format!("ws://127.0.0.1:{port}/ws?name={name}&code={code}&cols=100&rows=30");
    let stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(20)))
        .unwrap();
    let (mut ws, _) = tungstenite::client(url.as_str(), stream).unwrap();
    loop {
        match ws.read() {
            Ok(Message::Binary(b)) if String::from_utf8_lossy(&b).contains("Readout") => {
                return Ok(t.elapsed());
            }
            Ok(Message::Close(Some(f))) => return Err((u16::from(f.code), f.reason.to_string())),
            Ok(_) => {}
            Err(e) => return Err((0, e.to_string())),
        }
    }
}

/// A real OpenSSH student answering the code through `askpass`: the time
/// from starting `ssh` to its first frame. The student leaves with `q`.
fn ssh_join(srv: &Server, name: &str, askpass: &Path) -> Duration {
    let t = Instant::now();
    let mut c = code_ssh(srv, name, askpass, &["-tt"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    first_frame(&mut c);
    let took = t.elapsed();
    c.stdin.as_mut().unwrap().write_all(b"q").unwrap();
    let (code, err) = finish(c, 20);
    assert_eq!(code, 0, "{err}");
    took
}

/// A real OpenSSH client sending `askpass`'s wrong code: its stderr.
fn ssh_wrong(srv: &Server, name: &str, askpass: &Path) -> String {
    let o = code_ssh(srv, name, askpass, &["-tt"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(255));
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_class_stays_joinable_under_idle_connections_and_wrong_codes() {
    if !have_ssh() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let right = askpass(dir.path(), "right", CODE);
    let wrong = askpass(dir.path(), "wrong", "basalt");
    let mut srv = Server::start(dir.path(), &["--class-code", CODE, "--web", "127.0.0.1:0"]);
    assert!(
        srv.banner
            .contains("at most 150 students at once, 150 from one address"),
        "{}",
        srv.banner
    );
    let web = web_port(&srv);
    // 200 idle connections on each port: nothing said.
    let idle: Vec<TcpStream> = (0..200)
        .flat_map(|_| [srv.port, web].map(|p| TcpStream::connect(("127.0.0.1", p)).unwrap()))
        .collect();
    std::thread::sleep(Duration::from_millis(300));
    let w = web_join(web, "ada", CODE).unwrap();
    let s = ssh_join(&srv, "bob", &right);
    eprintln!("with 400 idle connections: first screen over the web in {w:?}, over SSH in {s:?}");
    assert!(
        w < Duration::from_secs(2) && s < Duration::from_secs(2),
        "{w:?} {s:?}"
    );

    // Wrong codes from this address: ten OpenSSH clients (three tries
    // each) while web clients keep sending them, 200 at least.
    let t = Instant::now();
    let sent = AtomicUsize::new(0);
    let refused = AtomicUsize::new(0);
    let ssh_done = AtomicBool::new(false);
    let errs: Vec<String> = std::thread::scope(|sc| {
        for _ in 0..6 {
            sc.spawn(|| {
                while !ssh_done.load(Ordering::SeqCst) || sent.load(Ordering::SeqCst) < 170 {
                    let i = sent.fetch_add(1, Ordering::SeqCst);
                    match web_join(web, &format!("m{i}"), "basalt") {
                        Err((4001, _)) => {}
                        Err((4003, why)) => {
                            assert_eq!(
                                why,
                                "too many wrong class codes from 127.0.0.1: try again in a moment"
                            );
                            refused.fetch_add(1, Ordering::SeqCst);
                        }
                        other => panic!("{other:?}"),
                    }
                }
            });
        }
        let ssh: Vec<_> = (0..10)
            .map(|i| {
                let (srv, wrong) = (&srv, &wrong);
                sc.spawn(move || ssh_wrong(srv, &format!("g{i}"), wrong))
            })
            .collect();
        let errs = ssh.into_iter().map(|h| h.join().unwrap()).collect();
        ssh_done.store(true, Ordering::SeqCst);
        errs
    });
    let (sent, refused) = (sent.into_inner(), refused.into_inner());
    eprintln!(
        "{} wrong codes ({sent} over the web, 10 OpenSSH clients) in {:?}: {refused} web ones refused unchecked",
        sent + 30,
        t.elapsed()
    );
    assert!(refused > 0, "the guesser was never slowed");
    // OpenSSH prints why: a wrong code, or the wait.
    for e in &errs {
        assert!(
            e.contains("Permission denied (keyboard-interactive)")
                || e.contains("too many wrong class codes from 127.0.0.1: try again in a moment"),
            "{e}"
        );
    }
    assert!(
        errs.iter()
            .any(|e| e.contains("Received disconnect from 127.0.0.1 port ")
                && e.contains("too many wrong class codes from 127.0.0.1: try again in a moment")),
        "{errs:?}"
    );

    let w = web_join(web, "cy", CODE).unwrap();
    let s = ssh_join(&srv, "di", &right);
    eprintln!("after the wrong codes: first screen over the web in {w:?}, over SSH in {s:?}");
    assert!(
        w < Duration::from_secs(2) && s < Duration::from_secs(2),
        "{w:?} {s:?}"
    );
    // The console: the refusals counted as they happen, a line a second.
    let log = srv.wait_log("the refusals", 10, |l| {
        l.contains("class codes refused unchecked") && l.contains(" wrong class codes")
    });
    assert!(
        log.contains("127.0.0.1 sends wrong class codes faster than 10 a second"),
        "{log}"
    );
    // A line a second at most, never a line per refusal.
    let lines: Vec<&str> = log
        .lines()
        .filter(|l| l.contains("refused in the last second: "))
        .collect();
    let mut times: Vec<&str> = lines.iter().map(|l| &l[..8]).collect();
    times.dedup();
    assert!(!lines.is_empty() && times.len() == lines.len(), "{log}");
    assert!(!log.contains("web: refused"), "{log}");
    drop(idle);
    // The goodbye counts the four students, not the connections.
    assert!(std::process::Command::new("kill")
        .args(["-TERM", &srv.pid().to_string()])
        .status()
        .unwrap()
        .success());
    let log = srv.wait_log("the goodbye", 20, |l| l.contains("the class has ended"));
    assert!(
        log.contains("the class has ended: 4 students came"),
        "{log}"
    );
    let _ = srv.child.wait();
}
