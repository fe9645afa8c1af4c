//! A TCP stream the server can cut. russh runs each connection in a task of
//! its own that a stalled client can keep waiting on a write forever; a
//! [`Killable`] stream fails every read and write once [`Kill::kill`] is
//! called (waking a pending one), so that task ends and frees everything.
//! It also fails a write the client has taken nothing of for
//! [`STALL`]: a client that stopped reading
//! (its buffers full) is let go though no new frame waits for it.

use std::future::Future;
use std::io;
use std::pin::Pin;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::task::{Context, Poll, Waker};

use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};

/// How long a client may take to accept one frame.
pub const STALL: std::time::Duration = std::time::Duration::from_secs(5);

#[derive(Debug, Default)]
struct State {
    killed: AtomicBool,
    /// The client sent something.
    read: AtomicBool,
    /// The tasks waiting on a read and on a write.
    wakers: Mutex<[Option<Waker>; 2]>,
}

/// Cuts its stream.
#[derive(Clone, Debug, Default)]
pub struct Kill(Arc<State>);

impl Kill {
    /// Whether the client sent anything yet.
    pub fn spoke(&self) -> bool {
        self.0.read.load(Ordering::Relaxed)
    }

    pub fn kill(&self) {
        self.0.killed.store(true, Ordering::SeqCst);
        let wakers = std::mem::take(&mut *self.0.wakers.lock().unwrap_or_else(|p| p.into_inner()));
        for w in wakers.into_iter().flatten() {
            w.wake();
        }
    }
}

pub struct Killable<S> {
    inner: S,
    state: Arc<State>,
    /// Since a write could not go on: it fails when this ends.
    stalled: Option<Pin<Box<tokio::time::Sleep>>>,
}

impl<S> Killable<S> {
    pub fn new(inner: S) -> (Killable<S>, Kill) {
        let kill = Kill::default();
        (
            Killable {
                inner,
                state: Arc::clone(&kill.0),
                stalled: None,
            },
            kill,
        )
    }

    /// `Err` once killed; else remembers the task to wake on a kill.
    fn check(&self, cx: &Context<'_>, slot: usize) -> io::Result<()> {
        if self.state.killed.load(Ordering::SeqCst) {
            return Err(io::ErrorKind::ConnectionAborted.into());
        }
        let mut w = self.state.wakers.lock().unwrap_or_else(|p| p.into_inner());
        if !w[slot].as_ref().is_some_and(|x| x.will_wake(cx.waker())) {
            w[slot] = Some(cx.waker().clone());
        }
        Ok(())
    }

    /// A write's outcome `r`: a write that has waited for the client
    /// [`STALL`] fails (and cuts the stream).
    fn stall<T>(&mut self, cx: &mut Context<'_>, r: Poll<io::Result<T>>) -> Poll<io::Result<T>> {
        if r.is_ready() {
            self.stalled = None;
            return r;
        }
        let timer = self
            .stalled
            .get_or_insert_with(|| Box::pin(tokio::time::sleep(STALL)));
        if timer.as_mut().poll(cx).is_ready() {
            self.stalled = None;
            self.state.killed.store(true, Ordering::SeqCst);
            return Poll::Ready(Err(io::ErrorKind::TimedOut.into()));
        }
        Poll::Pending
    }
}

impl<S: AsyncRead + Unpin> AsyncRead for Killable<S> {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        this.check(cx, 0)?;
        let before = buf.filled().len();
        let r = Pin::new(&mut this.inner).poll_read(cx, buf);
        if buf.filled().len() > before {
            this.state.read.store(true, Ordering::Relaxed);
        }
        r
    }
}

impl<S: AsyncWrite + Unpin> AsyncWrite for Killable<S> {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        this.check(cx, 1)?;
        let r = Pin::new(&mut this.inner).poll_write(cx, buf);
        this.stall(cx, r)
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        this.check(cx, 1)?;
        let r = Pin::new(&mut this.inner).poll_flush(cx);
        this.stall(cx, r)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        this.check(cx, 1)?;
        Pin::new(&mut this.inner).poll_shutdown(cx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tokio::io::{AsyncReadExt, AsyncWriteExt};

    #[tokio::test]
    async fn a_kill_wakes_a_pending_read_and_fails_writes() {
        let (a, _b) = tokio::io::duplex(64);
        let (mut s, kill) = Killable::new(a);
        let reader = tokio::spawn(async move {
            let mut buf = [0u8; 8];
            let r = s.read(&mut buf).await;
            (r.map_err(|e| e.kind()), s)
        });
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
        kill.kill();
        let (r, mut s) = reader.await.unwrap();
        assert_eq!(r, Err(io::ErrorKind::ConnectionAborted));
        let w = s.write_all(b"x").await.map_err(|e| e.kind());
        assert_eq!(w, Err(io::ErrorKind::ConnectionAborted));
    }

    #[tokio::test(start_paused = true)]
    async fn a_write_the_client_takes_nothing_of_fails_after_the_stall_time() {
        // A pipe of 64 bytes nobody reads.
        let (a, _b) = tokio::io::duplex(64);
        let (mut s, _kill) = Killable::new(a);
        let t = tokio::time::Instant::now();
        let w = s.write_all(&[0u8; 1000]).await.map_err(|e| e.kind());
        assert_eq!(w, Err(io::ErrorKind::TimedOut));
        assert_eq!(t.elapsed(), crate::serve::output::STALL);
        // Cut for good.
        let w = s.write_all(b"x").await.map_err(|e| e.kind());
        assert_eq!(w, Err(io::ErrorKind::ConnectionAborted));
        // A slow reader that takes something within the time is kept.
        let (a, mut b) = tokio::io::duplex(64);
        let (mut s, _kill) = Killable::new(a);
        let reader = tokio::spawn(async move {
            let mut buf = [0u8; 64];
            let mut n = 0;
            while n < 1000 {
                tokio::time::sleep(std::time::Duration::from_secs(1)).await;
                n += b.read(&mut buf).await.unwrap();
            }
        });
        s.write_all(&[0u8; 1000]).await.unwrap();
        reader.await.unwrap();
    }
}
