//! What a view leaves out while a poll's answer waits: the class decides
//! (`class::Classroom::withheld`), the terminal's views and the SVG
//! pictures (a phone's, the same code as `export --format svg`) obey.

/// What a view leaves out. The default leaves out nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Withheld {
    /// What gives or brackets a claim's answer beside the curves: the
    /// regime marks, the values at the marker, the map's colours and its
    /// Ψ = 1 contour, the load and contact views (both at the marker), and
    /// the legend's remarks on where a curve went ("= total here",
    /// "plastic < 1", "below the chart"): the legend only names curves.
    pub marks: bool,
    /// The slopes view's curves left out, in the order [`SLOPES`]: those
    /// whose drawing gives the answer (the plastic share's question: the
    /// plastic and total slopes; the total's minimum: all of them).
    pub slopes: [bool; 4],
    /// The indices view's curves left out, in the order [`INDICES`] (the
    /// index the question's hardness uses, and eq. 13 with Ψ*).
    pub indices: [bool; 4],
}

/// The slopes view's curves, as [`Withheld::slopes`] lists them.
pub const SLOPES: [&str; 4] = ["elastic", "plastic", "total", "Persson"];

/// The indices view's curves, as [`Withheld::indices`] lists them.
pub const INDICES: [&str; 4] = ["Ψ_GW", "Ψ_P", "Ψ*", "Ψ*asy"];

impl Withheld {
    /// Nothing left out.
    pub const NONE: Withheld = Withheld {
        marks: false,
        slopes: [false; 4],
        indices: [false; 4],
    };

    /// Whether anything is left out.
    pub fn any(&self) -> bool {
        *self != Withheld::NONE
    }

    /// What a picture says in place of a curve it leaves out.
    pub const CURVE_WAITS: &'static str = "after the reveal";
}
