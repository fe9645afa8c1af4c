//! The bound-constrained conjugate gradient (Polonsky & Keer 1999, with the
//! pressure cap of Almqvist et al. 2007): minimise ½⟨p, Kp⟩ − ⟨p, h⟩ over
//! 0 ≤ p ≤ H with mean(p) = p̄. H may differ from node to node (a hardness
//! per asperity).
//!
//! The conjugate directions live on the free set F = {0 < p < H}, with zero
//! mean over F so that a step keeps the load. After each step the pressure
//! is projected on [0, H], nodes whose gap says they are on the wrong side
//! of a bound are released (the conjugacy is restarted only when more than
//! one in [`RESTART_FRACTION`] of the free set is released), and the mean is
//! imposed exactly by a uniform shift of the loaded nodes if the step moved
//! it. A step that clipped, released and shifted nothing moved u = Kp by
//! −τ Kt, known without another transform.
//!
//! Stopping rule: the gap g = Kp − h + λ, with λ chosen so that g averages
//! to zero over F, must vanish on F, be ≥ 0 where p = 0 and ≤ 0 where p = H.
//! The residual is the root mean square over all nodes of what violates
//! that, divided by the rms height of the surface; the solver stops when it
//! is below the tolerance (on a u computed by a transform, not updated).

// Index loops walk several parallel arrays at once; clearer than zips.
#![allow(clippy::needless_range_loop)]

use rayon::prelude::*;

use crate::cap::{class, Cap, Set};
use crate::fft::Compliance;
use crate::load::{impose_mean, project};
use crate::par::{chunk_len, min_len};
use crate::step::step;
use crate::{ContactError, LoadResult, Options};

/// Why an iteration stopped early.
pub(crate) enum Stop {
    Converged,
    Cancelled,
}

/// Work arrays for one surface and one kernel, reused across loads.
pub(crate) struct Bccg {
    pub(crate) n2: usize,
    pub(crate) h: Vec<f64>,
    pub(crate) h_rms: f64,
    op: Compliance,
    u: Vec<f64>,
    t: Vec<f64>,
    r: Vec<f64>,
    best_p: Vec<f64>,
}

/// A release of more than 1/RESTART_FRACTION of the free set restarts the
/// conjugate directions. Restarting at every release (Polonsky & Keer) turns
/// the method into steepest descent while the contact's edges settle: on
/// fig2's 1024² surface the 13 loads took 5 738 iterations so, 1 363 with
/// this rule, to the same areas.
const RESTART_FRACTION: usize = 100;
/// Steps of u updated without a transform before it is computed afresh
/// (rounding drift).
const REFRESH: usize = 20;
/// Iterations without a better residual before the solver stops.
const STALL: usize = 50;
/// A stalled solve still counts as converged if its best residual is within
/// this factor of the tolerance (the floor that rounding sets).
const FLOOR_SLACK: f64 = 100.0;
/// The kept best iterate is replaced when the residual has halved since.
const BEST_FACTOR: f64 = 0.5;
/// What a pass over the gap summed.
#[derive(Clone, Copy)]
struct Sums {
    /// Σ_F g, Σ_F g², |F|.
    sum: f64,
    square: f64,
    n_f: usize,
    /// Σ_F of the last direction (its mean on today's F is removed).
    t_sum: f64,
    /// The smallest gap out of contact, the largest at the cap.
    zero_min: f64,
    cap_max: f64,
}

impl Default for Sums {
    fn default() -> Self {
        Sums {
            sum: 0.0,
            square: 0.0,
            n_f: 0,
            t_sum: 0.0,
            zero_min: f64::INFINITY,
            cap_max: f64::NEG_INFINITY,
        }
    }
}

impl Sums {
    fn merge(self, o: &Sums) -> Sums {
        Sums {
            sum: self.sum + o.sum,
            square: self.square + o.square,
            n_f: self.n_f + o.n_f,
            t_sum: self.t_sum + o.t_sum,
            zero_min: self.zero_min.min(o.zero_min),
            cap_max: self.cap_max.max(o.cap_max),
        }
    }

    /// The δ that makes the gap average zero over F.
    fn shift(&self) -> f64 {
        if self.n_f > 0 {
            return -self.sum / self.n_f as f64;
        }
        // No free node: any shift between the bounds' gaps; the middle.
        let (z, c) = (self.zero_min, self.cap_max);
        let lo = if c.is_finite() { -c } else { -z };
        let hi = if z.is_finite() { -z } else { -c };
        0.5 * (lo + hi)
    }

    /// Σ_F (g + δ)² from the pass's sums, unless cancellation could cost
    /// more than about 1e-6 of it (then `None`).
    fn free_square(&self, delta: f64) -> Option<f64> {
        if self.n_f == 0 {
            return Some(0.0);
        }
        let mean_part = self.n_f as f64 * delta * delta;
        let v = self.square - mean_part;
        (v > 1e-10 * mean_part).then_some(v)
    }
}

impl Bccg {
    pub(crate) fn new(h: Vec<f64>, op: Compliance) -> Self {
        let n2 = h.len();
        let mean = h.iter().sum::<f64>() / n2 as f64;
        let h_rms = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n2 as f64).sqrt();
        Bccg {
            n2,
            h,
            h_rms,
            op,
            u: vec![0.0; n2],
            t: vec![0.0; n2],
            r: vec![0.0; n2],
            best_p: vec![0.0; n2],
        }
    }

    /// Solve for mean pressure `p_mean` under the cap `cap`, starting from
    /// `p` (any non-negative field; it is re-projected first). On return `p`
    /// holds the pressure and `gap` the gap.
    pub(crate) fn solve<C: Cap>(
        &mut self,
        p_mean: f64,
        cap: &C,
        opts: &Options,
        p: &mut [f64],
        gap: &mut [f64],
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> Result<LoadResult, ContactError> {
        let n2 = self.n2;
        let target = p_mean * n2 as f64;
        if p_mean >= cap.mean() {
            // Everything at the hardness: the only admissible field.
            for i in 0..n2 {
                p[i] = cap.at(i);
            }
            self.op.apply(p, &mut self.u);
            for i in 0..n2 {
                gap[i] = self.u[i] - self.h[i];
            }
            let hi = gap.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            gap.iter_mut().for_each(|g| *g -= hi);
            return Ok(self.result(p_mean, cap, p, gap, 0, 0.0));
        }
        if self.h_rms == 0.0 && cap.max() == cap.mean() {
            // A flat surface carries the load uniformly.
            p.iter_mut().for_each(|v| *v = p_mean);
            gap.iter_mut().for_each(|g| *g = 0.0);
            return Ok(self.result(p_mean, cap, p, gap, 0, 0.0));
        }
        for i in 0..n2 {
            p[i] = p[i].clamp(0.0, cap.at(i));
        }
        if p.iter().all(|&v| v <= 0.0) {
            for i in 0..n2 {
                p[i] = p_mean.min(cap.at(i));
            }
        }
        let _ = impose_mean(p, cap, target, None);

        let mut g_old = 1.0;
        let mut restart = true;
        let mut tau_prev = f64::NAN;
        let mut residual;
        let mut it = 0;
        // The best iterate kept: near the rounding floor a step can be
        // garbage; the solver then returns to it and stops. `best` is the
        // best residual seen, `kept` the kept iterate's.
        let (mut best, mut best_it, mut kept) = (f64::INFINITY, 0usize, f64::INFINITY);
        // Whether u = Kp is known without a transform (the last step was a
        // plain conjugate-gradient step), and for how many steps.
        let (mut u_known, mut stale) = (false, 0usize);
        // λ of the last gap: the next is near it, which keeps Σ_F g² free of
        // cancellation when it is formed from one pass's sums.
        let mut lambda = 0.0;
        let stop = loop {
            let fresh = !u_known || stale >= REFRESH;
            if fresh {
                stale = 0;
                self.op.apply(p, &mut self.u);
            }
            let sums = self.gap_pass(p, cap, gap, lambda);
            let delta = sums.shift();
            lambda += delta;
            let n_f = sums.n_f;
            let g_sq = match sums.free_square(delta) {
                Some(v) => v,
                None => self.free_square(p, cap, gap, delta),
            };
            // Conjugate direction on F, mean zero there (the last
            // direction's mean over today's F removed; the gap's is zero),
            // built in the pass that finishes the gap and measures the
            // residual (unused if the solver stops here).
            let beta = if restart { 0.0 } else { g_sq / g_old };
            let t_bar = if n_f > 0 {
                sums.t_sum / n_f as f64
            } else {
                0.0
            };
            let (viol, num) = self.direction_pass(p, cap, gap, delta, Some((beta, t_bar)));
            residual = (viol / n2 as f64).sqrt() / self.h_rms;
            if residual <= opts.tolerance {
                if !fresh {
                    // Converged on the updated u: confirm on a computed one.
                    u_known = false;
                    continue;
                }
                break Stop::Converged;
            }
            if residual < best {
                best = residual;
                best_it = it;
                if residual < BEST_FACTOR * kept {
                    kept = residual;
                    self.best_p.copy_from_slice(p);
                }
            } else if it >= best_it + STALL || residual > 1e6 * best {
                // Stalled (or thrown off) at the rounding floor.
                p.copy_from_slice(&self.best_p);
                if kept <= FLOOR_SLACK * opts.tolerance {
                    self.op.apply(p, &mut self.u);
                    self.gap_of(p, cap, gap);
                    residual = kept;
                    break Stop::Converged;
                }
                let (its, res) = self.projected(p, cap, target, opts, gap, progress, it)?;
                it = its;
                residual = res;
                break Stop::Converged;
            }
            if !progress(it, residual) {
                break Stop::Cancelled;
            }
            if it >= opts.max_iterations {
                return Err(ContactError::NotConverged {
                    iterations: it,
                    residual,
                });
            }
            it += 1;
            g_old = g_sq.max(f64::MIN_POSITIVE);
            let mut tau = if n_f > 0 {
                // ⟨t, Kt⟩ (t is zero off F) from the transform's last pass.
                let den = self.op.apply_dot(&self.t, &mut self.r);
                if den > 0.0 && num > 0.0 {
                    num / den
                } else {
                    tau_prev
                }
            } else {
                tau_prev
            };
            if !tau.is_finite() || tau <= 0.0 {
                tau = self.op.diagonal_inverse();
            }
            tau_prev = tau;

            // Step, release, project. A node released from a bound moves by
            // the pressure that would close its own gap alone (1/K(0)), not
            // by the CG step, which belongs to the free set's conditioning.
            // u follows the plain step, and the few nodes off it one by one.
            let tau_r = tau.min(self.op.diagonal_inverse());
            let s = step(p, &mut self.u, gap, &self.t, &self.r, cap, (tau, tau_r));
            restart = s.released * RESTART_FRACTION > n_f;
            let shifted = impose_mean(p, cap, target, Some(s.count));
            u_known = !shifted
                && n_f > 0
                && match &s.off {
                    Some(off) if off.is_empty() => true,
                    Some(off) => self.op.add_nodes(&mut self.u, off),
                    None => false,
                };
            if u_known {
                stale += 1;
            }
        };
        match stop {
            Stop::Cancelled => Err(ContactError::Cancelled),
            Stop::Converged => Ok(self.result(p_mean, cap, p, gap, it, residual)),
        }
    }

    /// The gap u − h + λ0 (u must hold Kp) and the sums that give λ.
    fn gap_pass<C: Cap>(&mut self, p: &[f64], cap: &C, gap: &mut [f64], lambda0: f64) -> Sums {
        let n2 = self.n2;
        let (c, min) = (chunk_len(n2), min_len(n2));
        let parts: Vec<Sums> = gap
            .par_chunks_mut(c)
            .zip(self.u.par_chunks(c))
            .zip(self.h.par_chunks(c))
            .zip(p.par_chunks(c))
            .zip(self.t.par_chunks(c))
            .enumerate()
            .with_min_len(min)
            .map(|(k, ((((gap, u), h), p), t))| {
                let mut s = Sums::default();
                for j in 0..gap.len() {
                    let g = u[j] - h[j] + lambda0;
                    gap[j] = g;
                    match class(p[j], cap.at(k * c + j)) {
                        Set::Free => {
                            s.sum += g;
                            s.square += g * g;
                            s.n_f += 1;
                            s.t_sum += t[j];
                        }
                        Set::Zero => s.zero_min = s.zero_min.min(g),
                        Set::Cap => s.cap_max = s.cap_max.max(g),
                    }
                }
                s
            })
            .collect();
        parts.iter().fold(Sums::default(), |a, b| a.merge(b))
    }

    /// Σ_F (g + δ)², exactly (a pass of its own).
    fn free_square<C: Cap>(&self, p: &[f64], cap: &C, gap: &[f64], delta: f64) -> f64 {
        let n2 = self.n2;
        let (c, min) = (chunk_len(n2), min_len(n2));
        let parts: Vec<f64> = gap
            .par_chunks(c)
            .zip(p.par_chunks(c))
            .enumerate()
            .with_min_len(min)
            .map(|(k, (gap, p))| {
                let mut sq = 0.0;
                for j in 0..gap.len() {
                    if class(p[j], cap.at(k * c + j)) == Set::Free {
                        sq += (gap[j] + delta).powi(2);
                    }
                }
                sq
            })
            .collect();
        parts.iter().sum()
    }

    /// Adds δ to the gap and returns the squared violations of the contact
    /// conditions summed over all nodes; with `dir` = (β, t̄) also builds the
    /// conjugate direction t = g + β (t − t̄) on F (0 off F) and returns
    /// Σ_F g t.
    fn direction_pass<C: Cap>(
        &mut self,
        p: &[f64],
        cap: &C,
        gap: &mut [f64],
        delta: f64,
        dir: Option<(f64, f64)>,
    ) -> (f64, f64) {
        let n2 = self.n2;
        let (c, min) = (chunk_len(n2), min_len(n2));
        let parts: Vec<(f64, f64)> = gap
            .par_chunks_mut(c)
            .zip(self.t.par_chunks_mut(c))
            .zip(p.par_chunks(c))
            .enumerate()
            .with_min_len(min)
            .map(|(k, ((gap, t), p))| {
                let (mut viol, mut num) = (0.0, 0.0);
                for j in 0..gap.len() {
                    gap[j] += delta;
                    let gi = gap[j];
                    let v = match class(p[j], cap.at(k * c + j)) {
                        Set::Free => {
                            if let Some((beta, t_bar)) = dir {
                                let d = gi + beta * (t[j] - t_bar);
                                num += gi * d;
                                t[j] = d;
                            }
                            gi
                        }
                        Set::Zero => {
                            if dir.is_some() {
                                t[j] = 0.0;
                            }
                            gi.min(0.0)
                        }
                        Set::Cap => {
                            if dir.is_some() {
                                t[j] = 0.0;
                            }
                            gi.max(0.0)
                        }
                    };
                    viol += v * v;
                }
                (viol, num)
            })
            .collect();
        parts.iter().fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
    }

    /// The residual of the stopping rule for `p` (u must hold Kp), the gap
    /// left in `gap`.
    fn residual<C: Cap>(&mut self, p: &[f64], cap: &C, gap: &mut [f64]) -> f64 {
        let sums = self.gap_pass(p, cap, gap, 0.0);
        let (viol, _) = self.direction_pass(p, cap, gap, sums.shift(), None);
        (viol / self.n2 as f64).sqrt() / self.h_rms
    }

    /// Accelerated projected gradient (FISTA with O'Donoghue–Candès
    /// restarts) on the same problem, with the exact Euclidean projection on
    /// {0 ≤ p ≤ H, mean p = p̄}: slower than the conjugate gradient but
    /// convergent whatever the sets do; taken over when the conjugate
    /// gradient stalls (contacts where most nodes sit at the hardness).
    #[allow(clippy::too_many_arguments)]
    fn projected<C: Cap>(
        &mut self,
        p: &mut [f64],
        cap: &C,
        target: f64,
        opts: &Options,
        gap: &mut [f64],
        progress: &mut dyn FnMut(usize, f64) -> bool,
        mut it: usize,
    ) -> Result<(usize, f64), ContactError> {
        let n2 = self.n2;
        let step = 1.0 / self.op.max_eigenvalue();
        let mut y = p.to_vec();
        let mut prev = p.to_vec();
        let mut theta: f64 = 1.0;
        loop {
            self.op.apply(&y, &mut self.u);
            for i in 0..n2 {
                self.t[i] = y[i] - step * (self.u[i] - self.h[i]);
            }
            project(&mut self.t, cap, target);
            let mut dot = 0.0;
            for i in 0..n2 {
                dot += (y[i] - self.t[i]) * (self.t[i] - prev[i]);
            }
            let beta = if dot > 0.0 {
                theta = 1.0;
                0.0
            } else {
                let next = 0.5 * (1.0 + (1.0 + 4.0 * theta * theta).sqrt());
                let b = (theta - 1.0) / next;
                theta = next;
                b
            };
            for i in 0..n2 {
                y[i] = self.t[i] + beta * (self.t[i] - prev[i]);
                prev[i] = self.t[i];
            }
            it += 1;
            if it.is_multiple_of(10) {
                p.copy_from_slice(&prev);
                self.op.apply(p, &mut self.u);
                let residual = self.residual(p, cap, gap);
                if residual <= opts.tolerance {
                    return Ok((it, residual));
                }
                if !progress(it, residual) {
                    return Err(ContactError::Cancelled);
                }
                if it >= opts.max_iterations {
                    return Err(ContactError::NotConverged {
                        iterations: it,
                        residual,
                    });
                }
            }
        }
    }

    /// The gap of the converged `p` (u already holds Kp), λ from the free set.
    fn gap_of<C: Cap>(&self, p: &[f64], cap: &C, gap: &mut [f64]) {
        let (mut sum, mut n_f) = (0.0, 0usize);
        for i in 0..self.n2 {
            gap[i] = self.u[i] - self.h[i];
            if class(p[i], cap.at(i)) == Set::Free {
                sum += gap[i];
                n_f += 1;
            }
        }
        let lambda = if n_f > 0 { -sum / n_f as f64 } else { 0.0 };
        gap.iter_mut().for_each(|g| *g += lambda);
    }

    fn result<C: Cap>(
        &self,
        p_mean: f64,
        cap: &C,
        p: &[f64],
        gap: &[f64],
        iterations: usize,
        residual: f64,
    ) -> LoadResult {
        let n2 = self.n2 as f64;
        let (mut contact, mut plastic) = (0usize, 0usize);
        for (i, &v) in p.iter().enumerate() {
            if v > 0.0 {
                contact += 1;
                if v >= cap.at(i) {
                    plastic += 1;
                }
            }
        }
        let (contact, plastic) = (contact as f64 / n2, plastic as f64 / n2);
        let mean_gap = gap.iter().map(|g| g.max(0.0)).sum::<f64>() / n2;
        LoadResult {
            p_mean,
            hardness: cap.mean(),
            area: contact,
            elastic_area: contact - plastic,
            plastic_area: plastic,
            mean_gap,
            iterations,
            residual,
            perimeter: 0.0,
        }
    }
}
