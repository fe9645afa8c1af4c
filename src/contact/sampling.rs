//! How a power-law scene is sampled for the simulation: the cell (how many
//! of the longest wavelengths a side, with the spectrum rolled off flat
//! below q0), the grid (nodes per shortest wavelength, or a side given
//! outright) and the memory that grid takes.

use anyhow::bail;

/// The cell when none is given: K = 2 longest wavelengths a side
/// (docs/theory-vs-simulation.md, "What the comparison shows": over eight
/// seeds of fig2 at ζ = 16 the area scatters by 11 % at K = 1, 6 % at
/// K = 2 and 4 % at K = 4, which takes four times the nodes of K = 2).
pub const DEFAULT_CELL: u32 = 2;
/// Largest cell, in longest wavelengths.
pub const MAX_CELL: u32 = 64;
/// Nodes per shortest wavelength when no grid is given.
pub const DEFAULT_PER_WAVELENGTH: u32 = 8;
/// The grid side a power-law scene is solved on at most (and the memory
/// of the machine).
pub const MAX_GRID: usize = 4096;
/// Smallest grid side (a ζ = 1 surface still gets a real grid).
pub const MIN_GRID: usize = 32;
/// Bytes a node of a solve takes: the surface, pressure and gap, the
/// solver's four work arrays, half a complex row of the transform, the
/// kernel, the synthesis's temporaries and the map (measured: 1024²
/// solves in 86 MB).
pub const BYTES_PER_NODE: usize = 100;

/// How the grid side is chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Grid {
    /// The power of two giving at least this many nodes per shortest
    /// wavelength 2π/(ζ q0).
    PerWavelength(u32),
    /// This side (a power of two).
    Side(usize),
}

/// Where the size effect's hardness applies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Hardness {
    /// One cap for every node: the scene's H_use (H_y at the mean summit
    /// radius R_s with the size effect), as the theory uses it.
    #[default]
    Global,
    /// Each contact patch its own H_y from the curvature radius of the
    /// asperity under it (see `crate::contact::local`).
    Asperity,
    /// Each node the H_y of the summit steepest ascent takes it to, at that
    /// summit's curvature radius (see `crate::contact::local`).
    Summit,
}

impl Hardness {
    /// Global → asperity → summit → global (the explorer's `A`).
    pub fn next(self) -> Hardness {
        match self {
            Hardness::Global => Hardness::Asperity,
            Hardness::Asperity => Hardness::Summit,
            Hardness::Summit => Hardness::Global,
        }
    }

    /// The name the command line and the CSVs give it.
    pub fn name(self) -> &'static str {
        match self {
            Hardness::Global => "global",
            Hardness::Asperity => "asperity",
            Hardness::Summit => "summit",
        }
    }

    /// The radius a per-node hardness takes, `None` for one cap.
    pub fn radius(self) -> Option<super::local::Radius> {
        match self {
            Hardness::Global => None,
            Hardness::Asperity => Some(super::local::Radius::Asperity),
            Hardness::Summit => Some(super::local::Radius::Summit),
        }
    }
}

/// The unit a ζ sweep's load is fixed in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LoadScale {
    /// p̄ a fixed fraction of H0 at every ζ: the same absolute load, the
    /// question the paper's figures ask.
    #[default]
    H0,
    /// p̄ a fixed fraction of the hardness in use at each ζ (H_y(R_s) with
    /// the size effect: a heavier load as ζ grows).
    InUse,
}

impl LoadScale {
    /// The name the command line and the CSVs give it.
    pub fn name(self) -> &'static str {
        match self {
            LoadScale::H0 => "h0",
            LoadScale::InUse => "in-use",
        }
    }

    /// p̄/H_use of a sweep's load `load` (p̄/H0, or p̄/H_use as it stands)
    /// where the hardness in use is `h_use_over_h0` times H0.
    pub fn over_in_use(self, load: f64, h_use_over_h0: f64) -> f64 {
        match self {
            LoadScale::H0 => load / h_use_over_h0,
            LoadScale::InUse => load,
        }
    }
}

/// The cell, the grid and the hardness of a power-law scene's simulation,
/// and the unit of its ζ sweeps' load.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sampling {
    /// The cell side in longest wavelengths 2π/q0.
    pub cell: u32,
    pub grid: Grid,
    pub hardness: Hardness,
    pub loads: LoadScale,
}

impl Default for Sampling {
    fn default() -> Self {
        Sampling {
            cell: DEFAULT_CELL,
            grid: Grid::PerWavelength(DEFAULT_PER_WAVELENGTH),
            hardness: Hardness::Global,
            loads: LoadScale::H0,
        }
    }
}

impl Sampling {
    /// The grid side at magnification `zeta`, refused beyond the memory
    /// this machine has available.
    pub fn side(&self, zeta: f64) -> anyhow::Result<usize> {
        let n = self.nodes(zeta)?;
        check_memory(n)?;
        Ok(n)
    }

    /// [`Sampling::side`] whatever this machine's memory (another machine
    /// solves it: a cluster's node).
    pub fn nodes(&self, zeta: f64) -> anyhow::Result<usize> {
        let span = zeta * self.cell as f64;
        let n = match self.grid {
            Grid::PerWavelength(k) => {
                let need = (k as f64 * span).ceil();
                if !need.is_finite() || need > MAX_GRID as f64 {
                    bail!(
                        "ζ = {} in a cell of {} needs a grid of at least {need} nodes a side \
                         ({k} per shortest wavelength); the contact simulation solves up to \
                         {MAX_GRID} (ζ × cell ≤ {})",
                        crate::physical::print::fmt_num(zeta),
                        self.cell_words(),
                        MAX_GRID / k as usize
                    );
                }
                (need as usize).next_power_of_two().max(MIN_GRID)
            }
            Grid::Side(n) => {
                // More than two nodes per shortest wavelength hold its modes
                // (below the grid's Nyquist wavenumber).
                let need = 2.0 * span.floor() + 2.0;
                if (n as f64) < need {
                    bail!(
                        "a grid of {n} nodes a side cannot hold ζ = {} in a cell of {}: the \
                         shortest wavelength needs more than 2 nodes ({need} a side at least; \
                         8 per wavelength is the default)",
                        crate::physical::print::fmt_num(zeta),
                        self.cell_words(),
                    );
                }
                n
            }
        };
        Ok(n)
    }

    /// "1 longest wavelength", "2 longest wavelengths".
    pub fn cell_words(&self) -> String {
        let s = if self.cell == 1 { "" } else { "s" };
        format!("{} longest wavelength{s}", self.cell)
    }

    /// Nodes per shortest wavelength of an `n`-node side at `zeta`.
    pub fn per_wavelength(&self, n: usize, zeta: f64) -> f64 {
        n as f64 / (zeta * self.cell as f64)
    }
}

/// Refuses a grid whose solve would not fit in the memory this machine has
/// available (Linux's MemAvailable; elsewhere only [`MAX_GRID`] bounds it).
pub fn check_memory(n: usize) -> anyhow::Result<()> {
    let need = (n as f64).powi(2) * BYTES_PER_NODE as f64;
    if let Some(have) = available_memory() {
        if need > have as f64 {
            bail!(
                "a {n} × {n} grid needs about {} of memory to solve ({BYTES_PER_NODE} bytes a \
                 node); this machine has {} available",
                bytes_words(need),
                bytes_words(have as f64)
            );
        }
    }
    Ok(())
}

/// Bytes in words: "1.6 GB", "420 MB".
pub fn bytes_words(b: f64) -> String {
    if b >= 1e12 {
        format!("{:.1} TB", b / 1e12)
    } else if b >= 1e9 {
        format!("{:.1} GB", b / 1e9)
    } else {
        format!("{:.0} MB", (b / 1e6).max(1.0))
    }
}

/// MemAvailable of /proc/meminfo, in bytes.
fn available_memory() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_follows_the_cell_and_the_nodes_per_wavelength() {
        let s = |cell, grid| Sampling {
            cell,
            grid,
            ..Sampling::default()
        };
        let per = Grid::PerWavelength;
        assert_eq!(s(1, per(8)).side(128.0).unwrap(), 1024);
        assert_eq!(s(2, per(8)).side(128.0).unwrap(), 2048);
        assert_eq!(s(1, per(4)).side(128.0).unwrap(), 512);
        assert_eq!(s(1, per(8)).side(1.0).unwrap(), MIN_GRID);
        assert_eq!(s(1, Grid::Side(512)).side(128.0).unwrap(), 512);
        // Two nodes per shortest wavelength: its modes sit on the Nyquist
        // wavenumber, where a real grid keeps only the cosine.
        let e = s(1, Grid::Side(256)).side(128.0).unwrap_err().to_string();
        assert!(e.contains("cannot hold ζ = 128"), "{e}");
        assert!(e.contains("258 a side at least"), "{e}");
        let e = s(4, per(8)).side(1000.0).unwrap_err().to_string();
        assert!(e.contains("up to 4096"), "{e}");
    }

    #[test]
    fn a_grid_beyond_the_memory_names_the_memory() {
        let e = check_memory(1 << 20).unwrap_err().to_string();
        assert!(e.contains("needs about 110.0 TB of memory"), "{e}");
        assert!(e.contains("available"), "{e}");
    }
}
