//! Three numbers a row that are a profile, not an XYZ point cloud:
//!
//! - empty trailing cells: a Dektak CSV export closes every row with two
//!   commas (`0.0,-0.00933,,`), so each row has a third, empty cell: the
//!   columns after the second that hold nothing in any row are dropped;
//! - a validity column: a header naming a third column `valid` (an .hfm
//!   profile's `X;Y;valid`, then `[mm];[mm];[1/0]`): a row whose validity
//!   is 0 is a point not measured, its height undefined (filled as any
//!   undefined point, within `--max-undefined`); 1 a point measured.
//!
//! - a first column of the rows' numbers (0, 1, 2 … or 1, 2, 3 …: a
//!   Windows export's `index, x in µm, y in µm`): x and z follow it.
//!
//! What remains is an `x z` table, read by `columns`.

use crate::error::{Failure, Problem};
use crate::formats::text::header::Header;
use crate::formats::text::scan::Scan;

/// Rewrites `scan` as two columns where it is a profile of three (or
/// more) columns; the notes on what was read so.
pub(crate) fn as_profile(scan: &mut Scan<'_>, header: &Header) -> Result<Vec<String>, Failure> {
    let cols = scan.cols;
    if cols < 3 || header.has_size() || scan.rows() == 0 {
        return Ok(Vec::new());
    }
    let empty_after_two = scan
        .values
        .chunks_exact(cols)
        .all(|row| row[2..].iter().all(|v| v.is_nan()));
    if empty_after_two {
        keep_two(scan, (0, 1), |_, _| Ok(true))?;
        return Ok(Vec::new());
    }
    if cols != 3 {
        return Ok(Vec::new());
    }
    let first: Vec<f64> = scan.values.iter().step_by(3).copied().collect();
    if scan.rows() >= 4
        && (first[0] == 0.0 || first[0] == 1.0)
        && first
            .iter()
            .enumerate()
            .all(|(k, &v)| v == first[0] + k as f64)
        && scan.values[1..]
            .iter()
            .step_by(3)
            .zip(scan.values[4..].iter().step_by(3))
            .all(|(a, b)| b > a)
    {
        keep_two(scan, (1, 2), |_, _| Ok(true))?;
        return Ok(vec![format!(
            "the first column ({}, {}, {} …) read as the rows' numbers, x and z after it",
            first[0],
            first[0] + 1.0,
            first[0] + 2.0
        )]);
    }
    if !crate::formats::text::colunits::validity(&scan.header) {
        return Ok(Vec::new());
    }
    let lines = scan.row_lines.clone();
    let zeros = std::cell::Cell::new(0);
    keep_two(scan, (0, 1), |k, v| match v {
        1.0 => Ok(true),
        0.0 => {
            zeros.set(zeros.get() + 1);
            Ok(false)
        }
        v => Err((
            Some(lines[k]),
            Problem::Format(format!(
                "the validity column holds {}: 1 marks a measured point, 0 one not measured",
                if v.is_nan() {
                    "nothing".to_string()
                } else {
                    v.to_string()
                }
            )),
        )),
    })?;
    Ok(match zeros.get() {
        0 => Vec::new(),
        1 => vec!["1 point not measured (validity 0) read as undefined".to_string()],
        n => vec![format!(
            "{n} points not measured (validity 0) read as undefined"
        )],
    })
}

/// Keeps each row's x and z (columns `x`, `z`), z undefined where
/// `measured(row, third)` is false.
fn keep_two(
    scan: &mut Scan<'_>,
    (x, z): (usize, usize),
    measured: impl Fn(usize, f64) -> Result<bool, Failure>,
) -> Result<(), Failure> {
    let cols = scan.cols;
    let mut out = Vec::with_capacity(2 * scan.rows());
    for (k, row) in scan.values.chunks_exact(cols).enumerate() {
        let h = if measured(k, row[2])? {
            row[z]
        } else {
            f64::NAN
        };
        out.extend([row[x], h]);
    }
    scan.values = out;
    scan.cols = 2;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formats::text::scan::{head, scan};

    /// The notes where the table became x z, and its values (None undefined).
    type Read = (Option<Vec<String>>, Vec<Option<f64>>);

    fn two(t: &str) -> Result<Read, Failure> {
        let mut s = scan(t, head(t)?)?;
        let h = Header::read(&s.header)?;
        let notes = as_profile(&mut s, &h)?;
        let done = (s.cols == 2).then_some(notes);
        let v = s.values.iter().map(|v| (!v.is_nan()).then_some(*v));
        Ok((done, v.collect()))
    }

    #[test]
    fn trailing_cells_and_validity() {
        let (done, v) = two("Lateral um,Raw Micrometer,\n0.0,-0.5,,\n0.2,0.25,,\n").unwrap();
        assert_eq!(done, Some(vec![]));
        assert_eq!(v, [Some(0.0), Some(-0.5), Some(0.2), Some(0.25)]);
        let (done, v) = two("X;Y;valid\n[mm];[mm];[1/0]\n1;2;1\n2;9;0\n3;4;1\n").unwrap();
        assert_eq!(
            done.unwrap(),
            ["1 point not measured (validity 0) read as undefined"]
        );
        assert_eq!(v, [Some(1.), Some(2.), Some(2.), None, Some(3.), Some(4.)]);
        let (done, v) = two("index, x in µm, y in µm\n0,5,1\n1,6,2\n2,7,3\n3,8,4\n").unwrap();
        assert_eq!(
            done.unwrap(),
            ["the first column (0, 1, 2 …) read as the rows' numbers, x and z after it"]
        );
        assert_eq!(v[..4], [Some(5.), Some(1.), Some(6.), Some(2.)]);
        // Rows' numbers before an x that does not increase: a cloud.
        assert_eq!(two("0 0 1\n1 0 2\n2 1 3\n3 1 4\n").unwrap().0, None);
        // An XYZ cloud stays three columns.
        assert_eq!(two("x y z\n1 2 3\n4 5 6\n").unwrap().0, None);
        // A third column partly empty is no trailing cell.
        assert_eq!(two("1,2,3\n4,5,\n").unwrap().0, None);
        let e = two("X;Y;valid\n1;2;1\n2;9;0.5\n").unwrap_err();
        assert_eq!(e.0, Some(3));
        let e = two("X;Y;valid\n1;2;1\n2;9;\n").unwrap_err();
        assert_eq!(
            e,
            (
                Some(3),
                Problem::Format(
                    "the validity column holds nothing: 1 marks a measured point, 0 one \
                     not measured"
                        .into()
                )
            )
        );
    }
}
