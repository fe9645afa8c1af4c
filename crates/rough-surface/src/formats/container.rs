//! contact.engineering containers: the `.zip` a digital surface twin is
//! downloaded as, holding `meta.yml` (its surfaces and their topographies:
//! each a `name`, a `datafile: original:` member of the zip, its `unit`
//! and `size`) and the topographies' files as their instruments wrote
//! them. One topography is read — `--series NAME`, else the first that
//! reads — as its file is read anywhere, its unit taken from `meta.yml`
//! where the file names none; a note lists the others.

use std::io::{Cursor, Read};

use zip::ZipArchive;

use crate::error::{Failure, Problem};
use crate::heights::detrend::Detrend;
use crate::measured::{Measured, Options};
use crate::units::HeightUnit;

/// `meta.yml` is read up to this size.
const MAX_META: u64 = 4 << 20;

fn bad(s: impl AsRef<str>) -> Failure {
    (
        None,
        Problem::Format(format!("contact.engineering container: {}", s.as_ref())),
    )
}

/// A topography as `meta.yml` lists it.
#[derive(Clone, Debug, Default, PartialEq)]
struct Topography {
    name: String,
    file: String,
    unit: Option<String>,
    /// The form contact.engineering removes (`detrend_mode`: `center`,
    /// `height`, `curvature`; `slope` has no counterpart here).
    detrend: Option<Detrend>,
    /// contact.engineering's height scale (`height_scale`), as written.
    height_scale: Option<String>,
}

/// Whether the zip `bytes` is a contact.engineering container.
pub(crate) fn is_container(bytes: &[u8]) -> bool {
    ZipArchive::new(Cursor::new(bytes)).is_ok_and(|z| z.index_for_name("meta.yml").is_some())
}

/// The value of `key: value` on `line` (quotes removed).
fn value<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    let rest = line
        .trim_start()
        .trim_start_matches("- ")
        .strip_prefix(key)?;
    let v = rest.strip_prefix(':')?.trim();
    Some(v.trim_matches(|c| c == '"' || c == '\''))
}

/// The topographies `meta.yml` lists, in its order: each list item under a
/// `topographies:` key, its `name`, `datafile: original:` and `unit`.
fn topographies(meta: &str) -> Vec<Topography> {
    let mut out: Vec<Topography> = Vec::new();
    let mut list: Option<usize> = None;
    let mut item: Option<usize> = None;
    for line in meta.lines() {
        let indent = line.len() - line.trim_start().len();
        let t = line.trim_start();
        if t.is_empty() {
            continue;
        }
        if t.starts_with("topographies:") {
            list = Some(indent);
            item = None;
            continue;
        }
        let Some(l) = list else { continue };
        if indent < l || (indent == l && !t.starts_with("- ")) {
            list = None;
            continue;
        }
        if t.starts_with("- ") && item.is_none_or(|i| indent <= i) {
            item = Some(indent);
            out.push(Topography::default());
        }
        let (Some(i), Some(top)) = (item, out.last_mut()) else {
            continue;
        };
        // The item's own keys sit two columns in; `original` deeper.
        if indent <= i + 2 {
            if let Some(v) = value(line, "name") {
                top.name = v.to_string();
            } else if let Some(v) = value(line, "unit") {
                top.unit = Some(v.to_string());
            } else if let Some(v) = value(line, "height_scale") {
                top.height_scale = Some(v.to_string());
            } else if let Some(v) = value(line, "detrend_mode") {
                top.detrend = match v {
                    "center" => Some(Detrend::Mean),
                    "height" => Some(Detrend::Plane),
                    "curvature" => Some(Detrend::Curvature),
                    _ => None,
                };
            }
        }
        if let Some(v) = value(line, "original") {
            top.file = v.to_string();
        }
    }
    out.retain(|t| !t.file.is_empty());
    for t in &mut out {
        if t.name.is_empty() {
            t.name = t.file.clone();
        }
    }
    out
}

/// A member's extension as the readers take it.
fn ext_of(file: &str) -> String {
    crate::formats::gz::extension(std::path::Path::new(file))
}

/// How a member's bytes (named by their extension) are read as a file.
pub(crate) type Parse<'p> = &'p dyn Fn(&[u8], &Options, &str) -> Result<Measured, Failure>;

/// Reads the container `bytes`; `parse` reads a member's bytes as a file.
pub(crate) fn read(bytes: &[u8], opts: &Options, parse: Parse<'_>) -> Result<Measured, Failure> {
    let mut zip = ZipArchive::new(Cursor::new(bytes))
        .map_err(|e| bad(crate::formats::readers::x3p::unreadable(&e)))?;
    let member = |zip: &mut ZipArchive<Cursor<&[u8]>>, name: &str, limit: u64| {
        let f = zip
            .by_name(name)
            .map_err(|e| bad(format!("{name} cannot be opened ({e})")))?;
        if f.size() > limit {
            return Err(bad(format!(
                "{name} unpacks to more than {} MB",
                limit >> 20
            )));
        }
        let mut out = Vec::new();
        f.take(limit + 1)
            .read_to_end(&mut out)
            .map_err(|e| bad(format!("{name} cannot be unpacked ({e})")))?;
        Ok(out)
    };
    let meta = member(&mut zip, "meta.yml", MAX_META)?;
    let tops = topographies(&String::from_utf8_lossy(&meta));
    if tops.is_empty() {
        return Err(bad("meta.yml lists no topography"));
    }
    let names = tops
        .iter()
        .map(|t| format!("'{}'", t.name))
        .collect::<Vec<_>>()
        .join(", ");
    let inner = Options {
        series: None,
        ..opts.clone()
    };
    let one = |zip: &mut ZipArchive<Cursor<&[u8]>>, t: &Topography| -> Result<Measured, Failure> {
        let data = member(zip, &t.file, crate::limits::MAX_BYTES)?;
        // The form contact.engineering removes, unless --detrend says
        // another (periodic data keep their mean).
        let inner = match t.detrend {
            Some(d) if opts.detrend.is_none() && !opts.periodic && d != inner.detrend_mode() => {
                Options {
                    detrend: Some(d),
                    ..inner.clone()
                }
            }
            _ => inner.clone(),
        };
        let from_meta = inner.detrend != opts.detrend;
        // A text file's height scale set on contact.engineering (an
        // instrument's file gives its own, which meta.yml repeats).
        let scale = t
            .height_scale
            .as_deref()
            .filter(|v| v.parse::<f64>() != Ok(1.0))
            .filter(|_| {
                crate::formats::sniff::format(&data, &ext_of(&t.file))
                    == crate::formats::sniff::Format::Text
            });
        let parse = |data: &[u8], o: &Options, ext: &str| {
            parse(data, o, ext).map(|mut m| {
                if from_meta {
                    for n in &mut m.notes {
                        *n = n.replace("(--detrend ", "(meta.yml's detrend_mode ");
                    }
                }
                if let Some(v) = scale {
                    m.notes.push(format!(
                        "meta.yml's height_scale {v} is not applied: heights as the file gives them"
                    ));
                }
                m
            })
        };
        let ext = ext_of(&t.file);
        let m = parse(&data, &inner, &ext)?;
        // The file names no unit: the container's says it.
        let unitless = m
            .notes
            .iter()
            .any(|n| n.contains("(the file names no unit"));
        match t.unit.as_deref().and_then(HeightUnit::parse) {
            Some(u) if unitless && opts.lateral_unit.is_none() && opts.height_unit.is_none() => {
                let given = Options {
                    lateral_unit: Some(u),
                    height_unit: Some(u),
                    ..inner.clone()
                };
                // Said as the container's, not the command line's.
                Ok(match parse(&data, &given, &ext) {
                    Ok(mut g) => {
                        for n in &mut g.notes {
                            *n = n
                                .replace("(--lateral-unit)", "(meta.yml's unit)")
                                .replace("--lateral-unit; ", "meta.yml's unit; ")
                                .replace("--height-unit; ", "meta.yml's unit; ");
                        }
                        g
                    }
                    Err(_) => m,
                })
            }
            _ => Ok(m),
        }
    };
    let mut skipped = Vec::new();
    let (t, mut m) = match &opts.series {
        Some(s) => {
            let t = tops.iter().find(|t| t.name == *s).ok_or_else(|| {
                (
                    None,
                    Problem::Option(format!(
                        "--series '{s}': the container holds no topography of that name; \
                         its topographies are {names}"
                    )),
                )
            })?;
            let m = one(&mut zip, t).map_err(|(line, p)| {
                (
                    line,
                    Problem::Format(format!("topography '{}' ({}): {p}", t.name, t.file)),
                )
            })?;
            (t, m)
        }
        None => {
            let mut first = None;
            for t in &tops {
                match one(&mut zip, t) {
                    Ok(m) => {
                        first = Some((t, m));
                        break;
                    }
                    Err((_, p)) => skipped.push(format!("'{}' not read: {p}", t.name)),
                }
            }
            first.ok_or_else(|| bad(format!("no topography reads: {}", skipped.join("; "))))?
        }
    };
    let mut notes = Vec::new();
    if tops.len() > 1 {
        notes.push(format!(
            "{} topographies in this contact.engineering container ({names}): '{}' read, \
             --series NAME reads another",
            tops.len(),
            t.name
        ));
    }
    notes.extend(skipped);
    notes.append(&mut m.notes);
    m.notes = notes;
    // The caller sets the SHA-256 of the container itself.
    m.measurement = Some(t.name.clone());
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meta_yml_topographies() {
        let meta = "creation_time: x\nsurfaces:\n- category: exp\n  name: s\n  topographies:\n  \
                    - creator:\n      name: Lars\n    datafile:\n      original: a_X.asc\n    \
                    name: a.asc\n    size: !!python/tuple\n    - 2.0\n    unit: nm\n  - \
                    datafile:\n      original: b.001\n    detrend_mode: curvature\n    height_scale: 0.5\n    name: \"b 2\"\n    unit: mm\n  \
                    name: the surface\n";
        assert_eq!(
            topographies(meta),
            [
                Topography {
                    name: "a.asc".into(),
                    file: "a_X.asc".into(),
                    unit: Some("nm".into()),
                    detrend: None,
                    height_scale: None,
                },
                Topography {
                    name: "b 2".into(),
                    file: "b.001".into(),
                    unit: Some("mm".into()),
                    detrend: Some(Detrend::Curvature),
                    height_scale: Some("0.5".into()),
                }
            ]
        );
    }
}
