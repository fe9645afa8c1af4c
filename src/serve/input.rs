//! Bytes from an SSH client's terminal → key events for the explorer's key
//! table. crossterm decodes only its own stdin, so a session decodes what
//! the channel brings: printable UTF-8, Enter, Tab, Backspace (0x7f, 0x08),
//! Ctrl-letters, Esc, and the CSI / SS3 sequences of arrows, Home/End,
//! Shift-arrows (`CSI 1;2 C`) and Shift-Tab (`CSI Z`); and the terminal's
//! answer to "how large is the text area" (`CSI 18 t`, asked on Ctrl-L),
//! `CSI 8 ; rows ; cols t`, as a resize. A sequence split across reads is
//! kept until its end arrives; an Esc alone is Esc once the read that
//! carried it ends (a human cannot type the rest of a sequence within one
//! read).

use crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use super::limits::clamp_size;

/// What Ctrl-L sends the client: "report the text area's size in
/// characters" (xterm's `CSI 18 t`, answered `CSI 8 ; rows ; cols t` by
/// xterm, VTE, Windows Terminal and console, PuTTY, tmux …).
pub const ASK_SIZE: &[u8] = b"\x1b[18t";

/// The most bytes a session takes from one read; the rest of a larger read
/// is dropped, so a pasted megabyte costs nothing.
pub const MAX_READ: usize = 4096;

/// A pending escape sequence longer than this is garbage and is dropped.
const MAX_PENDING: usize = 16;

/// Reads after a size question ([`Decoder::expect_size`]) during which an
/// Esc that ends a read is held for the next one (the answer may be split
/// right after its Esc).
const AWAIT_READS: u8 = 3;

/// A decoder keeping what a read left unfinished.
#[derive(Debug, Default)]
pub struct Decoder {
    pending: Vec<u8>,
    /// Reads left in which a size report is awaited.
    awaiting: u8,
}

fn plain(code: KeyCode) -> KeyEvent {
    KeyEvent::new(code, KeyModifiers::NONE)
}

/// What the start of `b` holds.
enum Step {
    Key(KeyEvent, usize),
    /// The terminal's size report: columns, rows.
    Size(u16, u16, usize),
    /// Bytes that make no key (unknown sequences, stray continuation bytes).
    Skip(usize),
    /// The start of a sequence whose end has not arrived.
    Incomplete,
}

impl Decoder {
    pub fn new() -> Decoder {
        Decoder::default()
    }

    /// The terminal was asked for its size ([`ASK_SIZE`]): for the next
    /// few reads an Esc ending a read may be the start of the answer.
    pub fn expect_size(&mut self) {
        self.awaiting = AWAIT_READS;
    }

    /// The keys (and size reports, as [`Event::Resize`]) in `bytes` (at
    /// most [`MAX_READ`] of them are looked at), after whatever the
    /// previous read left pending.
    pub fn feed(&mut self, bytes: &[u8]) -> Vec<Event> {
        let bytes = &bytes[..bytes.len().min(MAX_READ)];
        let awaiting = self.awaiting > 0;
        self.awaiting = self.awaiting.saturating_sub(1);
        let mut buf = std::mem::take(&mut self.pending);
        buf.extend_from_slice(bytes);
        let mut keys = Vec::new();
        let mut i = 0;
        while i < buf.len() {
            match step(&buf[i..]) {
                Step::Key(k, n) => {
                    keys.push(Event::Key(k));
                    i += n;
                }
                Step::Size(cols, rows, n) => {
                    keys.push(Event::Resize(cols, rows));
                    self.awaiting = 0;
                    i += n;
                }
                Step::Skip(n) => i += n,
                Step::Incomplete => {
                    let rest = &buf[i..];
                    if rest == [0x1b] && !awaiting {
                        // A lone Esc at the end of a read is the Esc key.
                        keys.push(Event::Key(plain(KeyCode::Esc)));
                    } else if rest.len() <= MAX_PENDING {
                        self.pending = rest.to_vec();
                    }
                    break;
                }
            }
        }
        keys
    }
}

fn step(b: &[u8]) -> Step {
    match b[0] {
        0x1b => escape(b),
        b'\r' | b'\n' => Step::Key(plain(KeyCode::Enter), 1),
        b'\t' => Step::Key(plain(KeyCode::Tab), 1),
        0x7f | 0x08 => Step::Key(plain(KeyCode::Backspace), 1),
        c @ 0x01..=0x1a => Step::Key(
            KeyEvent::new(KeyCode::Char((b'a' + c - 1) as char), KeyModifiers::CONTROL),
            1,
        ),
        0x00 | 0x1c..=0x1f => Step::Skip(1),
        _ => utf8(b),
    }
}

fn utf8(b: &[u8]) -> Step {
    let len = match b[0] {
        0x00..=0x7f => 1,
        0xc2..=0xdf => 2,
        0xe0..=0xef => 3,
        0xf0..=0xf4 => 4,
        _ => return Step::Skip(1),
    };
    if b.len() < len {
        // Only continuation bytes so far: wait for the rest.
        return if b[1..].iter().all(|x| x & 0xc0 == 0x80) {
            Step::Incomplete
        } else {
            Step::Skip(1)
        };
    }
    match std::str::from_utf8(&b[..len]) {
        Ok(s) => {
            let c = s.chars().next().unwrap_or('\u{fffd}');
            let mods = if c.is_uppercase() {
                KeyModifiers::SHIFT
            } else {
                KeyModifiers::NONE
            };
            Step::Key(KeyEvent::new(KeyCode::Char(c), mods), len)
        }
        Err(_) => Step::Skip(1),
    }
}

fn escape(b: &[u8]) -> Step {
    let Some(&kind) = b.get(1) else {
        return Step::Incomplete;
    };
    match kind {
        b'[' => csi(b),
        b'O' => match b.get(2) {
            None => Step::Incomplete,
            Some(&f) => match final_key(f) {
                Some(code) => Step::Key(plain(code), 3),
                None => Step::Skip(3),
            },
        },
        0x1b => Step::Key(plain(KeyCode::Esc), 1),
        // Alt-key: the key alone (the explorer binds no Alt keys).
        _ => Step::Key(plain(KeyCode::Esc), 1),
    }
}

/// `ESC [ params final`: parameters are digits and `;`.
fn csi(b: &[u8]) -> Step {
    let body = &b[2..];
    let Some(end) = body.iter().position(|x| (0x40..=0x7e).contains(x)) else {
        return if body.iter().all(|x| (0x20..=0x3f).contains(x)) {
            Step::Incomplete
        } else {
            Step::Skip(2)
        };
    };
    let len = 2 + end + 1;
    let params = &body[..end];
    let fin = body[end];
    let nums: Vec<u32> = std::str::from_utf8(params)
        .unwrap_or("")
        .split(';')
        .map(|p| p.parse().unwrap_or(0))
        .collect();
    let mods = match nums.get(1) {
        Some(&m) if m >= 2 => modifiers(m - 1),
        _ => KeyModifiers::NONE,
    };
    let code = match fin {
        b'Z' => return Step::Key(KeyEvent::new(KeyCode::BackTab, KeyModifiers::SHIFT), len),
        // The text area's size, rows then columns (xterm's window ops).
        b't' => {
            return match nums[..] {
                [8, rows, cols] => {
                    let (c, r) = clamp_size(cols, rows);
                    Step::Size(c, r, len)
                }
                _ => Step::Skip(len),
            }
        }
        b'~' => match nums.first() {
            Some(1 | 7) => Some(KeyCode::Home),
            Some(4 | 8) => Some(KeyCode::End),
            Some(3) => Some(KeyCode::Delete),
            _ => None,
        },
        f => final_key(f),
    };
    match code {
        Some(c) => Step::Key(KeyEvent::new(c, mods), len),
        None => Step::Skip(len),
    }
}

fn final_key(f: u8) -> Option<KeyCode> {
    Some(match f {
        b'A' => KeyCode::Up,
        b'B' => KeyCode::Down,
        b'C' => KeyCode::Right,
        b'D' => KeyCode::Left,
        b'H' => KeyCode::Home,
        b'F' => KeyCode::End,
        _ => return None,
    })
}

/// xterm's modifier parameter minus one: bit 0 Shift, 1 Alt, 2 Ctrl.
fn modifiers(bits: u32) -> KeyModifiers {
    let mut m = KeyModifiers::NONE;
    if bits & 1 != 0 {
        m |= KeyModifiers::SHIFT;
    }
    if bits & 2 != 0 {
        m |= KeyModifiers::ALT;
    }
    if bits & 4 != 0 {
        m |= KeyModifiers::CONTROL;
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys(events: Vec<Event>) -> Vec<KeyEvent> {
        events
            .into_iter()
            .filter_map(|e| match e {
                Event::Key(k) => Some(k),
                _ => None,
            })
            .collect()
    }

    fn codes(bytes: &[u8]) -> Vec<(KeyCode, KeyModifiers)> {
        keys(Decoder::new().feed(bytes))
            .into_iter()
            .map(|k| (k.code, k.modifiers))
            .collect()
    }

    const N: KeyModifiers = KeyModifiers::NONE;
    const S: KeyModifiers = KeyModifiers::SHIFT;

    #[test]
    fn arrows_csi_and_ss3() {
        use KeyCode::*;
        assert_eq!(
            codes(b"\x1b[A\x1b[B\x1b[C\x1b[D\x1bOA\x1bOB\x1bOC\x1bOD"),
            [Up, Down, Right, Left, Up, Down, Right, Left].map(|c| (c, N))
        );
    }

    #[test]
    fn shift_arrows_tab_backtab() {
        assert_eq!(
            codes(b"\x1b[1;2C\x1b[1;2D\t\x1b[Z\x1b[1;5A"),
            [
                (KeyCode::Right, S),
                (KeyCode::Left, S),
                (KeyCode::Tab, N),
                (KeyCode::BackTab, S),
                (KeyCode::Up, KeyModifiers::CONTROL),
            ]
        );
    }

    #[test]
    fn enter_backspace_ctrl_c_esc() {
        assert_eq!(
            codes(b"\r\x7f\x08\x03"),
            [
                (KeyCode::Enter, N),
                (KeyCode::Backspace, N),
                (KeyCode::Backspace, N),
                (KeyCode::Char('c'), KeyModifiers::CONTROL),
            ]
        );
        assert_eq!(codes(b"\x1b"), [(KeyCode::Esc, N)]);
        assert_eq!(codes(b"\x1b\x1b"), [(KeyCode::Esc, N), (KeyCode::Esc, N)]);
    }

    #[test]
    fn utf8_and_letters() {
        assert_eq!(
            codes("qHé€😀".as_bytes()),
            [
                (KeyCode::Char('q'), N),
                (KeyCode::Char('H'), S),
                (KeyCode::Char('é'), N),
                (KeyCode::Char('€'), N),
                (KeyCode::Char('😀'), N),
            ]
        );
        // Invalid bytes make no key and do not swallow what follows.
        assert_eq!(codes(b"\xff\xc0q"), [(KeyCode::Char('q'), N)]);
    }

    #[test]
    fn sequences_split_across_reads() {
        let mut d = Decoder::new();
        assert!(d.feed(b"\x1b[1;").is_empty());
        let k = keys(d.feed(b"2C"));
        assert_eq!(k.len(), 1);
        assert_eq!((k[0].code, k[0].modifiers), (KeyCode::Right, S));
        let euro = "€".as_bytes();
        assert!(d.feed(&euro[..1]).is_empty());
        assert!(d.feed(&euro[1..2]).is_empty());
        assert_eq!(keys(d.feed(&euro[2..]))[0].code, KeyCode::Char('€'));
        assert!(d.feed(b"\x1bO").is_empty());
        assert_eq!(keys(d.feed(b"D"))[0].code, KeyCode::Left);
    }

    #[test]
    fn unknown_and_oversized_input() {
        assert_eq!(codes(b"\x1b[99xq"), [(KeyCode::Char('q'), N)]);
        let big = vec![b'j'; 100_000];
        assert_eq!(Decoder::new().feed(&big).len(), MAX_READ);
        // An endless unfinished sequence is dropped, not kept growing.
        let mut d = Decoder::new();
        let mut junk = b"\x1b[".to_vec();
        junk.extend(std::iter::repeat_n(b'1', 40));
        assert!(d.feed(&junk).is_empty());
        assert_eq!(keys(d.feed(b"k"))[0].code, KeyCode::Char('k'));
    }

    #[test]
    fn size_reports_are_resizes_also_when_split() {
        assert_eq!(
            Decoder::new().feed(b"\x1b[8;30;100tq"),
            [
                Event::Resize(100, 30),
                Event::Key(KeyEvent::new(KeyCode::Char('q'), N))
            ]
        );
        // Split anywhere across reads, as a slow link delivers it.
        let report = b"\x1b[8;41;132t";
        for cut in 1..report.len() {
            let mut d = Decoder::new();
            d.expect_size();
            let mut got = d.feed(&report[..cut]);
            got.extend(d.feed(&report[cut..]));
            assert_eq!(got, [Event::Resize(132, 41)], "cut at {cut}");
        }
        // Clamped like a window change; other window reports are ignored.
        assert_eq!(
            Decoder::new().feed(b"\x1b[8;0;99999t"),
            [Event::Resize(500, 1)]
        );
        assert!(Decoder::new().feed(b"\x1b[4;600;800t\x1b[8;24t").is_empty());
        // While an answer is awaited a lone Esc waits for the next read,
        // and is the Esc key if nothing follows it.
        let mut d = Decoder::new();
        d.expect_size();
        assert!(d.feed(b"\x1b").is_empty());
        assert_eq!(codes_of(d.feed(b"j")), [KeyCode::Esc, KeyCode::Char('j')]);
        assert_eq!(codes_of(d.feed(b"k")), [KeyCode::Char('k')]);
        // Three reads on, an Esc is Esc at once again.
        assert_eq!(codes_of(d.feed(b"\x1b")), [KeyCode::Esc]);
    }

    fn codes_of(events: Vec<Event>) -> Vec<KeyCode> {
        keys(events).into_iter().map(|k| k.code).collect()
    }
}
