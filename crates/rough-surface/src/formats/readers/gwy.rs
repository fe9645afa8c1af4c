//! Gwyddion's native files (`.gwy`, magic `GWYP`), their container read by
//! [`super::gwyser`], and the channels of a Gwyddion file's container
//! (both the `GWYP` files of Gwyddion 2 and the `GWYO` files of Gwyddion
//! 1, [`super::gwyo`]): channel
//! N is the `GwyDataField` at `/N/data` (`xres`, `yres`, `xreal`, `yreal`,
//! `si_unit_xy`, `si_unit_z` as `GwySIUnit` objects with a `unitstr`, and
//! `data`, xres × yres doubles row after row), its title the string
//! `/N/data/title`, its mask the data field `/N/mask` (a point > 0.5 is
//! masked). As SurfaceTopography reads them: sizes in the xy unit, heights
//! in the z unit, a channel holds heights when both are lengths, masked
//! points are undefined. A channel whose values have no unit is read as
//! heights in the sizes' unit, one without any unit in metres, each said
//! in a note (`--height-unit` and `--lateral-unit` then say what they are).

use std::collections::BTreeMap;

pub(crate) use super::gwyser::MAGIC;
use super::gwyser::{bad, text, File, Obj, Value};
use crate::error::Failure;
use crate::formats::readers::grid::Grid;
use crate::units::per_metre;

/// More channels than this are refused.
const MAX_CHANNELS: usize = 4096;

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
    /// is taken as the sizes' (`--height-unit` says it); or neither with
    /// a unit: sizes taken in metres (`--lateral-unit` says them).
    fn unitless(&self) -> bool {
        (per_metre(&self.unit_xy).is_some() || self.unit_xy.is_empty()) && self.unit_z.is_empty()
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

/// A container's channels as its entries are met.
#[derive(Default)]
pub(super) struct Channels<'a> {
    fields: BTreeMap<u32, Field<'a>>,
    titles: BTreeMap<u32, String>,
    masks: BTreeMap<u32, Field<'a>>,
}

impl<'a> Channels<'a> {
    /// The container's entry `name` of value `v`, kept when it is a
    /// channel's data field, title or mask.
    pub(super) fn add(
        &mut self,
        file: &File<'a>,
        name: &[u8],
        v: Value<'a>,
    ) -> Result<(), Failure> {
        let Some((n, what)) = key(name) else {
            return Ok(());
        };
        let k = text(name);
        match (what, v) {
            (b"/data", Value::Object(o)) => {
                if self.fields.len() == MAX_CHANNELS {
                    return Err(bad(format!("more than {MAX_CHANNELS} channels")));
                }
                self.fields.insert(n, field(file, o, &k)?);
            }
            (b"/data/title", Value::Str(s)) => {
                self.titles.insert(n, text(s));
            }
            (b"/mask", Value::Object(o)) => {
                if self.masks.len() == MAX_CHANNELS {
                    return Err(bad(format!("more than {MAX_CHANNELS} masks")));
                }
                self.masks.insert(n, field(file, o, &k)?);
            }
            _ => {}
        }
        Ok(())
    }

    /// The channels, by number.
    fn channels(self) -> BTreeMap<u32, Channel<'a>> {
        let Channels {
            fields,
            mut titles,
            mut masks,
        } = self;
        fields
            .into_iter()
            .map(|(n, field)| {
                let c = Channel {
                    field,
                    title: titles.remove(&n),
                    mask: masks.remove(&n),
                };
                (n, c)
            })
            .collect()
    }

    /// The heights of channel `choice` (see [`pick`]), a grid of
    /// `format`.
    pub(super) fn grid(self, choice: Option<&str>, format: &'static str) -> Result<Grid, Failure> {
        let chans = self.channels();
        if chans.is_empty() {
            return Err(bad("no channel (no '/N/data' data field): nothing to read"));
        }
        let (n, c) = pick(&chans, choice)?;
        let f = &c.field;
        // Sizes without a unit are read in metres, values without a unit in
        // the sizes' unit (each said in a note).
        let xy = per_metre(&f.unit_xy).unwrap_or(1.0);
        let zs = per_metre(&f.unit_z).unwrap_or(xy);
        let assumed = crate::formats::readers::assumed::Assumed {
            height: f.unit_z.is_empty().then_some(xy),
            lateral: f.unit_xy.is_empty().then_some(1.0),
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
            format,
            assumed,
        })
    }
}

/// Reads channel `choice` of a .gwy file (see [`Channels::grid`]).
pub(crate) fn read(bytes: &[u8], choice: Option<&str>) -> Result<Grid, Failure> {
    let file = File(bytes);
    if !bytes.starts_with(MAGIC) {
        return Err(bad("no 'GWYP' magic"));
    }
    let (top, _) = file.object(MAGIC.len(), bytes.len(), 0)?;
    if top.name != b"GwyContainer" {
        return Err(bad(format!(
            "the file holds a {}, not a GwyContainer",
            text(top.name)
        )));
    }
    let mut chans = Channels::default();
    file.each(top, 0, |name, v| chans.add(&file, name, v))?;
    chans.grid(choice, "Gwyddion .gwy")
}
