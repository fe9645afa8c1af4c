//! The characters the class's panels draw that are not plain ASCII.

/// The characters the class panels draw that are not plain ASCII, in one
/// place, with their ASCII stand-ins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClassGlyphs {
    /// Between the parts of a line, with its spaces.
    pub sep: &'static str,
    /// In a terminal size, 80×24.
    pub times: &'static str,
    pub half: &'static str,
    /// The end of a cut name.
    pub cut: &'static str,
    /// A histogram bar's cells, one to eight eighths full.
    pub bars: [&'static str; 8],
    /// The true value's column on the histogram.
    pub truth: &'static str,
}

pub const UNICODE: ClassGlyphs = ClassGlyphs {
    sep: " · ",
    times: "×",
    half: "½",
    cut: "…",
    bars: ["▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"],
    truth: "┃",
};

pub const ASCII: ClassGlyphs = ClassGlyphs {
    sep: " - ",
    times: "x",
    half: "1/2",
    cut: "~",
    bars: ["_", "_", ".", ".", ":", ":", "#", "#"],
    truth: "|",
};
