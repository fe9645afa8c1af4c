//! The contact views' CSV: the `#` lines that say which question each
//! number answers (the load and its unit, the hardness and its radius, the
//! cell, the grid, the seeds), then the rows.

use std::io::Write;

use super::{load_rows, sweep_rows, Simulation, Spec, Stat, SWEEP_LOAD};
use crate::physical::csv_number;
use crate::scene::State;

/// The contact view's CSV header: means over the seeds, then the spread;
/// then the load over H0 and the area with the grid's edge corrected.
pub const CONTACT_HEADER: &str = "p_over_h,area,elastic_area,plastic_area,mean_gap,iterations,\
residual,theory_area,theory_elastic_area,theory_plastic_area,area_sd,elastic_area_sd,\
plastic_area_sd,seeds,p_over_h0,area_corrected,area_corrected_sd";
/// The ζ sweep's CSV header.
pub const SWEEP_HEADER: &str = "zeta,p_over_h0,p_over_h,plastic_share,theory_plastic_share,\
area,theory_area,grid,iterations,residual,plastic_share_sd,area_sd,seeds,hardness_over_e,\
theory_hardness_over_e,patches,patch_radius,area_corrected,area_corrected_sd";

/// Persson's light-load κ = √(8/π): A/A0 = κ p̄/(E* h′).
pub const PERSSON_KAPPA: f64 = 1.5957691216057308;

/// Which elastic/plastic reading the theory's split takes, in words.
pub fn theory_split(model: rough_model::Model) -> &'static str {
    match model {
        rough_model::Model::ClosedForm => {
            "the closed form's elastic area is its image solution's mass on [0, H] and its \
             plastic area the total less that (Appendix A as docs/model.md reads it; Persson's \
             purely elastic erf as the elastic area would leave a far smaller plastic share)"
        }
        rough_model::Model::Exact => {
            "the exact two-barrier solution's elastic area is its mass on [0, H], its plastic \
             area the flux absorbed at H (load balance)"
        }
    }
}

/// The hardness a simulation caps its pressure at, in words: one cap, or
/// a cap per node and the radius it takes.
pub fn hardness_words(sim: &Simulation, state: &State) -> String {
    use super::local::Radius;
    let Some(law) = &sim.local else {
        return format!(
            "global: one cap {}/E* = {} at every node, as the theory has it",
            state.hardness_name(),
            csv_number::format(sim.hardness)
        );
    };
    let how = match law.radius {
        Radius::Asperity => {
            "asperity: each node capped at H0 sqrt(1 + R*/(1.2 R)) with R the curvature radius \
             of its asperity, the paraboloid fitted to the surface under its patch of the purely \
             elastic contact at the same load (a node outside the patches takes its nearest \
             patch's, a patch spanning the cell H0)"
        }
        Radius::Summit => {
            "summit: each node capped at H0 sqrt(1 + R*/(1.2 R)) with R = 1/(-laplacian(h)/2) \
             at the summit steepest ascent on the heights takes it to (the local maximum of its \
             8-neighbours' steepest rise; H0 where that summit is not convex)"
        }
    };
    format!(
        "{how} (H0/E* = {}, R* = {} m); hardness_in_use_over_e, the loads' unit, is the \
         theory's H_y at R_s",
        csv_number::format(law.h0),
        csv_number::format(law.r_star)
    )
}

/// The `#` lines of a contact CSV: `scene` (the scene as every view's CSV
/// has it, made by export), then what the simulation adds: how the surface
/// is solved and what it matches, the hardness, the theory and the units.
fn comments(
    out: &mut impl Write,
    scene: &[String],
    state: &State,
    sim: &Simulation,
    spec: &Spec,
    h_rms: &Stat,
) -> anyhow::Result<()> {
    let p = &state.params;
    // A sweep's first point solves another ζ than the scene's.
    let p = &p.with(rough_model::Axis::Zeta, sim.zeta).unwrap_or(*p);
    for l in scene {
        writeln!(out, "# {l}")?;
    }
    if let Some(m) = &sim.measured {
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), {m}, wavevectors \
             q ≤ zeta q0 = {} 1/m kept",
            csv_number::format(p.zeta() * p.q0())
        )?;
    } else {
        let n = sim.contact.n();
        let s = &spec.sampling;
        writeln!(
            out,
            "# simulation = elastic–perfectly-plastic BEM (rough-contact), periodic {n} × {n} grid \
             of side {} × 2π/q0 (cell: {}{}), {} nodes per shortest wavelength, power-law \
             Gaussian surface, {}{}",
            sim.cell,
            s.cell_words(),
            if sim.cell > 1 {
                ", the spectrum flat below q0"
            } else {
                ""
            },
            csv_number::format(s.per_wavelength(n, p.zeta())),
            spec.seeds.words(),
            if spec.seeds.count > 1 {
                format!(
                    " (columns: means over {} realisations; *_sd: their sample standard \
                     deviation)",
                    spec.seeds.count
                )
            } else {
                " (one realisation: the *_sd columns are NaN)".into()
            }
        )?;
        writeln!(
            out,
            "# surface = matched to the scene's rms slope sqrt(2 m2) = {} ({}); its own h_rms \
             {} m{} against the scene's {} m",
            csv_number::format(sim.rms_slope),
            match state.moments {
                rough_model::Moments::Asymptotic => {
                    "the paper's asymptotic moments, eq. 10; --moments truncated matches the \
                     truncated spectrum's"
                }
                rough_model::Moments::Truncated => "the truncated spectrum's moments",
            },
            csv_number::format(h_rms.mean),
            if h_rms.n > 1 {
                format!(
                    " (mean over the seeds, sd {})",
                    csv_number::format(h_rms.sd)
                )
            } else {
                String::new()
            },
            csv_number::format(p.h_rms()),
        )?;
    }
    writeln!(out, "# hardness = {}", hardness_words(sim, state))?;
    writeln!(
        out,
        "# hardness_in_use_over_e = {} ({}/E*, the pressure cap{}); rms_slope = {} (the \
         surface rescaled to the scene's sqrt(2 m2))",
        csv_number::format(sim.hardness),
        state.hardness_name(),
        if sim.local.is_some() {
            ", the loads' unit"
        } else {
            ""
        },
        csv_number::format(sim.rms_slope)
    )?;
    writeln!(
        out,
        "# theory = the {} model's finite-load areas at the index in use {} = {}; its split: {}",
        state.model.label(),
        if state.size_effect {
            "psi_star"
        } else {
            "psi_p"
        },
        csv_number::format(sim.psi.to_f64()),
        theory_split(state.model)
    )?;
    writeln!(
        out,
        "# units: areas as fractions of A0 at the load of the row (secants A(p)/A0, not initial \
         slopes: --view contact-slopes), mean_gap in m; residual: rms violation of the contact \
         conditions over h_rms (the largest over the seeds); area_corrected: the area less \
         (pi - 1 + ln 2)/24 of a node per side of the contact's perimeter (Yastrebov, Anciaux & \
         Molinari 2017: the grid's overcount along the contact's edge)"
    )?;
    Ok(())
}

pub(crate) fn push_row(buf: &mut String, fields: &[f64]) {
    for (k, v) in fields.iter().enumerate() {
        if k > 0 {
            buf.push(',');
        }
        csv_number::push(buf, *v);
    }
    buf.push('\n');
}

/// The contact view as CSV, `scene` its first `#` lines.
pub fn write_contact(
    out: &mut impl Write,
    state: &State,
    points: usize,
    spec: &Spec,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows, heights, beyond) = load_rows(state, points, spec)?;
    let ratio = super::rows::hardness_ratio(state);
    let mut buf = String::new();
    for r in &rows {
        push_row(
            &mut buf,
            &[
                r.p_over_h,
                r.area.mean,
                r.elastic.mean,
                r.plastic.mean,
                r.mean(|x| x.mean_gap),
                r.mean(|x| x.iterations as f64),
                r.residual(),
                r.theory.total,
                r.theory.elastic,
                r.theory.plastic,
                r.area.sd,
                r.elastic.sd,
                r.plastic.sd,
                r.runs.len() as f64,
                r.p_over_h * ratio,
                r.corrected.mean,
                r.corrected.sd,
            ],
        );
    }
    comments(out, scene, state, &sim, spec, &heights)?;
    writeln!(
        out,
        "# load = p_over_h = pbar/{h} (the theory's hardness in use, {h}/E* = {}); p_over_h0 = \
         pbar/H0",
        csv_number::format(sim.hardness),
        h = state.hardness_name(),
    )?;
    if let Some(k) = kappa(&sim, &rows) {
        writeln!(
            out,
            "# kappa = A/A0 over pbar/(E* h') at the lightest load p_over_h = {}: {} (the mean \
             over the seeds, h' = rms_slope; Persson's theory: sqrt(8/pi) = {})",
            csv_number::format(rows[0].p_over_h),
            csv_number::format(k),
            csv_number::format(PERSSON_KAPPA)
        )?;
    }
    for b in &beyond {
        writeln!(out, "# not solved: {b}")?;
    }
    writeln!(out, "{CONTACT_HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The ζ sweep as CSV, `scene` its first `#` lines.
pub fn write_contact_sweep(
    out: &mut impl Write,
    state: &State,
    spec: &Spec,
    scene: &[String],
) -> anyhow::Result<()> {
    let (sim, rows, heights) = sweep_rows(state, spec)?;
    let mut buf = String::new();
    for r in &rows {
        let (share, area, corrected) = (r.share(), r.area(), r.corrected_area());
        push_row(
            &mut buf,
            &[
                r.zeta,
                r.p_over_h0,
                r.p_over_h,
                share.mean,
                r.theory_share(),
                area.mean,
                r.theory.total,
                r.grid as f64,
                Stat::of(r.runs.iter().map(|x| x.iterations as f64)).mean,
                r.runs.iter().map(|x| x.residual).fold(0.0, f64::max),
                share.sd,
                area.sd,
                r.runs.len() as f64,
                Stat::of(r.hardness.iter().copied()).mean,
                r.theory_hardness,
                Stat::of(r.asperities.iter().map(|a| a.0 as f64)).mean,
                Stat::of(r.asperities.iter().map(|a| a.1)).mean,
                corrected.mean,
                corrected.sd,
            ],
        );
    }
    comments(out, scene, state, &sim, spec, &heights)?;
    writeln!(out, "# load = {}", sweep_load_words(state, spec))?;
    if sim.local.is_some() {
        writeln!(
            out,
            "# hardness_over_e: the load-weighted mean cap of the solution (with a hardness per \
             node; theory_hardness_over_e: the theory's H_y at R_s); patches: the asperities in \
             contact (the elastic contact's patches; with summit radii the summits its nodes \
             climb to), with their median curvature radius in m"
        )?;
    }
    writeln!(
        out,
        "# the simulation and theory lines above are the first zeta's; each zeta solves its own \
         grid (column grid) and hardness"
    )?;
    writeln!(out, "{SWEEP_HEADER}")?;
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// The sweep's load in words: its unit and what it means at each ζ.
pub fn sweep_load_words(state: &State, spec: &Spec) -> String {
    let h = state.hardness_name();
    let at = csv_number::format(SWEEP_LOAD);
    match spec.sampling.loads {
        super::LoadScale::H0 => format!(
            "pbar = {at} H0 at every zeta (the same absolute load; p_over_h = pbar/{h} at that \
             zeta; --load-scale in-use fixes pbar/{h} instead); plastic_share and area at that \
             load (secants, not initial slopes)"
        ),
        super::LoadScale::InUse => format!(
            "pbar = {at} {h} at each zeta (--load-scale in-use: a load that grows with {h}; \
             p_over_h0 = pbar/H0 at that zeta); plastic_share and area at that load (secants, \
             not initial slopes)"
        ),
    }
}

/// κ at the lightest load of `rows`: A/A0 over p̄/(E* h′), the mean over
/// the seeds (a measured map: its own rms slope).
pub fn kappa(sim: &Simulation, rows: &[super::LoadRow]) -> Option<f64> {
    let r = rows.first()?;
    let x = r.p_over_h * sim.hardness / sim.rms_slope;
    (x > 0.0 && r.area.mean.is_finite()).then(|| r.area.mean / x)
}
