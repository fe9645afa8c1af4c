//! Colours and characters, from one place. A theme is built from the
//! session's [`Glyphs`] (what it draws with), its [`Palette`] (the colours
//! the terminal promises) and whether colour is on. The plain theme
//! (NO_COLOR, or `c`) uses no colour at all: the four curves differ by
//! marker instead, and selection and emphasis use reverse video and bold.

use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;

use super::glyphs::Glyphs;

/// How one curve is drawn and named in the legend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveStyle {
    pub name: &'static str,
    pub style: Style,
    pub marker: Marker,
    /// What the legend shows in front of the name.
    pub sample: &'static str,
}

/// The colours a terminal promises. The curves and the text use the 16
/// basic colours in all of them; the regime map's scale is drawn in as
/// many as there are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Palette {
    /// The 16 ANSI colours (SGR 30–37, 90–97).
    Ansi16,
    /// xterm's 256 (SGR 38;5;N).
    Ansi256,
    /// 24-bit colour (SGR 38;2;R;G;B).
    #[default]
    TrueColor,
}

impl Palette {
    pub fn name(self) -> &'static str {
        match self {
            Palette::Ansi16 => "16 colours",
            Palette::Ansi256 => "256 colours",
            Palette::TrueColor => "24-bit colour",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    /// Whether anything is coloured (off under NO_COLOR, or after `c`).
    pub color: bool,
    /// The colours the terminal promises, used while `color` is on.
    pub palette: Palette,
    /// The characters the session draws with.
    pub glyphs: Glyphs,
    pub elastic: CurveStyle,
    pub plastic: CurveStyle,
    pub total: CurveStyle,
    pub persson: CurveStyle,
    /// The vertical line at the swept parameter's current value.
    pub marker_line: CurveStyle,
    /// The index view's curves and its line at Ψ = 1.
    pub psi_gw: CurveStyle,
    pub psi_p: CurveStyle,
    pub psi_star: CurveStyle,
    pub psi_asy: CurveStyle,
    pub psi_one: CurveStyle,
    /// The load view's initial-slope line from the origin.
    pub tangent: CurveStyle,
    /// Curves pinned with `g`.
    pub ghost: CurveStyle,
    pub selected: Style,
    pub title: Style,
    pub dim: Style,
    pub error: Style,
    pub ok: Style,
    /// The claims line: its own colour, not a curve's.
    pub claims: Style,
}

/// A curve's own character where curves are told apart by character: in
/// ASCII always, elsewhere without colour. `None`: the set's own marker.
fn own_char(glyphs: Glyphs, color: bool, braille_plain: char, ascii: char) -> Option<char> {
    match (glyphs, color) {
        (Glyphs::Ascii, _) => Some(ascii),
        (Glyphs::Braille, false) => Some(braille_plain),
        (_, false) => Some(ascii),
        _ => None,
    }
}

impl Theme {
    /// The theme of `glyphs` in `palette`, coloured or not.
    pub fn new(glyphs: Glyphs, palette: Palette, color: bool) -> Theme {
        let fg = |c: Color| {
            if color {
                Style::new().fg(c)
            } else {
                Style::new()
            }
        };
        // The main curves: the set's marker in colour; told apart by
        // character where there is no colour (braille keeps its dots for
        // the total) or in ASCII.
        let curve = |name, c: Color, plain: Option<(char, &'static str)>, ascii: char| {
            let own = match plain {
                Some((p, _)) => own_char(glyphs, color, p, ascii),
                None if glyphs == Glyphs::Ascii => Some(ascii),
                None => None,
            };
            let sample = match (own, plain) {
                (None, _) if glyphs == Glyphs::Braille && !color => "⠒⠒",
                (None, _) => glyphs.line_sample(),
                (Some(_), Some((_, s))) if glyphs == Glyphs::Braille => s,
                (Some(ch), _) => ascii_pair(ch),
            };
            CurveStyle {
                name,
                style: fg(c),
                marker: own.map_or(glyphs.marker(), Marker::Custom),
                sample,
            }
        };
        // A dotted reference line (Ψ = 1, the initial slope, the ghost).
        let dotted = |name, ascii: char, braille_sample: &'static str| {
            let marker = match (glyphs, color) {
                (Glyphs::Ascii, _) => Marker::Custom(ascii),
                (Glyphs::Braille, true) => Marker::Braille,
                (Glyphs::Braille, false) => Marker::Custom('·'),
                (_, true) => glyphs.marker(),
                (_, false) => Marker::Custom(ascii),
            };
            let sample = match glyphs {
                Glyphs::Braille if color => braille_sample,
                Glyphs::Braille => "··",
                _ => ascii_pair(ascii),
            };
            CurveStyle {
                name,
                style: fg(Color::DarkGray),
                marker,
                sample,
            }
        };
        let line = glyphs.vertical_line();
        let (psi_gw, psi_p, psi_star, psi_asy) = if glyphs.ascii_text() {
            // Longer names: eq. 13's curve is named in the help only.
            ("Psi_GW", "Psi_P", "Psi*", "Psi*asy")
        } else {
            ("Ψ_GW", "Ψ_P", "Ψ*", "Ψ*asy eq.13")
        };
        // Blue readable on black and on white: #5f5fff (xterm's index 63)
        // has a WCAG contrast of 4.6:1 on both (ANSI blue #0000ee: 2.3:1
        // on black); bright blue (#5c5cff in xterm's 16) 4.4:1 and 4.8:1.
        let blue = match palette {
            Palette::Ansi16 => Color::LightBlue,
            Palette::Ansi256 => Color::Indexed(63),
            Palette::TrueColor => Color::Rgb(95, 95, 255),
        };
        // The claims' teal, apart from Persson's green: #008282 4.5:1 on
        // black and 4.7:1 on white; xterm's index 30 (#008787) 4.8:1 and
        // 4.4:1; cyan where 16 colours are all.
        let teal = match palette {
            Palette::Ansi16 => Color::Cyan,
            Palette::Ansi256 => Color::Indexed(30),
            Palette::TrueColor => Color::Rgb(0, 130, 130),
        };
        Theme {
            color,
            palette,
            glyphs,
            claims: fg(teal),
            elastic: curve("elastic", Color::Reset, Some(('•', "••")), '*'),
            plastic: curve("plastic", blue, Some(('+', "++")), '+'),
            total: curve("total", Color::Red, None, '#'),
            persson: curve("Persson elastic", Color::Green, Some(('o', "oo")), 'o'),
            marker_line: CurveStyle {
                name: "marker",
                style: fg(Color::Yellow),
                marker: Marker::Custom(line),
                sample: if glyphs.ascii_only() { "|" } else { "│" },
            },
            psi_gw: curve(psi_gw, Color::Magenta, Some(('x', "xx")), 'x'),
            psi_p: curve(psi_p, blue, Some(('+', "++")), '+'),
            psi_star: curve(psi_star, Color::Red, None, '#'),
            psi_asy: curve(psi_asy, Color::Yellow, Some(('o', "oo")), 'o'),
            psi_one: CurveStyle {
                name: if glyphs.ascii_text() {
                    "Psi = 1"
                } else {
                    "Ψ = 1"
                },
                ..dotted("", '-', "··")
            },
            tangent: dotted("initial slope", '.', "··"),
            ghost: dotted("ghost", '.', "┄┄"),
            selected: Style::new()
                .add_modifier(Modifier::REVERSED)
                .add_modifier(Modifier::BOLD),
            title: Style::new().add_modifier(Modifier::BOLD),
            dim: fg(Color::DarkGray),
            error: if color {
                Style::new().fg(Color::Red).add_modifier(Modifier::BOLD)
            } else {
                Style::new().add_modifier(Modifier::BOLD)
            },
            ok: fg(Color::Green),
        }
    }

    /// The paper's colours in braille: elastic in the terminal's own
    /// foreground (white on dark, black on light), plastic blue, total red,
    /// Persson green.
    pub fn colored() -> Theme {
        Theme::new(Glyphs::Braille, Palette::TrueColor, true)
    }

    /// No colour codes at all; curves told apart by their markers.
    pub fn plain() -> Theme {
        Theme::new(Glyphs::Braille, Palette::TrueColor, false)
    }

    /// The same theme drawn with `glyphs`.
    pub fn with_glyphs(self, glyphs: Glyphs) -> Theme {
        Theme::new(glyphs, self.palette, self.color)
    }

    /// The same theme with colour on or off.
    pub fn with_color(self, color: bool) -> Theme {
        Theme::new(self.glyphs, self.palette, color)
    }

    /// The regime word: bold, no colour, because the chart's colours name
    /// curves (green Persson, red total, blue plastic) and must not mean a
    /// regime too.
    pub fn regime(&self) -> Style {
        Style::new().add_modifier(Modifier::BOLD)
    }
}

/// `c` twice, as a legend's sample.
fn ascii_pair(c: char) -> &'static str {
    match c {
        '*' => "**",
        '+' => "++",
        '#' => "##",
        'o' => "oo",
        'x' => "xx",
        '-' => "--",
        '.' => "..",
        '•' => "••",
        _ => "??",
    }
}

#[cfg(test)]
mod contrast_tests {
    use super::{Palette, Theme};
    use ratatui::style::Color;

    /// xterm's colour `n` of its 6×6×6 cube (16 … 231).
    fn xterm(n: u8) -> (u8, u8, u8) {
        const LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];
        let k = n - 16;
        (
            LEVELS[usize::from(k / 36)],
            LEVELS[usize::from(k / 6 % 6)],
            LEVELS[usize::from(k % 6)],
        )
    }

    /// WCAG 2 relative luminance and contrast ratio.
    fn luminance((r, g, b): (u8, u8, u8)) -> f64 {
        let lin = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.03928 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b)
    }

    fn contrast(a: (u8, u8, u8), b: (u8, u8, u8)) -> f64 {
        let (la, lb) = (luminance(a), luminance(b));
        (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
    }

    #[test]
    fn plastic_and_claims_read_on_dark_and_light() {
        let (black, white) = ((0, 0, 0), (255, 255, 255));
        for (palette, least) in [(Palette::TrueColor, 4.5), (Palette::Ansi256, 4.3)] {
            let t = Theme::new(super::Glyphs::Braille, palette, true);
            for (style, name) in [(t.plastic.style, "plastic"), (t.claims, "claims")] {
                let rgb = match style.fg {
                    Some(Color::Indexed(n)) => xterm(n),
                    Some(Color::Rgb(r, g, b)) => (r, g, b),
                    c => panic!("{name}: {c:?}"),
                };
                for bg in [black, white] {
                    let c = contrast(rgb, bg);
                    assert!(c >= least, "{name} {rgb:?} on {bg:?}: {c:.2}");
                }
            }
            assert_ne!(t.claims, t.persson.style);
        }
        // The old ANSI blue #0000ee on black: 2.3.
        assert!(contrast((0, 0, 238), (0, 0, 0)) < 2.5);
    }
}
