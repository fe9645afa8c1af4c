//! What a contact solution depends on, as a hashable key: the surface (its
//! spectrum, grid and seed), the pressure cap and the load. Two explorers
//! on the same inputs ask for the same key, whatever else differs between
//! their scenes (model, view, sweep), and so share one solution.

use rough_contact::{moments, synthesise, Boundary, Contact, PowerLaw};

use anyhow::bail;

use super::measured;
use super::sampling::{Hardness, Sampling};
use crate::scene::State;

/// The surface and cap of one simulation; every field is an input of
/// [`Surface::build`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SceneKey {
    /// Power law: amplitude Z, Hurst exponent, q0, ζ (as f64 bits).
    z: u64,
    hurst: u64,
    q0: u64,
    zeta: u64,
    /// The rms slope the realisation is rescaled to (f64 bits).
    rms_slope: u64,
    /// H_use/E*, the pressure cap (f64 bits).
    hardness: u64,
    /// Grid side of the surface.
    pub n: usize,
    /// Halvings of the grid solved: the surface sampled at every 2^coarse-th
    /// node of its n × n grid (0: all of them), a coarse answer first.
    pub coarse: u8,
    /// The cell side in longest wavelengths (1 for a measured map).
    pub cell: u32,
    /// A hardness per node: the radius it takes, H0/E* and R* (m) of the
    /// size-effect law, as f64 bits; `None`: the cap
    /// [`SceneKey::hardness`] everywhere.
    pub local: Option<(super::local::Radius, u64, u64)>,
    pub seed: u64,
    /// A measured map: its file's SHA-256 and how it was read
    /// ([`super::measured`]); `None`: the power law.
    pub surface: Option<super::measured::SurfaceId>,
}

/// Why a scene cannot be simulated, in the explorer's words.
pub fn unsolvable(state: &State, sampling: &Sampling) -> Option<String> {
    if state.is_measured() {
        return SceneKey::of(state, 0).err().map(|e| format!("{e:#}"));
    }
    sampling
        .side(state.params.zeta())
        .err()
        .map(|e| format!("{e:#}: lower ζ to compare"))
}

impl SceneKey {
    /// The power-law scene of `state` with phases from `seed`, sampled as
    /// by default. A measured map's key is its file's and reading's (the
    /// seed plays no part: it is stored as 0).
    pub fn of(state: &State, seed: u64) -> anyhow::Result<SceneKey> {
        SceneKey::with(state, seed, &Sampling::default())
    }

    /// [`SceneKey::of`] with the cell and grid of `sampling` (a measured
    /// map's are its own).
    pub fn with(state: &State, seed: u64, sampling: &Sampling) -> anyhow::Result<SceneKey> {
        let p = &state.params;
        let surface = state.roughness().surface(p, state.moments);
        let ix = surface.indices;
        let hardness = p.h0_over_e() * ix.hardness_in_use(state.size_effect);
        let local = match sampling.hardness.radius() {
            None => None,
            Some(_) if !state.size_effect => bail!(
                "a hardness per {} is the size effect's: switch it on (--size-effect on, e in \
                 the explorer)",
                if sampling.hardness == Hardness::Summit {
                    "summit"
                } else {
                    "asperity"
                }
            ),
            Some(r) => Some((r, p.h0_over_e().to_bits(), p.r_star().to_bits())),
        };
        if let Some((id, h)) = measured::heights_of(state)? {
            let plan = measured::plan(&h, p.zeta() * p.q0())?;
            return Ok(SceneKey {
                z: 0,
                hurst: 0,
                q0: p.q0().to_bits(),
                zeta: p.zeta().to_bits(),
                rms_slope: surface.spectrum.rms_slope.to_bits(),
                hardness: hardness.to_bits(),
                n: plan.n,
                coarse: 0,
                cell: 1,
                local,
                seed: 0,
                surface: Some(id),
            });
        }
        Ok(SceneKey {
            z: surface.spectrum.z.to_bits(),
            hurst: p.hurst().to_bits(),
            q0: p.q0().to_bits(),
            zeta: p.zeta().to_bits(),
            rms_slope: surface.spectrum.rms_slope.to_bits(),
            hardness: hardness.to_bits(),
            n: sampling.side(p.zeta())?,
            coarse: 0,
            cell: sampling.cell,
            local,
            seed,
            surface: None,
        })
    }

    /// Whether `other` solves the same heights on the same grid (it may cap
    /// them otherwise): a solve of one can start from the other's answer.
    pub fn same_surface(&self, other: &SceneKey) -> bool {
        SceneKey {
            hardness: 0,
            local: None,
            ..*self
        } == SceneKey {
            hardness: 0,
            local: None,
            ..*other
        }
    }

    /// The side of the grid solved: n, or n halved `coarse` times.
    pub fn side(&self) -> usize {
        self.n >> self.coarse
    }

    /// The same surface sampled on a grid of at most `most` nodes a side
    /// (at every second, fourth … node), if it is a power law's on a finer
    /// grid than that; a measured map has no coarse answer.
    pub fn coarser(&self, most: usize) -> Option<SceneKey> {
        if self.surface.is_some() || self.coarse > 0 || self.n <= most {
            return None;
        }
        let mut coarse = 0u8;
        while (self.n >> coarse) > most {
            coarse += 1;
        }
        Some(SceneKey { coarse, ..*self })
    }

    /// H_use/E*.
    pub fn hardness(&self) -> f64 {
        f64::from_bits(self.hardness)
    }

    /// The size-effect law of a hardness per asperity, if the key has one.
    pub fn local(&self) -> Option<super::local::Law> {
        self.local.map(|(radius, h0, r)| super::local::Law {
            h0: f64::from_bits(h0),
            r_star: f64::from_bits(r),
            radius,
        })
    }

    pub fn zeta(&self) -> f64 {
        f64::from_bits(self.zeta)
    }

    pub fn rms_slope(&self) -> f64 {
        f64::from_bits(self.rms_slope)
    }

    /// The cell's side: K longest wavelengths.
    pub fn length(&self) -> f64 {
        self.cell as f64 * std::f64::consts::TAU / f64::from_bits(self.q0)
    }

    /// The surface's heights, synthesised and rescaled to the scene's rms
    /// slope (a power-law scene only).
    pub fn heights(&self) -> anyhow::Result<Vec<f64>> {
        let f = f64::from_bits;
        let (n, q0) = (self.n, f(self.q0));
        let length = self.length();
        let law = PowerLaw {
            z: f(self.z),
            hurst: f(self.hurst),
            q0,
            q1: f(self.zeta) * q0,
            rolloff: self.cell > 1,
        };
        let mut h = synthesise(n, length, &law, self.seed)?;
        let got = moments(&h, n, length)?.rms_slope;
        if got.is_nan() || got <= 0.0 {
            anyhow::bail!(
                "the synthesised surface is flat on a {n} × {n} grid: no wavelength of the \
                 spectrum lies on it"
            );
        }
        let k = self.rms_slope() / got;
        h.iter_mut().for_each(|v| *v *= k);
        let mut side = n;
        for _ in 0..self.coarse {
            h = rough_contact::restrict(&h, side);
            side /= 2;
        }
        Ok(h)
    }

    /// The surface synthesised and rescaled, ready to be loaded (pressures
    /// in units of E*).
    pub fn build(&self) -> anyhow::Result<Contact> {
        let f = f64::from_bits;
        if let Some(id) = &self.surface {
            return measured::build(id, f(self.zeta) * f(self.q0));
        }
        let h = self.heights()?;
        Ok(Contact::new(
            h,
            self.side(),
            self.length(),
            1.0,
            Boundary::Periodic,
        )?)
    }
}

/// One node of a contact map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
#[repr(u8)]
pub enum Node {
    Out = 0,
    Elastic = 1,
    Plastic = 2,
}

/// The contact map of a solved pressure field: n × n row-major.
pub fn classify(pressure: &[f64], hardness: f64) -> Vec<Node> {
    pressure
        .iter()
        .map(|&p| {
            if p <= 0.0 {
                Node::Out
            } else if p >= hardness {
                Node::Plastic
            } else {
                Node::Elastic
            }
        })
        .collect()
}

/// The contact map of a pressure field under a cap per node.
pub fn classify_capped(pressure: &[f64], caps: &[f64]) -> Vec<Node> {
    pressure
        .iter()
        .zip(caps)
        .map(|(&p, &c)| {
            if p <= 0.0 {
                Node::Out
            } else if p >= c {
                Node::Plastic
            } else {
                Node::Elastic
            }
        })
        .collect()
}
