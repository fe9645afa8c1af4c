//! Height matrices: each row one y, successive x along the row (Gwyddion's
//! ASCII export, SurfaceTopography's `to_matrix`). One row, or one column
//! (SurfaceTopography's layout for a line scan), is a line scan.

use crate::error::{Failure, Problem};
use crate::formats::text::header::Header;
use crate::formats::text::scan::Scan;
use crate::measured::{Kind, Options};
use crate::spectrum::compute::{self, Computed};
use crate::spectrum::profiles;

pub(crate) fn read(
    scan: Scan<'_>,
    header: &Header,
    opts: &Options,
) -> Result<(Kind, Computed), Failure> {
    let (cols, rows) = (scan.cols, scan.rows());
    let line = cols == 1 || rows == 1;
    let n = if cols == 1 { rows } else { cols };
    if line {
        if n < 4 {
            return Err((
                None,
                Problem::TooFew {
                    axis: "the line",
                    got: n,
                },
            ));
        }
    } else if cols < 4 {
        return Err((
            scan.row_lines.first().copied(),
            Problem::TooFew {
                axis: "x",
                got: cols,
            },
        ));
    } else if rows < 4 {
        return Err((
            None,
            Problem::TooFew {
                axis: "y",
                got: rows,
            },
        ));
    }
    let (width, height) = header.sizes()?;
    let size_line = header
        .width
        .as_ref()
        .or(header.height.as_ref())
        .map(|s| s.line);
    if let (Some(_), Some(p)) = (size_line, opts.pixel_size) {
        return Err((
            size_line,
            Problem::Option(format!(
                "--pixel-size {} does not apply: the file gives its size",
                crate::lengths::typed_length(p)
            )),
        ));
    }
    let (z, note) = crate::units::heights(header.height_source(), opts.height_unit)?;
    let mut h = scan.values;
    if z != 1.0 {
        h.iter_mut().for_each(|v| *v /= z);
    }
    if line {
        let l = match (width, opts.pixel_size) {
            (Some(w), _) => w,
            (None, Some(p)) => p * n as f64,
            (None, None) => return Err((None, Problem::NoSize { line: true })),
        };
        let mut c =
            compute::line(h, l, opts.periodic, opts.detrend_mode()).map_err(|p| (None, p))?;
        c.notes.extend(note);
        return Ok((Kind::Line { n, l }, c));
    }
    let (lx, ly) = match (width, height, opts.pixel_size) {
        (Some(w), Some(hh), _) => (w, hh),
        (None, None, Some(p)) => (p * cols as f64, p * rows as f64),
        (None, None, None) => return Err((None, Problem::NoSize { line: false })),
        (w, _, _) => {
            let missing = if w.is_some() { "Height" } else { "Width" };
            return Err((
                size_line,
                Problem::BadHeader(format!(
                    "a map needs both '# Width:' and '# Height:'; '# {missing}:' is missing"
                )),
            ));
        }
    };
    if let Some(direction) = opts.direction {
        let mut c = profiles::profiles(
            h,
            (cols, rows),
            (lx, ly),
            (opts.periodic, opts.detrend_mode()),
            direction,
        )
        .map_err(|p| (None, p))?;
        c.notes.extend(note);
        let kind = Kind::Profiles {
            direction,
            nx: cols,
            ny: rows,
            lx,
            ly,
        };
        return Ok((kind, c));
    }
    let mut c = compute::map(
        h,
        (cols, rows),
        (lx, ly),
        opts.periodic,
        opts.detrend_mode(),
    )
    .map_err(|p| (None, p))?;
    c.notes.extend(note);
    Ok((
        Kind::Map {
            nx: cols,
            ny: rows,
            lx,
            ly,
        },
        c,
    ))
}
