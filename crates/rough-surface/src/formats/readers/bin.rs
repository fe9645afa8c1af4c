//! Bounded reading of a binary file's bytes: every read names what it
//! wanted and where, a read past the end is a refusal naming both, and a
//! raster is checked against the bytes there (and against
//! [`MAX_POINTS`]) before anything is allocated for it.

use crate::error::{Failure, Problem};

/// Heights read at most: as many doubles as [`crate::MAX_BYTES`] holds
/// (the x3p reader's limit too).
pub(crate) const MAX_POINTS: u64 = crate::limits::MAX_BYTES / 8;

/// A number stored in a file, in either byte order.
pub(crate) trait Num: Copy {
    const SIZE: usize;
    fn le(b: &[u8]) -> Self;
    fn be(b: &[u8]) -> Self;
    fn f64(self) -> f64;
}

macro_rules! num {
    ($($t:ty),*) => {$(
        impl Num for $t {
            const SIZE: usize = std::mem::size_of::<$t>();
            fn le(b: &[u8]) -> Self {
                <$t>::from_le_bytes(b.try_into().expect("SIZE bytes"))
            }
            fn be(b: &[u8]) -> Self {
                <$t>::from_be_bytes(b.try_into().expect("SIZE bytes"))
            }
            fn f64(self) -> f64 {
                self as f64
            }
        }
    )*};
}
num!(u8, i8, u16, i16, u32, i32, u64, i64, f32, f64);

/// Byte order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Order {
    Little,
    Big,
}

/// A file's bytes and the format's name for its messages.
#[derive(Clone, Copy)]
pub(crate) struct Bytes<'a> {
    pub b: &'a [u8],
    /// "Digital Surf .sur": each refusal starts with it.
    pub format: &'static str,
}

impl<'a> Bytes<'a> {
    pub fn new(b: &'a [u8], format: &'static str) -> Bytes<'a> {
        Bytes { b, format }
    }

    pub fn len(&self) -> usize {
        self.b.len()
    }

    /// A refusal: "FORMAT: s", on one line whatever names from the file
    /// it quotes.
    pub fn bad(&self, s: impl AsRef<str>) -> Failure {
        (
            None,
            Problem::Format(format!("{}: {}", self.format, printable(s.as_ref(), 400))),
        )
    }

    /// `len` bytes at `pos`.
    pub fn slice(&self, pos: usize, len: usize, what: &str) -> Result<&'a [u8], Failure> {
        match pos.checked_add(len) {
            Some(end) if end <= self.b.len() => Ok(&self.b[pos..end]),
            _ => Err(self.bad(format!(
                "{what} at byte {pos} ({len} bytes) runs past the end of the file \
                 ({} bytes): it is truncated or damaged",
                self.b.len()
            ))),
        }
    }

    /// The number at `pos`, little-endian.
    pub fn le<T: Num>(&self, pos: usize, what: &str) -> Result<T, Failure> {
        Ok(T::le(self.slice(pos, T::SIZE, what)?))
    }

    /// The number at `pos`, big-endian.
    pub fn be<T: Num>(&self, pos: usize, what: &str) -> Result<T, Failure> {
        Ok(T::be(self.slice(pos, T::SIZE, what)?))
    }

    /// The number at `pos` in byte order `o`.
    pub fn num<T: Num>(&self, pos: usize, o: Order, what: &str) -> Result<T, Failure> {
        match o {
            Order::Little => self.le(pos, what),
            Order::Big => self.be(pos, what),
        }
    }

    /// A fixed-size text field (Latin-1, NUL-padded), trimmed.
    pub fn text(&self, pos: usize, len: usize, what: &str) -> Result<String, Failure> {
        Ok(latin1(self.slice(pos, len, what)?))
    }

    /// The bytes of an nx × ny raster of `item`-byte values at `pos`,
    /// checked: nx and ny at least 1, no more than [`MAX_POINTS`], and in
    /// the file.
    pub fn raster(
        &self,
        pos: usize,
        (nx, ny): (u64, u64),
        item: usize,
        what: &str,
    ) -> Result<&'a [u8], Failure> {
        let points = nx.checked_mul(ny).filter(|p| (1..=MAX_POINTS).contains(p));
        let Some(points) = points else {
            return Err(self.bad(format!(
                "{what}: {nx} × {ny} points, {}",
                if nx == 0 || ny == 0 {
                    "no data".to_string()
                } else {
                    format!("more than the {MAX_POINTS} a file is read with")
                }
            )));
        };
        let len = points as usize * item;
        if pos > self.b.len() || len > self.b.len() - pos {
            return Err(self.bad(format!(
                "{what}: {nx} × {ny} points take {len} bytes from byte {pos}, \
                 but the file holds {} bytes: it is truncated or its sizes are wrong",
                self.b.len()
            )));
        }
        Ok(&self.b[pos..pos + len])
    }
}

/// The values of `raw` (numbers of type T in byte order `o`) as doubles.
pub(crate) fn values<T: Num>(raw: &[u8], o: Order) -> impl Iterator<Item = T> + '_ {
    raw.chunks_exact(T::SIZE).map(move |c| match o {
        Order::Little => T::le(c),
        Order::Big => T::be(c),
    })
}

/// Where `needle` first occurs in `hay`.
pub(crate) fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

/// Text from a file for a message: control characters as `?`, at most
/// `max` characters (then `…`).
pub(crate) fn printable(s: &str, max: usize) -> String {
    let mut out: String = s
        .chars()
        .take(max)
        .map(|c| if c.is_control() { '?' } else { c })
        .collect();
    if s.chars().nth(max).is_some() {
        out.push('…');
    }
    out
}

/// Latin-1 bytes up to the first NUL, trimmed of spaces.
pub(crate) fn latin1(b: &[u8]) -> String {
    let end = b.iter().position(|&c| c == 0).unwrap_or(b.len());
    b[..end]
        .iter()
        .map(|&c| c as char)
        .collect::<String>()
        .trim()
        .to_string()
}

/// Rows of a raster stored with the first row at the bottom: row j of
/// the result is row ny − 1 − j of `z`.
pub(crate) fn flip_rows(z: &mut [f64], nx: usize) {
    let ny = z.len() / nx.max(1);
    for j in 0..ny / 2 {
        let (top, bottom) = z.split_at_mut((ny - 1 - j) * nx);
        top[j * nx..(j + 1) * nx].swap_with_slice(&mut bottom[..nx]);
    }
}

/// Columns mirrored: x becomes nx − 1 − x in every row.
pub(crate) fn flip_columns(z: &mut [f64], nx: usize) {
    for row in z.chunks_exact_mut(nx.max(1)) {
        row.reverse();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_are_bounded() {
        let b = Bytes::new(&[1, 0, 0, 0, 2], "test");
        assert_eq!(b.le::<u32>(0, "a count").unwrap(), 1);
        assert_eq!(b.be::<u16>(3, "a count").unwrap(), 2);
        let e = b.le::<u32>(2, "a count").unwrap_err().1.to_string();
        assert_eq!(
            e,
            "test: a count at byte 2 (4 bytes) runs past the end of the file (5 bytes): \
             it is truncated or damaged"
        );
        assert!(b.le::<u64>(usize::MAX - 2, "x").is_err());
        let e = b
            .raster(1, (2, 3), 2, "the heights")
            .unwrap_err()
            .1
            .to_string();
        assert_eq!(
            e,
            "test: the heights: 2 × 3 points take 12 bytes from byte 1, but the file holds 5 \
             bytes: it is truncated or its sizes are wrong"
        );
        let e = b
            .raster(0, (1 << 40, 1 << 40), 2, "the heights")
            .unwrap_err();
        assert!(e.1.to_string().contains("more than the"));
        assert!(b
            .raster(0, (0, 3), 2, "h")
            .unwrap_err()
            .1
            .to_string()
            .contains("no data"));
        assert_eq!(b.raster(1, (2, 2), 1, "h").unwrap(), &[0, 0, 0, 2]);
    }

    #[test]
    fn flips() {
        let mut z = vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        flip_rows(&mut z, 2);
        assert_eq!(z, [5.0, 6.0, 3.0, 4.0, 1.0, 2.0]);
        flip_columns(&mut z, 2);
        assert_eq!(z, [6.0, 5.0, 4.0, 3.0, 2.0, 1.0]);
        assert_eq!(latin1(b" \xb5m\0xx"), "µm");
    }
}
