//! What a terminal can show, as far as its environment says: the glyph set
//! from the locale and TERM, the colours from TERM (and, locally,
//! COLORTERM and NO_COLOR). The explorer alone reads its own environment;
//! `roughtui serve` reads what each client sent (its pty's TERM and the
//! LANG / LC_* it passes with `SendEnv`).
//!
//! | what the terminal says | glyphs |
//! |---|---|
//! | the locale (first set of LC_ALL, LC_CTYPE, LANG) is not UTF-8 (`C`, `POSIX`, `en_US.ISO-8859-1`) | ascii |
//! | locally, no locale set: the C locale, as POSIX, tmux and ncurses read it | ascii |
//! | TERM `dumb`, `vt52`, `vt100`, `vt220`, … (any `vt*`), `ansi*`, `pcansi*`, `cons25` | ascii: no UTF-8 decoding (DEC terminals; ANSI.SYS-style terminals read bytes as code page 437) |
//! | TERM `linux` (the Linux console) | half: its font has the block elements and box lines, not braille or most Greek |
//! | anything else (xterm*, screen*, tmux*, rxvt*, putty*, …) with a UTF-8 locale, or served without a locale | braille |
//!
//! Colours: none for TERM `dumb` and `vt*` (monochrome terminals; curves
//! are told apart by character) or under NO_COLOR; 24-bit when COLORTERM
//! is `truecolor` or `24bit` (locally) or TERM ends in `-direct`; 256 when
//! TERM contains `256col`; else the 16 basic colours.

use super::glyphs::Glyphs;
use super::theme::{Palette, Theme};

/// What the locale says about the terminal's character set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Locale {
    /// Names UTF-8 (`en_US.UTF-8`, `C.UTF-8`, `de_DE.utf8`).
    Utf8,
    /// Set, to something that is not UTF-8 (`C`, `POSIX`, `fr_FR.ISO-8859-1`).
    Other,
    /// Not set (or set empty).
    Unset,
}

impl Locale {
    /// The locale that decides the character set: the first of LC_ALL,
    /// LC_CTYPE and LANG that is set and not empty, as `setlocale` reads
    /// them.
    pub fn of(var: impl Fn(&str) -> Option<String>) -> Locale {
        let value = ["LC_ALL", "LC_CTYPE", "LANG"]
            .into_iter()
            .filter_map(&var)
            .find(|v| !v.is_empty());
        match value {
            None => Locale::Unset,
            Some(v) => {
                let v = v.to_ascii_lowercase();
                if v.contains("utf-8") || v.contains("utf8") {
                    Locale::Utf8
                } else {
                    Locale::Other
                }
            }
        }
    }
}

/// Terminals that decode no UTF-8: DEC's VT family, the dumb terminal,
/// and ANSI.SYS-style terminals that show bytes in code page 437.
fn ascii_term(term: &str) -> bool {
    term == "dumb"
        || term.starts_with("vt")
        || term.starts_with("ansi")
        || term.starts_with("pcansi")
        || term == "cons25"
}

/// Terminals without colour.
fn monochrome_term(term: &str) -> bool {
    term == "dumb" || term.starts_with("vt")
}

/// What a terminal shows, as its environment says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Caps {
    pub glyphs: Glyphs,
    pub palette: Palette,
    /// Whether to colour at all.
    pub color: bool,
}

/// The glyph set for `term` (lower case) in `locale`; `unset` where no
/// locale was given.
pub fn glyphs_for(locale: Locale, term: &str, unset: Glyphs) -> Glyphs {
    let term = term.to_ascii_lowercase();
    match locale {
        Locale::Other => Glyphs::Ascii,
        _ if ascii_term(&term) => Glyphs::Ascii,
        Locale::Unset if unset == Glyphs::Ascii => Glyphs::Ascii,
        _ if term == "linux" => Glyphs::Half,
        Locale::Unset => unset,
        Locale::Utf8 => Glyphs::Braille,
    }
}

/// The colours `term` promises (`colorterm`: the COLORTERM variable).
pub fn palette_for(term: &str, colorterm: Option<&str>) -> Palette {
    let term = term.to_ascii_lowercase();
    let colorterm = colorterm.unwrap_or("").to_ascii_lowercase();
    if colorterm == "truecolor" || colorterm == "24bit" || term.ends_with("-direct") {
        Palette::TrueColor
    } else if term.contains("256col") {
        Palette::Ansi256
    } else {
        Palette::Ansi16
    }
}

impl Caps {
    /// The explorer's own terminal, from the variables `var` gives: the
    /// locale, TERM, COLORTERM, NO_COLOR. No locale means the C locale,
    /// so ASCII.
    pub fn local(var: impl Fn(&str) -> Option<String>) -> Caps {
        let term = var("TERM").unwrap_or_default();
        let no_color = var("NO_COLOR").is_some_and(|v| !v.is_empty());
        Caps {
            glyphs: glyphs_for(Locale::of(&var), &term, Glyphs::Ascii),
            palette: palette_for(&term, var("COLORTERM").as_deref()),
            color: !no_color && !monochrome_term(&term.to_ascii_lowercase()),
        }
    }

    /// This process's terminal.
    pub fn from_env() -> Caps {
        Caps::local(|k| std::env::var(k).ok())
    }

    /// A served client's terminal: its pty's TERM and the locale it sent
    /// (`var` answers LC_ALL, LC_CTYPE and LANG as the client sent them).
    /// Without a locale it gets braille, the default: the first screen
    /// says how to switch (Windows' OpenSSH and PuTTY send none, and the
    /// server cannot tell Windows Terminal, which shows braille, from the
    /// old console, which does not).
    pub fn served(term: &str, var: impl Fn(&str) -> Option<String>) -> Caps {
        Caps {
            glyphs: glyphs_for(Locale::of(var), term, Glyphs::Braille),
            palette: palette_for(term, None),
            color: !monochrome_term(&term.to_ascii_lowercase()),
        }
    }

    pub fn theme(self) -> Theme {
        Theme::new(self.glyphs, self.palette, self.color)
    }

    /// Why the drawing is not braille, for the first status line; `None`
    /// for braille.
    pub fn reason(self, var: impl Fn(&str) -> Option<String>, term: &str) -> Option<String> {
        if self.glyphs == Glyphs::Braille {
            return None;
        }
        let locale = ["LC_ALL", "LC_CTYPE", "LANG"]
            .into_iter()
            .find_map(|k| var(k).filter(|v| !v.is_empty()).map(|v| (k, v)));
        let why = match (Locale::of(&var), locale) {
            (Locale::Other, Some((k, v))) => format!("{k}={v} is not UTF-8"),
            (Locale::Unset, _) if !ascii_term(term) && term != "linux" => {
                "no locale set (LANG)".to_string()
            }
            _ => format!("TERM={term}"),
        };
        Some(why)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(pairs: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |k| {
            pairs
                .iter()
                .find(|(n, _)| *n == k)
                .map(|(_, v)| v.to_string())
        }
    }

    #[test]
    fn the_locale_is_the_first_of_lc_all_lc_ctype_lang() {
        assert_eq!(Locale::of(env(&[])), Locale::Unset);
        assert_eq!(Locale::of(env(&[("LANG", "")])), Locale::Unset);
        assert_eq!(Locale::of(env(&[("LANG", "en_US.UTF-8")])), Locale::Utf8);
        assert_eq!(Locale::of(env(&[("LANG", "de_DE.utf8")])), Locale::Utf8);
        assert_eq!(Locale::of(env(&[("LANG", "C")])), Locale::Other);
        assert_eq!(
            Locale::of(env(&[("LC_ALL", "C"), ("LANG", "en_US.UTF-8")])),
            Locale::Other
        );
        assert_eq!(
            Locale::of(env(&[
                ("LC_ALL", ""),
                ("LC_CTYPE", "C.UTF-8"),
                ("LANG", "C")
            ])),
            Locale::Utf8
        );
        assert_eq!(
            Locale::of(env(&[("LANG", "fr_FR.ISO-8859-1")])),
            Locale::Other
        );
    }

    /// The choice table of the module's documentation, row by row.
    #[test]
    fn term_and_locale_choose_the_glyphs() {
        use Glyphs::*;
        use Locale::*;
        let rows: &[(Locale, &str, Glyphs, Glyphs)] = &[
            // locale, TERM, locally, served
            (Utf8, "xterm-256color", Braille, Braille),
            (Utf8, "screen", Braille, Braille),
            (Utf8, "tmux-256color", Braille, Braille),
            (Utf8, "xterm", Braille, Braille),
            (Utf8, "linux", Half, Half),
            (Utf8, "vt100", Ascii, Ascii),
            (Utf8, "vt220", Ascii, Ascii),
            (Utf8, "VT102", Ascii, Ascii),
            (Utf8, "dumb", Ascii, Ascii),
            (Utf8, "ansi", Ascii, Ascii),
            (Other, "xterm-256color", Ascii, Ascii),
            (Other, "linux", Ascii, Ascii),
            (Unset, "xterm-256color", Ascii, Braille),
            (Unset, "xterm", Ascii, Braille),
            (Unset, "linux", Ascii, Half),
            (Unset, "vt100", Ascii, Ascii),
            (Unset, "", Ascii, Braille),
        ];
        for &(locale, term, local, served) in rows {
            assert_eq!(glyphs_for(locale, term, Ascii), local, "{locale:?} {term}");
            assert_eq!(
                glyphs_for(locale, term, Braille),
                served,
                "{locale:?} {term}"
            );
        }
    }

    #[test]
    fn term_and_colorterm_choose_the_colours() {
        use Palette::*;
        assert_eq!(palette_for("xterm", None), Ansi16);
        assert_eq!(palette_for("linux", None), Ansi16);
        assert_eq!(palette_for("xterm-256color", None), Ansi256);
        assert_eq!(palette_for("screen-256color", None), Ansi256);
        assert_eq!(palette_for("xterm-direct", None), TrueColor);
        assert_eq!(palette_for("xterm-256color", Some("truecolor")), TrueColor);
        assert_eq!(palette_for("xterm", Some("24bit")), TrueColor);
        assert_eq!(palette_for("xterm", Some("yes")), Ansi16);

        let c = Caps::local(env(&[("LANG", "C.UTF-8"), ("TERM", "xterm-256color")]));
        assert_eq!(
            (c.glyphs, c.palette, c.color),
            (Glyphs::Braille, Ansi256, true)
        );
        let c = Caps::local(env(&[("LANG", "C.UTF-8"), ("TERM", "vt220")]));
        assert_eq!((c.glyphs, c.color), (Glyphs::Ascii, false));
        let c = Caps::local(env(&[
            ("LANG", "C.UTF-8"),
            ("TERM", "xterm"),
            ("NO_COLOR", "1"),
        ]));
        assert!(!c.color);
        let c = Caps::local(env(&[("LANG", "C.UTF-8"), ("NO_COLOR", "")]));
        assert!(c.color, "an empty NO_COLOR is not set (no-color.org)");
        let c = Caps::served("vt100", env(&[("LANG", "C")]));
        assert_eq!((c.glyphs, c.color), (Glyphs::Ascii, false));
        let c = Caps::served("xterm-256color", env(&[]));
        assert_eq!((c.glyphs, c.palette), (Glyphs::Braille, Ansi256));
    }

    #[test]
    fn the_reason_names_what_decided() {
        let var = env(&[("LANG", "C")]);
        let c = Caps::local(&var);
        assert_eq!(
            c.reason(&var, "xterm").as_deref(),
            Some("LANG=C is not UTF-8")
        );
        let var = env(&[]);
        let c = Caps::local(&var);
        assert_eq!(
            c.reason(&var, "xterm").as_deref(),
            Some("no locale set (LANG)")
        );
        let var = env(&[("LANG", "en_US.UTF-8")]);
        let c = Caps::served("vt100", &var);
        assert_eq!(c.reason(&var, "vt100").as_deref(), Some("TERM=vt100"));
        let c = Caps::served("xterm", &var);
        assert_eq!(c.reason(&var, "xterm"), None);
    }
}
