//! Colours and markers, from one place. The plain theme (NO_COLOR) uses no
//! colour at all: the four curves differ by marker instead, and selection and
//! emphasis use reverse video and bold.

use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;

use rough_model::Regime;

/// How one curve is drawn and named in the legend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveStyle {
    pub name: &'static str,
    pub style: Style,
    pub marker: Marker,
    /// What the legend shows in front of the name.
    pub sample: &'static str,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    pub color: bool,
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
    pub selected: Style,
    pub title: Style,
    pub dim: Style,
    pub error: Style,
    pub ok: Style,
}

impl Theme {
    /// The paper's colours: elastic in the terminal's own foreground
    /// (white on dark, black on light), plastic blue, total red, Persson green.
    pub fn colored() -> Theme {
        let curve = |name, color: Color| CurveStyle {
            name,
            style: Style::new().fg(color),
            marker: Marker::Braille,
            sample: "━━",
        };
        Theme {
            color: true,
            elastic: curve("elastic", Color::Reset),
            plastic: curve("plastic", Color::Blue),
            total: curve("total", Color::Red),
            persson: curve("Persson elastic", Color::Green),
            marker_line: CurveStyle {
                name: "marker",
                style: Style::new().fg(Color::Yellow),
                marker: Marker::Custom('│'),
                sample: "│",
            },
            psi_gw: curve("Ψ_GW", Color::Magenta),
            psi_p: curve("Ψ_P", Color::Blue),
            psi_star: curve("Ψ*", Color::Red),
            psi_asy: curve("Ψ*asy eq.13", Color::Yellow),
            psi_one: CurveStyle {
                name: "Ψ = 1",
                style: Style::new().fg(Color::DarkGray),
                marker: Marker::Braille,
                sample: "··",
            },
            tangent: CurveStyle {
                name: "initial slope",
                style: Style::new().fg(Color::DarkGray),
                marker: Marker::Braille,
                sample: "··",
            },
            selected: Style::new()
                .add_modifier(Modifier::REVERSED)
                .add_modifier(Modifier::BOLD),
            title: Style::new().add_modifier(Modifier::BOLD),
            dim: Style::new().fg(Color::DarkGray),
            error: Style::new().fg(Color::Red).add_modifier(Modifier::BOLD),
            ok: Style::new().fg(Color::Green),
        }
    }

    /// No colour codes at all; curves told apart by their markers.
    pub fn plain() -> Theme {
        let curve = |name, marker: Marker, sample| CurveStyle {
            name,
            style: Style::new(),
            marker,
            sample,
        };
        Theme {
            color: false,
            elastic: curve("elastic", Marker::Custom('•'), "••"),
            plastic: curve("plastic", Marker::Custom('+'), "++"),
            total: curve("total", Marker::Braille, "⠒⠒"),
            persson: curve("Persson elastic", Marker::Custom('o'), "oo"),
            marker_line: curve("marker", Marker::Custom('│'), "│"),
            psi_gw: curve("Ψ_GW", Marker::Custom('x'), "xx"),
            psi_p: curve("Ψ_P", Marker::Custom('+'), "++"),
            psi_star: curve("Ψ*", Marker::Braille, "⠒⠒"),
            psi_asy: curve("Ψ*asy eq.13", Marker::Custom('o'), "oo"),
            psi_one: curve("Ψ = 1", Marker::Custom('·'), "··"),
            tangent: curve("initial slope", Marker::Custom('·'), "··"),
            selected: Style::new()
                .add_modifier(Modifier::REVERSED)
                .add_modifier(Modifier::BOLD),
            title: Style::new().add_modifier(Modifier::BOLD),
            dim: Style::new(),
            error: Style::new().add_modifier(Modifier::BOLD),
            ok: Style::new(),
        }
    }

    /// Plain when NO_COLOR is set to anything non-empty (no-color.org).
    pub fn from_env() -> Theme {
        match std::env::var_os("NO_COLOR") {
            Some(v) if !v.is_empty() => Theme::plain(),
            _ => Theme::colored(),
        }
    }

    pub fn regime(&self, r: Regime) -> Style {
        let base = Style::new().add_modifier(Modifier::BOLD);
        if !self.color {
            return base;
        }
        base.fg(match r {
            Regime::Elastic => Color::Green,
            Regime::ElastoPlastic => Color::Yellow,
            Regime::Plastic => Color::Red,
        })
    }
}
