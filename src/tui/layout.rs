//! The screen's regions, from ratatui's [`Layout`]. Both `update` (how many
//! points a curve needs: the graph's width in braille dots) and the views
//! (where to draw) read them from here, so neither imports the other.

use ratatui::layout::{Constraint, Layout, Rect};

/// The smallest terminal the explorer draws in; below it, a short message
/// (the class counts the students' terminals below it).
pub use crate::class::MIN_SIZE;

/// Rows the sliders, readout and chart keep when a lesson's caption takes
/// more rows than usual (at 80×24, a caption of up to 7 rows).
pub const MAIN_ROWS: u16 = 14;

/// Columns left of the graph for the y labels and the axis line.
pub const Y_LABEL_W: u16 = 5;

/// The screen's regions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Regions {
    pub header: Rect,
    /// The scene's caption and, on its last row, the claims checked live.
    pub caption: Rect,
    pub sliders: Rect,
    pub readout: Rect,
    /// The chart panel: title, legend, axes, labels and the graph.
    pub chart: Rect,
    /// The plot inside the chart panel: below the title and legend, right of
    /// the y labels and axis, above the x axis and its labels.
    pub graph: Rect,
    pub status: Rect,
    pub footer: Rect,
    /// Rows per slider (2 adds a position bar).
    pub slider_rows: u16,
}

impl Regions {
    /// The regions of `area`, or `None` if it is smaller than [`MIN_SIZE`].
    pub fn of(area: Rect) -> Option<Regions> {
        Regions::with_caption(area, 0)
    }

    /// The regions of `area` with `rows` for the caption where that is more
    /// than its usual 2 (3 from 30 rows), as long as the chart and the
    /// sliders keep [`MAIN_ROWS`].
    pub fn with_caption(area: Rect, rows: u16) -> Option<Regions> {
        let (w, h) = (area.width, area.height);
        if w < MIN_SIZE.0 || h < MIN_SIZE.1 {
            return None;
        }
        let left = (w * 2 / 5).clamp(34, 44);
        let usual = if h >= 30 { 3 } else { 2 };
        let caption_rows = rows.min(h.saturating_sub(3 + MAIN_ROWS)).max(usual);
        let [header, caption, main, status, footer] = Layout::vertical([
            Constraint::Length(1),
            Constraint::Length(caption_rows),
            Constraint::Fill(1),
            Constraint::Length(1),
            Constraint::Length(1),
        ])
        .areas(area);
        let [side, _, chart] = Layout::horizontal([
            Constraint::Length(left),
            Constraint::Length(1),
            Constraint::Fill(1),
        ])
        .areas(main);
        let slider_rows = if main.height >= 27 { 2 } else { 1 };
        let [sliders, readout] =
            Layout::vertical([Constraint::Length(1 + 5 * slider_rows), Constraint::Fill(1)])
                .areas(side);
        Some(Regions {
            header,
            caption,
            sliders,
            readout,
            chart,
            graph: graph_in(chart),
            status,
            footer,
            slider_rows,
        })
    }

    /// The slopes view's graph: a row less at the top, where the view says
    /// which reading of the elastic/plastic split its shares use.
    pub fn slopes_graph(&self) -> Rect {
        Rect {
            y: self.graph.y + 1,
            height: self.graph.height.saturating_sub(1),
            ..self.graph
        }
    }

    /// The graph of `view`'s chart.
    pub fn graph_of(&self, view: crate::scene::View) -> Rect {
        if view == crate::scene::View::Slopes {
            self.slopes_graph()
        } else {
            self.graph
        }
    }

    /// The regions of a terminal of `size` (columns, rows).
    pub fn of_size(size: (u16, u16)) -> Option<Regions> {
        Regions::of(Rect::new(0, 0, size.0, size.1))
    }

    /// The regions of an explorer's screen: its size, and the rows its
    /// caption asks for in a class or a lesson
    /// ([`crate::tui::caption::rows`]).
    pub fn of_app(app: &crate::tui::app::App) -> Option<Regions> {
        let (w, h) = app.size;
        Regions::with_caption(Rect::new(0, 0, w, h), crate::tui::caption::rows(app))
    }
}

/// The graph inside a chart panel.
pub fn graph_in(chart: Rect) -> Rect {
    let [_, column, _] = Layout::horizontal([
        Constraint::Length(Y_LABEL_W + 1),
        Constraint::Fill(1),
        Constraint::Length(2),
    ])
    .areas(chart);
    let [_, graph, _] = Layout::vertical([
        Constraint::Length(2),
        Constraint::Fill(1),
        Constraint::Length(2),
    ])
    .areas(column);
    graph
}
