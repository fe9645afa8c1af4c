//! TIFF files as instruments write them (JPK's scans, Park Systems'
//! images): their image file directories (IFDs) and the tags in them,
//! read with every offset and count checked against the bytes
//! ([`Bytes`]). The makers keep their heights and scales in tags of their
//! own — Park Systems its heights as a tag of megabytes — which a TIFF
//! image decoder hands back as a list of values, one allocation of 32
//! bytes a byte; here a tag's bytes are a slice of the file, and an
//! image's uncompressed strips are read straight into heights.

use std::collections::BTreeMap;

use super::bin::{Bytes, Order};
use crate::error::Failure;

/// A little-endian TIFF's first bytes.
pub(crate) const LITTLE: &[u8] = b"II*\0";
/// A big-endian TIFF's first bytes.
pub(crate) const BIG: &[u8] = b"MM\0*";

/// IFDs read at most.
const MAX_IFDS: usize = 1024;
/// Entries of one IFD read at most.
const MAX_ENTRIES: usize = 2048;
/// Values of one tag read as numbers at most (a strip's offsets).
const MAX_VALUES: usize = 1 << 20;

/// One tag: its type, its count and where its value's bytes are.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Entry {
    pub ty: u16,
    pub count: u64,
    /// Where the value is (inside the entry when it fits in 4 bytes).
    at: usize,
}

/// The size of one value of TIFF type `ty` (0 unknown).
fn size_of(ty: u16) -> usize {
    match ty {
        1 | 2 | 6 | 7 => 1,
        3 | 8 => 2,
        4 | 9 | 11 | 13 => 4,
        5 | 10 | 12 => 8,
        _ => 0,
    }
}

/// A TIFF's directories.
pub(crate) struct Tiff<'a> {
    pub b: Bytes<'a>,
    pub order: Order,
    /// Each IFD's tags, in the file's order.
    pub ifds: Vec<BTreeMap<u16, Entry>>,
}

impl<'a> Tiff<'a> {
    /// The directories of the TIFF `bytes`, named `format` in messages.
    pub fn read(bytes: &'a [u8], format: &'static str) -> Result<Tiff<'a>, Failure> {
        Tiff::read_up_to(bytes, format, MAX_IFDS)
    }

    /// The first directory's tags of the TIFF `bytes`, if it reads (to
    /// tell makers' TIFFs apart).
    pub fn first(bytes: &'a [u8]) -> Option<Tiff<'a>> {
        Tiff::read_up_to(bytes, "TIFF", 1).ok()
    }

    /// The first `most` directories.
    fn read_up_to(bytes: &'a [u8], format: &'static str, most: usize) -> Result<Tiff<'a>, Failure> {
        let b = Bytes::new(bytes, format);
        let order = if bytes.starts_with(LITTLE) {
            Order::Little
        } else if bytes.starts_with(BIG) {
            Order::Big
        } else {
            return Err(b.bad("not a TIFF file (no 'II*' or 'MM*' at its start)"));
        };
        let mut ifds = Vec::new();
        let mut seen = std::collections::HashSet::new();
        let mut at = b.num::<u32>(4, order, "the first directory's offset")? as usize;
        while at != 0 {
            if !seen.insert(at) || ifds.len() >= MAX_IFDS {
                return Err(b.bad(format!(
                    "its directories loop or number more than {MAX_IFDS}: the file is damaged"
                )));
            }
            let n = b.num::<u16>(at, order, "a directory's size")? as usize;
            if n > MAX_ENTRIES {
                return Err(b.bad(format!("a directory of {n} tags")));
            }
            b.slice(at + 2, 12 * n + 4, "a directory")?;
            let mut tags = BTreeMap::new();
            for k in 0..n {
                let e = at + 2 + 12 * k;
                let tag = b.num::<u16>(e, order, "a tag")?;
                let ty = b.num::<u16>(e + 2, order, "a tag's type")?;
                let count = b.num::<u32>(e + 4, order, "a tag's count")? as u64;
                let len = count.saturating_mul(size_of(ty) as u64);
                let at = if len <= 4 {
                    e + 8
                } else {
                    b.num::<u32>(e + 8, order, "a tag's offset")? as usize
                };
                tags.insert(tag, Entry { ty, count, at });
            }
            ifds.push(tags);
            if ifds.len() == most {
                break;
            }
            at = b.num::<u32>(at + 2 + 12 * n, order, "the next directory's offset")? as usize;
        }
        if ifds.is_empty() {
            return Err(b.bad("no image directory"));
        }
        Ok(Tiff { b, order, ifds })
    }

    /// The bytes of tag `tag`'s value in IFD `ifd`, if the tag is there
    /// (refused if they run past the end of the file).
    pub fn bytes(&self, ifd: usize, tag: u16) -> Result<Option<&'a [u8]>, Failure> {
        let Some(e) = self.ifds.get(ifd).and_then(|t| t.get(&tag)) else {
            return Ok(None);
        };
        let len = e.count.saturating_mul(size_of(e.ty) as u64);
        let len = usize::try_from(len).unwrap_or(usize::MAX);
        self.b
            .slice(e.at, len, &format!("tag {tag}'s value"))
            .map(Some)
    }

    /// Tag `tag` of IFD `ifd` as numbers (of an integer or floating-point
    /// type; at most [`MAX_VALUES`]), if it is there.
    pub fn numbers(&self, ifd: usize, tag: u16) -> Result<Option<Vec<f64>>, Failure> {
        let Some(raw) = self.bytes(ifd, tag)? else {
            return Ok(None);
        };
        let ty = self.ifds[ifd][&tag].ty;
        let n = raw.len() / size_of(ty).max(1);
        if n > MAX_VALUES {
            return Err(self
                .b
                .bad(format!("tag {tag} of image {ifd} holds {n} values")));
        }
        (0..n)
            .map(|k| self.value(raw, ty, k, tag))
            .collect::<Result<Vec<f64>, Failure>>()
            .map(Some)
    }

    /// Value `k` of a tag of type `ty` whose bytes are `raw`.
    fn value(&self, raw: &[u8], ty: u16, k: usize, tag: u16) -> Result<f64, Failure> {
        let b = Bytes::new(raw, self.b.format);
        let o = self.order;
        let what = "a tag's value";
        Ok(match ty {
            1 | 7 => b.le::<u8>(k, what)? as f64,
            6 => b.le::<i8>(k, what)? as f64,
            3 => b.num::<u16>(2 * k, o, what)? as f64,
            8 => b.num::<i16>(2 * k, o, what)? as f64,
            4 | 13 => b.num::<u32>(4 * k, o, what)? as f64,
            9 => b.num::<i32>(4 * k, o, what)? as f64,
            11 => b.num::<f32>(4 * k, o, what)? as f64,
            12 => b.num::<f64>(8 * k, o, what)?,
            5 => b.num::<u32>(8 * k, o, what)? as f64 / b.num::<u32>(8 * k + 4, o, what)? as f64,
            10 => b.num::<i32>(8 * k, o, what)? as f64 / b.num::<i32>(8 * k + 4, o, what)? as f64,
            _ => return Err(self.b.bad(format!("tag {tag} is not a number"))),
        })
    }

    /// Tag `tag` of IFD `ifd` as one number (its first), if it is there.
    pub fn number(&self, ifd: usize, tag: u16) -> Result<Option<f64>, Failure> {
        let Some(raw) = self.bytes(ifd, tag)? else {
            return Ok(None);
        };
        if raw.is_empty() {
            return Ok(None);
        }
        let ty = self.ifds[ifd][&tag].ty;
        self.value(raw, ty, 0, tag).map(Some)
    }

    /// Tag `tag` of IFD `ifd` as text (its bytes up to the first NUL,
    /// UTF-8 or else Latin-1), if it is there.
    pub fn text(&self, ifd: usize, tag: u16) -> Result<Option<String>, Failure> {
        Ok(self.bytes(ifd, tag)?.map(|raw| {
            let end = raw.iter().position(|&c| c == 0).unwrap_or(raw.len());
            match std::str::from_utf8(&raw[..end]) {
                Ok(s) => s.trim().to_string(),
                Err(_) => super::bin::latin1(&raw[..end]),
            }
        }))
    }

    /// Refuses a file whose images' strips run past its end (a file cut
    /// short), read or not.
    pub fn strips_inside(&self) -> Result<(), Failure> {
        for ifd in 0..self.ifds.len() {
            let offsets = self.numbers(ifd, 273)?.unwrap_or_default();
            let counts = self.numbers(ifd, 279)?.unwrap_or_default();
            for (k, (&at, &len)) in offsets.iter().zip(&counts).enumerate() {
                self.b.slice(
                    at as usize,
                    len as usize,
                    &format!("image {ifd}'s strip {k}"),
                )?;
            }
        }
        Ok(())
    }

    /// The image of IFD `ifd` — one sample a pixel, uncompressed, in
    /// strips — as its width, its height and its values, row after row.
    pub fn image(&self, ifd: usize) -> Result<(usize, usize, Vec<f64>), Failure> {
        let page = format!("image {ifd}");
        let need = |tag: u16, what: &str| -> Result<f64, Failure> {
            self.number(ifd, tag)?
                .ok_or_else(|| self.b.bad(format!("{page} has no {what}")))
        };
        let nx = need(256, "width")? as u64;
        let ny = need(257, "length")? as u64;
        let bits = self.number(ifd, 258)?.unwrap_or(1.0) as u32;
        let format = self.number(ifd, 339)?.unwrap_or(1.0) as u32;
        let compression = self.number(ifd, 259)?.unwrap_or(1.0);
        let samples = self.number(ifd, 277)?.unwrap_or(1.0);
        if compression != 1.0 {
            return Err(self.b.bad(format!(
                "{page} is compressed (TIFF compression {compression}): uncompressed images are read"
            )));
        }
        if samples != 1.0 {
            return Err(self.b.bad(format!("{page} has {samples} samples a pixel")));
        }
        let item = match (format, bits) {
            (1 | 2, 8 | 16 | 32) | (3, 32 | 64) => bits as usize / 8,
            _ => {
                return Err(self.b.bad(format!(
                    "{page} holds values of {bits} bits of sample format {format}"
                )))
            }
        };
        let offsets = self
            .numbers(ifd, 273)?
            .ok_or_else(|| self.b.bad(format!("{page} has no strips")))?;
        let counts = self.numbers(ifd, 279)?.unwrap_or_default();
        // The whole raster, checked before anything is allocated for it.
        let total = self.b.raster(0, (nx, ny), item, &page).map(|r| r.len())?;
        let mut raw = Vec::with_capacity(total);
        for (k, &at) in offsets.iter().enumerate() {
            let left = total - raw.len();
            if left == 0 {
                break;
            }
            let len = counts.get(k).map_or(left, |&c| (c as usize).min(left));
            raw.extend_from_slice(self.b.slice(
                at as usize,
                len,
                &format!("{page}'s strip {k}"),
            )?);
        }
        if raw.len() != total {
            return Err(self.b.bad(format!(
                "{page}'s strips hold {} bytes where {nx} × {ny} values of {bits} bits take {total}",
                raw.len()
            )));
        }
        let o = self.order;
        let v: Vec<f64> = match (format, bits) {
            (1, 8) => raw.iter().map(|&c| c as f64).collect(),
            (2, 8) => raw.iter().map(|&c| c as i8 as f64).collect(),
            (1, 16) => super::bin::values::<u16>(&raw, o).map(f64::from).collect(),
            (2, 16) => super::bin::values::<i16>(&raw, o).map(f64::from).collect(),
            (1, 32) => super::bin::values::<u32>(&raw, o).map(f64::from).collect(),
            (2, 32) => super::bin::values::<i32>(&raw, o).map(f64::from).collect(),
            (3, 32) => super::bin::values::<f32>(&raw, o).map(f64::from).collect(),
            _ => super::bin::values::<f64>(&raw, o).collect(),
        };
        Ok((nx as usize, ny as usize, v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A little TIFF: one IFD of 2 × 2 int16 values and an ASCII tag.
    fn little() -> Vec<u8> {
        let mut b = b"II*\0".to_vec();
        b.extend(8u32.to_le_bytes());
        let tags: [(u16, u16, u32, u32); 6] = [
            (256, 3, 1, 2),
            (257, 3, 1, 2),
            (258, 3, 1, 16),
            (273, 4, 1, 8 + 2 + 6 * 12 + 4),
            (339, 3, 1, 2),
            (0x8050, 2, 3, u32::from_le_bytes(*b"ab\0\0")),
        ];
        b.extend((tags.len() as u16).to_le_bytes());
        for (tag, ty, count, v) in tags {
            b.extend(tag.to_le_bytes());
            b.extend(ty.to_le_bytes());
            b.extend(count.to_le_bytes());
            b.extend(v.to_le_bytes());
        }
        b.extend(0u32.to_le_bytes());
        for v in [1i16, -2, 3, -4] {
            b.extend(v.to_le_bytes());
        }
        b
    }

    #[test]
    fn directories_and_images() {
        let b = little();
        let t = Tiff::read(&b, "T").unwrap();
        assert_eq!(t.ifds.len(), 1);
        assert_eq!(t.text(0, 0x8050).unwrap().unwrap(), "ab");
        assert_eq!(t.number(0, 256).unwrap(), Some(2.0));
        assert_eq!(t.number(0, 999).unwrap(), None);
        assert_eq!(t.image(0).unwrap(), (2, 2, vec![1.0, -2.0, 3.0, -4.0]));
        let cut = &b[..b.len() - 1];
        let e = Tiff::read(cut, "T").unwrap().image(0).unwrap_err().1;
        assert!(e.to_string().contains("runs past the end"), "{e}");
        // A directory pointing at itself.
        let mut looped = b.clone();
        let next = 8 + 2 + 6 * 12;
        looped[next..next + 4].copy_from_slice(&8u32.to_le_bytes());
        let e = Tiff::read(&looped, "T").err().unwrap().1.to_string();
        assert!(e.contains("loop"), "{e}");
    }
}
