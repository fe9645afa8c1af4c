//! The class in a browser, tested as students meet it: headless Chromium
//! (Debian's chromium and chromium-driver, driven by selenium) beside an
//! OpenSSH lecturer and student in tmux, one class for both; and the
//! requests the web server must refuse, from raw TCP and WebSocket
//! clients.
//!
//! Skipped (with a note) when chromium, chromium-driver, selenium, ssh or
//! tmux is missing, unless ROUGHTUI_REQUIRE_BROWSER / _SSH / _TMUX are set,
//! as in `.ci/run`.

mod common;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

use common::browser::{have_browser, web_port, Browsers};
use common::lecture::{csvs, lecturer_key, lecturer_line};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;

const CODE: &str = "granite";

fn class(dir: &std::path::Path) -> (Server, std::path::PathBuf, u16) {
    let key = lecturer_key(dir);
    let keys = key.with_extension("pub");
    let srv = Server::start(
        dir,
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--class-code",
            CODE,
            "--web",
            "127.0.0.1:0",
        ],
    );
    let port = web_port(&srv);
    (srv, key, port)
}

#[test]
fn a_browser_joins_by_url_follows_answers_sees_the_reveal_and_the_goodbye() {
    if !(have_browser() && have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (mut srv, key, port) = class(dir.path());
    let page = format!("http://127.0.0.1:{port}/");
    let room = Room::new("web", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer", 30, |s| s.contains("Readout"));
    // An SSH student in the same class (the code through SSH_ASKPASS is
    // the SSH tests' business: here the web's).
    let mut b = Browsers::start();
    // A wrong code is refused with the reason, in the form.
    b.open("eve", &format!("{page}?code=basalt&name=eve"), (900, 700));
    let mut why = String::new();
    for _ in 0..100 {
        why = b.js("eve", "return document.getElementById('why').textContent");
        if why.contains("wrong") {
            break;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    assert_eq!(why, "\"wrong class code: try again\"");
    b.close("eve");
    // ?code=…&name=… joins at once, as a follower of the lecturer.
    b.open("ada", &format!("{page}?code={CODE}&name=ada"), (1200, 800));
    let s = b.wait("ada", "following", 30, |s| {
        s.contains("following the lecturer")
    });
    assert!(s.contains("roughtui [fig2]"), "{s}");
    room.wait("lect", "ada in the class", 20, |s| {
        s.contains("1 student · 1 following")
    });
    let log = srv.wait_log("the join", 20, |l| {
        l.contains("join  ada from 127.0.0.1 over the web")
    });
    assert!(log.contains("braille"), "{log}");
    // Follow: the lecturer's marker moves on ada's screen.
    room.keys("lect", &["Right"]);
    b.wait("ada", "the lecturer's move", 20, |s| s.contains("ζ = 178"));
    // A poll: ada answers with Shift+→ (fine) and Enter, from the browser.
    room.keys("lect", &["v"]);
    b.wait("ada", "the question", 20, |s| {
        s.contains("Predict: where does the plastic share pass ½?")
    });
    b.keys("ada", &["S-Right", "S-Right", "Enter"]);
    b.wait("ada", "the answer sent", 20, |s| {
        s.contains("you answered ζ = 199.5")
    });
    room.wait("lect", "1/1 answered", 20, |s| s.contains("1/1 answered"));
    // A phone: the compact screen, the poll still on it; back again.
    b.resize("ada", (390, 700));
    let phone = b.wait("ada", "the compact screen", 20, |s| {
        s.lines().count() >= 10
            && s.lines().all(|l| l.trim_end().chars().count() <= 80)
            && s.contains("you answered")
    });
    assert!(!phone.contains("enlarge the terminal"), "{phone}");
    b.resize("ada", (1200, 800));
    b.wait("ada", "the full screen", 20, |s| s.contains("Readout"));
    // The reveal, then the answers' histogram for everyone (`d`).
    room.keys("lect", &["v"]);
    b.wait("ada", "the reveal", 20, |s| {
        s.contains("the model: ζ = 321.5 · you: 199.5 · 38 % low")
    });
    room.keys("lect", &["d"]);
    b.wait("ada", "the histogram", 20, |s| {
        s.contains("ζ = 321.5 · 1 answer")
    });
    room.keys("lect", &["S"]);
    room.wait("lect", "the CSV", 20, |_| csvs(dir.path()).len() == 1);
    let csv = std::fs::read_to_string(&csvs(dir.path())[0]).unwrap();
    assert!(csv.lines().any(|l| l.contains(",ada,199.5")), "{csv}");
    // The lecturer's help names Q; Q shows the join address full screen.
    room.keys("lect", &["Q"]);
    let q = room.wait("lect", "the QR code", 20, |s| {
        s.contains("join the class: http://")
    });
    assert!(q.contains(&format!("?code={CODE}")), "{q}");
    room.keys("lect", &["Escape"]);
    // The goodbye: SIGTERM ends the class; the browser's terminal says so
    // and the page offers to join again.
    assert!(std::process::Command::new("kill")
        .args(["-TERM", &srv.pid().to_string()])
        .status()
        .unwrap()
        .success());
    let bye = b.wait("ada", "the goodbye", 20, |s| {
        s.contains("roughtui: the class has ended")
    });
    // The last screen stays above it.
    let above = bye.split("roughtui: the class has ended").next().unwrap();
    assert!(above.contains("q quit"), "{bye}");
    let ended = b.js(
        "ada",
        "return document.getElementById('endwhy').textContent",
    );
    assert_eq!(ended, "\"the class has ended\"");
    let _ = srv.child.wait();
}

/// A raw request and the server's whole answer.
fn raw(port: u16, bytes: &[u8]) -> String {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(15))).unwrap();
    let _ = s.write_all(bytes);
    let mut out = Vec::new();
    let _ = s.read_to_end(&mut out);
    String::from_utf8_lossy(&out).into_owned()
}

#[test]
fn the_web_refuses_what_it_must_and_a_closed_tab_keeps_its_answer() {
    if !(have_browser() && have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (srv, key, port) = class(dir.path());
    // Malformed HTTP, a head over 8 KiB, another site's page, a file that
    // is not the page's: a status and one line each.
    let a = raw(port, b"\x16\x03\x01 not http at all\r\n\r\n");
    assert!(
        a.starts_with("HTTP/1.1 400") && a.ends_with("roughtui: a malformed HTTP request\n"),
        "{a}"
    );
    let big = format!(
        "GET / HTTP/1.1\r\nHost: x\r\nX-Pad: {}\r\n\r\n",
        "a".repeat(9000)
    );
    assert!(raw(port, big.as_bytes()).starts_with("HTTP/1.1 431"));
    for path in [
        "/../../etc/passwd",
        "/Cargo.toml",
        "/web/app.js",
        "/%2e%2e/Cargo.toml",
    ] {
        let req = format!("GET {path} HTTP/1.1\r\nHost: x\r\n\r\n");
        assert!(
            raw(port, req.as_bytes()).starts_with("HTTP/1.1 404"),
            "{path}"
        );
    }
    let up = |origin: &str| {
        format!(
            "GET /ws?name=x&code={CODE} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: {origin}\r\n\
             Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n\
             Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n"
        )
    };
    let evil = raw(port, up("http://evil.example").as_bytes());
    assert!(evil.starts_with("HTTP/1.1 403"), "{evil}");
    assert!(
        evil.contains("a page from another site may not open the class"),
        "{evil}"
    );
    // The page itself still loads; HEAD gets its head alone (a link
    // checker's, a proxy's); other methods a 405.
    let page = raw(port, b"GET / HTTP/1.1\r\nHost: x\r\n\r\n");
    assert!(page.starts_with("HTTP/1.1 200") && page.contains("xterm.js"));
    let head = raw(port, b"HEAD / HTTP/1.1\r\nHost: x\r\n\r\n");
    let (h, body) = head.split_once("\r\n\r\n").unwrap();
    assert!(h.starts_with("HTTP/1.1 200") && body.is_empty(), "{head}");
    let length = |h: &str| {
        h.lines()
            .find_map(|l| l.strip_prefix("Content-Length: "))
            .map(str::to_string)
    };
    assert_eq!(length(h), length(page.split_once("\r\n\r\n").unwrap().0));
    let post = raw(
        port,
        b"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n",
    );
    assert!(post.starts_with("HTTP/1.1 405"), "{post}");

    let room = Room::new("webbad", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer", 30, |s| s.contains("Readout"));
    // A WebSocket client that resizes to 0×0 and 10000×10000: clamped
    // (1×1, 500×200 in the class list), the session goes on; then a
    // message over 16 KiB ends it with its reason.
    let url = format!("ws://127.0.0.1:{port}/ws?name=rex&code={CODE}&cols=100&rows=30");
    let stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(10)))
        .unwrap();
    let (mut ws, _) = tokio_tungstenite::tungstenite::client(url.as_str(), stream).unwrap();
    use tokio_tungstenite::tungstenite::Message;
    // The first frame (the page's note of its seat may come before it).
    loop {
        match ws.read().unwrap() {
            Message::Binary(_) => break,
            Message::Text(t) => assert!(t.starts_with("seat "), "{t}"),
            m => panic!("{m:?}"),
        }
    }
    ws.send(Message::text("resize 0 0")).unwrap();
    room.keys("lect", &["w"]);
    room.wait("lect", "1x1", 20, |s| {
        s.contains("rex") && s.contains("1×1")
    });
    ws.send(Message::text("resize 10000 10000")).unwrap();
    room.wait("lect", "500x200", 20, |s| s.contains("500×200"));
    room.keys("lect", &["w"]);
    let _ = ws.send(Message::binary(vec![b'l'; 64 * 1024]));
    let mut reason = String::new();
    for _ in 0..50 {
        match ws.read() {
            Ok(Message::Close(Some(f))) => {
                reason = f.reason.to_string();
                assert_eq!(u16::from(f.code), 1009);
                break;
            }
            Ok(_) => continue,
            Err(_) => break,
        }
    }
    assert_eq!(reason, "a message over 16 KiB: the session ended");
    srv.wait_log("the line", 20, |l| {
        l.contains("web: 127.0.0.1 sent a message over 16 KiB: its session ended")
    });

    // A tab closed mid-poll: its answer stays counted, and in the CSV.
    let mut b = Browsers::start();
    b.open(
        "ann",
        &format!("http://127.0.0.1:{port}/?code={CODE}&name=ann"),
        (1200, 800),
    );
    b.wait("ann", "following", 30, |s| {
        s.contains("following the lecturer")
    });
    room.keys("lect", &["v"]);
    b.wait("ann", "the question", 20, |s| s.contains("Predict:"));
    b.keys("ann", &["Enter"]);
    room.wait("lect", "1/1", 20, |s| s.contains("1/1 answered"));
    b.close("ann");
    room.wait("lect", "ann gone, her answer kept", 20, |s| {
        s.contains("0 students · 1/1 answered")
    });
    room.keys("lect", &["v", "S"]);
    room.wait("lect", "the CSV", 20, |_| csvs(dir.path()).len() == 1);
    let csv = std::fs::read_to_string(&csvs(dir.path())[0]).unwrap();
    assert!(csv.lines().any(|l| l.contains(",ann,128,")), "{csv}");
    srv.wait_log("ann's leave", 20, |l| {
        l.contains("leave ann from 127.0.0.1 over the web")
    });
}
