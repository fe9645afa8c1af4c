//! CSV of the index, map and load views. Each starts with the scene in `#`
//! lines (pandas' `comment='#'` skips them), then the header. Undefined
//! values (eq. 13 at R* = 0) are empty fields; numbers are in
//! [`crate::physical::csv_number`]'s form.

use std::io::Write;

use crate::figure::scene_text::csv_comments;
use crate::figure::{
    FigureOptions, IndexSeries, LoadCurve, MapSpec, RegimeMap, SpectrumSeries, View,
};
use crate::physical::csv_number;
use crate::scene::State;

/// The index view's CSV header after the first column, which is named
/// after the swept parameter (`zeta`, `h0_over_e`, …).
pub const INDICES_HEADER: &str = "psi_gw,psi_p,psi_star,psi_star_asymptotic,hy_over_h0";
/// The map's CSV header after the first two columns, named after the
/// parameters across and up (one row per cell, across fastest).
pub const MAP_HEADER: &str = "psi,elastic,plastic,total,plastic_share";
/// The load view's CSV header.
pub const LOAD_HEADER: &str = "load,elastic,plastic,total";
/// The spectrum view's CSV header: q (1/m), the data's PSD (C^iso in m⁴ or
/// C1D in m³, SurfaceTopography's convention) and the power law fitted
/// over [q0, q1] (empty outside that band).
pub const SPECTRUM_HEADER: &str = "q,psd,fit";

/// Rows computed and written at a time, so memory stays bounded.
const BLOCK: usize = 1 << 14;

/// Appends one CSV line; `None` is an empty field.
fn push_row(buf: &mut String, fields: &[Option<f64>]) {
    for (k, v) in fields.iter().enumerate() {
        if k > 0 {
            buf.push(',');
        }
        if let Some(v) = v {
            csv_number::push(buf, *v);
        }
    }
    buf.push('\n');
}

/// Writes `head` (the `#` lines and the header), then the rows
/// `block(range, buf)` formats, block by block.
fn write_blocks(
    out: &mut impl Write,
    head: &str,
    points: usize,
    mut block: impl FnMut(std::ops::Range<usize>, &mut String) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    // Fail before the header if the request itself is bad.
    block(0..0, &mut String::new())?;
    out.write_all(head.as_bytes())?;
    let mut buf = String::new();
    let mut start = 0;
    while start < points {
        let end = (start + BLOCK).min(points);
        buf.clear();
        block(start..end, &mut buf)?;
        out.write_all(buf.as_bytes())?;
        start = end;
    }
    out.flush()?;
    Ok(())
}

/// The `#` lines of `view` and the header: the swept parameter's column,
/// then `rest`.
fn head(state: &State, view: View, points: usize, rest: &str) -> String {
    let opts = FigureOptions {
        points,
        ..FigureOptions::default()
    };
    format!(
        "{}{},{rest}\n",
        csv_comments(state, view, &opts),
        state.sweep.axis().field()
    )
}

/// The indices of `state` at `points` points of its sweep.
pub fn write_indices(out: &mut impl Write, state: &State, points: usize) -> anyhow::Result<()> {
    let head = head(state, View::Indices, points, INDICES_HEADER);
    write_blocks(out, &head, points, |range, buf| {
        let s = IndexSeries::compute_range(state, points, range)?;
        for i in 0..s.len() {
            push_row(
                buf,
                &[
                    Some(s.x[i]),
                    Some(s.psi_gw[i]),
                    Some(s.psi_p[i]),
                    Some(s.psi_star[i]),
                    s.psi_star_asymptotic[i],
                    Some(s.hardness_ratio[i]),
                ],
            );
        }
        Ok(())
    })
}

/// The areas of `state` at `points` loads from 0 to 1.
pub fn write_load(out: &mut impl Write, state: &State, points: usize) -> anyhow::Result<()> {
    let opts = FigureOptions {
        points,
        ..FigureOptions::default()
    };
    let head = format!("{}{LOAD_HEADER}\n", csv_comments(state, View::Load, &opts));
    write_blocks(out, &head, points, |range, buf| {
        let c = LoadCurve::compute_range(state, points, range)?;
        for i in 0..c.load.len() {
            let row = [c.load[i], c.elastic[i], c.plastic[i], c.total[i]];
            push_row(buf, &row.map(Some));
        }
        Ok(())
    })
}

/// The regime map of `state` on `opts.grid` with `opts.map_y` up: rows from
/// the bottom of the y range, x fastest.
pub fn write_map(out: &mut impl Write, state: &State, opts: &FigureOptions) -> anyhow::Result<()> {
    let spec = MapSpec::of(state, opts.grid, opts.map_y)?;
    let m = RegimeMap::compute(&spec);
    out.write_all(csv_comments(state, View::Map, opts).as_bytes())?;
    writeln!(
        out,
        "{},{},{MAP_HEADER}",
        spec.x.axis().field(),
        spec.y.axis().field()
    )?;
    let mut buf = String::new();
    for row in 0..spec.rows {
        buf.clear();
        let y = spec.y_at(row);
        for col in 0..spec.cols {
            let k = row * spec.cols + col;
            let fields = [
                spec.x_at(col),
                y,
                m.psi[k],
                m.elastic[k],
                m.plastic[k],
                m.total[k],
                m.share[k],
            ];
            push_row(&mut buf, &fields.map(Some));
        }
        out.write_all(buf.as_bytes())?;
    }
    out.flush()?;
    Ok(())
}

/// A measured surface's spectrum and the power law fitted over [q0, q1].
pub fn write_spectrum(out: &mut impl Write, state: &State) -> anyhow::Result<()> {
    let s = SpectrumSeries::of(state)?;
    let opts = FigureOptions::default();
    out.write_all(csv_comments(state, View::Spectrum, &opts).as_bytes())?;
    writeln!(out, "{SPECTRUM_HEADER}")?;
    let mut buf = String::new();
    for i in 0..s.q.len() {
        push_row(&mut buf, &[Some(s.q[i]), Some(s.psd[i]), s.fit[i]]);
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}
