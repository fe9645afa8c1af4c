//! `export --view moments`: per ζ the moments and what the model makes of
//! them (SI units), the real-space numbers and the Hurst fit (or the power
//! law's parameters) as `#` comment lines before the header; or the same
//! as an SVG picture.

use std::io::Write;

use anyhow::bail;

use super::MAX_SVG_POINTS;
use crate::cli::{ExportArgs, FormatArg};
use crate::figure::{moment_comments, render_moments_svg, scene_text, MomentSeries};
use crate::physical::csv_number;
use crate::scene::State;

/// The moments view's CSV header: ζ, q1 (1/m), λ1 (m), the profile moments
/// m0 (m²), m2 (dimensionless), m4 (1/m²), h_rms (m), h′ (dimensionless), h″ (1/m) and
/// R_s (m).
pub const MOMENTS_HEADER: &str = "zeta,q1,lambda1,m0,m2,m4,h_rms,h_prime,h_dprime,r_s";

/// Refuses the options that do not apply to the moments view.
pub(super) fn check(args: &ExportArgs) -> anyhow::Result<()> {
    for (given, opt) in [
        (args.grid.is_some(), "--grid"),
        (args.map_y.is_some(), "--map-y"),
    ] {
        if given {
            bail!("{opt} applies only to --view map, not to --view moments");
        }
    }
    Ok(())
}

pub(super) fn run(
    format: FormatArg,
    state: &State,
    points: usize,
    out: &mut impl Write,
) -> anyhow::Result<()> {
    if format == FormatArg::Svg {
        if points > MAX_SVG_POINTS {
            bail!(
                "--points {points} is too many for --format svg: at most {MAX_SVG_POINTS} \
                 (CSV takes up to 10000000)"
            );
        }
        let svg = render_moments_svg(state, points)?;
        out.write_all(svg.as_bytes())?;
        out.flush()?;
        return Ok(());
    }
    // The surface's notes first, as every CSV of a surface has them.
    for n in state.surface.iter().flat_map(|s| s.notes()) {
        writeln!(out, "# {n}")?;
    }
    write_moments(out, state, points)
}

/// The comment lines and the table of `state`'s moments at `points` ζ.
pub fn write_moments(out: &mut impl Write, state: &State, points: usize) -> anyhow::Result<()> {
    let s = MomentSeries::of(state, points)?;
    // The scene first, as every CSV has it, then what stands beside the
    // moments.
    let span = format!(
        "cutoffs = zeta from {} to {}, {points} points (log-spaced)",
        csv_number::format(s.zeta[0]),
        csv_number::format(s.zeta[s.len() - 1])
    );
    for c in scene_text::full_lines_of(state, "moments", span)
        .into_iter()
        .chain(moment_comments(state))
    {
        writeln!(out, "# {c}")?;
    }
    writeln!(out, "{MOMENTS_HEADER}")?;
    let mut buf = String::new();
    for i in 0..s.len() {
        let row = [
            s.zeta[i],
            s.q1[i],
            s.lambda1[i],
            s.m0[i],
            s.m2[i],
            s.m4[i],
            s.h_rms[i],
            s.h_prime[i],
            s.h_dprime[i],
            s.r_s[i],
        ];
        for (k, v) in row.iter().enumerate() {
            if k > 0 {
                buf.push(',');
            }
            csv_number::push(&mut buf, *v);
        }
        buf.push('\n');
        if buf.len() > 1 << 16 {
            out.write_all(buf.as_bytes())?;
            buf.clear();
        }
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}
