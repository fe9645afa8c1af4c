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
//! What remains is an `x z` table, read by `columns`.

use crate::error::{Failure, Problem};
use crate::header::Header;
use crate::text::Scan;

/// Rewrites `scan` as two columns where it is a profile of three (or
/// more) columns: `None` where it is not, else the rows marked not
/// measured.
pub(crate) fn as_profile(scan: &mut Scan<'_>, header: &Header) -> Result<Option<usize>, Failure> {
    let cols = scan.cols;
    if cols < 3 || header.has_size() || scan.rows() == 0 {
        return Ok(None);
    }
    let empty_after_two = scan
        .values
        .chunks_exact(cols)
        .all(|row| row[2..].iter().all(|v| v.is_nan()));
    if empty_after_two {
        keep_two(scan, |_, _| Ok(true))?;
        return Ok(Some(0));
    }
    if cols != 3 || !crate::colunits::validity(&scan.header) {
        return Ok(None);
    }
    let lines = scan.row_lines.clone();
    let zeros = std::cell::Cell::new(0);
    keep_two(scan, |k, v| match v {
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
    Ok(Some(zeros.get()))
}

/// Keeps each row's x and z, z undefined where `measured(row, third)` is
/// false.
fn keep_two(
    scan: &mut Scan<'_>,
    measured: impl Fn(usize, f64) -> Result<bool, Failure>,
) -> Result<(), Failure> {
    let cols = scan.cols;
    let mut out = Vec::with_capacity(2 * scan.rows());
    for (k, row) in scan.values.chunks_exact(cols).enumerate() {
        let z = if measured(k, row[2])? {
            row[1]
        } else {
            f64::NAN
        };
        out.extend([row[0], z]);
    }
    scan.values = out;
    scan.cols = 2;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::{head, scan};

    fn two(t: &str) -> Result<(Option<usize>, Vec<Option<f64>>), Failure> {
        let mut s = scan(t, head(t)?)?;
        let h = Header::read(&s.header)?;
        let done = as_profile(&mut s, &h)?;
        let v = s.values.iter().map(|v| (!v.is_nan()).then_some(*v));
        Ok((done, v.collect()))
    }

    #[test]
    fn trailing_cells_and_validity() {
        let (done, v) = two("Lateral um,Raw Micrometer,\n0.0,-0.5,,\n0.2,0.25,,\n").unwrap();
        assert_eq!(done, Some(0));
        assert_eq!(v, [Some(0.0), Some(-0.5), Some(0.2), Some(0.25)]);
        let (done, v) = two("X;Y;valid\n[mm];[mm];[1/0]\n1;2;1\n2;9;0\n3;4;1\n").unwrap();
        assert_eq!(done, Some(1));
        assert_eq!(v, [Some(1.), Some(2.), Some(2.), None, Some(3.), Some(4.)]);
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
