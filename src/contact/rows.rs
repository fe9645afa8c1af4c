//! The contact views' rows: each load (or ζ) solved for every seed, with
//! the mean and spread over the realisations.

use anyhow::{bail, Context};
use rough_contact::LoadResult;
use rough_model::Areas;

use super::{loads, measured, sweep_zetas, Simulation, Spec, Stat, SWEEP_LOAD};
use crate::scene::State;

/// One load of the contact view, over the seeds.
pub struct LoadRow {
    pub p_over_h: f64,
    /// Each seed's result, in seed order.
    pub runs: Vec<LoadResult>,
    pub area: Stat,
    pub elastic: Stat,
    pub plastic: Stat,
    /// The area with the grid's edge corrected (Yastrebov et al. 2017).
    pub corrected: Stat,
    pub theory: Areas,
}

impl LoadRow {
    fn of(p_over_h: f64, runs: Vec<LoadResult>, theory: Areas) -> LoadRow {
        LoadRow {
            p_over_h,
            area: Stat::of(runs.iter().map(|r| r.area)),
            elastic: Stat::of(runs.iter().map(|r| r.elastic_area)),
            plastic: Stat::of(runs.iter().map(|r| r.plastic_area)),
            corrected: Stat::of(runs.iter().map(|r| r.corrected_area())),
            runs,
            theory,
        }
    }

    /// The mean of `f` over the seeds.
    pub fn mean(&self, f: impl Fn(&LoadResult) -> f64) -> f64 {
        Stat::of(self.runs.iter().map(f)).mean
    }

    /// The largest residual over the seeds.
    pub fn residual(&self) -> f64 {
        self.runs.iter().map(|r| r.residual).fold(0.0, f64::max)
    }
}

/// The seeds of `spec` checked against the scene: a measured map has one
/// realisation only.
pub(super) fn check_seeds(state: &State, spec: &Spec) -> anyhow::Result<()> {
    if spec.seeds.count == 0 {
        bail!("--seeds 0: at least one realisation is needed");
    }
    if state.is_measured() && spec.seeds.count > 1 {
        bail!(
            "--seeds {} does not apply to a measured map: it is solved on its own heights, one \
             realisation",
            spec.seeds.count
        );
    }
    Ok(())
}

/// The scene at `points` loads from 1e-3 H to H for each seed of `spec`
/// (each load warm-started from the last); the first seed's simulation (for
/// the parameter lines), the rms heights of the realisations, and the
/// loads not solved: with a hardness per asperity, those above what the
/// asperities can carry (for any seed), each with why — their rows are
/// left out.
pub fn load_rows(
    state: &State,
    points: usize,
    spec: &Spec,
) -> anyhow::Result<(Simulation, Vec<LoadRow>, Stat, Vec<String>)> {
    check_seeds(state, spec)?;
    let loads = loads(points);
    let mut runs: Vec<Vec<LoadResult>> = vec![vec![]; loads.len()];
    let mut theory: Vec<Option<Areas>> = vec![None; loads.len()];
    let mut beyond: Vec<Option<String>> = vec![None; loads.len()];
    let (mut first, mut heights) = (None, vec![]);
    for seed in spec.seeds.iter() {
        let mut sim = Simulation::with(state, seed, &spec.sampling)?;
        heights.push(sim.contact.h_rms());
        for (k, &p_over_h) in loads.iter().enumerate() {
            match sim.solve(p_over_h, &mut |_, _| true) {
                Ok((r, t)) => {
                    runs[k].push(r);
                    theory[k] = Some(t);
                }
                Err(e) if e.downcast_ref::<super::local::Beyond>().is_some() => {
                    beyond[k].get_or_insert(format!("p̄/H = {p_over_h}, seed {seed}: {e}"));
                }
                Err(e) => {
                    return Err(e.context(format!("contact at p̄/H = {p_over_h}, seed {seed}")))
                }
            }
        }
        first.get_or_insert(sim);
    }
    let first = first.ok_or_else(|| anyhow::anyhow!("no seed to solve"))?;
    let mut rows = vec![];
    for (((p, r), t), b) in loads.into_iter().zip(runs).zip(theory).zip(&beyond) {
        if let (Some(t), None) = (t, b) {
            rows.push(LoadRow::of(p, r, t));
        }
    }
    if rows.is_empty() {
        bail!(
            "no load solved: {}",
            beyond.iter().flatten().next().map_or("", String::as_str)
        );
    }
    Ok((
        first,
        rows,
        Stat::of(heights),
        beyond.into_iter().flatten().collect(),
    ))
}

/// One magnification of the ζ sweep, over the seeds.
pub struct SweepRow {
    pub zeta: f64,
    /// The load over H0 and over the theory's hardness in use at this ζ
    /// (H0, or H_y(R_s) with the size effect).
    pub p_over_h0: f64,
    pub p_over_h: f64,
    pub grid: usize,
    pub runs: Vec<LoadResult>,
    pub theory: Areas,
    /// The load-weighted hardness of each run, H/E* (the cap itself without
    /// a hardness per asperity).
    pub hardness: Vec<f64>,
    /// With a hardness per asperity, each run's asperities in contact: how
    /// many, and their median curvature radius (m).
    pub asperities: Vec<(usize, f64)>,
    /// The scene's cap at this ζ, H_use/E* (the theory's).
    pub theory_hardness: f64,
}

impl SweepRow {
    /// Plastic share of the simulated contact area over the seeds (a
    /// realisation without contact left out).
    pub fn share(&self) -> Stat {
        Stat::of(self.runs.iter().map(|r| share(r.plastic_area, r.area)))
    }
    /// Contact area over the seeds.
    pub fn area(&self) -> Stat {
        Stat::of(self.runs.iter().map(|r| r.area))
    }
    /// Contact area less the grid's overcount along its edge (Yastrebov et
    /// al. 2017), over the seeds.
    pub fn corrected_area(&self) -> Stat {
        Stat::of(self.runs.iter().map(|r| r.corrected_area()))
    }
    /// The theory's plastic share at the same load.
    pub fn theory_share(&self) -> f64 {
        share(self.theory.plastic, self.theory.total)
    }
}

fn share(plastic: f64, total: f64) -> f64 {
    if total > 0.0 {
        plastic / total
    } else {
        f64::NAN
    }
}

/// The scene at ζ = 1, 2, …, 128 and the load [`SWEEP_LOAD`] (over H0, or
/// over the hardness in use at each ζ: `spec.sampling.loads`) for each
/// seed; the first point's simulation (for the parameter lines) and its
/// realisations' rms heights.
pub fn sweep_rows(state: &State, spec: &Spec) -> anyhow::Result<(Simulation, Vec<SweepRow>, Stat)> {
    check_seeds(state, spec)?;
    let mut rows = vec![];
    let mut first = None;
    let mut heights = vec![];
    for (zeta, s) in sweep_states(state)? {
        let ratio = hardness_ratio(&s);
        let p_over_h = spec.sampling.loads.over_in_use(SWEEP_LOAD, ratio);
        let (mut runs, mut theory, mut grid) = (vec![], None, 0);
        let (mut hardness, mut asperities) = (vec![], vec![]);
        let first_zeta = first.is_none();
        for seed in spec.seeds.iter() {
            let mut sim = Simulation::with(&s, seed, &spec.sampling)?;
            let (r, t) = sim
                .solve(p_over_h, &mut |_, _| true)
                .with_context(|| format!("contact at ζ = {zeta}, seed {seed}"))?;
            runs.push(r);
            theory = Some(t);
            grid = sim.contact.n();
            match &sim.last_local {
                Some(l) => {
                    hardness.push(l.mean_hardness);
                    asperities.push((l.patches, l.radius[0]));
                }
                None => hardness.push(sim.hardness),
            }
            if first_zeta {
                heights.push(sim.contact.h_rms());
                first.get_or_insert(sim);
            }
        }
        let theory = theory.ok_or_else(|| anyhow::anyhow!("no seed to solve"))?;
        rows.push(SweepRow {
            zeta,
            p_over_h0: p_over_h * ratio,
            p_over_h,
            grid,
            runs,
            theory,
            hardness,
            asperities,
            theory_hardness: s.params.h0_over_e() * ratio,
        });
    }
    let first = first.ok_or_else(|| anyhow::anyhow!("no ζ to sweep"))?;
    Ok((first, rows, Stat::of(heights)))
}

/// H_use/H0 of the scene: 1, or H_y(R_s)/H0 with the size effect.
pub fn hardness_ratio(state: &State) -> f64 {
    state
        .roughness()
        .surface(&state.params, state.moments)
        .indices
        .hardness_in_use(state.size_effect)
}

/// The scene at each ζ of a sweep: 1, 2, 4, …, 128 (a measured map's from
/// the first that keeps a mode of its solved square to its data's
/// largest).
pub(super) fn sweep_states(state: &State) -> anyhow::Result<Vec<(f64, State)>> {
    let zeta_max = state.roughness().zeta_max() * (1.0 + 1e-12);
    let zeta_min = match measured::heights_of(state)? {
        Some((_, h)) => measured::lowest_zeta(&h) * (1.0 - 1e-9),
        None => 0.0,
    };
    sweep_zetas()
        .into_iter()
        .filter(|z| (zeta_min..=zeta_max).contains(z))
        .map(|zeta| {
            let mut s = state.clone();
            s.params = s
                .params
                .with(rough_model::Axis::Zeta, zeta)
                .map_err(|e| anyhow::anyhow!("ζ = {zeta}: {e}"))?;
            Ok((zeta, s))
        })
        .collect()
}
