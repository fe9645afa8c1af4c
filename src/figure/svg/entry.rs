//! A legend's entry: its label, colour and sample — what the pictures'
//! legend draws and what a phone's page is handed instead.

use plotters::style::RGBColor;

/// How a legend entry's sample is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sample {
    Solid(u32),
    Dashed,
    /// A filled dot of this radius (a simulation's points).
    Dot(u32),
}

#[derive(Clone, Debug)]
pub(crate) struct Entry {
    pub label: String,
    pub colour: RGBColor,
    pub sample: Sample,
}
