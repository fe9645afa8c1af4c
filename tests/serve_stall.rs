//! A client that stops reading (a laptop shut mid-class, a stuck
//! program): the server keeps little for it and lets it go soon. Between
//! the client and the server sits a relay on loopback that passes the
//! client's bytes on but, once told, reads nothing more from the server,
//! so the server's bytes wait in the kernel's buffers as they would for a
//! client gone quiet. The client keeps asking for full redraws (window
//! changes, 500×200), the heaviest frames there are.

mod common;

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use common::browser::web_port;
use common::serve::Server;
use tokio_tungstenite::tungstenite::{self, Message};

/// A relay to `port`: its own port, the flag that stops it reading from
/// the server, and the local port of its connection to the server.
struct Relay {
    port: u16,
    stall: Arc<AtomicBool>,
    upstream: Arc<std::sync::OnceLock<u16>>,
}

fn relay(port: u16) -> Relay {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let me = listener.local_addr().unwrap().port();
    let stall = Arc::new(AtomicBool::new(false));
    let upstream = Arc::new(std::sync::OnceLock::new());
    let (st, up) = (Arc::clone(&stall), Arc::clone(&upstream));
    std::thread::spawn(move || {
        let (client, _) = listener.accept().unwrap();
        let server = TcpStream::connect(("127.0.0.1", port)).unwrap();
        let _ = up.set(server.local_addr().unwrap().port());
        let (mut c_in, mut s_out) = (client.try_clone().unwrap(), server.try_clone().unwrap());
        std::thread::spawn(move || {
            let mut buf = [0u8; 16384];
            while let Ok(n) = c_in.read(&mut buf) {
                if n == 0 || s_out.write_all(&buf[..n]).is_err() {
                    break;
                }
            }
        });
        let (mut s_in, mut c_out) = (server, client);
        let mut buf = [0u8; 16384];
        loop {
            if st.load(Ordering::SeqCst) {
                // Reads nothing more; holds the sockets a while.
                std::thread::sleep(Duration::from_secs(60));
                return;
            }
            match s_in.read(&mut buf) {
                Ok(0) | Err(_) => return,
                Ok(n) => {
                    if c_out.write_all(&buf[..n]).is_err() {
                        return;
                    }
                }
            }
        }
    });
    Relay {
        port: me,
        stall,
        upstream,
    }
}

/// The bytes waiting between the server and the relay: the server's
/// send queue and the relay's receive queue (/proc/net/tcp), or `None`
/// once the server has closed its end.
fn queued(server_port: u16, relay_port: u16) -> Option<(u64, u64)> {
    let text = std::fs::read_to_string("/proc/net/tcp").unwrap();
    let port = |hex: &str| u16::from_str_radix(hex.rsplit(':').next().unwrap(), 16).unwrap();
    let mut server_side = None;
    let mut relay_side = 0;
    for l in text.lines().skip(1) {
        let f: Vec<&str> = l.split_whitespace().collect();
        let (local, remote, state) = (port(f[1]), port(f[2]), f[3]);
        let (tx, rx) = f[4].split_once(':').unwrap();
        let (tx, rx) = (
            u64::from_str_radix(tx, 16).unwrap(),
            u64::from_str_radix(rx, 16).unwrap(),
        );
        // 01: established.
        if local == server_port && remote == relay_port && state == "01" {
            server_side = Some(tx);
        }
        if local == relay_port && remote == server_port {
            relay_side = rx;
        }
    }
    server_side.map(|tx| (tx, relay_side))
}

/// Stalls the relay, then waits for the server to close its end: the time
/// that took, the time since the bytes waiting last grew (the buffers on
/// the way full: from then on nothing the client does not read can go),
/// and the most bytes that waited meanwhile in the server's send queue
/// and in the relay's receive queue.
fn stall_until_cut(srv_port: u16, r: &Relay, keep_asking: impl Fn()) -> Cut {
    let up = *r.upstream.get().unwrap();
    r.stall.store(true, Ordering::SeqCst);
    let t = Instant::now();
    let mut most = (0, 0);
    let mut full = t;
    while let Some((tx, rx)) = queued(srv_port, up) {
        if tx + rx > most.0 + most.1 {
            full = Instant::now();
        }
        most = (most.0.max(tx), most.1.max(rx));
        assert!(
            t.elapsed() < Duration::from_secs(60),
            "held {most:?} bytes for a minute"
        );
        keep_asking();
        std::thread::sleep(Duration::from_millis(50));
    }
    Cut {
        took: t.elapsed(),
        after_full: full.elapsed(),
        tx: most.0,
        rx: most.1,
    }
}

#[derive(Debug)]
struct Cut {
    took: Duration,
    after_full: Duration,
    tx: u64,
    rx: u64,
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_stops_reading_is_let_go_with_little_kept() {
    let dir = tempfile::tempdir().unwrap();
    let srv = Server::start(dir.path(), &["--web", "127.0.0.1:0"]);

    // Over SSH.
    let r = relay(srv.port);
    let (_h, ch) = common::client::student(r.port, "sam", 500, 200)
        .await
        .unwrap();
    tokio::time::sleep(Duration::from_millis(500)).await;
    let ch = Arc::new(ch);
    let rt = tokio::runtime::Handle::current();
    let asking = Arc::new(std::sync::atomic::AtomicU32::new(0));
    let (c, a) = (Arc::clone(&ch), Arc::clone(&asking));
    let port = srv.port;
    let ssh = tokio::task::spawn_blocking(move || {
        stall_until_cut(port, &r, || {
            let i = a.fetch_add(1, Ordering::SeqCst);
            let c = Arc::clone(&c);
            rt.spawn(async move {
                let _ = tokio::time::timeout(
                    Duration::from_millis(200),
                    c.window_change(500 - i % 2, 200, 0, 0),
                )
                .await;
            });
        })
    })
    .await
    .unwrap();

    // Over the web.
    let web = web_port(&srv);
    let r = relay(web);
    let stream = TcpStream::connect(("127.0.0.1", r.port)).unwrap();
    let url = format!("ws://127.0.0.1:{}/ws?name=wes&cols=500&rows=200", r.port);
    let (ws, _) = tungstenite::client(url.as_str(), stream).unwrap();
    let ws = std::sync::Mutex::new(ws);
    std::thread::sleep(Duration::from_millis(500));
    let i = std::sync::atomic::AtomicU32::new(0);
    let web = stall_until_cut(web, &r, || {
        let n = i.fetch_add(1, Ordering::SeqCst);
        let _ = ws
            .lock()
            .unwrap()
            .send(Message::text(format!("resize {} 200", 500 - n % 2)));
    });
    eprintln!("a client that stopped reading, over SSH: {ssh:?}; over the web: {web:?}");
    let stall = roughtui::serve::output::STALL;
    for c in [ssh, web] {
        // Let go within the stall time once nothing more could go (and
        // the whole within half a minute, however busy the machine).
        assert!(c.after_full < stall + Duration::from_secs(2), "{c:?}");
        assert!(c.took < Duration::from_secs(30), "{c:?}");
        // The kernel's doubled SEND_BUFFER (and its bookkeeping's slack).
        assert!(c.tx <= 3 * u64::from(roughtui::serve::SEND_BUFFER), "{c:?}");
        // The client's receive buffer, which stopped growing when it
        // stopped reading.
        assert!(c.rx <= 1 << 20, "{c:?}");
    }
}
