//! HDF5 files as instruments write them (JPK's `.h5-jpk`, Zygo's `.datx`),
//! through the pure-Rust `hdf5-reader` crate, opened with limits: no chunk
//! and no read larger than the file may hold ([`crate::limits::MAX_BYTES`]),
//! no external files. Its errors become one line naming the format; its
//! attributes and datasets are read here as the readers need them: text,
//! numbers, compound values whose fields are strings or sequences of
//! numbers (fixed or variable-length), and any numeric dataset as doubles.

use hdf5_reader::{Attribute, Dataset, Datatype, H5Type, Hdf5File, OpenOptions, SliceInfo};

use super::bin::{Bytes, Order};
use super::zipped::one_line;
use crate::error::Failure;

/// An HDF5 file's first bytes.
pub(crate) const MAGIC: &[u8] = b"\x89HDF\r\n\x1a\n";

/// The line for an error of the HDF5 reader in a file of `format`.
pub(crate) fn bad(format: &'static str) -> impl Fn(hdf5_reader::error::Error) -> Failure {
    move |e| {
        Bytes::new(&[], format).bad(format!(
            "its HDF5 structure cannot be read ({}): the file is truncated or damaged",
            one_line(&e.to_string())
        ))
    }
}

/// The HDF5 file in `bytes`, opened with limits.
pub(crate) fn open(bytes: &[u8], format: &'static str) -> Result<Hdf5File, Failure> {
    let max = crate::limits::MAX_BYTES as usize;
    let opts = OpenOptions::default()
        .with_max_chunk_bytes(max.min(64 << 20))
        .with_max_read_bytes(max)
        .with_chunk_cache_bytes(16 << 20);
    Hdf5File::from_bytes_with_options(bytes, opts).map_err(bad(format))
}

/// The attribute `name` of `attrs`.
fn find<'a>(attrs: &'a [Attribute], name: &str) -> Option<&'a Attribute> {
    attrs.iter().find(|a| a.name == name)
}

/// Attribute `name` as text (its first string), if it is one.
pub(crate) fn text(attrs: &[Attribute], name: &str) -> Option<String> {
    let a = find(attrs, name)?;
    a.read_strings()
        .ok()
        .and_then(|s| s.into_iter().next())
        .map(|s| s.trim_end_matches('\0').trim().to_string())
}

/// Attribute `name` as a number (its first), if it is one.
pub(crate) fn number(attrs: &[Attribute], name: &str) -> Option<f64> {
    let a = find(attrs, name)?;
    a.read_as_f64()
        .ok()
        .or_else(|| a.read_1d::<f64>().ok()?.first().copied())
}

/// A value of a compound's field, as the readers need it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Field {
    Text(String),
    Numbers(Vec<f64>),
    Other,
}

fn order(o: hdf5_reader::ByteOrder) -> Order {
    match o {
        hdf5_reader::ByteOrder::LittleEndian => Order::Little,
        hdf5_reader::ByteOrder::BigEndian => Order::Big,
    }
}

/// Numbers of type `dt` in `raw` (as many as fit).
fn numbers(raw: &[u8], dt: &Datatype) -> Option<Vec<f64>> {
    use super::bin::values;
    Some(match dt {
        Datatype::FloatingPoint {
            size: 8,
            byte_order,
        } => values::<f64>(raw, order(*byte_order)).collect(),
        Datatype::FloatingPoint {
            size: 4,
            byte_order,
        } => values::<f32>(raw, order(*byte_order))
            .map(f64::from)
            .collect(),
        Datatype::FixedPoint {
            size,
            signed,
            byte_order,
        } => {
            let o = order(*byte_order);
            match (size, signed) {
                (1, true) => values::<i8>(raw, o).map(f64::from).collect(),
                (1, false) => values::<u8>(raw, o).map(f64::from).collect(),
                (2, true) => values::<i16>(raw, o).map(f64::from).collect(),
                (2, false) => values::<u16>(raw, o).map(f64::from).collect(),
                (4, true) => values::<i32>(raw, o).map(f64::from).collect(),
                (4, false) => values::<u32>(raw, o).map(f64::from).collect(),
                (8, true) => values::<i64>(raw, o).map(|v| v as f64).collect(),
                (8, false) => values::<u64>(raw, o).map(|v| v as f64).collect(),
                _ => return None,
            }
        }
        _ => return None,
    })
}

/// The size of one value of `dt` in a compound (a variable-length value
/// is a reference of `vlen` bytes).
fn size_of(dt: &Datatype, vlen: usize) -> usize {
    match dt {
        Datatype::FixedPoint { size, .. } | Datatype::FloatingPoint { size, .. } => *size as usize,
        Datatype::String {
            size: hdf5_reader::StringSize::Fixed(n),
            ..
        } => *n as usize,
        Datatype::String { .. } | Datatype::VarLen { .. } => vlen,
        Datatype::Compound { size, .. } | Datatype::Opaque { size, .. } => *size as usize,
        Datatype::Array { base, dims } => dims
            .iter()
            .try_fold(size_of(base, vlen), |a, &d| a.checked_mul(d as usize))
            .unwrap_or(usize::MAX),
        Datatype::Enum { base, .. } => size_of(base, vlen),
        Datatype::Reference { size, .. } | Datatype::Bitfield { size, .. } => *size as usize,
    }
}

/// Resolves a variable-length reference to its bytes (values of
/// `element` bytes).
pub(crate) type Resolve<'r> = &'r dyn Fn(&[u8], usize) -> Option<Vec<u8>>;

/// The fields of the compound elements in `raw` of type `dt`: one map of
/// field names to values an element. `resolve` reads variable-length
/// values; `vlen` is the size of their references.
pub(crate) fn compound(
    raw: &[u8],
    dt: &Datatype,
    vlen: usize,
    resolve: Resolve<'_>,
) -> Vec<Vec<(String, Field)>> {
    let Datatype::Compound { size, fields } = dt else {
        return Vec::new();
    };
    let size = (*size as usize).max(1);
    raw.chunks_exact(size)
        .take(1 << 16)
        .map(|e| {
            fields
                .iter()
                .map(|f| {
                    let at = f.byte_offset as usize;
                    let len = size_of(&f.datatype, vlen);
                    let bytes = at
                        .checked_add(len)
                        .and_then(|end| e.get(at..end))
                        .unwrap_or(&[]);
                    let value = match &f.datatype {
                        Datatype::String {
                            size: hdf5_reader::StringSize::Fixed(_),
                            ..
                        } => Field::Text(super::bin::latin1(bytes)),
                        Datatype::String { .. } => resolve(bytes, 1)
                            .map(|b| Field::Text(String::from_utf8_lossy(&b).trim().to_string()))
                            .unwrap_or(Field::Other),
                        Datatype::VarLen { base, kind, .. } => match kind {
                            hdf5_reader::VarLenKind::String => resolve(bytes, 1)
                                .map(|b| {
                                    Field::Text(
                                        String::from_utf8_lossy(&b)
                                            .trim_end_matches('\0')
                                            .trim()
                                            .to_string(),
                                    )
                                })
                                .unwrap_or(Field::Other),
                            _ => resolve(bytes, size_of(base, vlen))
                                .and_then(|b| numbers(&b, base))
                                .map(Field::Numbers)
                                .unwrap_or(Field::Other),
                        },
                        Datatype::Array { base, .. } => numbers(bytes, base)
                            .map(Field::Numbers)
                            .unwrap_or(Field::Other),
                        other => numbers(bytes, other)
                            .map(Field::Numbers)
                            .unwrap_or(Field::Other),
                    };
                    (f.name.clone(), value)
                })
                .collect()
        })
        .collect()
}

/// The compound attribute `name` of dataset `ds`, its first element.
pub(crate) fn compound_attr(ds: &Dataset, name: &str) -> Option<Vec<(String, Field)>> {
    let attrs = ds.attributes();
    let a = find(&attrs, name)?;
    let resolve = |r: &[u8], n: usize| ds.resolve_vlen_reference_bytes(r, n).ok();
    compound(&a.raw_data, &a.datatype, ds.vlen_reference_size(), &resolve)
        .into_iter()
        .next()
}

/// The values `selection` picks of dataset `ds`, as read.
fn slice<T: H5Type>(
    ds: &Dataset,
    selection: &SliceInfo,
) -> Result<Vec<T>, hdf5_reader::error::Error> {
    ds.read_slice::<T>(selection)
        .map(|a| a.into_iter().collect())
}

/// The numeric values `selection` picks of dataset `ds`, as doubles.
pub(crate) fn values(
    ds: &Dataset,
    selection: &SliceInfo,
    format: &'static str,
) -> Result<Vec<f64>, Failure> {
    let e = bad(format);
    fn conv<T: Into<f64>>(v: Vec<T>) -> Vec<f64> {
        v.into_iter().map(Into::into).collect()
    }
    Ok(match ds.dtype() {
        Datatype::FloatingPoint { size: 8, .. } => slice::<f64>(ds, selection).map_err(e)?,
        Datatype::FloatingPoint { size: 4, .. } => conv(slice::<f32>(ds, selection).map_err(e)?),
        Datatype::FixedPoint { size, signed, .. } => match (size, signed) {
            (1, true) => conv(slice::<i8>(ds, selection).map_err(e)?),
            (1, false) => conv(slice::<u8>(ds, selection).map_err(e)?),
            (2, true) => conv(slice::<i16>(ds, selection).map_err(e)?),
            (2, false) => conv(slice::<u16>(ds, selection).map_err(e)?),
            (4, true) => conv(slice::<i32>(ds, selection).map_err(e)?),
            (4, false) => conv(slice::<u32>(ds, selection).map_err(e)?),
            (8, true) => slice::<i64>(ds, selection)
                .map_err(e)?
                .into_iter()
                .map(|v| v as f64)
                .collect(),
            _ => slice::<u64>(ds, selection)
                .map_err(e)?
                .into_iter()
                .map(|v| v as f64)
                .collect(),
        },
        other => {
            return Err(Bytes::new(&[], format).bad(format!(
                "the dataset '{}' holds {}, not numbers",
                super::bin::printable(ds.name(), 80),
                super::bin::printable(&format!("{other:?}"), 80)
            )))
        }
    })
}
