//! The views a scene can be shown on.

/// One of the explorer's charts, each exportable as CSV or SVG (a
/// snapshot records it as `view: Map`).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum View {
    /// Initial slopes of the contact areas against the swept parameter.
    #[default]
    Slopes,
    /// The plasticity indices against the swept parameter.
    Indices,
    /// The regime map: plastic share over two parameters.
    Map,
    /// Contact areas against the load at the current parameters.
    Load,
    /// A measured surface's spectrum with the fitted power law and q1.
    Spectrum,
    /// The scene's surface solved by the boundary-element contact beside
    /// the theory's areas (the explorer only; `export --view contact`).
    Contact,
}

impl View {
    /// Every view, in Tab order.
    pub const ALL: [View; 6] = [
        View::Slopes,
        View::Indices,
        View::Map,
        View::Load,
        View::Spectrum,
        View::Contact,
    ];

    /// The views of a power-law scene, in Tab order.
    const POWER_LAW: [View; 5] = [
        View::Slopes,
        View::Indices,
        View::Map,
        View::Load,
        View::Contact,
    ];

    /// The views a scene has, in Tab order: the spectrum only on a
    /// measured surface; the contact view last.
    pub fn cycle(measured: bool) -> &'static [View] {
        if measured {
            &View::ALL
        } else {
            &View::POWER_LAW
        }
    }

    /// Whether a scene (`measured` or not) has this view.
    pub fn exists(self, measured: bool) -> bool {
        View::cycle(measured).contains(&self)
    }

    /// The view's name on the command line (`--view NAME`).
    pub fn name(self) -> &'static str {
        match self {
            View::Slopes => "slopes",
            View::Indices => "indices",
            View::Map => "map",
            View::Load => "load",
            View::Spectrum => "spectrum",
            View::Contact => "contact",
        }
    }

    /// The view called `name` (as [`View::name`] gives it).
    pub fn parse(name: &str) -> Option<View> {
        View::ALL.into_iter().find(|v| v.name() == name)
    }

    /// The next view in Tab order of a scene (`measured` or not): after
    /// load comes the spectrum on a measured surface, then contact.
    pub fn next(self, measured: bool) -> View {
        let all = View::cycle(measured);
        let i = all.iter().position(|&v| v == self).unwrap_or(0);
        all[(i + 1) % all.len()]
    }

    /// The previous view in Tab order (Shift-Tab).
    pub fn prev(self, measured: bool) -> View {
        let all = View::cycle(measured);
        let i = all.iter().position(|&v| v == self).unwrap_or(0);
        all[(i + all.len() - 1) % all.len()]
    }
}
