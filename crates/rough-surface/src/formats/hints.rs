//! What to say about a file roughtui does not read: the way to one it does.

/// What to do with a point cloud.
pub(crate) const XYZ_HINT: &str = "a regular grid of heights is needed: open it in \
    Gwyddion as XYZ data, rasterize it (XYZ Data → Rasterize) and save it as .gwy or .x3p \
    (or File → Save As → ASCII data matrix)";

/// The line for a file of a format that Gwyddion reads and roughtui does
/// not.
pub(crate) fn hint(what: &str) -> String {
    format!(
        "looks like {what}: open it in Gwyddion and save it as .gwy or .x3p \
         (or File → Save As → ASCII data matrix, .txt)"
    )
}
