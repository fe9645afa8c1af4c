//! A browser's WebSocket: checked (the upgrade's headers, `Origin` against
//! `Host`), then the join (the class code and its wrong-code limit, a
//! student's place under `--max-sessions` / `--max-per-address`, as over
//! SSH), then the same explorer session an SSH student gets
//! ([`crate::serve::session`]): the browser's messages become its input,
//! its frames go back as binary messages through the same one-frame slot,
//! and the close frame carries why it ended. A refusal is a close frame
//! with a code from 4000 and its reason, which the page shows in its form.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Instant;

use futures_util::{SinkExt, StreamExt};
use tokio::io::AsyncWriteExt;
use tokio::net::TcpStream;
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;
use tokio_tungstenite::tungstenite::protocol::{CloseFrame, Role as WsRole, WebSocketConfig};
use tokio_tungstenite::tungstenite::{Error as WsError, Message};
use tokio_tungstenite::WebSocketStream;

use super::url::param;
use super::{refuse, same_origin, Head, Refusal};
use crate::class::Transport;
use crate::serve::auth::Role;
use crate::serve::code::Turn;
use crate::serve::limits::clamp_size;
use crate::serve::output::{Bye, STALL};
use crate::serve::session::{self, Input, Render, Start, Wire, WireIn};
use crate::serve::term::ClientTerm;
use crate::serve::Shared;

/// The largest message (and frame) a browser may send: keys and sizes
/// are a few bytes; a paste is cut to the session's own read bound.
pub const MAX_MESSAGE: usize = 16 * 1024;

/// Close codes the page tells apart: refused before the explorer started
/// (back to the form with the reason), and the session's end.
pub const REFUSED: u16 = 4000;
pub const WRONG_CODE: u16 = 4001;
pub const FULL: u16 = 4002;
/// The code was not checked (its address sent wrong ones too fast): the
/// page tries again by itself a moment later.
pub const BUSY: u16 = 4003;

/// The 101 answer, after the upgrade's headers and the origin are checked.
pub async fn upgrade(
    shared: Arc<Shared>,
    mut socket: TcpStream,
    peer: SocketAddr,
    head: Head,
    rest: Vec<u8>,
) {
    let checked = (|| {
        let host = head.host.as_deref().ok_or(Refusal(400, "no Host header"))?;
        if let Some(o) = &head.origin {
            if !same_origin(o, host) {
                return Err(Refusal(
                    403,
                    "a page from another site may not open the class",
                ));
            }
        }
        if !head.upgrade || !head.version_13 {
            return Err(Refusal(426, "/ws is the class's WebSocket (version 13)"));
        }
        head.key.clone().ok_or(Refusal(400, "no Sec-WebSocket-Key"))
    })();
    let key = match checked {
        Ok(k) => k,
        Err(r) => {
            shared.refusals.count(&super::refused(&r));
            return refuse(&mut socket, &r).await;
        }
    };
    let accept = tokio_tungstenite::tungstenite::handshake::derive_accept_key(key.as_bytes());
    let answer = format!(
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
         Sec-WebSocket-Accept: {accept}\r\n\r\n"
    );
    if socket.write_all(answer.as_bytes()).await.is_err() {
        return;
    }
    // Keys are a few bytes: a read buffer of 4 KiB, not tungstenite's
    // 128 KiB, for each of a class's idle sessions.
    let config = WebSocketConfig::default()
        .read_buffer_size(4 * 1024)
        .max_message_size(Some(MAX_MESSAGE))
        .max_frame_size(Some(MAX_MESSAGE));
    let ws = WebSocketStream::from_partially_read(socket, rest, WsRole::Server, Some(config)).await;
    join(shared, ws, peer, &head.query).await;
}

async fn close(ws: &mut WebSocketStream<TcpStream>, code: u16, why: &str) {
    // A close frame's reason is at most 123 bytes.
    let mut reason = why.to_string();
    while reason.len() > 123 {
        reason.pop();
    }
    let frame = CloseFrame {
        code: CloseCode::from(code),
        reason: reason.into(),
    };
    let _ = tokio::time::timeout(STALL, ws.close(Some(frame))).await;
}

/// The class code and a place, then the session.
async fn join(shared: Arc<Shared>, mut ws: WebSocketStream<TcpStream>, peer: SocketAddr, q: &str) {
    let ip = peer.ip();
    let name = param(q, "name").unwrap_or_default();
    if name.trim().is_empty() {
        return close(&mut ws, REFUSED, "a name, please: the class list shows it").await;
    }
    if let Some(code) = shared.class_code.clone() {
        let typed = param(q, "code").unwrap_or_default();
        let wrongs = &shared.wrong_codes;
        match wrongs.turn(ip, Instant::now()) {
            Turn::Now => {}
            Turn::At(t) => tokio::time::sleep_until(t.into()).await,
            Turn::Refused(first) => {
                if first {
                    shared.log.line(&crate::serve::code::too_fast(ip));
                }
                shared.refusals.count(crate::serve::code::UNCHECKED);
                let wait = crate::serve::code::wait_line(ip);
                return close(&mut ws, BUSY, &wait).await;
            }
        }
        if code.matches(typed.as_bytes()) {
            wrongs.right(ip, Instant::now());
        } else {
            shared.refusals.count(crate::serve::code::WRONG);
            let why = if typed.is_empty() {
                "this class needs its code: ask your lecturer"
            } else {
                "wrong class code: try again"
            };
            return close(&mut ws, WRONG_CODE, why).await;
        }
    }
    let seat = match shared.seats.enter(ip) {
        Ok(p) => p,
        Err(full) => {
            let why = crate::serve::full_text(full, &shared.seats, ip);
            shared.log.line(&format!("turned away {ip}: {why}"));
            return close(&mut ws, FULL, &why).await;
        }
    };
    let size = |k: &str, d: u32| param(q, k).and_then(|v| v.parse().ok()).unwrap_or(d);
    let size = clamp_size(size("cols", 80), size("rows", 24));
    // xterm.js: 256 colours, UTF-8 (braille).
    let mut client = ClientTerm::default();
    client.set_term("xterm-256color");
    client.env("LANG", "C.UTF-8");
    let (keys, input) = mpsc::channel(16);
    let (slot, frames) = mpsc::channel(1);
    let (notes_tx, notes) = mpsc::unbounded_channel();
    let bye = Bye::default();
    // The page's phone layout: a picture and buttons (else xterm.js).
    let phone = param(q, "layout").as_deref() == Some("phone");
    // The seat a reloaded page held: 32 hexadecimal digits, or none.
    let token =
        param(q, "seat").filter(|t| t.len() == 32 && t.bytes().all(|b| b.is_ascii_hexdigit()));
    session::spawn(Start {
        shared: Arc::clone(&shared),
        wire: Wire {
            input: Input::Web(input),
            slot,
            bye: bye.clone(),
            via: if phone {
                " over the web (phone)"
            } else {
                " over the web"
            },
            render: if phone {
                Render::Phone
            } else {
                Render::Terminal
            },
            notes: Some(notes_tx),
        },
        role: Role::Student,
        size,
        name,
        addr: ip,
        client,
        transport: if phone {
            Transport::Phone
        } else {
            Transport::Web
        },
        token,
    });
    let link = Link {
        keys,
        frames,
        notes,
        bye,
        phone,
    };
    pump(&shared, ws, link, ip).await;
    drop(seat);
}

/// A session's side of a WebSocket: its input, its frames (a phone's as
/// text), the page's notes (the seat) and its goodbye.
struct Link {
    keys: mpsc::Sender<WireIn>,
    frames: mpsc::Receiver<Vec<u8>>,
    notes: mpsc::UnboundedReceiver<String>,
    bye: Bye,
    phone: bool,
}

/// Moves messages both ways until either side ends: the browser's input
/// to the session, the session's frames to the browser (a browser that
/// takes none for [`STALL`] is dropped); at the session's end its goodbye
/// and a close frame with the reason.
async fn pump(
    shared: &Shared,
    mut ws: WebSocketStream<TcpStream>,
    link: Link,
    ip: std::net::IpAddr,
) {
    let Link {
        keys,
        mut frames,
        mut notes,
        bye,
        phone,
    } = link;
    loop {
        tokio::select! {
            msg = ws.next() => {
                let input = match msg {
                    Some(Ok(Message::Binary(b))) => WireIn::Data(b.to_vec()),
                    Some(Ok(Message::Text(t))) => match resize(t.as_str()) {
                        Some((w, h)) => WireIn::Resize(w, h),
                        None => WireIn::Command(t.as_str().to_string()),
                    },
                    Some(Ok(Message::Close(_))) | None => return,
                    Some(Ok(_)) => continue,
                    Some(Err(WsError::Capacity(_))) => {
                        shared.log.line(&format!(
                            "web: {ip} sent a message over {} KiB: its session ended",
                            MAX_MESSAGE / 1024
                        ));
                        drop(keys);
                        // The session's goodbye, then the close frame.
                        bye.set(format!("a message over {} KiB: the session ended", MAX_MESSAGE / 1024));
                        while frames.recv().await.is_some() {}
                        return finish(&mut ws, &bye, 1009, phone).await;
                    }
                    Some(Err(_)) => return,
                };
                if keys.send(input).await.is_err() {
                    return;
                }
            }
            Some(note) = notes.recv() => {
                let sent = tokio::time::timeout(STALL, ws.send(Message::text(note))).await;
                if !matches!(sent, Ok(Ok(()))) {
                    return;
                }
            }
            frame = frames.recv() => match frame {
                Some(bytes) => {
                    let msg = if phone {
                        Message::text(String::from_utf8_lossy(&bytes).into_owned())
                    } else {
                        Message::Binary(bytes.into())
                    };
                    let sent = tokio::time::timeout(STALL, ws.send(msg)).await;
                    if !matches!(sent, Ok(Ok(()))) {
                        return;
                    }
                }
                None => return finish(&mut ws, &bye, 1000, phone).await,
            },
        }
    }
}

/// The session ended: the terminal restored (and why, on its own line),
/// then a close frame whose reason the page shows.
async fn finish(ws: &mut WebSocketStream<TcpStream>, bye: &Bye, code: u16, phone: bool) {
    let why = bye.why();
    let bytes = bye.bytes();
    // (A phone's page has no terminal: the close frame's reason says it.)
    if !phone {
        let _ = tokio::time::timeout(STALL, ws.send(Message::Binary(bytes.into()))).await;
    }
    close(ws, code, why.as_deref().unwrap_or("you left the class")).await;
}

/// `resize COLS ROWS`, clamped as a window change over SSH.
pub fn resize(text: &str) -> Option<(u16, u16)> {
    let mut w = text.strip_prefix("resize ")?.split(' ');
    let cols: u32 = w.next()?.parse().ok()?;
    let rows: u32 = w.next()?.parse().ok()?;
    Some(clamp_size(cols, rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resizes_are_clamped_and_junk_ignored() {
        assert_eq!(resize("resize 120 40"), Some((120, 40)));
        assert_eq!(resize("resize 0 0"), Some((1, 1)));
        assert_eq!(resize("resize 10000 10000"), Some((500, 200)));
        assert_eq!(resize("resize -1 5"), None);
        assert_eq!(resize("hello"), None);
        assert_eq!(resize("resize 99999999999 1"), None);
    }
}
