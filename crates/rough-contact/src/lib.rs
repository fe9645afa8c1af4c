//! Elastic–perfectly-plastic contact of a rigid rough surface on an elastic
//! half-space, by boundary elements: the beside-the-theory simulation of
//! roughtui's contact view.
//!
//! - Compliance in Fourier space, ũ(q) = 2 p̃(q)/(E* |q|) on a periodic
//!   cell (the kernel of Tamaas and ContactMechanics), or Love's influence
//!   coefficients on a zero-padded 2N × 2N grid for a non-periodic window.
//! - Pressure saturation at the hardness (Kato's saturated contact): find p
//!   minimising ½⟨p, Kp⟩ − ⟨p, h⟩ with 0 ≤ p ≤ H and mean(p) = p̄, by a
//!   bound-constrained conjugate gradient ([`Contact::solve`] states the
//!   stopping rule).
//! - Surfaces: [`synthesise`] a periodic Gaussian power-law surface from a
//!   seed; [`low_pass`] a measured map to q ≤ ζ q0.
//!
//! No hardening, no adhesion, no tangential traction, small slopes.
//! Memory: about ten N² arrays of f64 (periodic), forty for the free
//! boundary's padded grid.

pub mod asperity;
mod cap;
mod fft;
mod load;
mod multigrid;
mod par;
mod solver;
mod sparse;
mod step;
mod surface;

use std::fmt;

pub use multigrid::{prolong, restrict};
pub use surface::{low_pass, moments, resample, synthesise, Moments, PowerLaw};

/// Threads a solve's passes run on (rayon's pool: the machine's cores, or
/// `RAYON_NUM_THREADS`).
pub fn threads() -> usize {
    rayon::current_num_threads()
}

/// How the grid meets what lies beyond it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Boundary {
    /// The surface repeats with period L in x and y.
    Periodic,
    /// The surface is a window on an infinite half-space loaded only inside
    /// it (measured maps that are not periodic).
    Free,
}

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Stop when the rms violation of the contact conditions, relative to
    /// the rms height, is at most this.
    pub tolerance: f64,
    /// Give up after this many iterations.
    pub max_iterations: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tolerance: 1e-10,
            max_iterations: 20_000,
        }
    }
}

/// One load's result. Areas are fractions of the nominal area A0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoadResult {
    /// Imposed mean pressure p̄.
    pub p_mean: f64,
    /// The pressure cap in use (∞: purely elastic).
    pub hardness: f64,
    /// Contact area (p > 0).
    pub area: f64,
    /// Elastic part, 0 < p < H.
    pub elastic_area: f64,
    /// Plastic part, p = H.
    pub plastic_area: f64,
    /// Mean separation over A0: mean of max(gap, 0).
    pub mean_gap: f64,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// Final residual (see [`Contact::solve`]).
    pub residual: f64,
    /// The contact's perimeter: the sides between a node in contact and a
    /// neighbour out of it (4-neighbours; across the cell's edges on a
    /// periodic grid), over the number of nodes.
    pub perimeter: f64,
}

/// The share of a node side that a grid's contact area counts too much,
/// (π − 1 + ln 2)/24 (Yastrebov, Anciaux & Molinari, Tribol. Int. 114,
/// 2017; Tamaas's `Statistics2D.contact` applies the same).
pub const PERIMETER_CORRECTION: f64 = (std::f64::consts::PI - 1.0 + std::f64::consts::LN_2) / 24.0;

impl LoadResult {
    /// The contact area less the grid's overcount along the contact's
    /// edge: A − c·P with c = [`PERIMETER_CORRECTION`] and P the
    /// [`LoadResult::perimeter`] (both as fractions of A0).
    pub fn corrected_area(&self) -> f64 {
        (self.area - PERIMETER_CORRECTION * self.perimeter).max(0.0)
    }
}

/// What went wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum ContactError {
    /// The inputs are not a valid problem; the message says which and why.
    Input(String),
    /// The iteration limit was reached.
    NotConverged { iterations: usize, residual: f64 },
    /// The progress callback asked to stop.
    Cancelled,
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ContactError::Input(s) => write!(f, "{s}"),
            ContactError::NotConverged {
                iterations,
                residual,
            } => write!(
                f,
                "contact solver did not converge: residual {residual:.3e} after {iterations} iterations"
            ),
            ContactError::Cancelled => write!(f, "contact solution cancelled"),
        }
    }
}

impl std::error::Error for ContactError {}

/// A rigid rough surface against an elastic half-space, ready to be loaded.
pub struct Contact {
    n: usize,
    length: f64,
    periodic: bool,
    bccg: solver::Bccg,
    pressure: Vec<f64>,
    gap: Vec<f64>,
    last_load: Option<f64>,
}

impl Contact {
    /// `heights`: n × n, row-major (x fastest), of the rigid surface (up is
    /// towards the half-space: contact starts at the highest point);
    /// `length`: side of the cell; `e_star`: composite modulus.
    pub fn new(
        heights: Vec<f64>,
        n: usize,
        length: f64,
        e_star: f64,
        boundary: Boundary,
    ) -> Result<Self, ContactError> {
        if n < 2 || !n.is_power_of_two() {
            return Err(ContactError::Input(format!(
                "grid side {n}: must be a power of two, at least 2"
            )));
        }
        if heights.len() != n * n {
            return Err(ContactError::Input(format!(
                "{} heights for a {n} × {n} grid",
                heights.len()
            )));
        }
        if let Some(i) = heights.iter().position(|v| !v.is_finite()) {
            return Err(ContactError::Input(format!(
                "height at row {}, column {} is not a finite number",
                i / n,
                i % n
            )));
        }
        if !(length.is_finite() && length > 0.0) {
            return Err(ContactError::Input(format!(
                "cell side {length}: must be finite and positive"
            )));
        }
        if !(e_star.is_finite() && e_star > 0.0) {
            return Err(ContactError::Input(format!(
                "composite modulus {e_star}: must be finite and positive"
            )));
        }
        let op = match boundary {
            Boundary::Periodic => fft::Compliance::periodic(n, length, e_star),
            Boundary::Free => fft::Compliance::free(n, length, e_star),
        };
        Ok(Contact {
            n,
            length,
            periodic: boundary == Boundary::Periodic,
            bccg: solver::Bccg::new(heights, op),
            pressure: vec![0.0; n * n],
            gap: vec![0.0; n * n],
            last_load: None,
        })
    }

    /// Grid side.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Cell side.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// rms height of the surface (the residual's scale).
    pub fn h_rms(&self) -> f64 {
        self.bccg.h_rms
    }

    /// The rigid surface's heights, n × n row-major.
    pub fn heights(&self) -> &[f64] {
        &self.bccg.h
    }

    /// The next solve starts from `p` (n × n, any non-negative field),
    /// rescaled to its load, instead of the last solution.
    pub fn start_from(&mut self, p: &[f64]) -> Result<(), ContactError> {
        if p.len() != self.pressure.len() {
            return Err(ContactError::Input(format!(
                "a start of {} values for a {n} × {n} grid",
                p.len(),
                n = self.n
            )));
        }
        let mean = p.iter().sum::<f64>() / p.len() as f64;
        self.pressure.copy_from_slice(p);
        self.last_load = (mean.is_finite() && mean > 0.0).then_some(mean);
        Ok(())
    }

    /// Pressure of the last solution, n × n row-major.
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Gap of the last solution (zero on the elastic contact, negative
    /// where the cap let the surface through).
    pub fn gap(&self) -> &[f64] {
        &self.gap
    }

    /// Solve at mean pressure `p_mean` (0 < p̄ ≤ H) with the pressure capped
    /// at `hardness` (`f64::INFINITY` for a purely elastic contact).
    ///
    /// Stopping rule: with the gap g = u − h + λ (λ makes g average zero
    /// over the nodes with 0 < p < H), the residual is the rms over all
    /// nodes of g on those nodes, min(g, 0) where p = 0 and max(g, 0) where
    /// p = H, divided by the surface's rms height; the solver stops when it
    /// is ≤ `opts.tolerance`. The mean pressure is imposed exactly at every
    /// iteration. Starts from the previous solution, rescaled, if any.
    pub fn solve(
        &mut self,
        p_mean: f64,
        hardness: f64,
        opts: &Options,
    ) -> Result<LoadResult, ContactError> {
        self.solve_with_progress(p_mean, hardness, opts, &mut |_, _| true)
    }

    /// [`Contact::solve`] with `progress(iteration, residual)` called at
    /// every iteration; returning false cancels.
    pub fn solve_with_progress(
        &mut self,
        p_mean: f64,
        hardness: f64,
        opts: &Options,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> Result<LoadResult, ContactError> {
        if hardness.is_nan() || hardness <= 0.0 {
            return Err(ContactError::Input(format!(
                "hardness {hardness}: must be positive (∞ for elastic)"
            )));
        }
        self.check(p_mean, hardness, opts)?;
        self.run(
            p_mean.min(hardness),
            &cap::Uniform(hardness),
            opts,
            progress,
        )
    }

    /// [`Contact::solve_with_progress`] with a hardness for each node
    /// (`caps`, n × n row-major, each positive, ∞ for elastic): the size
    /// effect node by node. The result's `hardness` is the caps' mean.
    pub fn solve_capped(
        &mut self,
        p_mean: f64,
        caps: &[f64],
        opts: &Options,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> Result<LoadResult, ContactError> {
        if caps.len() != self.pressure.len() {
            return Err(ContactError::Input(format!(
                "{} hardnesses for a {n} × {n} grid",
                caps.len(),
                n = self.n
            )));
        }
        if let Some(i) = caps.iter().position(|c| c.is_nan() || *c <= 0.0) {
            return Err(ContactError::Input(format!(
                "hardness {} at row {}, column {}: must be positive (∞ for elastic)",
                caps[i],
                i / self.n,
                i % self.n
            )));
        }
        let mean = caps.iter().sum::<f64>() / caps.len() as f64;
        let max = caps.iter().cloned().fold(0.0, f64::max);
        self.check(p_mean, mean, opts)?;
        let cap = cap::PerNode { caps, max, mean };
        self.run(p_mean.min(mean), &cap, opts, progress)
    }

    fn check(&self, p_mean: f64, hardness: f64, opts: &Options) -> Result<(), ContactError> {
        if !(p_mean.is_finite() && p_mean > 0.0) {
            return Err(ContactError::Input(format!(
                "mean pressure {p_mean}: must be finite and positive"
            )));
        }
        if p_mean > hardness * (1.0 + 1e-12) {
            return Err(ContactError::Input(format!(
                "mean pressure {p_mean} above the hardness {hardness}: no admissible pressure"
            )));
        }
        if opts.tolerance.is_nan() || opts.tolerance <= 0.0 {
            return Err(ContactError::Input(format!(
                "tolerance {}: must be positive",
                opts.tolerance
            )));
        }
        Ok(())
    }

    fn run<C: cap::Cap>(
        &mut self,
        p_mean: f64,
        cap: &C,
        opts: &Options,
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> Result<LoadResult, ContactError> {
        if let Some(prev) = self.last_load {
            let k = p_mean / prev;
            self.pressure.iter_mut().for_each(|v| *v *= k);
        }
        self.last_load = None;
        let r = self.bccg.solve(
            p_mean,
            cap,
            opts,
            &mut self.pressure,
            &mut self.gap,
            progress,
        );
        match r {
            Ok(mut r) => {
                self.last_load = Some(p_mean);
                r.perimeter = perimeter(&self.pressure, self.n, self.periodic);
                Ok(r)
            }
            Err(e) => {
                self.pressure.iter_mut().for_each(|v| *v = 0.0);
                Err(e)
            }
        }
    }

    /// Solve each load in turn (each warm-starts the next).
    pub fn sweep(
        &mut self,
        loads: &[f64],
        hardness: f64,
        opts: &Options,
    ) -> Result<Vec<LoadResult>, ContactError> {
        loads
            .iter()
            .map(|&p| self.solve(p, hardness, opts))
            .collect()
    }
}

/// The sides between a node with p > 0 and a 4-neighbour with p = 0 of the
/// n × n field `p`, over n² (periodic: across the cell's edges too; else
/// only inside the grid).
pub fn perimeter(p: &[f64], n: usize, periodic: bool) -> f64 {
    let on = |i: usize| p[i] > 0.0;
    let mut sides = 0usize;
    for y in 0..n {
        for x in 0..n {
            let i = y * n + x;
            // Each side once: the one to the right and the one below.
            if x + 1 < n || periodic {
                sides += usize::from(on(i) != on(y * n + (x + 1) % n));
            }
            if y + 1 < n || periodic {
                sides += usize::from(on(i) != on(((y + 1) % n) * n + x));
            }
        }
    }
    sides as f64 / (n * n) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tamaas 2.9's `FloodFill.getClusters` on this 16 × 16 map gives
    /// perimeters 14 (a 3 × 4 block), 6 (two nodes joined across the
    /// cell's edge) and 4 (one node); its `Statistics2D.contact` with a
    /// perimeter of one side takes 0.118114 of a node off.
    #[test]
    fn the_perimeter_counts_sides_as_tamaas_does() {
        let n = 16;
        let mut p = vec![0.0; n * n];
        for y in 2..5 {
            for x in 3..7 {
                p[y * n + x] = 1.0;
            }
        }
        p[10 * n + 10] = 1.0;
        p[0] = 1.0;
        p[(n - 1) * n] = 1.0;
        assert_eq!(perimeter(&p, n, true) * (n * n) as f64, 24.0);
        // Without the wrap the pair is two corner nodes of two inner sides
        // each.
        assert_eq!(perimeter(&p, n, false) * (n * n) as f64, 22.0);
        assert!((PERIMETER_CORRECTION - 0.1181141597562391).abs() < 1e-15);
    }
}
