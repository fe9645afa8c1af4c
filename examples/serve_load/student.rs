//! A student of the load test, over SSH (a russh client), over the web
//! (a WebSocket client, as the page's xterm.js speaks to the server) or
//! on a phone (the page's phone layout: its messages are the picture and
//! the texts around it): keys in, frames out, the same to the caller.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use futures_util::{SinkExt, StreamExt};
use russh::ChannelMsg;
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::WebSocketStream;

use super::client;

pub enum Student {
    Ssh(client::Client),
    /// A terminal's page or a phone's: a frame is a binary message (the
    /// terminal's bytes) or a text one (a phone's page).
    Web(Box<WebSocketStream<TcpStream>>),
}

/// How a student reaches the class.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    Ssh,
    Web,
    Phone,
}

/// Every frame a session gets, with when and its bytes.
pub type Frames = Arc<Mutex<Vec<(Instant, usize)>>>;

/// What keeps a recorded session open (its connection's other half).
pub type Keep = Box<dyn std::any::Any + Send>;

impl Student {
    pub async fn ssh(port: u16, name: &str) -> anyhow::Result<Student> {
        Ok(Student::Ssh(client::student(port, name, 100, 30).await?))
    }

    pub async fn web(port: u16, name: &str) -> anyhow::Result<Student> {
        Student::page(port, name, "").await
    }

    /// A phone's page (upright: the picture's default shape).
    pub async fn phone(port: u16, name: &str) -> anyhow::Result<Student> {
        Student::page(port, name, "&layout=phone").await
    }

    async fn page(port: u16, name: &str, extra: &str) -> anyhow::Result<Student> {
        let stream = TcpStream::connect(("127.0.0.1", port)).await?;
        stream.set_nodelay(true)?;
        let url = format!("ws://127.0.0.1:{port}/ws?name={name}&cols=100&rows=30{extra}");
        let (ws, _) = tokio_tungstenite::client_async(url, stream).await?;
        Ok(Student::Web(Box::new(ws)))
    }

    /// A student over `via`, at the SSH or the web port.
    pub async fn new(via: Via, (ssh, web): (u16, u16), name: &str) -> anyhow::Result<Student> {
        match via {
            Via::Ssh => Student::ssh(ssh, name).await,
            Via::Web => Student::web(web, name).await,
            Via::Phone => Student::phone(web, name).await,
        }
    }

    pub async fn send(&mut self, keys: &[u8]) -> anyhow::Result<()> {
        match self {
            Student::Ssh((_, ch)) => ch.data(keys).await?,
            Student::Web(ws) => ws.send(Message::binary(keys.to_vec())).await?,
        }
        Ok(())
    }

    /// The next frame's bytes within `wait`; `None` when none came.
    async fn frame(&mut self, wait: Duration) -> Option<usize> {
        let until = tokio::time::Instant::now() + wait;
        loop {
            match self {
                Student::Ssh((_, ch)) => match tokio::time::timeout_at(until, ch.wait()).await {
                    Ok(Some(ChannelMsg::Data { data })) => return Some(data.len()),
                    Ok(Some(_)) => {}
                    _ => return None,
                },
                Student::Web(ws) => match tokio::time::timeout_at(until, ws.next()).await {
                    Ok(Some(Ok(Message::Binary(b)))) => return Some(b.len()),
                    Ok(Some(Ok(Message::Text(t)))) => return Some(t.len()),
                    Ok(Some(Ok(_))) => {}
                    _ => return None,
                },
            }
        }
    }

    /// Waits for the next frame (5 s at most): when it came and its bytes.
    pub async fn next_frame(&mut self) -> anyhow::Result<(Instant, usize)> {
        match self.frame(Duration::from_secs(5)).await {
            Some(n) => Ok((Instant::now(), n)),
            None => anyhow::bail!("no frame within 5 s"),
        }
    }

    /// Reads until no data came for `quiet`; the bytes read.
    pub async fn drain(&mut self, quiet: Duration) -> usize {
        let mut n = 0;
        while let Some(b) = self.frame(quiet).await {
            n += b;
        }
        n
    }

    /// Records every frame from now on in a task of its own.
    pub fn record(self) -> (Keep, Frames) {
        let frames: Frames = Arc::default();
        let f = Arc::clone(&frames);
        match self {
            Student::Ssh((h, ch)) => {
                let (mut read, write) = ch.split();
                tokio::spawn(async move {
                    while let Some(msg) = read.wait().await {
                        if let ChannelMsg::Data { data } = msg {
                            f.lock().unwrap().push((Instant::now(), data.len()));
                        }
                    }
                });
                (Box::new((h, write)), frames)
            }
            Student::Web(mut ws) => {
                let (stop, mut stopped) = tokio::sync::oneshot::channel::<()>();
                tokio::spawn(async move {
                    loop {
                        tokio::select! {
                            msg = ws.next() => match msg {
                                Some(Ok(Message::Binary(b))) => {
                                    f.lock().unwrap().push((Instant::now(), b.len()));
                                }
                                Some(Ok(Message::Text(t))) => {
                                    f.lock().unwrap().push((Instant::now(), t.len()));
                                }
                                Some(Ok(_)) => {}
                                _ => return,
                            },
                            _ = &mut stopped => return,
                        }
                    }
                });
                (Box::new(stop), frames)
            }
        }
    }
}
