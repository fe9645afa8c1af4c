//! A client's terminal as the server learns it: the pty's TERM and size,
//! and the locale the client passes (OpenSSH's `SendEnv LANG LC_*`, the
//! default in Debian's, Fedora's and macOS's ssh_config; Windows' OpenSSH
//! and PuTTY send none). From them the session's glyphs and colours
//! ([`Caps::served`]), and the first screen's line on how to switch.

use std::time::Duration;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Clear, Widget};

use crate::tui::caps::Caps;
use crate::tui::glyphs::Glyphs;

/// The longest TERM or locale value kept; a longer one is refused (env)
/// or cut (TERM).
pub const MAX_VALUE: usize = 64;

/// How long the first screen's line on switching the drawing stays
/// (unless a key comes first).
pub const HINT_FOR: Duration = Duration::from_secs(8);

/// What the client said about its terminal before the shell.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ClientTerm {
    /// The pty's TERM (lower case, at most [`MAX_VALUE`] characters).
    pub term: String,
    /// LANG and LC_* as the client sent them, the last of each name kept.
    pub locale: Vec<(String, String)>,
}

/// Whether `name` is one of the variables a client may send: LANG or
/// LC_* (LC_ALL, LC_CTYPE, …). Everything else is refused.
pub fn is_locale_name(name: &str) -> bool {
    name == "LANG"
        || name.strip_prefix("LC_").is_some_and(|r| {
            !r.is_empty() && r.bytes().all(|b| b.is_ascii_uppercase() || b == b'_')
        })
}

/// Whether a locale value is one to keep: short printable ASCII
/// (`en_US.UTF-8`, `C`, `de_DE@euro`).
fn is_locale_value(value: &str) -> bool {
    value.len() <= MAX_VALUE && value.bytes().all(|b| b.is_ascii_graphic())
}

impl ClientTerm {
    /// The pty's TERM.
    pub fn set_term(&mut self, term: &str) {
        self.term = term
            .chars()
            .filter(char::is_ascii_graphic)
            .take(MAX_VALUE)
            .collect::<String>()
            .to_ascii_lowercase();
    }

    /// An env request: kept if it names a locale variable with a sane
    /// value; whether it was accepted.
    pub fn env(&mut self, name: &str, value: &str) -> bool {
        if !is_locale_name(name) || !is_locale_value(value) {
            return false;
        }
        self.locale.retain(|(n, _)| n != name);
        self.locale.push((name.to_string(), value.to_string()));
        true
    }

    fn var(&self, name: &str) -> Option<String> {
        self.locale
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.clone())
    }

    /// The session's glyphs and colours (`forced`: `--marker`), and why
    /// they are not braille when the client's terminal decided it.
    pub fn caps(&self, forced: Option<Glyphs>) -> (Caps, Option<String>) {
        let var = |k: &str| self.var(k);
        let mut caps = Caps::served(&self.term, var);
        let why = match forced {
            Some(g) => {
                caps.glyphs = g;
                None
            }
            None => caps.reason(var, &self.term),
        };
        (caps, why)
    }
}

/// The first screen's line: how to switch if the chart shows boxes, or why
/// it is drawn as it is.
pub fn hint(glyphs: Glyphs, why: Option<&str>) -> String {
    match why {
        Some(why) => format!(
            "{} drawing ({why}): M switches, Ctrl-L redraws",
            glyphs.describe()
        ),
        None => "chart shows boxes, ? or odd signs: press M to switch the drawing; Ctrl-L redraws"
            .into(),
    }
}

/// Draws `text` over the status row (the screen's second row from the
/// bottom), as the glyphs write it; a text of several lines ends there,
/// its first lines above it.
pub fn draw_hint(buf: &mut Buffer, text: &str, glyphs: Glyphs) {
    let area = buf.area;
    let lines: Vec<&str> = text.lines().collect();
    if usize::from(area.height) < lines.len() + 1 {
        return;
    }
    let style = Style::new().add_modifier(Modifier::REVERSED | Modifier::BOLD);
    for (i, l) in lines.iter().rev().enumerate() {
        let row = Rect::new(area.x, area.bottom() - 2 - i as u16, area.width, 1);
        Clear.render(row, buf);
        Line::styled(glyphs.text(l).into_owned(), style).render(row, buf);
    }
}

/// The first screen's line with the student's name in the class
/// (`ada-2` when another `ada` came first).
pub fn name_line(name: &str) -> String {
    format!("you are {name} in this class")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::theme::Palette;

    #[test]
    fn only_lang_and_lc_variables_are_taken() {
        let mut t = ClientTerm::default();
        for ok in ["LANG", "LC_ALL", "LC_CTYPE", "LC_MESSAGES", "LC_TIME"] {
            assert!(t.env(ok, "C.UTF-8"), "{ok}");
        }
        for refused in [
            "PATH",
            "LD_PRELOAD",
            "TERM",
            "LC_",
            "lc_all",
            "LANGUAGE",
            "LC_ALL2",
        ] {
            assert!(!t.env(refused, "C.UTF-8"), "{refused}");
        }
        assert!(!t.env("LANG", "en_US.UTF-8\n"));
        assert!(!t.env("LANG", &"x".repeat(65)));
        assert!(!t.env("LANG", "a b"));
        assert_eq!(t.locale.len(), 5);
        assert!(t.env("LANG", "C"));
        assert_eq!(t.var("LANG").as_deref(), Some("C"));
        assert_eq!(t.locale.len(), 5);
    }

    #[test]
    fn the_client_terminal_decides_the_drawing() {
        let mut t = ClientTerm::default();
        t.set_term("xterm-256color");
        let (c, why) = t.caps(None);
        assert_eq!(
            (c.glyphs, c.palette, c.color),
            (Glyphs::Braille, Palette::Ansi256, true)
        );
        assert_eq!(why, None);
        t.env("LANG", "C");
        let (c, why) = t.caps(None);
        assert_eq!(c.glyphs, Glyphs::Ascii);
        assert_eq!(why.as_deref(), Some("LANG=C is not UTF-8"));
        // LC_ALL outranks LANG.
        t.env("LC_ALL", "en_US.UTF-8");
        assert_eq!(t.caps(None).0.glyphs, Glyphs::Braille);
        let mut t = ClientTerm::default();
        t.set_term("VT100");
        assert_eq!(t.term, "vt100");
        let (c, why) = t.caps(None);
        assert_eq!((c.glyphs, c.color), (Glyphs::Ascii, false));
        assert_eq!(why.as_deref(), Some("TERM=vt100"));
        assert_eq!(t.caps(Some(Glyphs::Block)).0.glyphs, Glyphs::Block);
        t.set_term("linux");
        assert_eq!(t.caps(None).0.glyphs, Glyphs::Half);
        t.set_term("xterm\x1b[2J\u{3b6}");
        assert_eq!(t.term, "xterm[2j");
    }

    #[test]
    fn the_hint_fits_80_columns_and_names_m() {
        for (g, why) in [
            (Glyphs::Braille, None),
            (Glyphs::Ascii, Some("LC_CTYPE=de_DE@euro is not UTF-8")),
            (Glyphs::Half, Some("TERM=linux")),
        ] {
            let h = hint(g, why);
            assert!(h.chars().count() <= 80, "{h}");
            assert!(h.contains("M "), "{h}");
        }
    }
}
