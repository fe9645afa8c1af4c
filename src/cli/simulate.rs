//! How the contact simulation samples a power-law scene: the cell, the
//! grid, where the hardness applies and what a ζ sweep's load is fixed in
//! (export's contact views, the explorer's, a served class's).

use clap::{Args, ValueEnum};

use super::values::{parse_cell, parse_contact_grid, parse_per_wavelength};

/// How the contact simulation samples a power-law scene (export's contact
/// views, the explorer's contact view, a served class's).
#[derive(Debug, Args, Clone, Default)]
pub struct Simulate {
    /// The simulated cell's side in longest wavelengths 2π/q0, the spectrum
    /// flat below q0 (contact views; default 2 in export, 1 in the
    /// explorer, whose first answer must come quickly).
    #[arg(long, value_name = "K", value_parser = parse_cell)]
    pub cell: Option<u32>,
    /// The simulation's grid, nodes a side, a power of two (contact views;
    /// default: 8 nodes per shortest wavelength).
    #[arg(long, value_name = "N", value_parser = parse_contact_grid, conflicts_with = "per_wavelength")]
    pub contact_grid: Option<usize>,
    /// The simulation's nodes per shortest wavelength 2π/(ζ q0), the grid
    /// the power of two giving as many (contact views; default 8).
    #[arg(long, value_name = "K", value_parser = parse_per_wavelength)]
    pub per_wavelength: Option<u32>,
    /// Where the size effect's hardness applies in the simulation: one cap
    /// everywhere (default), each contact patch that of its asperity, or
    /// each node that of its summit.
    #[arg(long, value_enum)]
    pub hardness: Option<HardnessArg>,
    /// The load of a ζ sweep (contact-sweep, contact-slopes, the explorer's
    /// `b`): fixed in H0 at every ζ (default), or a fixed fraction of the
    /// hardness in use at each ζ (H_y(R_s) with the size effect).
    #[arg(long, value_enum, value_name = "h0|in-use")]
    pub load_scale: Option<LoadScaleArg>,
}

/// `--load-scale`: the unit a ζ sweep's load is fixed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LoadScaleArg {
    /// p̄ a fixed fraction of H0 at every ζ: the same absolute load.
    H0,
    /// p̄ a fixed fraction of the hardness in use at each ζ.
    InUse,
}

impl Simulate {
    /// `base` with what the command line sets.
    pub fn sampling(&self, base: crate::contact::Sampling) -> crate::contact::Sampling {
        use crate::contact::{Grid, Hardness};
        let mut s = base;
        if let Some(k) = self.cell {
            s.cell = k;
        }
        if let Some(n) = self.contact_grid {
            s.grid = Grid::Side(n);
        }
        if let Some(k) = self.per_wavelength {
            s.grid = Grid::PerWavelength(k);
        }
        match self.load_scale {
            Some(LoadScaleArg::H0) => s.loads = crate::contact::LoadScale::H0,
            Some(LoadScaleArg::InUse) => s.loads = crate::contact::LoadScale::InUse,
            None => {}
        }
        match self.hardness {
            Some(HardnessArg::Asperity) => s.hardness = Hardness::Asperity,
            Some(HardnessArg::Summit) => s.hardness = Hardness::Summit,
            Some(HardnessArg::Global) => s.hardness = Hardness::Global,
            None => {}
        }
        s
    }

    /// The options given, by name (a measured map refuses them).
    pub fn given(&self) -> [(bool, &'static str); 5] {
        [
            (self.hardness.is_some(), "--hardness"),
            (self.load_scale.is_some(), "--load-scale"),
            (self.cell.is_some(), "--cell"),
            (self.contact_grid.is_some(), "--contact-grid"),
            (self.per_wavelength.is_some(), "--per-wavelength"),
        ]
    }

    /// Refuses the options that do not apply to `state`: a measured map is
    /// solved on its own heights, its square and grid set by the data and
    /// ζ; a hardness per asperity needs the size effect.
    pub fn check(&self, state: &crate::scene::State) -> anyhow::Result<()> {
        if state.is_measured() {
            if let Some((_, opt)) = self.given().into_iter().skip(2).find(|(g, _)| *g) {
                anyhow::bail!(
                    "{opt} does not apply to a measured map: it is solved on its own heights, \
                     its square and grid set by the data and ζ"
                );
            }
        }
        Ok(())
    }
}

/// Where the simulation's hardness applies (contact views).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HardnessArg {
    /// One cap everywhere: the scene's H_use, as the theory uses it.
    Global,
    /// Each contact patch the size effect's H_y of the asperity under it
    /// (its curvature radius in place of R_s; needs the size effect on).
    Asperity,
    /// Each node the size effect's H_y of its own summit: steepest ascent
    /// on the heights to the local maximum, that maximum's curvature radius
    /// (needs the size effect on).
    Summit,
}
