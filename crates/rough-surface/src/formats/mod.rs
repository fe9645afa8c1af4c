//! The formats and their readers. A file's bytes are told apart by
//! [`sniff`] (magic bytes, the extension only where a format has none),
//! unpacked first where gzip-compressed ([`gz`]); then
//!
//! - a binary format is read by its reader in [`readers`] — x3p, Gwyddion's
//!   .gwy and the instruments' own formats, one module a format — to a
//!   [`readers::grid::Grid`] of heights in metres;
//! - text by [`text`]: a height matrix, two columns (a line scan or a PSD
//!   table) or a contact.engineering download; a large matrix is streamed
//!   ([`stream`]);
//! - a contact.engineering container ([`container`]) by reading the file it
//!   holds as any other.
//!
//! What is not read gets a line saying how to convert it ([`hints`]).
//!
//! A new binary format is a module of its own in `readers/`, reading its
//! bytes to a `Grid`, and a row of `readers::NATIVE` (its name, whether it
//! holds channels, how its bytes are told, its reader); the line
//! [`sniff`] gave for it while it was not read goes.

pub(crate) mod container;
pub(crate) mod gz;
pub(crate) mod hints;
pub(crate) mod readers;
pub(crate) mod sniff;
pub(crate) mod stream;
pub(crate) mod text;

use crate::error::{Failure, Problem};
use crate::formats::readers::grid::Grid;
use crate::measured::Options;

/// The grid of `bytes` in `format`: its reader's, or the line saying why
/// there is none.
pub(crate) fn grid_of(
    format: &sniff::Format,
    bytes: &[u8],
    opts: &Options,
) -> Result<Grid, Failure> {
    match format {
        sniff::Format::X3p => readers::x3p::read(bytes),
        sniff::Format::Gwy => readers::gwy::read(bytes, opts.channel.as_deref()),
        sniff::Format::Native(n) => readers::read(n, bytes, opts),
        sniff::Format::Other(s) => Err((None, Problem::Format(s.clone()))),
        sniff::Format::Text => Err((
            None,
            Problem::Format("text: not an x3p or .gwy file".to_string()),
        )),
    }
}
