//! Digital Surf compressed `.sur` and `.pro` (magic `DSCOMPRESSED`, what
//! MountainsMap writes by default), read to the layout rosettasciio and
//! surfalize read: the 512-byte header of an uncompressed file
//! ([`super::sur`]), its comment and private zone, then a directory — a
//! 32-bit count of streams and, for each, its unpacked and packed sizes
//! (32 bits each) — and the streams, zlib-compressed, one after the other;
//! unpacked and joined they are the heights an uncompressed file holds.
//!
//! Every size is checked before anything is unpacked: the unpacked sizes
//! must add up to the header's points, the packed ones must lie in the
//! file, and no stream may claim more than zlib can make of its bytes, so
//! that a bomb is refused before a byte of it is unpacked and a stream is
//! never unpacked past the size it claims.

use std::io::Read;

use super::bin::Bytes;
use super::sur::{grid, header};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Digital Surf compressed .sur";
pub(crate) const MAGIC: &[u8] = b"DSCOMPRESSED";

/// What zlib makes of a byte at most (its deflate's limit is 1032:1).
const MAX_RATIO: u64 = 1032;

pub(crate) fn read(bytes: &[u8]) -> Result<Grid, Failure> {
    let b = Bytes::new(bytes, NAME);
    let h = header(&b)?;
    let want = (h.nx as u64)
        .checked_mul(h.ny as u64)
        .filter(|&p| p <= super::bin::MAX_POINTS)
        .ok_or_else(|| {
            b.bad(format!(
                "the heights: {} × {} points, more than the {} a file is read with",
                h.nx,
                h.ny,
                super::bin::MAX_POINTS
            ))
        })?
        * h.item as u64;
    let count = b.le::<u32>(h.data, "the number of compressed streams")? as usize;
    let dir = h.data + 4;
    if count == 0 || count > (b.len().saturating_sub(dir)) / 8 {
        return Err(b.bad(format!(
            "{count} compressed streams where the file has room for {}: it is truncated \
             or damaged",
            b.len().saturating_sub(dir) / 8
        )));
    }
    let mut sizes = Vec::with_capacity(count);
    let (mut unpacked, mut at) = (0u64, dir + 8 * count);
    for k in 0..count {
        let raw = b.le::<u32>(dir + 8 * k, "a stream's unpacked size")? as u64;
        let zip = b.le::<u32>(dir + 8 * k + 4, "a stream's packed size")? as usize;
        let what = format!("compressed stream {k}");
        b.slice(at, zip, &what)?;
        if raw > MAX_RATIO * zip as u64 + 64 {
            return Err(b.bad(format!(
                "{what} claims {raw} bytes unpacked from {zip}: more than zlib makes of \
                 them (damaged or hostile)"
            )));
        }
        unpacked += raw;
        sizes.push((at, zip, raw));
        at += zip;
    }
    if unpacked != want {
        return Err(b.bad(format!(
            "the compressed streams unpack to {unpacked} bytes where the header's {} × {} \
             points of {} bytes take {want}: it is damaged",
            h.nx, h.ny, h.item
        )));
    }
    let mut raw = Vec::new();
    for (k, &(at, zip, size)) in sizes.iter().enumerate() {
        let start = raw.len();
        let mut d = flate2::read::ZlibDecoder::new(&bytes[at..at + zip]).take(size + 1);
        d.read_to_end(&mut raw).map_err(|e| {
            b.bad(format!(
                "compressed stream {k} cannot be unpacked ({e}): it is truncated or damaged"
            ))
        })?;
        let got = (raw.len() - start) as u64;
        if got != size {
            return Err(b.bad(format!(
                "compressed stream {k} unpacks to {} bytes where its directory says {size}: \
                 it is damaged",
                if got > size {
                    format!("more than {size}")
                } else {
                    got.to_string()
                }
            )));
        }
    }
    Ok(grid(NAME, &h, &raw))
}
