//! A phone's picture: a view drawn by the very code of `export --format
//! svg`, at a phone's shape, without the lines under the chart (the page
//! writes the scene, the step, the caption and the question as text it
//! can wrap) and with the legend handed back as entries the page lists
//! under the picture (a box inside a phone's plot would cover the curves,
//! one beside it would leave the plot no room). The grid's white lines on
//! the white ground, which draw nothing, are left out of the document.

use std::cell::{Cell, RefCell};

use plotters::prelude::RGBColor;

use super::entry::{Entry, Sample};
use crate::figure::{FigureOptions, View};
use crate::scene::State;

thread_local! {
    /// The picture's size while a phone's picture is drawn.
    static SHAPE: Cell<Option<(u32, u32)>> = const { Cell::new(None) };
    /// The legend's entries of the phone's picture being drawn.
    static ENTRIES: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

/// A phone's picture: the SVG document and its legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    pub svg: String,
    pub legend: Vec<LegendEntry>,
}

/// One entry of a phone picture's legend: its label, its colour
/// (`#RRGGBB`) and whether its curve is dashed (or a dot, a simulation's
/// points).
#[derive(Clone, Debug, PartialEq)]
pub struct LegendEntry {
    pub label: String,
    pub colour: String,
    pub sample: &'static str,
}

/// The shapes a phone's picture is drawn at (SVG units; the page scales
/// it to its width): upright for a phone held upright, wide for one on
/// its side. Few shapes, so that followers share their pictures.
pub const UPRIGHT: (u32, u32) = (480, 420);
pub const WIDE: (u32, u32) = (720, 400);

/// The size a picture is drawn at: a phone's shape while one is drawn.
pub(super) fn size() -> Option<(u32, u32)> {
    SHAPE.with(Cell::get)
}

/// Keeps a legend's entry for the page (while a phone's picture is
/// drawn); whether it was kept (else the legend is drawn in the picture).
pub(super) fn keep(entries: &[Entry]) -> bool {
    if size().is_none() {
        return false;
    }
    ENTRIES.with(|e| e.borrow_mut().extend(entries.iter().cloned()));
    true
}

/// Forgets what an earlier drawing kept (a picture drawn again).
pub(super) fn start() {
    ENTRIES.with(|e| e.borrow_mut().clear());
}

/// Draws `draw` (an SVG document) as a phone's picture of `shape`.
fn drawn(
    shape: (u32, u32),
    draw: impl FnOnce() -> anyhow::Result<String>,
) -> anyhow::Result<Picture> {
    struct Reset;
    impl Drop for Reset {
        fn drop(&mut self) {
            SHAPE.with(|s| s.set(None));
            ENTRIES.with(|e| e.borrow_mut().clear());
        }
    }
    let _reset = Reset;
    SHAPE.with(|s| s.set(Some(shape)));
    start();
    let svg = draw()?;
    let legend = ENTRIES.with(|e| std::mem::take(&mut *e.borrow_mut()));
    Ok(Picture {
        svg: without_white_lines(&svg),
        legend: legend.iter().map(entry).collect(),
    })
}

/// `view` of `state` as a phone's picture of `shape` ([`UPRIGHT`],
/// [`WIDE`]): what [`super::render_svg`] draws, less what `opts.withheld`
/// keeps back while a poll's answer waits.
pub fn render_phone(
    view: View,
    state: &State,
    opts: &FigureOptions,
    shape: (u32, u32),
) -> anyhow::Result<Picture> {
    drawn(shape, || super::render_svg(view, state, opts))
}

/// A picture of `shape` drawn by `draw` (the contact view's, which
/// `crate::contact` draws) as a phone's: the same shape, the legend kept.
pub fn render_phone_with(
    shape: (u32, u32),
    draw: impl FnOnce() -> anyhow::Result<String>,
) -> anyhow::Result<Picture> {
    drawn(shape, draw)
}

/// A phone's picture with only `text` in it: what stands for a view that
/// has no picture now (the contact view before its solution, a view that
/// waits for a poll's reveal).
pub fn phone_note(title: &str, text: &str, shape: (u32, u32)) -> Picture {
    let (w, h) = shape;
    let mut svg = format!(
        "<svg width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
         xmlns=\"http://www.w3.org/2000/svg\">\n<rect x=\"0\" y=\"0\" width=\"{w}\" \
         height=\"{h}\" fill=\"#FFFFFF\"/>\n<text x=\"{}\" y=\"30\" text-anchor=\"middle\" \
         font-family=\"sans-serif\" font-size=\"16\">{}</text>\n",
        w / 2,
        super::xml_text(title)
    );
    let lines = super::wrap::wrap(text, (w / 9) as usize);
    let top = h / 2 - 11 * lines.len() as u32;
    for (i, l) in lines.iter().enumerate() {
        svg.push_str(&format!(
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-family=\"sans-serif\" \
             font-size=\"16\" fill=\"#666666\">{}</text>\n",
            w / 2,
            top + 22 * i as u32,
            super::xml_text(l)
        ));
    }
    svg.push_str("</svg>\n");
    Picture {
        svg,
        legend: Vec::new(),
    }
}

fn entry(e: &Entry) -> LegendEntry {
    let RGBColor(r, g, b) = e.colour;
    LegendEntry {
        label: e.label.clone(),
        colour: format!("#{r:02X}{g:02X}{b:02X}"),
        sample: match e.sample {
            Sample::Solid(_) => "solid",
            Sample::Dashed => "dashed",
            Sample::Dot(_) => "dot",
        },
    }
}

/// `svg` without the grid's white lines (on a white ground they draw
/// nothing; a third of a slopes picture's bytes).
fn without_white_lines(svg: &str) -> String {
    svg.lines()
        .filter(|l| !(l.starts_with("<line") && l.contains("stroke=\"#FFFFFF\"")))
        .collect::<Vec<_>>()
        .join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_phones_picture_has_its_shape_and_its_legend_apart() {
        let s = crate::presets::load("fig2").unwrap();
        let opts = FigureOptions::default();
        let p = render_phone(View::Slopes, &s, &opts, UPRIGHT).unwrap();
        assert!(
            p.svg.starts_with("<svg width=\"480\" height=\"420\""),
            "{}",
            &p.svg[..80]
        );
        let labels: Vec<&str> = p.legend.iter().map(|e| e.label.as_str()).collect();
        assert_eq!(
            labels[1..],
            ["elastic", "plastic", "total", "Persson elastic √(2/π)/Ψ_P"]
        );
        assert!(labels[0].ends_with("the marker"), "{labels:?}");
        assert_eq!(p.legend[2].colour, "#0000FF");
        assert_eq!(p.legend[4].sample, "dashed");
        // No legend box and no caption in the picture; no white lines.
        assert!(!p.svg.contains(">\nelastic\n<"), "the legend is drawn");
        assert!(!p.svg.contains("stroke=\"#FFFFFF\" stroke-width=\"1\" x1"));
        assert!(!p.svg.contains("H0/E = 0.01"), "a caption is drawn");
        // The export's picture is as before.
        let full = crate::figure::render_svg(View::Slopes, &s, &opts).unwrap();
        assert!(full.starts_with("<svg width=\"900\" height=\"600\""));
        assert!(full.contains(">\nelastic\n<"));
        let small = p.svg.len();
        assert!(small < full.len() * 2 / 3, "{small} of {}", full.len());
    }
}
