//! `roughtui serve --web ADDR:PORT`: the class in a browser. One page
//! (xterm.js and a few lines of glue, built into the binary: [`assets`])
//! and a WebSocket at `/ws` that carries the same explorer session an SSH
//! student gets ([`socket`]). Plain HTTP for a classroom network; behind a
//! reverse proxy for TLS (docs/teaching.md).
//!
//! What a request may be: `GET` (or `HEAD`) of one of the page's files, or `GET` of `/ws`
//! with the WebSocket upgrade, its `Origin` (when sent) the page's own
//! (the `Host` it asked), its head at most [`MAX_HEAD`] bytes within
//! [`HEAD_TIME`]. Anything else gets a status and one line, and the
//! connection closes; no path from a request reaches the file system.

pub mod assets;
pub mod json;
pub mod phone;
pub mod socket;
mod url;

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};

use super::gate::{Gate, Knock, Place};
use super::limits::Limits;
use super::Shared;

/// The most bytes of a request's head (request line and headers).
pub const MAX_HEAD: usize = 8 * 1024;

/// The most headers a request may have.
const MAX_HEADERS: usize = 32;

/// How long a client may take to send a request's head.
pub const HEAD_TIME: Duration = Duration::from_secs(10);

/// Accepts web connections until the server stops: each waits at `gate`
/// until its request is answered (a page's file) or it becomes a
/// student's WebSocket (then it holds a student's place); `live` counts
/// the open ones.
pub async fn serve(listener: TcpListener, shared: Arc<Shared>, gate: Gate, live: Limits) {
    let mut ending = shared.ending.subscribe();
    loop {
        let (socket, peer) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(x) => x,
                Err(_) => {
                    tokio::time::sleep(Duration::from_millis(100)).await;
                    continue;
                }
            },
            _ = ending.changed() => return,
        };
        let place = gate.enter(peer.ip());
        let Ok(permit) = live.enter(peer.ip()) else {
            continue;
        };
        let _ = socket.set_nodelay(true);
        let shared = Arc::clone(&shared);
        tokio::spawn(async move {
            let _permit = permit;
            connection(shared, socket, peer, place).await;
        });
    }
}

/// A request's head, parsed: what the server looks at.
#[derive(Debug, Default)]
pub struct Head {
    pub method: String,
    pub path: String,
    pub query: String,
    pub host: Option<String>,
    pub origin: Option<String>,
    pub upgrade: bool,
    pub key: Option<String>,
    pub version_13: bool,
}

/// Why a request is refused: its status and line.
#[derive(Debug, PartialEq, Eq)]
pub struct Refusal(pub u16, pub &'static str);

/// Parses a request's head from `buf`: the head and its length, `Ok(None)`
/// while it is incomplete.
pub fn parse(buf: &[u8]) -> Result<Option<(Head, usize)>, Refusal> {
    let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
    let mut req = httparse::Request::new(&mut headers);
    let n = match req.parse(buf) {
        Ok(httparse::Status::Complete(n)) => n,
        Ok(httparse::Status::Partial) if buf.len() >= MAX_HEAD => {
            return Err(Refusal(431, "the request's head is over 8 KiB"));
        }
        Ok(httparse::Status::Partial) => return Ok(None),
        Err(httparse::Error::TooManyHeaders) => {
            return Err(Refusal(431, "the request has more than 32 headers"))
        }
        Err(_) => return Err(Refusal(400, "a malformed HTTP request")),
    };
    let target = req.path.unwrap_or("/");
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let mut head = Head {
        method: req.method.unwrap_or("").to_string(),
        path: path.to_string(),
        query: query.to_string(),
        ..Head::default()
    };
    for h in req.headers.iter() {
        let value = || {
            std::str::from_utf8(h.value)
                .ok()
                .map(|v| v.trim().to_string())
        };
        let name = h.name.to_ascii_lowercase();
        match name.as_str() {
            "host" => head.host = value(),
            "origin" => head.origin = value(),
            "upgrade" => {
                head.upgrade |= value().is_some_and(|v| v.eq_ignore_ascii_case("websocket"))
            }
            "sec-websocket-key" => head.key = value(),
            "sec-websocket-version" => head.version_13 = value().as_deref() == Some("13"),
            _ => {}
        }
    }
    Ok(Some((head, n)))
}

/// Whether a browser's `Origin` is the page's own: `http://` or
/// `https://` (behind a TLS proxy) and the `Host` the request names.
pub fn same_origin(origin: &str, host: &str) -> bool {
    let rest = origin
        .strip_prefix("http://")
        .or_else(|| origin.strip_prefix("https://"));
    rest.is_some_and(|r| r.eq_ignore_ascii_case(host))
}

/// Reads a request's head within [`HEAD_TIME`]: the head and the bytes
/// read past it (a client may send its first WebSocket frame at once).
async fn read_head(socket: &mut TcpStream, knock: &Knock) -> Result<(Head, Vec<u8>), Refusal> {
    let mut buf = Vec::with_capacity(1024);
    let read = async {
        let mut chunk = [0u8; 2048];
        loop {
            let n = socket
                .read(&mut chunk)
                .await
                .map_err(|_| Refusal(400, "the connection failed"))?;
            if n == 0 {
                return Err(Refusal(400, "the request ended before its head did"));
            }
            knock.spoke();
            buf.extend_from_slice(&chunk[..n]);
            if let Some((head, len)) = parse(&buf[..buf.len().min(MAX_HEAD)])? {
                return Ok((head, buf[len..].to_vec()));
            }
        }
    };
    tokio::time::timeout(HEAD_TIME, read)
        .await
        .unwrap_or(Err(Refusal(408, "the request's head took over 10 s")))
}

async fn connection(shared: Arc<Shared>, mut socket: TcpStream, peer: SocketAddr, place: Place) {
    let read = tokio::select! {
        r = read_head(&mut socket, &place.knock) => r,
        // Closed to make room at the gate (counted there).
        () = place.knock.closed() => return,
    };
    let (head, rest) = match read {
        Ok(x) => x,
        Err(r) => {
            refuse(&mut socket, &r).await;
            shared.refusals.count(&refused(&r));
            return;
        }
    };
    let method = head.method.as_str();
    if method != "GET" && !(method == "HEAD" && head.path != "/ws") {
        let r = Refusal(405, "only GET (and HEAD of a page's file) is served here");
        shared.refusals.count(&refused(&r));
        return refuse(&mut socket, &r).await;
    }
    if head.path == "/ws" {
        // A student's WebSocket: a student's place from now on.
        drop(place);
        return socket::upgrade(shared, socket, peer, head, rest).await;
    }
    match assets::find(&head.path) {
        Some(a) => {
            let mut out = format!(
                "HTTP/1.1 200 OK\r\nContent-Type: {}\r\nContent-Length: {}\r\n\
                 Cache-Control: {}\r\n{}Connection: close\r\n\r\n",
                a.mime,
                a.body.len(),
                a.cache,
                SECURITY_HEADERS
            )
            .into_bytes();
            if method == "GET" {
                out.extend_from_slice(a.body);
            }
            let _ = tokio::time::timeout(super::output::STALL * 6, socket.write_all(&out)).await;
            let _ = socket.shutdown().await;
        }
        None => {
            let r = Refusal(404, "no such page here");
            shared.refusals.count(&refused(&r));
            refuse(&mut socket, &r).await;
        }
    }
}

/// How the console counts a refusal: "requests refused 408 (the
/// request's head took over 10 s)".
pub fn refused(r: &Refusal) -> String {
    format!("web requests refused {} ({})", r.0, r.1)
}

/// The page's own files and its WebSocket only; no framing by others.
const SECURITY_HEADERS: &str = "X-Content-Type-Options: nosniff\r\n\
     X-Frame-Options: DENY\r\n\
     Referrer-Policy: no-referrer\r\n\
     Content-Security-Policy: default-src 'self'; style-src 'self' 'unsafe-inline'; \
     connect-src 'self' ws: wss:; frame-ancestors 'none'\r\n";

/// A status and its line, then the connection closes.
pub async fn refuse(socket: &mut TcpStream, r: &Refusal) {
    let reason = match r.0 {
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        426 => "Upgrade Required",
        431 => "Request Header Fields Too Large",
        _ => "Error",
    };
    let body = format!("roughtui: {}\n", r.1);
    let out = format!(
        "HTTP/1.1 {} {reason}\r\nContent-Type: text/plain; charset=utf-8\r\n\
         Content-Length: {}\r\n{SECURITY_HEADERS}Connection: close\r\n\r\n{body}",
        r.0,
        body.len()
    );
    let _ = tokio::time::timeout(super::output::STALL, socket.write_all(out.as_bytes())).await;
    let _ = socket.shutdown().await;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heads_are_parsed_and_bounded() {
        let req = b"GET /ws?name=ada&code=x HTTP/1.1\r\nHost: 10.0.0.1:8080\r\n\
              Origin: http://10.0.0.1:8080\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
              Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\nXY";
        let (h, n) = parse(req).unwrap().unwrap();
        assert_eq!(
            (h.path.as_str(), h.query.as_str()),
            ("/ws", "name=ada&code=x")
        );
        assert!(h.upgrade && h.version_13 && h.key.is_some());
        assert!(same_origin(
            h.origin.as_deref().unwrap(),
            h.host.as_deref().unwrap()
        ));
        // The head ends before the first frame's bytes.
        assert_eq!(&req[n..], b"XY");
        assert!(matches!(parse(b"GET / HTTP/1.1\r\nHost: a"), Ok(None)));
        assert_eq!(
            parse(b"\x00\x01garbage\r\n\r\n").unwrap_err(),
            Refusal(400, "a malformed HTTP request")
        );
        let big = format!("GET / HTTP/1.1\r\nX: {}\r\n", "a".repeat(MAX_HEAD));
        assert_eq!(parse(&big.as_bytes()[..MAX_HEAD]).unwrap_err().0, 431);
        let many: String = (0..40).map(|i| format!("X{i}: 1\r\n")).collect();
        let req = format!("GET / HTTP/1.1\r\n{many}\r\n");
        assert_eq!(parse(req.as_bytes()).unwrap_err().0, 431);
    }

    #[test]
    fn the_origin_must_be_the_pages_own() {
        assert!(same_origin("http://10.0.0.1:8080", "10.0.0.1:8080"));
        assert!(same_origin(
            "https://class.example.org",
            "class.example.org"
        ));
        assert!(!same_origin("http://evil.example:8080", "10.0.0.1:8080"));
        assert!(!same_origin("http://10.0.0.1:8080.evil", "10.0.0.1:8080"));
        assert!(!same_origin("null", "10.0.0.1:8080"));
    }
}
