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
mod bcr;
pub(crate) mod bin;
mod chan;
mod datx;
mod di;
mod frt;
pub(crate) mod grid;
pub(crate) mod gwy;
mod gwyo;
pub(crate) mod gwyser;
mod h5;
mod h5jpk;
mod ibw;
mod jpk;
mod keyence;
mod metropro;
mod nid;
mod opd;
mod opdx;
mod park;
pub(crate) mod plu;
mod plux;
mod sdf;
mod sur;
mod surz;
mod sxm;
pub(crate) mod tiffs;
mod wsxm;
pub(crate) mod x3p;
mod xqd;
mod zipped;
mod zon;

use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::measured::Options;

/// A format read natively: what it is called, whether it holds channels,
/// how its bytes are told and how they are read. A new format is a module
/// of its own and a row of [`NATIVE`].
pub(crate) struct Native {
    /// The format for people, as messages and summaries name it.
    pub(crate) name: &'static str,
    /// Whether the format holds several channels (`--channel`).
    channels: bool,
    /// Whether `bytes`, of a file named with extension `ext` (lower case),
    /// are in this format: magic bytes, the extension only where the
    /// format has none.
    is: fn(bytes: &[u8], ext: &str) -> bool,
    /// Reads the channel named (a format of channels), else the first of
    /// heights.
    read: fn(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure>,
}

impl PartialEq for Native {
    fn eq(&self, other: &Native) -> bool {
        self.name == other.name
    }
}

impl std::fmt::Debug for Native {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

/// The formats read natively, in the order they are told apart (the
/// first whose bytes match is taken: the extension alone last).
static NATIVE: &[Native] = &[
    Native {
        name: sur::NAME,
        channels: false,
        is: |b, _| b.starts_with(sur::MAGIC),
        read: |b, _| sur::read(b),
    },
    Native {
        name: di::NAME,
        channels: true,
        is: |b, _| di::is_di(b),
        read: di::read,
    },
    Native {
        name: opd::NAME,
        channels: true,
        is: |b, _| b.get(2..).is_some_and(|b| b.starts_with(opd::MAGIC)),
        read: opd::read,
    },
    Native {
        name: metropro::NAME,
        channels: false,
        is: |b, _| metropro::MAGICS.iter().any(|m| b.starts_with(m)),
        read: |b, _| metropro::read(b),
    },
    Native {
        name: al3d::NAME,
        channels: false,
        is: |b, _| b.starts_with(al3d::MAGIC),
        read: |b, _| al3d::read(b),
    },
    Native {
        name: nid::NAME,
        channels: true,
        is: |b, _| b.starts_with(nid::MAGIC),
        read: nid::read,
    },
    Native {
        name: sdf::NAME,
        channels: false,
        is: |b, _| b.starts_with(sdf::ASCII) || b.starts_with(sdf::BINARY),
        read: |b, _| sdf::read(b),
    },
    Native {
        name: opdx::NAME,
        channels: true,
        is: |b, _| b.starts_with(opdx::MAGIC),
        read: opdx::read,
    },
    Native {
        name: frt::NAME,
        channels: true,
        is: |b, _| b.starts_with(frt::MAGIC),
        read: frt::read,
    },
    Native {
        name: ibw::NAME,
        channels: true,
        is: |b, _| ibw::is_ibw(b),
        read: ibw::read,
    },
    Native {
        name: keyence::NAME,
        channels: true,
        is: |b, _| keyence::is_vk(b),
        read: keyence::read,
    },
    Native {
        name: zon::NAME,
        channels: false,
        is: |b, _| zon::MAGICS.iter().any(|m| b.starts_with(m)),
        read: |b, _| zon::read(b),
    },
    Native {
        name: plux::NAME,
        channels: true,
        is: |b, ext| b.starts_with(x3p::MAGIC) && (ext == "plux" || plux::is_plux(b)),
        read: plux::read,
    },
    Native {
        name: park::NAME,
        channels: false,
        is: |b, _| park::is_park(b),
        read: |b, _| park::read(b),
    },
    Native {
        name: jpk::NAME,
        channels: true,
        is: |b, _| jpk::is_jpk(b),
        read: jpk::read,
    },
    Native {
        name: h5jpk::NAME,
        channels: true,
        is: |b, ext| b.starts_with(h5::MAGIC) && (ext == "h5-jpk" || h5jpk::is_h5jpk(b)),
        read: h5jpk::read,
    },
    Native {
        name: datx::NAME,
        channels: false,
        is: |b, ext| b.starts_with(h5::MAGIC) && (ext == "datx" || datx::is_datx(b)),
        read: |b, _| datx::read(b),
    },
    Native {
        name: surz::NAME,
        channels: false,
        is: |b, _| b.starts_with(surz::MAGIC),
        read: |b, _| surz::read(b),
    },
    Native {
        name: wsxm::NAME,
        channels: false,
        is: |b, _| b.starts_with(wsxm::MAGIC),
        read: |b, _| wsxm::read(b),
    },
    Native {
        name: bcr::NAME,
        channels: false,
        is: |b, _| bcr::is_bcr(b),
        read: |b, _| bcr::read(b),
    },
    Native {
        name: sxm::NAME,
        channels: true,
        is: |b, _| b.starts_with(sxm::MAGIC),
        read: sxm::read,
    },
    Native {
        name: gwyo::NAME,
        channels: true,
        is: |b, _| b.starts_with(gwyo::MAGIC),
        read: gwyo::read,
    },
    Native {
        name: xqd::NAME,
        channels: false,
        is: |b, ext| xqd::is_xqd(b) && matches!(ext, "xqp" | "xqpx" | "xqi" | "xqix"),
        read: |_, _| xqd::not_heights(),
    },
    Native {
        name: xqd::NAME,
        channels: false,
        is: |b, _| xqd::is_xqd(b),
        read: |b, _| xqd::read(b),
    },
    Native {
        name: plu::NAME,
        channels: true,
        is: |b, ext| matches!(ext, "plu" | "apx") && plu::looks_like(b).is_some(),
        read: plu::read,
    },
];

/// The native format of the zip `bytes` that is not an x3p (a Sensofar
/// .plux), if it is one.
pub(crate) fn sniff_zip(bytes: &[u8], ext: &str) -> Option<&'static Native> {
    NATIVE
        .iter()
        .find(|n| n.name == plux::NAME && (n.is)(bytes, ext))
}

/// The line for a TIFF file whose directories cannot be read, if they
/// cannot.
pub(crate) fn damaged_tiff(bytes: &[u8]) -> Option<String> {
    tiffs::Tiff::read(bytes, "TIFF")
        .err()
        .map(|(_, p)| p.to_string())
}

/// The native format of `bytes` (a file named with extension `ext`, lower
/// case), if any.
pub(crate) fn sniff(bytes: &[u8], ext: &str) -> Option<&'static Native> {
    NATIVE.iter().find(|n| (n.is)(bytes, ext))
}

/// Reads `bytes` of format `n`: the channel `opts.channel` names, else the
/// first of heights.
pub(crate) fn read(n: &Native, bytes: &[u8], opts: &Options) -> Result<Grid, Failure> {
    let choice = opts.channel.as_deref();
    if choice.is_some() && !n.channels {
        return Err(chan::none(n.name));
    }
    (n.read)(bytes, choice)
}
