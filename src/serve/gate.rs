//! The gate: connections that have not logged in yet (SSH) or not sent
//! their request (the web). They are many and cheap for anyone on the
//! network to open, so they are bounded — at most [`WAITING`] per
//! transport — but never by turning newcomers away: when the gate is
//! full, the connection that has waited longest without a word (or, if
//! every one has spoken, the one that has waited longest) is closed to
//! make room. Two hundred idle connections hold no student back, from
//! another address or from the same one (a campus NAT).
//!
//! And the console's count of what was refused, written once a second as
//! it happens ([`Refusals`]), instead of a line per refusal.

use std::collections::BTreeMap;
use std::net::IpAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use tokio::sync::Notify;

/// Connections that may wait at the gate, per transport.
pub const WAITING: usize = 512;

/// A connection at the gate: whether it has spoken, and how to close it.
#[derive(Debug, Default)]
pub struct Knock {
    spoke: AtomicBool,
    closed: Notify,
    kill: Mutex<Option<super::stream::Kill>>,
}

impl Knock {
    /// The client sent something (an SSH banner, a request's first bytes).
    pub fn spoke(&self) {
        self.spoke.store(true, Ordering::Relaxed);
    }

    /// Resolves when the gate closes this connection to make room.
    pub async fn closed(&self) {
        self.closed.notified().await;
    }

    /// Cuts `kill`'s stream too when the gate closes the connection.
    pub fn cuts(&self, kill: super::stream::Kill) {
        *self.kill.lock().unwrap_or_else(|p| p.into_inner()) = Some(kill);
    }

    /// Whether the client sent anything yet.
    pub fn has_spoken(&self) -> bool {
        self.spoke.load(Ordering::Relaxed)
            || (self.kill.lock().unwrap_or_else(|p| p.into_inner()))
                .as_ref()
                .is_some_and(super::stream::Kill::spoke)
    }

    fn close(&self) {
        // `notify_one` keeps the wake-up for a task not yet waiting.
        self.closed.notify_one();
        if let Some(k) = self.kill.lock().unwrap_or_else(|p| p.into_inner()).as_ref() {
            k.kill();
        }
    }
}

#[derive(Debug, Default)]
struct Inner {
    next: u64,
    waiting: BTreeMap<u64, (Instant, IpAddr, Arc<Knock>)>,
}

/// The connections at one transport's gate.
#[derive(Clone, Debug)]
pub struct Gate {
    cap: usize,
    inner: Arc<Mutex<Inner>>,
    refusals: Arc<Refusals>,
}

/// A place at the gate; dropping it (the connection logged in, or ended)
/// frees it.
#[derive(Debug)]
pub struct Place {
    id: u64,
    inner: Arc<Mutex<Inner>>,
    pub knock: Arc<Knock>,
}

impl Gate {
    pub fn new(cap: usize, refusals: Arc<Refusals>) -> Gate {
        Gate {
            cap: cap.max(1),
            inner: Arc::default(),
            refusals,
        }
    }

    /// A place for a connection from `ip`: always given; when the gate is
    /// full, the connection that waited longest in silence (else the
    /// longest) is closed for it.
    pub fn enter(&self, ip: IpAddr) -> Place {
        let knock = Arc::new(Knock::default());
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        if g.waiting.len() >= self.cap {
            let silent = g
                .waiting
                .iter()
                .find(|(_, w)| !w.2.has_spoken())
                .map(|(id, _)| *id);
            let oldest = silent.or_else(|| g.waiting.keys().next().copied());
            if let Some((_, _, k)) = oldest.and_then(|id| g.waiting.remove(&id)) {
                k.close();
                self.refusals.count(CLOSED_FOR_ROOM);
            }
        }
        g.next += 1;
        let id = g.next;
        g.waiting
            .insert(id, (Instant::now(), ip, Arc::clone(&knock)));
        Place {
            id,
            inner: Arc::clone(&self.inner),
            knock,
        }
    }

    /// Closes every connection at the gate (the server stops: nobody
    /// waiting there is a student to say goodbye to).
    pub fn close_all(&self) {
        let waiting =
            std::mem::take(&mut self.inner.lock().unwrap_or_else(|p| p.into_inner()).waiting);
        for (_, _, k) in waiting.values() {
            k.close();
        }
    }

    /// Connections at the gate now.
    pub fn waiting(&self) -> usize {
        self.inner
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .waiting
            .len()
    }
}

impl Drop for Place {
    fn drop(&mut self) {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        g.waiting.remove(&self.id);
    }
}

/// What the console says of a connection the gate closed.
pub const CLOSED_FOR_ROOM: &str = "connections closed unanswered to make room (the gate was full)";

/// What was refused since the console last said it, by what.
#[derive(Debug, Default)]
pub struct Refusals(Mutex<BTreeMap<String, u64>>);

impl Refusals {
    pub fn count(&self, what: &str) {
        let mut m = self.0.lock().unwrap_or_else(|p| p.into_inner());
        *m.entry(what.to_string()).or_insert(0) += 1;
    }

    /// The console's line on what was refused since the last one (and
    /// the connections waiting at the gates, `waiting`), if anything was:
    /// "refused in the last second: 142 requests (408 the request's head
    /// took over 10 s), 3 wrong class codes; 200 connections wait".
    pub fn line(&self, waiting: usize) -> Option<String> {
        let m = std::mem::take(&mut *self.0.lock().unwrap_or_else(|p| p.into_inner()));
        if m.is_empty() {
            return None;
        }
        let parts: Vec<String> = m.iter().map(|(what, n)| format!("{n} {what}")).collect();
        let mut line = format!("refused in the last second: {}", parts.join(", "));
        if waiting > 0 {
            line.push_str(&format!(
                "; {waiting} connection{} at the gate",
                if waiting == 1 { "" } else { "s" }
            ));
        }
        Some(line)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn a_full_gate_closes_the_longest_silent_connection_for_a_newcomer() {
        let r = Arc::new(Refusals::default());
        let g = Gate::new(3, Arc::clone(&r));
        let ip: IpAddr = "10.0.0.1".parse().unwrap();
        let a = g.enter(ip);
        let b = g.enter(ip);
        let c = g.enter(ip);
        // a spoke: b is the longest silent one.
        a.knock.spoke();
        let d = g.enter(ip);
        assert_eq!(g.waiting(), 3);
        // b was closed (its notification kept for when it waits).
        tokio::time::timeout(std::time::Duration::from_secs(1), b.knock.closed())
            .await
            .unwrap();
        c.knock.spoke();
        d.knock.spoke();
        // All spoke: the longest waiting goes.
        let _e = g.enter(ip);
        tokio::time::timeout(std::time::Duration::from_secs(1), a.knock.closed())
            .await
            .unwrap();
        drop((c, d));
        assert_eq!(g.waiting(), 1);
        assert_eq!(
            r.line(1).unwrap(),
            format!("refused in the last second: 2 {CLOSED_FOR_ROOM}; 1 connection at the gate")
        );
        assert_eq!(r.line(1), None);
    }
}
