//! Units in a two-column table's header line: `x (mm),z (um)`,
//! `x [mm]  z [µm]`, `# x/mm z/um` — each column's name, then its unit in
//! parentheses, brackets or after a slash.

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
    let tokens = line
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | ';' | '#'))
        .filter(|t| !t.is_empty());
    for t in tokens {
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

/// The units of an `x z` header, (x, z), with its line: the first header
/// line that names two columns and a unit for at least one of them.
pub(crate) fn scan_units<'a>(
    lines: &'a [(usize, &'a str)],
) -> Option<(usize, Option<String>, Option<String>)> {
    lines.iter().find_map(|&(line, text)| {
        let cols = columns(text)?;
        match &cols[..] {
            [x, z] if x.unit.is_some() || z.unit.is_some() => {
                Some((line, x.unit.clone(), z.unit.clone()))
            }
            _ => None,
        }
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
