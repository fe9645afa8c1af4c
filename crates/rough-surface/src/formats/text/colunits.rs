//! Units in a two-column table's header line: `x (mm),z (um)`,
//! `x [mm]  z [µm]`, `# x/mm z/um` — each column's name, then its unit in
//! parentheses, brackets or after a slash; a names line and a units line
//! under it (`X;Y;valid`, `[mm];[mm];[1/0]`: a validity column third);
//! a name and its unit as words (`Lateral um,Raw Micrometer`) or with
//! "in" (`x in µm,y in µm`).

/// A column's name and the unit written with it, if any.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Column {
    pub name: String,
    pub unit: Option<String>,
}

/// `name(unit)`, `name[unit]` or `name/unit` in one token; `(unit)` or
/// `[unit]` alone is the previous name's unit.
fn split(token: &str) -> (Option<&str>, Option<&str>) {
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let (Some(a), true) = (token.find(open), token.ends_with(close)) {
            let name = token[..a].trim();
            let unit = token[a + 1..token.len() - 1].trim();
            return ((!name.is_empty()).then_some(name), Some(unit));
        }
    }
    if let Some((name, unit)) = token.split_once('/') {
        if !name.is_empty() && !unit.is_empty() {
            return (Some(name), Some(unit));
        }
    }
    (Some(token), None)
}

/// The columns a header line names, in order; `None` unless every unit
/// is attached to a name.
pub(crate) fn columns(line: &str) -> Option<Vec<Column>> {
    let mut out: Vec<Column> = Vec::new();
    let mut tokens = line
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | ';' | '#'))
        .filter(|t| !t.is_empty());
    while let Some(t) = tokens.next() {
        // `x in µm` (a Windows export's header): the unit after "in".
        if t.eq_ignore_ascii_case("in") && out.last().is_some_and(|c| c.unit.is_none()) {
            let unit = tokens.next()?;
            out.last_mut()?.unit = Some(unit.to_string());
            continue;
        }
        match split(t) {
            (Some(name), unit) => out.push(Column {
                name: name.to_lowercase(),
                unit: unit.map(str::to_string),
            }),
            (None, Some(unit)) => {
                let last = out.last_mut().filter(|c| c.unit.is_none())?;
                last.unit = Some(unit.to_string());
            }
            (None, None) => return None,
        }
    }
    Some(out)
}

/// Whether `c` is a validity column (`valid`, `validity`: 1 a point
/// measured, 0 not).
fn is_validity(c: &Column) -> bool {
    c.name.starts_with("valid")
}

/// Whether a header line names three columns, the third a validity
/// column (`X;Y;valid` of an .hfm profile).
pub(crate) fn validity(lines: &[(usize, &str)]) -> bool {
    lines.iter().any(|&(_, t)| {
        columns(t).is_some_and(|c| c.len() == 3 && is_validity(&c[2]) && !is_validity(&c[0]))
    })
}

/// Whether a header names the columns of a profile in a way only a
/// profile's header does: a validity column, or a name and unit as words
/// (`Lateral um,Raw Micrometer`).
pub(crate) fn names_profile(lines: &[(usize, &str)]) -> bool {
    validity(lines) || lines.iter().any(|&(_, t)| worded(t).is_some())
}

/// A line of units only, one a column: `[mm];[mm];[1/0]`.
fn units_only(line: &str) -> Option<Vec<String>> {
    line.split(|c: char| c.is_whitespace() || matches!(c, ',' | ';' | '#'))
        .filter(|t| !t.is_empty())
        .map(|t| {
            let t = t.strip_prefix('[')?.strip_suffix(']')?;
            Some(t.trim().to_string())
        })
        .collect()
}

/// `Lateral um,Raw Micrometer,` (a Dektak CSV): two fields, each a name
/// and its unit as the last word.
fn worded(line: &str) -> Option<(String, String)> {
    let fields: Vec<&str> = line
        .split([',', ';', '\t'])
        .map(str::trim)
        .filter(|f| !f.is_empty())
        .collect();
    let [x, z] = fields[..] else { return None };
    let unit = |f: &str| {
        let (_, u) = f.rsplit_once(' ')?;
        crate::units::per_metre(u).map(|_| u.to_string())
    };
    Some((unit(x)?, unit(z)?))
}

/// The units of an `x z` header, (x, z), with its line: the first header
/// line that names two columns (and maybe a validity column third) and a
/// unit for at least one of them; a names line followed by a line of
/// units only (`X;Y;valid` then `[mm];[mm];[1/0]`); or two fields, each a
/// name and its unit (`Lateral um,Raw Micrometer`).
pub(crate) fn scan_units<'a>(
    lines: &'a [(usize, &'a str)],
) -> Option<(usize, Option<String>, Option<String>)> {
    lines.iter().enumerate().find_map(|(k, &(line, text))| {
        if let Some((x, z)) = worded(text) {
            return Some((line, Some(x), Some(z)));
        }
        let cols = columns(text)?;
        let named = match &cols[..] {
            [x, z] => Some((x, z)),
            [x, z, v] if is_validity(v) => Some((x, z)),
            [i, x, z] if i.name == "index" => Some((x, z)),
            _ => None,
        };
        let (x, z) = named?;
        if x.unit.is_some() || z.unit.is_some() {
            return Some((line, x.unit.clone(), z.unit.clone()));
        }
        let units = units_only(lines.get(k + 1)?.1)?;
        (units.len() == cols.len()).then(|| {
            (
                lines[k + 1].0,
                Some(units[0].clone()),
                Some(units[1].clone()),
            )
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_units() {
        let u = |s: &'static str| Some(s.to_string());
        for (text, x, z) in [
            ("x (mm),z (um)", u("mm"), u("um")),
            ("x [mm]  z [µm]", u("mm"), u("µm")),
            ("x/mm z/um", u("mm"), u("um")),
            ("x(nm);height(nm)", u("nm"), u("nm")),
            ("x [mm] z", u("mm"), None),
        ] {
            assert_eq!(scan_units(&[(1, text)]), Some((1, x, z)), "{text}");
        }
        assert_eq!(scan_units(&[(1, "x z")]), None);
        // An .hfm profile's names, then its units; a Dektak CSV's header.
        let hfm = [(2, "X;Y;valid"), (3, "[mm];[mm];[1/0]")];
        assert_eq!(scan_units(&hfm), Some((3, u("mm"), u("mm"))));
        assert!(validity(&hfm));
        assert!(!validity(&[(1, "x y z")]));
        assert_eq!(
            scan_units(&[(5, "Lateral um,Raw Micrometer,")]),
            Some((5, u("um"), u("Micrometer")))
        );
        assert_eq!(
            scan_units(&[(1, "x in µm,y in µm ")]),
            Some((1, u("µm"), u("µm")))
        );
        assert_eq!(scan_units(&[(1, "x (mm) y (mm) z (um)")]), None);
        assert_eq!(
            columns("x (mm),z (um)").unwrap()[1],
            Column {
                name: "z".into(),
                unit: Some("um".into())
            }
        );
    }
}
