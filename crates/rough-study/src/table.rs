//! The one reader of the reference tables: `#` comment lines, a header of
//! column names, then one row of numbers per line (`inf` for infinity, an
//! empty field for "not defined"). Columns are found by name, so their order
//! may change.

use std::collections::HashMap;
use std::fmt;

/// A malformed table or a missing column, with where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableError(String);

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for TableError {}

/// One reference table, every field read as a number.
#[derive(Clone, Debug)]
pub struct Table {
    /// Where it came from (file name, or `text`), for messages.
    pub name: String,
    pub columns: Vec<String>,
    /// One entry per data line; `None` for an empty field.
    pub rows: Vec<Vec<Option<f64>>>,
    index: HashMap<String, usize>,
}

impl Table {
    /// Reads `name` from [`crate::DATA_DIR`], or the file at `name` when it
    /// is an absolute path.
    pub fn read(name: &str) -> Result<Table, TableError> {
        let path = if name.starts_with('/') {
            name.to_string()
        } else {
            format!("{}/{name}", crate::DATA_DIR)
        };
        let text =
            std::fs::read_to_string(&path).map_err(|e| TableError(format!("{path}: {e}")))?;
        Table::parse(name, &text)
    }

    /// Parses a table's text; `name` appears in the errors.
    pub fn parse(name: &str, text: &str) -> Result<Table, TableError> {
        let err = |msg: String| TableError(format!("{name}: {msg}"));
        let mut lines = text
            .lines()
            .map(str::trim)
            .enumerate()
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let (_, header) = lines.next().ok_or_else(|| err("no header line".into()))?;
        let columns: Vec<String> = header.split(',').map(|c| c.trim().to_owned()).collect();
        let mut rows = Vec::new();
        for (i, line) in lines {
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            if fields.len() != columns.len() {
                return Err(err(format!(
                    "line {}: {} fields, expected {}",
                    i + 1,
                    fields.len(),
                    columns.len()
                )));
            }
            let row = fields
                .iter()
                .map(|f| match *f {
                    "" => Ok(None),
                    f => match f.parse::<f64>() {
                        Ok(v) if !v.is_nan() => Ok(Some(v)),
                        _ => Err(err(format!("line {}: bad number {f:?}", i + 1))),
                    },
                })
                .collect::<Result<Vec<_>, _>>()?;
            rows.push(row);
        }
        if rows.is_empty() {
            return Err(err("no data rows".into()));
        }
        let index = columns
            .iter()
            .enumerate()
            .map(|(i, c)| (c.clone(), i))
            .collect();
        Ok(Table {
            name: name.to_string(),
            columns,
            rows,
            index,
        })
    }

    /// The index of column `name`.
    pub fn col(&self, name: &str) -> Result<usize, TableError> {
        self.index
            .get(name)
            .copied()
            .ok_or_else(|| TableError(format!("{}: no column {name:?}", self.name)))
    }

    /// The value in `row` of column `name`; `None` for an empty field.
    /// Panics on an unknown column: for tests, which name their columns.
    pub fn get(&self, row: &[Option<f64>], name: &str) -> Option<f64> {
        row[self.col(name).unwrap_or_else(|e| panic!("{e}"))]
    }
}

/// The columns of both models' three outputs (elastic, plastic, total), as
/// the slopes and areas tables name them.
pub const MODEL_COLUMNS: [&str; 6] = [
    "exact_elastic",
    "exact_plastic",
    "exact_total",
    "closed_elastic",
    "closed_plastic",
    "closed_total",
];

/// One row of the slopes reference: ψ, the exact and the closed-form slopes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlopeRow {
    pub psi: f64,
    /// Elastic, plastic, total of the exact model.
    pub exact: [f64; 3],
    /// Elastic, plastic, total of the paper's closed form.
    pub closed: [f64; 3],
}

/// The rows of a slopes table (by default [`crate::SLOPES_CSV`]); every one
/// of its seven columns must be filled.
pub fn slopes_reference(text: &str) -> Result<Vec<SlopeRow>, TableError> {
    let t = Table::parse("slopes.csv", text)?;
    let mut names = ["psi"; 7];
    names[1..].copy_from_slice(&MODEL_COLUMNS);
    let mut idx = [0; 7];
    for (slot, name) in idx.iter_mut().zip(names) {
        *slot = t.col(name)?;
    }
    t.rows
        .iter()
        .enumerate()
        .map(|(n, row)| {
            let mut v = [0.0; 7];
            for (k, &j) in idx.iter().enumerate() {
                v[k] = row[j].ok_or_else(|| {
                    TableError(format!("slopes.csv: row {}: no {}", n + 1, names[k]))
                })?;
            }
            Ok(SlopeRow {
                psi: v[0],
                exact: [v[1], v[2], v[3]],
                closed: [v[4], v[5], v[6]],
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_reference_parses_with_corners() {
        let r = slopes_reference(crate::SLOPES_CSV).unwrap();
        assert!(r.len() > 100);
        assert!(r.iter().any(|x| x.psi <= 1e-8) && r.iter().any(|x| x.psi >= 1e8));
        let zero = r.iter().find(|x| x.psi == 0.0).unwrap();
        assert_eq!(zero.exact, [f64::INFINITY, 0.0, f64::INFINITY]);
    }

    #[test]
    fn columns_by_name_and_bad_rows_refused() {
        let t = "# c\npsi,exact_total,exact_plastic,exact_elastic,closed_elastic,closed_plastic,closed_total\n1.0,3,2,1,4,5,6\n";
        let r = slopes_reference(t).unwrap();
        assert_eq!(r[0].exact, [1.0, 2.0, 3.0]);
        assert_eq!(r[0].closed, [4.0, 5.0, 6.0]);
        let e = slopes_reference("psi,exact_elastic\n1,2\n").unwrap_err();
        assert!(e.to_string().contains("no column \"exact_plastic\""), "{e}");
        let bad = "psi,exact_elastic,exact_plastic,exact_total,closed_elastic,closed_plastic,closed_total\n1,2,3\n";
        let e = slopes_reference(bad).unwrap_err();
        assert!(
            e.to_string().contains("line 2: 3 fields, expected 7"),
            "{e}"
        );
        assert!(Table::parse("t", "a,b\n1,nan\n").is_err());
        assert!(Table::parse("t", "a,b\n").is_err());
        let t = Table::parse("t", "a,b\n1,\n-inf,2e-3\n").unwrap();
        assert_eq!(t.get(&t.rows[0], "b"), None);
        assert_eq!(t.get(&t.rows[1], "a"), Some(f64::NEG_INFINITY));
    }
}
