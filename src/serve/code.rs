//! The class code (`--class-code WORD`, `--class-code-file F`) and the
//! limit on wrong codes.
//!
//! Wrong codes are counted per address: [`WRONG_PER_MINUTE`] in a minute
//! are answered as usual; past that the address waits a minute from its
//! latest wrong code. A campus NAT puts a whole room behind one address,
//! so waiting must not lock the room out: while an address waits, its
//! codes are still checked, one every [`PACE`] in turn (a room of 60 is in
//! within seconds), and a wrong one ends its connection at once with a line
//! saying to wait. A guesser behind the room's address gets ten tries a
//! second at most instead of as many as its connections allow; one with an
//! address of its own gets five a minute, then ten a second while it waits.

use std::collections::{HashMap, VecDeque};
use std::net::IpAddr;
use std::path::Path;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::{bail, Context};

/// The longest class code, in bytes.
pub const MAX_CODE_BYTES: usize = 200;

/// A class code students type at "class code:".
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClassCode(String);

impl ClassCode {
    /// `--class-code WORD`: surrounding blanks dropped; empty, multi-line,
    /// control characters or over [`MAX_CODE_BYTES`] refused.
    pub fn word(word: &str) -> anyhow::Result<ClassCode> {
        let w = word.trim();
        if w.is_empty() {
            bail!("the class code is empty");
        }
        if w.chars().any(char::is_control) {
            bail!("the class code holds a control character (or more than one line)");
        }
        if w.len() > MAX_CODE_BYTES {
            bail!(
                "the class code is {} bytes long: at most {MAX_CODE_BYTES}",
                w.len()
            );
        }
        Ok(ClassCode(w.to_string()))
    }

    /// `--class-code-file F`: the file's text, as [`ClassCode::word`] takes it.
    pub fn read(path: &Path) -> anyhow::Result<ClassCode> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read the class code file {}", path.display()))?;
        if text.trim().is_empty() {
            bail!("the class code file {} is empty", path.display());
        }
        ClassCode::word(&text).with_context(|| format!("class code file {}", path.display()))
    }

    /// The code itself (for the web page's join address).
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// Whether `typed` (blanks around it dropped) is the code; the time
    /// taken does not depend on where they differ.
    pub fn matches(&self, typed: &[u8]) -> bool {
        let t = typed.trim_ascii();
        let c = self.0.as_bytes();
        if t.len() != c.len() {
            return false;
        }
        t.iter().zip(c).fold(0u8, |acc, (a, b)| acc | (a ^ b)) == 0
    }
}

/// Wrong codes an address may send in a minute before it waits.
pub const WRONG_PER_MINUTE: usize = 5;
/// The window wrong codes are counted in, and how long an address waits.
pub const MINUTE: Duration = Duration::from_secs(60);
/// While an address waits, one of its codes is checked per this much time.
pub const PACE: Duration = Duration::from_millis(100);
/// While an address waits, a code whose turn is further off than this is
/// not taken at all.
pub const MAX_AHEAD: Duration = Duration::from_secs(20);
/// Addresses remembered before the stale ones are dropped.
const PRUNE_AT: usize = 4096;

#[derive(Debug)]
struct Address {
    /// The wrong codes of the last minute.
    wrong: VecDeque<Instant>,
    /// Waiting until then.
    until: Option<Instant>,
    /// The next free turn while waiting.
    next: Instant,
}

impl Address {
    fn waiting(&self, now: Instant) -> bool {
        self.until.is_some_and(|u| u > now)
    }

    fn stale(&self, now: Instant) -> bool {
        !self.waiting(now) && self.wrong.back().is_none_or(|t| now - *t >= MINUTE)
    }
}

/// When a code may be checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    Now,
    /// The address waits: at this instant.
    At(Instant),
    /// The address waits and its queue is too long: not at all.
    Refused,
}

/// The wrong codes per address, shared by all connections.
#[derive(Debug, Default)]
pub struct WrongCodes(Mutex<HashMap<IpAddr, Address>>);

impl WrongCodes {
    fn with<T>(&self, ip: IpAddr, now: Instant, f: impl FnOnce(&mut Address) -> T) -> T {
        let mut m = self.0.lock().unwrap_or_else(|p| p.into_inner());
        if m.len() >= PRUNE_AT {
            m.retain(|_, a| !a.stale(now));
        }
        let a = m.entry(ip).or_insert_with(|| Address {
            wrong: VecDeque::new(),
            until: None,
            next: now,
        });
        let out = f(a);
        if a.stale(now) {
            m.remove(&ip);
        }
        out
    }

    /// The turn of a code from `ip` that arrived at `now`.
    pub fn turn(&self, ip: IpAddr, now: Instant) -> Turn {
        self.with(ip, now, |a| {
            if !a.waiting(now) {
                return Turn::Now;
            }
            let at = a.next.max(now);
            if at - now > MAX_AHEAD {
                return Turn::Refused;
            }
            a.next = at + PACE;
            Turn::At(at)
        })
    }

    /// A wrong code from `ip` at `now`; whether the address now waits.
    pub fn wrong(&self, ip: IpAddr, now: Instant) -> bool {
        self.with(ip, now, |a| {
            while a.wrong.front().is_some_and(|t| now - *t >= MINUTE) {
                a.wrong.pop_front();
            }
            a.wrong.push_back(now);
            if a.wrong.len() > WRONG_PER_MINUTE {
                a.wrong.pop_front();
            }
            if a.wrong.len() >= WRONG_PER_MINUTE {
                a.until = Some(now + MINUTE);
            }
            a.waiting(now)
        })
    }

    /// Whether `ip` waits at `now`.
    pub fn waiting(&self, ip: IpAddr, now: Instant) -> bool {
        self.with(ip, now, |a| a.waiting(now))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_from_words_and_files() {
        let c = ClassCode::word("  tribology \n").unwrap();
        assert!(c.matches(b"tribology"));
        assert!(c.matches(b" tribology\n"));
        assert!(!c.matches(b"Tribology"));
        assert!(!c.matches(b"tribolog"));
        assert!(!c.matches(b""));
        let e = |w: &str| ClassCode::word(w).unwrap_err().to_string();
        assert_eq!(e("  "), "the class code is empty");
        assert!(e("a\nb").contains("more than one line"));
        assert!(e(&"x".repeat(201)).contains("201 bytes long"));

        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join("code");
        std::fs::write(&f, "hertz\n").unwrap();
        assert!(ClassCode::read(&f).unwrap().matches(b"hertz"));
        std::fs::write(&f, "\n \n").unwrap();
        let e = format!("{:#}", ClassCode::read(&f).unwrap_err());
        assert!(e.contains("is empty") && e.contains("code"), "{e}");
        std::fs::write(&f, b"\xff\xfe").unwrap();
        let e = format!("{:#}", ClassCode::read(&f).unwrap_err());
        assert!(e.starts_with("cannot read the class code file"), "{e}");
        let e = format!(
            "{:#}",
            ClassCode::read(&dir.path().join("none")).unwrap_err()
        );
        assert!(e.contains("No such file"), "{e}");
    }

    #[test]
    fn five_wrong_codes_a_minute_then_the_address_waits_but_is_not_shut() {
        let w = WrongCodes::default();
        let ip: IpAddr = "10.0.0.1".parse().unwrap();
        let other: IpAddr = "10.0.0.2".parse().unwrap();
        let t0 = Instant::now();
        for i in 0..4 {
            assert!(!w.wrong(ip, t0 + Duration::from_secs(i)));
            assert_eq!(w.turn(ip, t0 + Duration::from_secs(i)), Turn::Now);
        }
        let t5 = t0 + Duration::from_secs(4);
        assert!(w.wrong(ip, t5));
        // Waiting: codes are checked in turn, PACE apart.
        assert_eq!(w.turn(ip, t5), Turn::At(t5));
        assert_eq!(w.turn(ip, t5), Turn::At(t5 + PACE));
        assert_eq!(w.turn(ip, t5), Turn::At(t5 + 2 * PACE));
        // Another address is not slowed.
        assert_eq!(w.turn(other, t5), Turn::Now);
        // A queue longer than MAX_AHEAD is not taken.
        let mut refused = false;
        for _ in 0..400 {
            if w.turn(ip, t5) == Turn::Refused {
                refused = true;
                break;
            }
        }
        assert!(refused);
        // The wait ends a minute after the latest wrong code…
        assert!(w.waiting(ip, t5 + MINUTE - Duration::from_millis(1)));
        assert!(!w.waiting(ip, t5 + MINUTE));
        assert_eq!(w.turn(ip, t5 + MINUTE), Turn::Now);
        // …and a wrong code while waiting extends it.
        let w = WrongCodes::default();
        for i in 0..5 {
            w.wrong(ip, t0 + Duration::from_secs(i));
        }
        w.wrong(ip, t0 + Duration::from_secs(50));
        assert!(w.waiting(ip, t0 + Duration::from_secs(100)));
        assert!(!w.waiting(ip, t0 + Duration::from_secs(110)));
    }

    #[test]
    fn wrong_codes_spread_over_minutes_never_wait() {
        let w = WrongCodes::default();
        let ip: IpAddr = "10.0.0.1".parse().unwrap();
        let t0 = Instant::now();
        for i in 0..50 {
            assert!(!w.wrong(ip, t0 + Duration::from_secs(15 * i)));
        }
    }
}
