//! Connection limits: at most `max_sessions` at once and at most
//! `max_per_address` from one source address. A [`Permit`] holds a place
//! and gives it back when dropped, however the connection ends.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex};

/// Window sizes a session accepts: anything else is clamped into this.
pub const MIN_SIZE: (u16, u16) = (1, 1);
pub const MAX_SIZE: (u16, u16) = (500, 200);

/// A client's (columns, rows) clamped to what a session draws.
pub fn clamp_size(cols: u32, rows: u32) -> (u16, u16) {
    let c = cols.clamp(u32::from(MIN_SIZE.0), u32::from(MAX_SIZE.0));
    let r = rows.clamp(u32::from(MIN_SIZE.1), u32::from(MAX_SIZE.1));
    (c as u16, r as u16)
}

#[derive(Debug, Default)]
struct Counts {
    total: usize,
    per_address: HashMap<IpAddr, usize>,
}

/// The places taken, shared by the accept loop and its connections.
#[derive(Clone, Debug)]
pub struct Limits {
    max_sessions: usize,
    max_per_address: usize,
    counts: Arc<Mutex<Counts>>,
}

/// Why a connection was turned away.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Full {
    Server,
    Address,
}

/// A place taken; dropping it frees it.
#[derive(Debug)]
pub struct Permit {
    ip: IpAddr,
    counts: Arc<Mutex<Counts>>,
}

impl Limits {
    pub fn new(max_sessions: usize, max_per_address: usize) -> Limits {
        Limits {
            max_sessions,
            max_per_address,
            counts: Arc::default(),
        }
    }

    /// A place for a connection from `ip`, if one is free.
    pub fn enter(&self, ip: IpAddr) -> Result<Permit, Full> {
        let mut c = self.counts.lock().unwrap_or_else(|p| p.into_inner());
        if c.total >= self.max_sessions {
            return Err(Full::Server);
        }
        let n = c.per_address.entry(ip).or_insert(0);
        if *n >= self.max_per_address {
            return Err(Full::Address);
        }
        *n += 1;
        c.total += 1;
        Ok(Permit {
            ip,
            counts: Arc::clone(&self.counts),
        })
    }

    pub fn max_sessions(&self) -> usize {
        self.max_sessions
    }

    pub fn max_per_address(&self) -> usize {
        self.max_per_address
    }

    /// Connections open now.
    pub fn open(&self) -> usize {
        self.counts.lock().unwrap_or_else(|p| p.into_inner()).total
    }
}

impl Drop for Permit {
    fn drop(&mut self) {
        let mut c = self.counts.lock().unwrap_or_else(|p| p.into_inner());
        c.total -= 1;
        if let Some(n) = c.per_address.get_mut(&self.ip) {
            *n -= 1;
            if *n == 0 {
                c.per_address.remove(&self.ip);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn places_are_counted_and_given_back() {
        let l = Limits::new(3, 2);
        let a: IpAddr = "127.0.0.1".parse().unwrap();
        let b: IpAddr = "127.0.0.2".parse().unwrap();
        let p1 = l.enter(a).unwrap();
        let _p2 = l.enter(a).unwrap();
        assert_eq!(l.enter(a).unwrap_err(), Full::Address);
        let _p3 = l.enter(b).unwrap();
        assert_eq!(l.enter(b).unwrap_err(), Full::Server);
        assert_eq!(l.open(), 3);
        drop(p1);
        assert_eq!(l.open(), 2);
        assert!(l.enter(a).is_ok());
    }

    #[test]
    fn sizes_are_clamped() {
        assert_eq!(clamp_size(0, 0), (1, 1));
        assert_eq!(clamp_size(10_000, 10_000), (500, 200));
        assert_eq!(clamp_size(u32::MAX, 24), (500, 24));
        assert_eq!(clamp_size(80, 24), (80, 24));
    }
}
