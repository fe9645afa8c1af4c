//! The characters the explorer draws with, one set per session: what the
//! charts are drawn in (braille dots, half blocks, blocks, ASCII), the
//! frames, axes and slider bars, and the names of the symbols in the text
//! (Ψ_P or Psi_P). Views ask the session's [`Glyphs`] (it travels in the
//! [`super::theme::Theme`]) and never hard-code a character that a
//! terminal might not show.
//!
//! - **braille** (the default): Unicode throughout, curves in braille dots
//!   (2 × 4 per cell).
//! - **half** and **block**: curves in half blocks (1 × 2 per cell) or whole
//!   blocks; frames in the light box-drawing lines. Besides ASCII they use
//!   only ▀ ▄ █ and ─ │ ┌ ┐ └ ┘ ├ ┤ ┬ ┴ ┼, which every console font has
//!   (code page 437, the Linux console's, Windows' Consolas and Lucida
//!   Console), and text is written in ASCII names (Psi_P, zeta, um).
//! - **ascii**: every character below 0x80: curves as `*`, `+`, `#`, `o`,
//!   frames of `-`, `|`, `+`.

use std::borrow::Cow;

use ratatui::symbols::{border, Marker};

use crate::cli::MarkerArg;
use crate::physical::ascii::to_ascii;

/// A set of characters to draw with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Glyphs {
    #[default]
    Braille,
    Half,
    Block,
    Ascii,
}

/// The axis lines of a chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    pub vertical: &'static str,
    pub horizontal: &'static str,
    pub corner: &'static str,
    /// A tick on the y axis (pointing left, at a label).
    pub y_tick: &'static str,
    /// A tick on the x axis (pointing down, at a label).
    pub x_tick: &'static str,
}

/// A slider's bar: `├───●────┤`, with arrows for a value off either end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SliderBar {
    pub left: char,
    pub line: char,
    pub knob: char,
    pub right: char,
    pub below: char,
    pub above: char,
}

/// A place on a chart's x axis where the regime changes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// The index in use crosses 1.
    PsiOne,
    /// The plastic share crosses 10 %.
    ShareLow,
    /// The plastic share crosses 90 %.
    ShareHigh,
}

impl Glyphs {
    pub const ALL: [Glyphs; 4] = [Glyphs::Braille, Glyphs::Half, Glyphs::Block, Glyphs::Ascii];

    /// The name on the command line (`--marker`) and in the status line.
    pub fn name(self) -> &'static str {
        match self {
            Glyphs::Braille => "braille",
            Glyphs::Half => "half",
            Glyphs::Block => "block",
            Glyphs::Ascii => "ascii",
        }
    }

    /// What the set draws with, for the status line.
    pub fn describe(self) -> &'static str {
        match self {
            Glyphs::Braille => "braille dots",
            Glyphs::Half => "half blocks",
            Glyphs::Block => "blocks",
            Glyphs::Ascii => "ASCII",
        }
    }

    /// The set `--marker NAME` names.
    pub fn from_name(name: &str) -> Option<Glyphs> {
        Glyphs::ALL.into_iter().find(|g| g.name() == name)
    }

    /// The next set (the `M` key): braille, half, block, ascii, braille …
    pub fn next(self) -> Glyphs {
        let i = Glyphs::ALL.iter().position(|g| *g == self).unwrap_or(0);
        Glyphs::ALL[(i + 1) % Glyphs::ALL.len()]
    }

    /// Whether text is written in ASCII names (all sets but braille).
    pub fn ascii_text(self) -> bool {
        self != Glyphs::Braille
    }

    /// Whether every character drawn is ASCII.
    pub fn ascii_only(self) -> bool {
        self == Glyphs::Ascii
    }

    /// `text` as this set writes it: unchanged in braille; else every
    /// character outside ASCII by its ASCII name ([`crate::physical::ascii::ascii_name`]).
    pub fn text(self, text: &str) -> Cow<'_, str> {
        if !self.ascii_text() || text.is_ascii() {
            return Cow::Borrowed(text);
        }
        Cow::Owned(to_ascii(text))
    }

    /// The one character that marks text cut short.
    pub fn cut(self) -> char {
        if self.ascii_text() {
            '~'
        } else {
            '…'
        }
    }

    /// The chart marker of the curves drawn in colour.
    pub fn marker(self) -> Marker {
        match self {
            Glyphs::Braille => Marker::Braille,
            Glyphs::Half => Marker::HalfBlock,
            Glyphs::Block => Marker::Block,
            Glyphs::Ascii => Marker::Custom('*'),
        }
    }

    /// Points per cell of the chart's grid, across and up (as ratatui's
    /// canvas counts them for [`Glyphs::marker`]).
    pub fn dots(self) -> (f64, f64) {
        match self {
            Glyphs::Braille => (2.0, 4.0),
            Glyphs::Half => (1.0, 2.0),
            Glyphs::Block | Glyphs::Ascii => (1.0, 1.0),
        }
    }

    /// A legend's sample of a line drawn with [`Glyphs::marker`].
    pub fn line_sample(self) -> &'static str {
        match self {
            Glyphs::Braille => "━━",
            Glyphs::Half => "▀▀",
            Glyphs::Block => "██",
            Glyphs::Ascii => "**",
        }
    }

    /// A chart's axis lines.
    pub fn frame(self) -> Frame {
        if self.ascii_only() {
            Frame {
                vertical: "|",
                horizontal: "-",
                corner: "+",
                y_tick: "+",
                x_tick: "+",
            }
        } else {
            Frame {
                vertical: "│",
                horizontal: "─",
                corner: "└",
                y_tick: "┤",
                x_tick: "┬",
            }
        }
    }

    /// The border of a panel (the help, a student's snapshot).
    pub fn border(self) -> border::Set<'static> {
        if self.ascii_only() {
            border::Set {
                top_left: "+",
                top_right: "+",
                bottom_left: "+",
                bottom_right: "+",
                vertical_left: "|",
                vertical_right: "|",
                horizontal_top: "-",
                horizontal_bottom: "-",
            }
        } else {
            border::PLAIN
        }
    }

    /// A vertical line drawn as a chart's curve (the marker's line).
    pub fn vertical_line(self) -> char {
        if self.ascii_only() {
            '|'
        } else {
            '│'
        }
    }

    /// In front of the selected slider.
    pub fn selected(self) -> &'static str {
        if self.ascii_text() {
            "> "
        } else {
            "▶ "
        }
    }

    /// Beside the swept parameter's slider.
    pub fn swept(self) -> char {
        if self.ascii_text() {
            '~'
        } else {
            '↔'
        }
    }

    pub fn slider_bar(self) -> SliderBar {
        match self {
            Glyphs::Braille => SliderBar {
                left: '├',
                line: '─',
                knob: '●',
                right: '┤',
                below: '◂',
                above: '▸',
            },
            Glyphs::Half | Glyphs::Block => SliderBar {
                left: '├',
                line: '─',
                knob: '█',
                right: '┤',
                below: '<',
                above: '>',
            },
            Glyphs::Ascii => SliderBar {
                left: '|',
                line: '-',
                knob: 'O',
                right: '|',
                below: '<',
                above: '>',
            },
        }
    }

    /// A regime mark on the x axis.
    pub fn mark(self, mark: Mark) -> &'static str {
        match (self.ascii_text(), mark) {
            (false, Mark::PsiOne) => "ψ",
            (false, Mark::ShareLow) => "◦",
            (false, Mark::ShareHigh) => "●",
            (true, Mark::PsiOne) => "^",
            (true, Mark::ShareLow) => "o",
            (true, Mark::ShareHigh) => "@",
        }
    }

    /// The regime map's cell: two points, upper in the foreground colour
    /// over lower in the background; in ASCII one point, a coloured space.
    pub fn map_cell(self) -> &'static str {
        if self.ascii_only() {
            " "
        } else {
            "▀"
        }
    }

    /// A cell of the map's colour legend.
    pub fn map_swatch(self) -> &'static str {
        if self.ascii_only() {
            " "
        } else {
            "█"
        }
    }

    /// The map's current point.
    pub fn map_point(self) -> &'static str {
        if self.ascii_text() {
            "X"
        } else {
            "◆"
        }
    }
}

/// `--marker`'s choice.
impl From<MarkerArg> for Glyphs {
    fn from(m: MarkerArg) -> Self {
        match m {
            MarkerArg::Braille => Glyphs::Braille,
            MarkerArg::Half => Glyphs::Half,
            MarkerArg::Block => Glyphs::Block,
            MarkerArg::Ascii => Glyphs::Ascii,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_cycle_and_parse() {
        let mut g = Glyphs::Braille;
        let mut seen = vec![];
        for _ in 0..4 {
            seen.push(g.name());
            g = g.next();
        }
        assert_eq!(seen, ["braille", "half", "block", "ascii"]);
        assert_eq!(g, Glyphs::Braille);
        assert_eq!(Glyphs::from_name("half"), Some(Glyphs::Half));
        assert_eq!(Glyphs::from_name("foo"), None);
    }

    #[test]
    fn text_is_ascii_in_every_set_but_braille() {
        let t = "Ψ_P reaches 1 at ζ = 3272 · h_rms 1 µm…10 µm, H0·dA/dp̄/A0, ½, —, 😀";
        assert_eq!(Glyphs::Braille.text(t), t);
        let a = "Psi_P reaches 1 at zeta = 3272 | h_rms 1 um...10 um, \
                 H0*dA/dpbar/A0, 1/2, -, ?";
        for g in [Glyphs::Half, Glyphs::Block, Glyphs::Ascii] {
            assert_eq!(g.text(t), a);
        }
        assert!(matches!(Glyphs::Ascii.text("plain"), Cow::Borrowed(_)));
        assert_eq!(Glyphs::Ascii.text("use mm, µm (um), nm"), "use mm, um, nm");
    }

    #[test]
    fn the_ascii_set_draws_only_ascii() {
        let g = Glyphs::Ascii;
        let f = g.frame();
        let b = g.border();
        let s = g.slider_bar();
        let mut all = vec![
            f.vertical,
            f.horizontal,
            f.corner,
            f.y_tick,
            f.x_tick,
            b.top_left,
            b.horizontal_top,
            b.vertical_left,
            g.selected(),
            g.line_sample(),
            g.map_cell(),
            g.map_swatch(),
            g.map_point(),
        ]
        .concat();
        all.extend([g.cut(), g.swept(), g.vertical_line()]);
        all.extend([s.left, s.line, s.knob, s.right, s.below, s.above]);
        for m in [Mark::PsiOne, Mark::ShareLow, Mark::ShareHigh] {
            all.push_str(g.mark(m));
        }
        assert!(all.is_ascii(), "{all}");
        assert!(matches!(g.marker(), Marker::Custom(c) if c.is_ascii()));
    }

    #[test]
    fn half_and_block_use_only_console_font_characters() {
        // ASCII, the block elements and the light box-drawing lines.
        let ok = |c: char| c.is_ascii() || "▀▄█─│┌┐└┘├┤┬┴┼".contains(c);
        for g in [Glyphs::Half, Glyphs::Block] {
            let f = g.frame();
            let s = g.slider_bar();
            let mut all = [
                f.vertical,
                f.horizontal,
                f.corner,
                f.y_tick,
                f.x_tick,
                g.selected(),
                g.line_sample(),
                g.map_cell(),
                g.map_swatch(),
                g.map_point(),
            ]
            .concat();
            all.extend([g.cut(), g.swept(), g.vertical_line()]);
            all.extend([s.left, s.line, s.knob, s.right, s.below, s.above]);
            for m in [Mark::PsiOne, Mark::ShareLow, Mark::ShareHigh] {
                all.push_str(g.mark(m));
            }
            assert!(all.chars().all(ok), "{g:?}: {all}");
        }
    }
}
