//! Gwyddion's serialisation (the `.gwy` files of Gwyddion 2, magic `GWYP`),
//! read to the published layout (Gwyddion user guide, "Gwyddion native file format"):
//! after the magic, one serialised object — a NUL-terminated type name, a
//! 32-bit little-endian byte count, then components, each a NUL-terminated
//! name, a type character and a value: `b` boolean, `c` character, `i`
//! int32, `q` int64, `d` double, `s` string, `o` object, and arrays `C`,
//! `I`, `Q`, `D`, `S`, `O` (a 32-bit count, then the items).
//!
//! The top object is a `GwyContainer`; channel N is the `GwyDataField` at
//! `/N/data` (`xres`, `yres`, `xreal`, `yreal`, `si_unit_xy`, `si_unit_z`
//! as `GwySIUnit` objects with a `unitstr`, and `data`, xres × yres
//! doubles row after row), its title the string `/N/data/title`, its mask
//! the data field `/N/mask` (a point > 0.5 is masked). As SurfaceTopography
//! reads them: sizes in the xy unit, heights in the z unit, a channel holds
//! heights when both are lengths, masked points are undefined.
//!
//! The channels of the container are read by [`super::gwy`]. The
//! reader borrows from the file's bytes and checks every count against
//! the bytes left before using it, so a damaged file allocates nothing
//! beyond the heights of the channel taken (no more than the file's size)
//! and nests no deeper than [`MAX_DEPTH`] objects.

use crate::error::{Failure, Problem};

/// The magic at the start of a .gwy file.
pub(crate) const MAGIC: &[u8] = b"GWYP";
/// Objects nested deeper than this are refused (Gwyddion's own files nest
/// four or five).
pub(crate) const MAX_DEPTH: usize = 64;

pub(super) fn bad(s: impl AsRef<str>) -> Failure {
    (
        None,
        Problem::Format(format!(
            "Gwyddion .gwy: {}",
            super::bin::printable(s.as_ref(), 400)
        )),
    )
}

pub(super) fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A serialised object: its type name and the bytes of its components.
#[derive(Clone, Copy)]
pub(super) struct Obj<'a> {
    pub name: &'a [u8],
    /// Where the components start and end in the file.
    start: usize,
    end: usize,
}

/// One component's value; arrays stay bytes of the file.
pub(super) enum Value<'a> {
    Int(i32),
    Double(f64),
    Str(&'a [u8]),
    Object(Obj<'a>),
    Doubles(&'a [u8]),
    Other,
}

/// The file's bytes, read with bounds.
pub(super) struct File<'a>(pub &'a [u8]);

impl<'a> File<'a> {
    /// A NUL-terminated string at `pos` ending before `end`; the position
    /// after its NUL.
    pub(super) fn cstr(
        &self,
        pos: usize,
        end: usize,
        what: &str,
    ) -> Result<(&'a [u8], usize), Failure> {
        let b = &self.0[pos.min(end)..end];
        match b.iter().position(|&c| c == 0) {
            Some(n) => Ok((&b[..n], pos + n + 1)),
            None => Err(bad(format!(
                "{what} at byte {pos} runs past its end (the file is truncated or damaged)"
            ))),
        }
    }

    pub(super) fn bytes<const N: usize>(
        &self,
        pos: usize,
        end: usize,
        what: &str,
    ) -> Result<[u8; N], Failure> {
        if pos.checked_add(N).is_none_or(|e| e > end) {
            return Err(bad(format!(
                "{what} at byte {pos} runs past its end (the file is truncated or damaged)"
            )));
        }
        Ok(self.0[pos..pos + N].try_into().expect("N bytes"))
    }

    pub(super) fn u32(&self, pos: usize, end: usize, what: &str) -> Result<usize, Failure> {
        Ok(u32::from_le_bytes(self.bytes(pos, end, what)?) as usize)
    }

    /// The object at `pos` within `end`, its components checked (nested
    /// objects too); the position after it.
    pub(super) fn object(
        &self,
        pos: usize,
        end: usize,
        depth: usize,
    ) -> Result<(Obj<'a>, usize), Failure> {
        if depth > MAX_DEPTH {
            return Err(bad(format!(
                "objects nested deeper than {MAX_DEPTH} levels at byte {pos}"
            )));
        }
        let (name, p) = self.cstr(pos, end, "an object's name")?;
        let size = self.u32(p, end, "an object's size")?;
        let start = p + 4;
        if size > end - start {
            return Err(bad(format!(
                "object '{}' at byte {pos} claims {size} bytes where {} are left \
                 (the file is truncated or damaged)",
                text(name),
                end - start
            )));
        }
        let obj = Obj {
            name,
            start,
            end: start + size,
        };
        self.each(obj, depth, |_, _| Ok(()))?;
        Ok((obj, obj.end))
    }

    /// Calls `f` with each component of `obj`.
    pub(super) fn each(
        &self,
        obj: Obj<'a>,
        depth: usize,
        mut f: impl FnMut(&'a [u8], Value<'a>) -> Result<(), Failure>,
    ) -> Result<(), Failure> {
        let mut pos = obj.start;
        while pos < obj.end {
            let (name, p) = self.cstr(pos, obj.end, "a component's name")?;
            let [ty] = self.bytes(p, obj.end, "a component's type")?;
            let (value, next) = self.value(name, ty, p + 1, obj.end, depth)?;
            f(name, value)?;
            pos = next;
        }
        Ok(())
    }

    /// The value of component `name`, of type `ty`, at `pos`.
    pub(super) fn value(
        &self,
        name: &[u8],
        ty: u8,
        pos: usize,
        end: usize,
        depth: usize,
    ) -> Result<(Value<'a>, usize), Failure> {
        let what = format!("component '{}'", text(name));
        let fixed = |n: usize| -> Result<(Value<'a>, usize), Failure> {
            if n > end - pos {
                return Err(bad(format!(
                    "{what} at byte {pos} runs past its end (the file is truncated or damaged)"
                )));
            }
            Ok((Value::Other, pos + n))
        };
        match ty {
            b'b' | b'c' => fixed(1),
            b'i' => Ok((
                Value::Int(i32::from_le_bytes(self.bytes(pos, end, &what)?)),
                pos + 4,
            )),
            b'q' => fixed(8),
            b'd' => Ok((
                Value::Double(f64::from_le_bytes(self.bytes(pos, end, &what)?)),
                pos + 8,
            )),
            b's' => {
                let (s, p) = self.cstr(pos, end, &what)?;
                Ok((Value::Str(s), p))
            }
            b'o' => {
                let (o, p) = self.object(pos, end, depth + 1)?;
                Ok((Value::Object(o), p))
            }
            b'C' | b'I' | b'Q' | b'D' => {
                let count = self.u32(pos, end, &what)?;
                let item = match ty {
                    b'C' => 1,
                    b'I' => 4,
                    _ => 8,
                };
                let start = pos + 4;
                let left = end - start;
                if count > left / item {
                    return Err(bad(format!(
                        "{what} at byte {pos} claims {count} values ({} bytes) where {left} \
                         bytes are left (the file is truncated or damaged)",
                        count as u64 * item as u64
                    )));
                }
                let data = &self.0[start..start + count * item];
                let v = if ty == b'D' {
                    Value::Doubles(data)
                } else {
                    Value::Other
                };
                Ok((v, start + count * item))
            }
            b'S' | b'O' => {
                let count = self.u32(pos, end, &what)?;
                let mut p = pos + 4;
                // Each item takes at least one byte.
                if count > end - p {
                    return Err(bad(format!(
                        "{what} at byte {pos} claims {count} items where {} bytes are left \
                         (the file is truncated or damaged)",
                        end - p
                    )));
                }
                for _ in 0..count {
                    p = if ty == b'S' {
                        self.cstr(p, end, &what)?.1
                    } else {
                        self.object(p, end, depth + 1)?.1
                    };
                }
                Ok((Value::Other, p))
            }
            t => Err(bad(format!(
                "{what} at byte {} has the unknown type '{}'",
                pos - 1,
                (t as char).escape_default()
            ))),
        }
    }
}
