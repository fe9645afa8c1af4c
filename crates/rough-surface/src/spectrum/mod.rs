//! The spectrum and its fit: from prepared heights to the moment table and
//! the log-binned display spectrum (a map, a line, a map's profiles), the
//! real-space numbers beside them, the default fit band and the power-law
//! fit through it.

pub(crate) mod amplitude;
pub(crate) mod anisotropy;
pub(crate) mod band;
pub(crate) mod bins;
pub(crate) mod compute;
pub(crate) mod fit;
pub(crate) mod profiles;
pub(crate) mod realspace;
