//! A student's snapshot (`s`): there is no disk of theirs to save on, so
//! the session leaves the alternate screen and prints the snapshot's RON,
//! exactly as a save would write it, on the terminal's normal screen —
//! no border, long lines wrapped by the terminal itself (a copy joins them
//! again), the terminal's own scrollback to scroll it. `y` puts it on the
//! student's clipboard with OSC 52 (xterm, kitty, WezTerm, iTerm2, Windows
//! Terminal, foot, Alacritty; tmux with `set-clipboard on`; PuTTY and
//! GNOME Terminal ignore it); any other key goes back to the explorer.

use base64::Engine as _;
use crossterm::cursor::{Hide, Show};
use crossterm::event::{KeyCode, KeyEvent};
use crossterm::terminal::{EnterAlternateScreen, LeaveAlternateScreen};

/// The line after the snapshot.
pub const KEYS: &str = "-- y copies it to your clipboard (OSC 52) · any other key goes back --";

/// The panel open: the text shown.
pub struct Panel {
    ron: String,
}

/// What a key does to an open panel.
pub enum Key {
    /// Stays open; these bytes go to the terminal.
    Stay(Vec<u8>),
    /// Closes; these bytes go first, then the explorer is drawn whole.
    Close(Vec<u8>),
}

/// `ron` in ASCII where the terminal is: characters outside it as RON's
/// `\u{…}` escapes (they occur only inside strings), so the text still
/// reads back as the same snapshot.
fn ascii(ron: &str) -> String {
    let mut s = String::with_capacity(ron.len());
    for c in ron.chars() {
        if c.is_ascii() {
            s.push(c);
        } else {
            s.push_str(&format!("\\u{{{:x}}}", c as u32));
        }
    }
    s
}

impl Panel {
    /// Opens the panel on `ron`; the bytes that show it.
    pub fn open(ron: String, ascii_only: bool) -> (Panel, Vec<u8>) {
        let ron = if ascii_only { ascii(&ron) } else { ron };
        let mut out = Vec::new();
        let _ = crossterm::execute!(out, LeaveAlternateScreen, Show);
        let head = "-- your snapshot: save it as a .ron file; roughtui --load FILE opens it --";
        let keys = if ascii_only {
            KEYS.replace('·', "-")
        } else {
            KEYS.into()
        };
        let mut text = format!("\r\n{head}\r\n");
        for line in ron.lines() {
            text.push_str(line);
            text.push_str("\r\n");
        }
        text.push_str(&keys);
        text.push_str("\r\n");
        out.extend_from_slice(text.as_bytes());
        (Panel { ron }, out)
    }

    pub fn key(&self, key: KeyEvent) -> Key {
        if key.code == KeyCode::Char('y') {
            let b64 = base64::engine::general_purpose::STANDARD.encode(self.ron.as_bytes());
            let mut out = format!("\x1b]52;c;{b64}\x07").into_bytes();
            out.extend_from_slice(
                b"-- copied to your clipboard, where your terminal takes OSC 52 --\r\n",
            );
            return Key::Stay(out);
        }
        Key::Close(self.close())
    }

    /// The bytes that go back to the explorer's screen (then drawn whole).
    pub fn close(&self) -> Vec<u8> {
        let mut out = Vec::new();
        let _ = crossterm::execute!(out, EnterAlternateScreen, Hide);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_keeps_the_snapshot() {
        let s = crate::presets::load("fig2").unwrap();
        let a = ascii(&s.to_ron());
        assert!(a.is_ascii());
        assert!(a.contains("\\u{3b6}"), "ζ escaped");
        assert_eq!(crate::scene::State::from_ron(&a).unwrap(), s);
    }
}
