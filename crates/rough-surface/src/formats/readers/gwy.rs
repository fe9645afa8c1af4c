//! Gwyddion's native files (`.gwy`, magic `GWYP`), read to the published
//! serialisation (Gwyddion user guide, "Gwyddion native file format"):
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
//! The reader borrows from the file's bytes and checks every count against
//! the bytes left before using it, so a damaged file allocates nothing
//! beyond the heights of the channel taken (no more than the file's size)
//! and nests no deeper than [`MAX_DEPTH`] objects.

use std::collections::BTreeMap;

use crate::error::{Failure, Problem};
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

/// The magic at the start of a .gwy file.
pub(crate) const MAGIC: &[u8] = b"GWYP";
/// Objects nested deeper than this are refused (Gwyddion's own files nest
/// four or five).
pub(crate) const MAX_DEPTH: usize = 64;
/// More channels than this are refused.
const MAX_CHANNELS: usize = 4096;

fn bad(s: impl AsRef<str>) -> Failure {
    (
        None,
        Problem::Format(format!("Gwyddion .gwy: {}", s.as_ref())),
    )
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A serialised object: its type name and the bytes of its components.
#[derive(Clone, Copy)]
struct Obj<'a> {
    name: &'a [u8],
    /// Where the components start and end in the file.
    start: usize,
    end: usize,
}

/// One component's value; arrays stay bytes of the file.
enum Value<'a> {
    Int(i32),
    Double(f64),
    Str(&'a [u8]),
    Object(Obj<'a>),
    Doubles(&'a [u8]),
    Other,
}

/// The file's bytes, read with bounds.
struct File<'a>(&'a [u8]);

impl<'a> File<'a> {
    /// A NUL-terminated string at `pos` ending before `end`; the position
    /// after its NUL.
    fn cstr(&self, pos: usize, end: usize, what: &str) -> Result<(&'a [u8], usize), Failure> {
        let b = &self.0[pos.min(end)..end];
        match b.iter().position(|&c| c == 0) {
            Some(n) => Ok((&b[..n], pos + n + 1)),
            None => Err(bad(format!(
                "{what} at byte {pos} runs past its end (the file is truncated or damaged)"
            ))),
        }
    }

    fn bytes<const N: usize>(
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

    fn u32(&self, pos: usize, end: usize, what: &str) -> Result<usize, Failure> {
        Ok(u32::from_le_bytes(self.bytes(pos, end, what)?) as usize)
    }

    /// The object at `pos` within `end`, its components checked (nested
    /// objects too); the position after it.
    fn object(&self, pos: usize, end: usize, depth: usize) -> Result<(Obj<'a>, usize), Failure> {
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
    fn each(
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
    fn value(
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

/// A channel's data field, its arrays still in the file.
struct Field<'a> {
    xres: usize,
    yres: usize,
    xreal: f64,
    yreal: f64,
    unit_xy: String,
    unit_z: String,
    data: &'a [u8],
}

impl Field<'_> {
    /// Heights (or sizes) of a length unit, and that unit per metre.
    fn is_length(&self) -> bool {
        per_metre(&self.unit_xy).is_some() && per_metre(&self.unit_z).is_some()
    }

    /// Sizes of a length unit, values without a unit: heights whose unit
    /// is taken as the sizes' (`--height-unit` says it).
    fn unitless(&self) -> bool {
        per_metre(&self.unit_xy).is_some() && self.unit_z.is_empty()
    }

    fn value(&self, i: usize) -> f64 {
        f64::from_le_bytes(self.data[8 * i..8 * i + 8].try_into().expect("8 bytes"))
    }
}

/// A `GwySIUnit`'s string ("" without one).
fn unit<'a>(file: &File<'a>, o: Obj<'a>, depth: usize) -> Result<String, Failure> {
    let mut u = String::new();
    file.each(o, depth, |name, v| {
        if let (b"unitstr", Value::Str(s)) = (name, v) {
            u = text(s).trim().to_string();
        }
        Ok(())
    })?;
    Ok(u)
}

/// The data field `o`, stored under `key`.
fn field<'a>(file: &File<'a>, o: Obj<'a>, key: &str) -> Result<Field<'a>, Failure> {
    if o.name != b"GwyDataField" {
        return Err(bad(format!(
            "'{key}' is a {}, not a GwyDataField",
            text(o.name)
        )));
    }
    let (mut xres, mut yres) = (None, None);
    let (mut xreal, mut yreal) = (None, None);
    let (mut unit_xy, mut unit_z) = (String::new(), String::new());
    let mut data = None;
    file.each(o, 1, |name, v| {
        match (name, v) {
            (b"xres", Value::Int(n)) => xres = Some(n),
            (b"yres", Value::Int(n)) => yres = Some(n),
            (b"xreal", Value::Double(x)) => xreal = Some(x),
            (b"yreal", Value::Double(x)) => yreal = Some(x),
            (b"si_unit_xy", Value::Object(u)) => unit_xy = unit(file, u, 2)?,
            (b"si_unit_z", Value::Object(u)) => unit_z = unit(file, u, 2)?,
            (b"data", Value::Doubles(d)) => data = Some(d),
            _ => {}
        }
        Ok(())
    })?;
    let missing = |what: &str| bad(format!("'{key}' has no {what}"));
    let res = |n: Option<i32>, what: &str| -> Result<usize, Failure> {
        match n {
            Some(n) if n >= 1 => Ok(n as usize),
            Some(n) => Err(bad(format!("'{key}' has {what} = {n}"))),
            None => Err(missing(what)),
        }
    };
    let (xres, yres) = (res(xres, "xres")?, res(yres, "yres")?);
    let data = data.ok_or_else(|| missing("data (an array of doubles)"))?;
    if xres.checked_mul(yres) != Some(data.len() / 8) {
        return Err(bad(format!(
            "'{key}' is {xres} × {yres} points but its data holds {} values",
            data.len() / 8
        )));
    }
    // As Gwyddion (and SurfaceTopography): a negative size counts by its
    // magnitude.
    let size = |x: Option<f64>, what: &str| -> Result<f64, Failure> {
        match x {
            Some(x) if x.is_finite() && x != 0.0 => Ok(x.abs()),
            Some(x) => Err(bad(format!("'{key}' has {what} = {x}"))),
            None => Err(missing(what)),
        }
    };
    Ok(Field {
        xres,
        yres,
        xreal: size(xreal, "xreal")?,
        yreal: size(yreal, "yreal")?,
        unit_xy,
        unit_z,
        data,
    })
}

/// `/N/data`, `/N/data/title`, `/N/mask`: the channel N and what it is.
fn key(name: &[u8]) -> Option<(u32, &[u8])> {
    let rest = name.strip_prefix(b"/")?;
    let digits = rest.iter().take_while(|c| c.is_ascii_digit()).count();
    if digits == 0 || digits > 9 {
        return None;
    }
    let n = std::str::from_utf8(&rest[..digits]).ok()?.parse().ok()?;
    Some((n, &rest[digits..]))
}

/// One channel of the file.
struct Channel<'a> {
    field: Field<'a>,
    title: Option<String>,
    mask: Option<Field<'a>>,
}

impl Channel<'_> {
    fn describe(&self, n: u32) -> String {
        let title = self.title.as_deref().unwrap_or("untitled");
        let unit = if self.field.unit_z.is_empty() {
            "no unit"
        } else {
            &self.field.unit_z
        };
        format!("{n} '{title}' ({unit})")
    }
}

/// The channels of a .gwy file, by number.
fn channels<'a>(file: &File<'a>) -> Result<BTreeMap<u32, Channel<'a>>, Failure> {
    let b = file.0;
    if !b.starts_with(MAGIC) {
        return Err(bad("no 'GWYP' magic"));
    }
    let (top, _) = file.object(MAGIC.len(), b.len(), 0)?;
    if top.name != b"GwyContainer" {
        return Err(bad(format!(
            "the file holds a {}, not a GwyContainer",
            text(top.name)
        )));
    }
    let mut fields = BTreeMap::new();
    let mut titles = BTreeMap::new();
    let mut masks = BTreeMap::new();
    file.each(top, 0, |name, v| {
        let Some((n, what)) = key(name) else {
            return Ok(());
        };
        let k = text(name);
        match (what, v) {
            (b"/data", Value::Object(o)) => {
                if fields.len() == MAX_CHANNELS {
                    return Err(bad(format!("more than {MAX_CHANNELS} channels")));
                }
                fields.insert(n, field(file, o, &k)?);
            }
            (b"/data/title", Value::Str(s)) => {
                titles.insert(n, text(s));
            }
            (b"/mask", Value::Object(o)) => {
                if masks.len() == MAX_CHANNELS {
                    return Err(bad(format!("more than {MAX_CHANNELS} masks")));
                }
                masks.insert(n, field(file, o, &k)?);
            }
            _ => {}
        }
        Ok(())
    })?;
    Ok(fields
        .into_iter()
        .map(|(n, field)| {
            let c = Channel {
                field,
                title: titles.remove(&n),
                mask: masks.remove(&n),
            };
            (n, c)
        })
        .collect())
}

/// The channels of a .gwy file for people: "0 'Height' (m), 1 'Phase'
/// (deg)".
fn list(chans: &BTreeMap<u32, Channel<'_>>) -> String {
    chans
        .iter()
        .map(|(n, c)| c.describe(*n))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The channel `choice` names (its number or its title), else the first
/// whose heights and sizes are lengths.
fn pick<'c, 'a>(
    chans: &'c BTreeMap<u32, Channel<'a>>,
    choice: Option<&str>,
) -> Result<(u32, &'c Channel<'a>), Failure> {
    let all = list(chans);
    let Some(choice) = choice else {
        return chans
            .iter()
            .find(|(_, c)| c.field.is_length())
            .or_else(|| chans.iter().find(|(_, c)| c.field.unitless()))
            .map(|(n, c)| (*n, c))
            .ok_or_else(|| {
                bad(format!(
                    "no channel holds heights (sizes and values in a unit of length): {all}"
                ))
            });
    };
    let choice = choice.trim();
    let found = if let Ok(n) = choice.parse::<u32>() {
        chans
            .get_key_value(&n)
            .ok_or_else(|| bad(format!("no channel {n}; the channels are {all}")))?
    } else {
        let mut titled = chans.iter().filter(|(_, c)| {
            c.title
                .as_deref()
                .is_some_and(|t| t.trim().eq_ignore_ascii_case(choice))
        });
        let first = titled.next().ok_or_else(|| {
            bad(format!(
                "no channel titled '{choice}'; the channels are {all}"
            ))
        })?;
        if let Some((m, _)) = titled.next() {
            return Err(bad(format!(
                "channels {} and {m} are both titled '{choice}': give the number \
                 (--channel {})",
                first.0, first.0
            )));
        }
        first
    };
    let (n, c) = found;
    if !c.field.is_length() && !c.field.unitless() {
        let (u, which) = if per_metre(&c.field.unit_z).is_none() {
            (&c.field.unit_z, "values")
        } else {
            (&c.field.unit_xy, "sizes")
        };
        let u = if u.is_empty() { "no unit" } else { u };
        return Err(bad(format!(
            "channel {} holds {which} in {u}, not a length: the channels are {all}",
            c.describe(*n)
        )));
    }
    Ok((*n, c))
}

/// Reads channel `choice` of a .gwy file (see [`pick`]).
pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let file = File(bytes);
    let chans = channels(&file)?;
    if chans.is_empty() {
        return Err(bad("no channel (no '/N/data' data field): nothing to read"));
    }
    let (n, c) = pick(&chans, choice)?;
    let f = &c.field;
    let xy = per_metre(&f.unit_xy).expect("a length");
    // Values without a unit are read in the sizes' unit (said in a note).
    let zs = per_metre(&f.unit_z).unwrap_or(xy);
    let assumed = crate::formats::readers::assumed::Assumed {
        height: f.unit_z.is_empty().then_some(xy),
        lateral: None,
    };
    let points = f.xres * f.yres;
    let mut z: Vec<f64> = (0..points)
        .map(|i| {
            let v = f.value(i);
            if v.is_finite() {
                v / zs
            } else {
                f64::NAN
            }
        })
        .collect();
    let mut notes = Vec::new();
    if chans.len() > 1 {
        let others: Vec<String> = chans
            .iter()
            .filter(|(m, _)| **m != n)
            .map(|(m, o)| o.describe(*m))
            .collect();
        notes.push(format!(
            "channel {} read; also in the file: {} (--channel N or TITLE)",
            c.describe(n),
            others.join(", ")
        ));
    }
    let nonfinite = z.iter().filter(|v| v.is_nan()).count();
    if nonfinite > 0 {
        notes.push(format!(
            "{nonfinite} NaN or infinite values read as undefined points"
        ));
    }
    if let Some(m) = &c.mask {
        if (m.xres, m.yres) != (f.xres, f.yres) {
            return Err(bad(format!(
                "the mask '/{n}/mask' is {} × {} points where the channel is {} × {}",
                m.xres, m.yres, f.xres, f.yres
            )));
        }
        let mut masked = 0;
        for (i, v) in z.iter_mut().enumerate() {
            if m.value(i) > 0.5 {
                masked += 1;
                *v = f64::NAN;
            }
        }
        if masked > 0 {
            notes.push(format!(
                "{masked} points under the mask '/{n}/mask' read as undefined"
            ));
        }
    }
    Ok(Grid {
        nx: f.xres,
        ny: f.yres,
        lx: f.xreal / xy,
        ly: if f.yres == 1 { 0.0 } else { f.yreal / xy },
        z,
        notes,
        format: "Gwyddion .gwy",
        assumed,
    })
}
