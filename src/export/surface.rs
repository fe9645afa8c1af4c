//! `roughtui export --view surface`: the scene's synthetic surface exactly
//! as the contact views solve it (the seed's modes on the cell and grid of
//! `--cell`, `--contact-grid` / `--per-wavelength`, rescaled to the scene's
//! rms slope), as a height matrix with its size and unit in the header that
//! Gwyddion's ASCII export and SurfaceTopography write. `roughtui --surface
//! FILE --periodic` reads it back, and so does SurfaceTopography's
//! `read_topography`, so that another code can solve the same contact
//! (scripts/surface_tamaas_reference.py solves it with Tamaas).

use std::io::Write;

use anyhow::bail;

use crate::cli::{ExportArgs, FormatArg};
use crate::contact::scene::SceneKey;
use crate::contact::{Sampling, Seeds, DEFAULT_SEED};
use crate::figure::scene_text::full_lines_of;
use crate::physical::csv_number;
use crate::scene::State;

/// What the surface view spans, in full.
fn span(key: &SceneKey, sampling: &Sampling, length: f64) -> String {
    let n = key.n;
    format!(
        "surface = the contact views' heights: periodic {n} × {n} grid of side {} m (a cell of \
         {}), {} nodes per shortest wavelength, seed {}",
        csv_number::format(length),
        sampling.cell_words(),
        csv_number::format(sampling.per_wavelength(n, key.zeta())),
        key.seed
    )
}

/// `roughtui export --view surface`.
pub fn export(args: &ExportArgs, out: &mut impl Write) -> anyhow::Result<()> {
    super::refuse_given(
        "surface",
        "it writes one seed's heights (--seed, --cell, --contact-grid or --per-wavelength pick \
         them)",
        &[
            (args.grid.is_some(), "--grid"),
            (args.map_y.is_some(), "--map-y"),
            (args.sweep.is_some(), "--sweep"),
            (args.points.is_some(), "--points"),
            (args.seeds.is_some(), "--seeds"),
            (args.simulate.hardness.is_some(), "--hardness"),
            (args.simulate.load_scale.is_some(), "--load-scale"),
        ],
    )?;
    if args.format == FormatArg::Svg {
        bail!("--view surface is a height matrix: text only (no --format svg)");
    }
    let state = super::state_of(args)?;
    if state.is_measured() {
        bail!(
            "--view surface writes the synthetic surface of a power-law scene: a measured map's \
             heights are its file's"
        );
    }
    args.simulate.check(&state)?;
    let sampling = args.simulate.sampling(Sampling::default());
    let seed = args.seed.or(state.seed).unwrap_or(DEFAULT_SEED);
    write(out, &state, &sampling, seed)
}

/// Writes the heights of `state`'s surface for `seed` on `sampling`'s cell
/// and grid: the header (size and unit), the scene in `#` lines, then one
/// line per grid row (y), one height per node (x), in metres with every
/// digit.
pub fn write(
    out: &mut impl Write,
    state: &State,
    sampling: &Sampling,
    seed: u64,
) -> anyhow::Result<()> {
    let key = SceneKey::with(state, seed, sampling)?;
    let h = key.heights()?;
    let (n, length) = (key.n, key.length());
    let l = csv_number::format(length);
    let mut s = String::with_capacity(n * n * 24 + 4096);
    s.push_str(&format!(
        "# Channel: Height (roughtui synthetic surface of scene {:?}, {})\n\
         # Width: {l} m\n# Height: {l} m\n# Value units: m\n",
        state.name,
        Seeds::one(seed).words()
    ));
    for line in full_lines_of(state, "surface", span(&key, sampling, length)) {
        s.push_str(&format!("# {line}\n"));
    }
    s.push_str(&format!(
        "# synthesis = power-law Gaussian surface, wavevectors q0 … zeta q0 (the spectrum flat \
         below q0 in a cell of more than one longest wavelength), rescaled to the scene's rms \
         slope sqrt(2 m2) = {}; rows along y from the first, values along x; periodic\n\
         # hardness_in_use_over_e = {} ({}/E*, the contact views' pressure cap and load unit); \
         to solve it in cell units divide lengths and heights by the side L\n",
        csv_number::format(key.rms_slope()),
        csv_number::format(key.hardness()),
        state.hardness_name()
    ));
    out.write_all(s.as_bytes())?;
    for row in h.chunks(n) {
        s.clear();
        for (i, v) in row.iter().enumerate() {
            if i > 0 {
                s.push(' ');
            }
            csv_number::push(&mut s, *v);
        }
        s.push('\n');
        out.write_all(s.as_bytes())?;
    }
    out.flush()?;
    Ok(())
}
