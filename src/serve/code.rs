//! The class code (`--class-code WORD`, `--class-code-file F`) and the
//! limit on wrong codes.
//!
//! Codes are checked per address at a bounded rate ([`WrongCodes`]): a
//! burst of [`BURST`], then [`PER_SECOND`] a second; a right code gives
//! its check back, so only wrong codes use them up. A campus NAT puts a
//! whole room behind one address, so the limit must not lock the room
//! out: no queue of a guesser's codes stands before a student's (a code
//! waits [`MAX_WAIT`] at most for its turn, past that it is refused
//! unchecked at once with a line), and once the guesser stops, the room's
//! codes are checked at once.

use std::collections::HashMap;
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

/// Wrong codes an address may send at once (a room's typos), and how
/// many more it may send each second after that: the rate codes are
/// checked at while an address sends wrong ones.
pub const BURST: f64 = 10.0;
pub const PER_SECOND: f64 = 10.0;
/// While an address has no check left, a code waits this long at most for
/// one (in turn); past that it is refused unchecked.
pub const MAX_WAIT: Duration = Duration::from_millis(500);
/// What the console counts: a wrong class code, and a code refused
/// unchecked (its address sent wrong ones faster than they are checked).
pub const WRONG: &str = "wrong class codes";
pub const UNCHECKED: &str = "class codes refused unchecked (wrong ones came too fast)";

/// The console's line when an address first sends wrong codes faster
/// than they are checked.
pub fn too_fast(ip: IpAddr) -> String {
    format!(
        "{ip} sends wrong class codes faster than {PER_SECOND} a second: \
         codes past that are refused unchecked while it does"
    )
}

/// What a student whose code was refused unchecked reads.
pub fn wait_line(ip: IpAddr) -> String {
    format!("too many wrong class codes from {ip}: try again in a moment")
}

/// Addresses remembered before the stale ones are dropped.
const PRUNE_AT: usize = 4096;

#[derive(Debug)]
struct Address {
    /// Checks left (refilled at [`PER_SECOND`], at most [`BURST`]).
    checks: f64,
    /// When `checks` was last refilled.
    at: Instant,
    /// The next free turn while the address has no check left.
    next: Instant,
    /// Whether the console was told this address ran out.
    told: bool,
}

impl Address {
    fn refill(&mut self, now: Instant) {
        let dt = now.saturating_duration_since(self.at).as_secs_f64();
        self.checks = (self.checks + dt * PER_SECOND).min(BURST);
        self.at = now;
        if self.checks >= BURST {
            self.told = false;
        }
    }

    fn stale(&self, now: Instant) -> bool {
        self.checks + now.saturating_duration_since(self.at).as_secs_f64() * PER_SECOND >= BURST
            && self.next <= now
    }
}

/// When a code may be checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    Now,
    /// The address has no check left: at this instant (within [`MAX_WAIT`]).
    At(Instant),
    /// The address has no check left for [`MAX_WAIT`]: not at all (the
    /// code is refused unchecked; `true` the first time, for the console).
    Refused(bool),
}

/// The wrong codes per address, shared by all connections: each check of
/// a code takes one of the address's checks, a right code gives it back.
/// So a room behind one address gets in however many codes a guesser there
/// sends (a right code waits [`MAX_WAIT`] at most, and none once the
/// guesser stops), and a guesser gets [`PER_SECOND`] tries a second.
#[derive(Debug, Default)]
pub struct WrongCodes(Mutex<HashMap<IpAddr, Address>>);

impl WrongCodes {
    fn with<T>(&self, ip: IpAddr, now: Instant, f: impl FnOnce(&mut Address) -> T) -> T {
        let mut m = self.0.lock().unwrap_or_else(|p| p.into_inner());
        if m.len() >= PRUNE_AT {
            m.retain(|_, a| !a.stale(now));
        }
        let a = m.entry(ip).or_insert_with(|| Address {
            checks: BURST,
            at: now,
            next: now,
            told: false,
        });
        a.refill(now);
        let out = f(a);
        if a.stale(now) {
            m.remove(&ip);
        }
        out
    }

    /// The turn of a code from `ip` that arrived at `now`: its check is
    /// taken (give it back with [`WrongCodes::right`]).
    pub fn turn(&self, ip: IpAddr, now: Instant) -> Turn {
        self.with(ip, now, |a| {
            if a.checks >= 1.0 && a.next <= now {
                a.checks -= 1.0;
                return Turn::Now;
            }
            // In turn, one per 1/PER_SECOND, while the wait is short.
            let pace = Duration::from_secs_f64(1.0 / PER_SECOND);
            let at = a.next.max(now + pace.mul_f64((1.0 - a.checks).max(0.0)));
            if at - now > MAX_WAIT {
                let first = !std::mem::replace(&mut a.told, true);
                return Turn::Refused(first);
            }
            a.next = at + pace;
            a.checks -= 1.0;
            Turn::At(at)
        })
    }

    /// The code checked was right: its check is given back.
    pub fn right(&self, ip: IpAddr, now: Instant) {
        self.with(ip, now, |a| a.checks = (a.checks + 1.0).min(BURST));
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
    fn a_guesser_gets_ten_checks_a_second_and_the_room_gets_in_once_it_stops() {
        let w = WrongCodes::default();
        let ip: IpAddr = "10.0.0.1".parse().unwrap();
        let other: IpAddr = "10.0.0.2".parse().unwrap();
        let t0 = Instant::now();
        // A burst of 200 wrong codes at once: ten checked now, five more
        // within the next half second in turn, the rest refused unchecked.
        let turns: Vec<Turn> = (0..200).map(|_| w.turn(ip, t0)).collect();
        let now = turns.iter().filter(|t| **t == Turn::Now).count();
        let later: Vec<Instant> = turns
            .iter()
            .filter_map(|t| match t {
                Turn::At(i) => Some(*i),
                _ => None,
            })
            .collect();
        assert_eq!(now, 10);
        assert_eq!(later.len(), 5);
        assert!(later
            .windows(2)
            .all(|p| p[1] - p[0] == Duration::from_millis(100)));
        assert!(*later.last().unwrap() - t0 <= MAX_WAIT);
        assert_eq!(turns[15], Turn::Refused(true));
        assert_eq!(turns[16], Turn::Refused(false));
        // Another address is not slowed.
        assert_eq!(w.turn(other, t0), Turn::Now);
        // Once the guesser stops, a student's right code is checked within
        // half a second (the turns taken), then at once; it costs no check.
        let t1 = t0 + Duration::from_millis(600);
        match w.turn(ip, t1) {
            Turn::Now => {}
            Turn::At(at) => assert!(at - t1 <= Duration::from_millis(200), "{:?}", at - t1),
            t => panic!("{t:?}"),
        }
        w.right(ip, t1);
        let t2 = t0 + Duration::from_secs(3);
        for _ in 0..30 {
            assert_eq!(w.turn(ip, t2), Turn::Now);
            w.right(ip, t2);
        }
    }

    #[test]
    fn a_few_wrong_codes_a_second_never_wait() {
        let w = WrongCodes::default();
        let ip: IpAddr = "10.0.0.1".parse().unwrap();
        let t0 = Instant::now();
        for i in 0..500 {
            assert_eq!(w.turn(ip, t0 + Duration::from_millis(150 * i)), Turn::Now);
        }
    }
}
