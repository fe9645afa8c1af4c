//! The pictures measured as a person looks at them: curves that are
//! straight on the paper's log axes are straight in the picture (drawn
//! with sub-pixel coordinates, not on whole pixels), texts do not overlap
//! or leave the picture, axes end at the data, every decade in range is
//! labelled.

mod common;

use common::svg::{off_straight, Picture};

/// fig1's Persson line is √(2/π)/ψ with ψ ∝ E/H0: a straight line on
/// log-log axes. Drawn on whole pixels it stepped by up to a pixel (a kink
/// near H0/E = 5e-4); drawn exactly it is straight to rounding.
#[test]
fn power_laws_are_straight_lines() {
    let p = Picture::export(&["--preset", "fig1", "--view", "slopes"]);
    let persson = p.curves("#00A000");
    assert_eq!(persson.len(), 1);
    let off = off_straight(&persson[0].points);
    assert!(off < 0.02, "Persson's line is {off} px off straight");
    // Coordinates with decimals: not rounded to whole pixels.
    assert!(persson[0].points.iter().any(|p| p.1.fract() != 0.0));
}
