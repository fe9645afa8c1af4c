//! Gwyddion 1.x files (`.gwy` with the magic `GWYO`), read to the layout
//! Gwyddion 2 still reads them by: after the magic, the container's type
//! name `GwyContainer` (NUL-terminated) and a 32-bit little-endian byte
//! count, then its entries, each a 32-bit GLib type number (20 boolean,
//! 16 character, 24 int32, 40 int64, 60 double, 64 string, 80 object), a
//! NUL-terminated key and the value — an object serialised as in a
//! Gwyddion 2 file ([`super::gwyser`]). The channels are then read as a
//! Gwyddion 2 file's ([`super::gwy`]): `/0/data` and its title and
//! mask.

use super::gwy::Channels;
use super::gwyser::{bad, text, File, Value};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;

pub(crate) const NAME: &str = "Gwyddion 1 .gwy";
pub(crate) const MAGIC: &[u8] = b"GWYO";

pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let file = File(bytes);
    let end = bytes.len();
    let (name, p) = file.cstr(MAGIC.len(), end, "the container's name")?;
    if name != b"GwyContainer" {
        return Err(bad(format!(
            "a Gwyddion 1 file holding a {}, not a GwyContainer",
            text(name)
        )));
    }
    let size = file.u32(p, end, "the container's size")?;
    let start = p + 4;
    if size > end - start {
        return Err(bad(format!(
            "the container claims {size} bytes where {} are left (the file is truncated or \
             damaged)",
            end - start
        )));
    }
    let end = start + size;
    let mut chans = Channels::default();
    let mut pos = start;
    while pos < end {
        let ty = file.u32(pos, end, "an entry's type")?;
        let (key, p) = file.cstr(pos + 4, end, "an entry's key")?;
        let what = format!("entry '{}'", text(key));
        let fixed = |n: usize| -> Result<usize, Failure> {
            match p.checked_add(n) {
                Some(e) if e <= end => Ok(e),
                _ => Err(bad(format!(
                    "{what} at byte {p} runs past its end (the file is truncated or damaged)"
                ))),
            }
        };
        pos = match ty {
            20 | 16 => fixed(1)?,
            24 => fixed(4)?,
            40 => fixed(8)?,
            60 => {
                let next = fixed(8)?;
                let v = f64::from_le_bytes(file.bytes(p, end, &what)?);
                chans.add(&file, key, Value::Double(v))?;
                next
            }
            64 => {
                let (s, next) = file.cstr(p, end, &what)?;
                chans.add(&file, key, Value::Str(s))?;
                next
            }
            80 => {
                let (o, next) = file.object(p, end, 1)?;
                chans.add(&file, key, Value::Object(o))?;
                next
            }
            t => {
                return Err(bad(format!(
                    "{what} at byte {pos} has the unknown type {t}: the file is damaged"
                )))
            }
        };
    }
    chans.grid(choice, NAME)
}
