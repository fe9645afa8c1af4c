//! Binary files, read natively: ISO 25178-72 x3p, Gwyddion's .gwy and the
//! instruments' own formats, each format a module of its own behind
//! [`sniff`](crate::formats::sniff) (magic bytes, the extension only where
//! a format has none), each reading to a [`Grid`] — heights in metres,
//! sizes from the file, undefined (non-measured, invalid, masked) points
//! NaN, units it does not give [`assumed`] — that the map pipeline fills
//! and computes as it does every surface ([`grid::compute`]).
//!
//! The layouts are the published ones and those Gwyddion's and
//! SurfaceTopography's readers go by (read for the facts, not translated);
//! every file was checked against SurfaceTopography 1.27.1's reading of
//! real instruments' files (`scripts/instruments_reference.py`). Every
//! count, size and offset is checked against the bytes there before it is
//! used ([`bin::Bytes`]), so a damaged or hostile file is one line and
//! allocates no more than its heights.

mod al3d;
pub(crate) mod assumed;
mod bin;
mod chan;
mod di;
mod frt;
pub(crate) mod grid;
pub(crate) mod gwy;
mod ibw;
mod metropro;
mod nid;
mod opd;
mod opdx;
mod plu;
mod sdf;
mod sur;
pub(crate) mod x3p;

use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::measured::Options;

/// The formats read natively.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Native {
    Sur,
    Plu,
    Di,
    Opd,
    MetroPro,
    Al3d,
    Nid,
    Ibw,
    Sdf,
    Opdx,
    Frt,
}

impl Native {
    /// The format for people, as messages and summaries name it.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Native::Sur => sur::NAME,
            Native::Plu => plu::NAME,
            Native::Di => di::NAME,
            Native::Opd => opd::NAME,
            Native::MetroPro => metropro::NAME,
            Native::Al3d => al3d::NAME,
            Native::Nid => nid::NAME,
            Native::Ibw => ibw::NAME,
            Native::Sdf => sdf::NAME,
            Native::Opdx => opdx::NAME,
            Native::Frt => frt::NAME,
        }
    }

    /// Whether the format holds several channels (`--channel`).
    pub(crate) fn has_channels(self) -> bool {
        !matches!(
            self,
            Native::Sur | Native::MetroPro | Native::Al3d | Native::Sdf
        )
    }
}

/// The native format of `bytes` (a file named with extension `ext`, lower
/// case), if any.
pub(crate) fn sniff(bytes: &[u8], ext: &str) -> Option<Native> {
    let starts = |m: &[u8]| bytes.starts_with(m);
    Some(if starts(sur::MAGIC) {
        Native::Sur
    } else if di::is_di(bytes) {
        Native::Di
    } else if bytes.get(2..).is_some_and(|b| b.starts_with(opd::MAGIC)) {
        Native::Opd
    } else if metropro::MAGICS.iter().any(|m| starts(m)) {
        Native::MetroPro
    } else if starts(al3d::MAGIC) {
        Native::Al3d
    } else if starts(nid::MAGIC) {
        Native::Nid
    } else if starts(sdf::ASCII) || starts(sdf::BINARY) {
        Native::Sdf
    } else if starts(opdx::MAGIC) {
        Native::Opdx
    } else if starts(frt::MAGIC) {
        Native::Frt
    } else if ibw::is_ibw(bytes) {
        Native::Ibw
    } else if matches!(ext, "plu" | "apx") {
        Native::Plu
    } else {
        return None;
    })
}

/// Reads `bytes` of format `n`: the channel `opts.channel` names, else the
/// first of heights.
pub(crate) fn read(n: Native, bytes: &[u8], opts: &Options) -> Result<Grid, Failure> {
    let choice = opts.channel.as_deref();
    if choice.is_some() && !n.has_channels() {
        return Err(chan::none(n.name()));
    }
    match n {
        Native::Sur => sur::read(bytes),
        Native::Plu => plu::read(bytes, choice),
        Native::Di => di::read(bytes, choice),
        Native::Opd => opd::read(bytes, choice),
        Native::MetroPro => metropro::read(bytes),
        Native::Al3d => al3d::read(bytes),
        Native::Nid => nid::read(bytes, choice),
        Native::Ibw => ibw::read(bytes, choice),
        Native::Sdf => sdf::read(bytes),
        Native::Opdx => opdx::read(bytes, choice),
        Native::Frt => frt::read(bytes, choice),
    }
}
