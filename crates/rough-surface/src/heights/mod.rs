//! The heights' preparation, before any spectrum: the form removed
//! (mean, plane, quadratic), undefined points filled within what the read
//! allows, the window and the passes that do it all over a large map.

pub(crate) mod allow;
pub(crate) mod detrend;
pub(crate) mod fill;
pub(crate) mod prepare;
