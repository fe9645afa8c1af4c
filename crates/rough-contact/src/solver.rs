//! The bound-constrained conjugate gradient (Polonsky & Keer 1999, with the
//! pressure cap of Almqvist et al. 2007): minimise ½⟨p, Kp⟩ − ⟨p, h⟩ over
//! 0 ≤ p ≤ H with mean(p) = p̄.
//!
//! The conjugate directions live on the free set F = {0 < p < H}; their mean
//! over F is removed so that a step keeps the load. After each step the
//! pressure is projected on [0, H], nodes whose gap says they are on the
//! wrong side of a bound are released (and the conjugacy restarted), and the
//! mean is imposed exactly by a uniform shift of the loaded nodes.
//!
//! Stopping rule: the gap g = Kp − h + λ, with λ chosen so that g averages
//! to zero over F, must vanish on F, be ≥ 0 where p = 0 and ≤ 0 where p = H.
//! The residual is the root mean square over all nodes of what violates
//! that, divided by the rms height of the surface; the solver stops when it
//! is below the tolerance.

// Index loops walk several parallel arrays at once; clearer than zips.
#![allow(clippy::needless_range_loop)]

use crate::fft::Compliance;
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

/// Iterations without a better residual before the solver stops.
const STALL: usize = 50;
/// A stalled solve still counts as converged if its best residual is within
/// this factor of the tolerance (the floor that rounding sets).
const FLOOR_SLACK: f64 = 100.0;

#[derive(Clone, Copy, PartialEq)]
enum Set {
    Zero,
    Free,
    Cap,
}

fn class(p: f64, cap: f64) -> Set {
    if p <= 0.0 {
        Set::Zero
    } else if p >= cap {
        Set::Cap
    } else {
        Set::Free
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
    pub(crate) fn solve(
        &mut self,
        p_mean: f64,
        cap: f64,
        opts: &Options,
        p: &mut [f64],
        gap: &mut [f64],
        progress: &mut dyn FnMut(usize, f64) -> bool,
    ) -> Result<LoadResult, ContactError> {
        let n2 = self.n2;
        let target = p_mean * n2 as f64;
        if p_mean >= cap {
            // Everything at the hardness: the only admissible field.
            p.iter_mut().for_each(|v| *v = cap);
            self.op.apply(p, &mut self.u);
            for i in 0..n2 {
                gap[i] = self.u[i] - self.h[i];
            }
            let hi = gap.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            gap.iter_mut().for_each(|g| *g -= hi);
            return Ok(self.result(p_mean, cap, p, gap, 0, 0.0));
        }
        if self.h_rms == 0.0 {
            // A flat surface carries the load uniformly.
            p.iter_mut().for_each(|v| *v = p_mean);
            gap.iter_mut().for_each(|g| *g = 0.0);
            return Ok(self.result(p_mean, cap, p, gap, 0, 0.0));
        }
        p.iter_mut().for_each(|v| *v = v.clamp(0.0, cap));
        if p.iter().all(|&v| v <= 0.0) {
            p.iter_mut().for_each(|v| *v = p_mean);
        }
        impose_mean(p, cap, target);

        let mut g_old = 1.0;
        let mut restart = true;
        let mut tau_prev = f64::NAN;
        let mut residual;
        let mut it = 0;
        // The best iterate so far: near the rounding floor a step can be
        // garbage; the solver then returns to the best one and stops.
        let (mut best, mut best_it) = (f64::INFINITY, 0usize);
        let stop = loop {
            let (res, g_sq, n_f) = self.kkt(p, cap, gap);
            residual = res;
            if residual <= opts.tolerance {
                break Stop::Converged;
            }
            if residual < best {
                best = residual;
                best_it = it;
                self.best_p.copy_from_slice(p);
            } else if it >= best_it + STALL || residual > 1e6 * best {
                // Stalled (or thrown off) at the rounding floor.
                p.copy_from_slice(&self.best_p);
                if best <= FLOOR_SLACK * opts.tolerance {
                    self.op.apply(p, &mut self.u);
                    self.gap_of(p, cap, gap);
                    residual = best;
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

            // Conjugate direction on F.
            let beta = if restart { 0.0 } else { g_sq / g_old };
            g_old = g_sq.max(f64::MIN_POSITIVE);
            for i in 0..n2 {
                self.t[i] = if class(p[i], cap) == Set::Free {
                    gap[i] + beta * self.t[i]
                } else {
                    0.0
                };
            }
            let mut tau = if n_f > 0 {
                self.op.apply(&self.t, &mut self.r);
                let (mut rs, mut ts) = (0.0, 0.0);
                for i in 0..n2 {
                    if class(p[i], cap) == Set::Free {
                        rs += self.r[i];
                        ts += self.t[i];
                    }
                }
                let rbar = rs / n_f as f64;
                let (mut num, mut den) = (0.0, 0.0);
                for i in 0..n2 {
                    if class(p[i], cap) == Set::Free {
                        num += gap[i] * self.t[i];
                        den += (self.r[i] - rbar) * self.t[i];
                    }
                }
                let _ = ts;
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
            let tau_r = tau.min(self.op.diagonal_inverse());
            let mut released = false;
            for i in 0..n2 {
                let gi = gap[i];
                let pi = p[i];
                p[i] = match class(pi, cap) {
                    Set::Free => (pi - tau * self.t[i]).clamp(0.0, cap),
                    Set::Zero if gi < 0.0 => {
                        released = true;
                        (-tau_r * gi).min(cap)
                    }
                    Set::Cap if gi > 0.0 => {
                        released = true;
                        (cap - tau_r * gi).max(0.0)
                    }
                    _ => pi,
                };
            }
            restart = released;
            impose_mean(p, cap, target);
        };
        match stop {
            Stop::Cancelled => Err(ContactError::Cancelled),
            Stop::Converged => Ok(self.result(p_mean, cap, p, gap, it, residual)),
        }
    }

    /// u = Kp, the gap with λ from the free set, and the residual of the
    /// stopping rule; also Σ_F g² and |F| for the conjugate gradient.
    fn kkt(&mut self, p: &[f64], cap: f64, gap: &mut [f64]) -> (f64, f64, usize) {
        let n2 = self.n2;
        self.op.apply(p, &mut self.u);
        // Raw gap and λ from the free set.
        let (mut sum_f, mut n_f) = (0.0, 0usize);
        let (mut zero_min, mut cap_max) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..n2 {
            let g = self.u[i] - self.h[i];
            gap[i] = g;
            match class(p[i], cap) {
                Set::Free => {
                    sum_f += g;
                    n_f += 1;
                }
                Set::Zero => zero_min = zero_min.min(g),
                Set::Cap => cap_max = cap_max.max(g),
            }
        }
        let lambda = if n_f > 0 {
            -sum_f / n_f as f64
        } else {
            // No free node: any λ between the bounds' gaps; the middle.
            let lo = if cap_max.is_finite() {
                -cap_max
            } else {
                -zero_min
            };
            let hi = if zero_min.is_finite() {
                -zero_min
            } else {
                -cap_max
            };
            0.5 * (lo + hi)
        };
        let mut viol = 0.0;
        let mut g_sq = 0.0;
        for i in 0..n2 {
            gap[i] += lambda;
            let gi = gap[i];
            let v = match class(p[i], cap) {
                Set::Free => {
                    g_sq += gi * gi;
                    gi
                }
                Set::Zero => gi.min(0.0),
                Set::Cap => gi.max(0.0),
            };
            viol += v * v;
        }
        ((viol / n2 as f64).sqrt() / self.h_rms, g_sq, n_f)
    }

    /// Accelerated projected gradient (FISTA with O'Donoghue–Candès
    /// restarts) on the same problem, with the exact Euclidean projection on
    /// {0 ≤ p ≤ H, mean p = p̄}: slower than the conjugate gradient but
    /// convergent whatever the sets do; taken over when the conjugate
    /// gradient stalls (contacts where most nodes sit at the hardness).
    #[allow(clippy::too_many_arguments)]
    fn projected(
        &mut self,
        p: &mut [f64],
        cap: f64,
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
            impose_mean_on(&mut self.t, cap, target, Level::All);
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
                let (residual, _, _) = self.kkt(p, cap, gap);
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
    fn gap_of(&self, p: &[f64], cap: f64, gap: &mut [f64]) {
        let (mut sum, mut n_f) = (0.0, 0usize);
        for i in 0..self.n2 {
            gap[i] = self.u[i] - self.h[i];
            if class(p[i], cap) == Set::Free {
                sum += gap[i];
                n_f += 1;
            }
        }
        let lambda = if n_f > 0 { -sum / n_f as f64 } else { 0.0 };
        gap.iter_mut().for_each(|g| *g += lambda);
    }

    fn result(
        &self,
        p_mean: f64,
        cap: f64,
        p: &[f64],
        gap: &[f64],
        iterations: usize,
        residual: f64,
    ) -> LoadResult {
        let n2 = self.n2 as f64;
        let contact = p.iter().filter(|&&v| v > 0.0).count() as f64 / n2;
        let plastic = p.iter().filter(|&&v| v >= cap).count() as f64 / n2;
        let mean_gap = gap.iter().map(|g| g.max(0.0)).sum::<f64>() / n2;
        LoadResult {
            p_mean,
            hardness: cap,
            area: contact,
            elastic_area: contact - plastic,
            plastic_area: plastic,
            mean_gap,
            iterations,
            residual,
        }
    }
}

/// Make mean(p) exact by a uniform shift s of the free nodes (0 < p < cap),
/// clipped to [0, cap]: the root of the monotone piecewise-linear
/// Σ clip(pᵢ + s) = target, by Newton's method kept inside a bracket. Nodes
/// at the cap stay there unless the free nodes cannot make up the load
/// alone; nodes out of contact stay out unless the loaded ones cannot carry
/// it even at the cap.
pub(crate) fn impose_mean(p: &mut [f64], cap: f64, target: f64) {
    impose_mean_on(p, cap, target, Level::Auto);
}

/// Which nodes the shift of [`impose_mean_on`] moves.
#[derive(Clone, Copy, PartialEq)]
pub(crate) enum Level {
    /// As few as can make up the load (see [`impose_mean`]).
    Auto,
    /// Every node: the exact Euclidean projection on the constraints.
    All,
}

pub(crate) fn impose_mean_on(p: &mut [f64], cap: f64, target: f64, how: Level) {
    let (mut n_free, mut n_cap) = (0.0, 0.0);
    for &v in p.iter() {
        match class(v, cap) {
            Set::Free => n_free += 1.0,
            Set::Cap => n_cap += 1.0,
            Set::Zero => {}
        }
    }
    let cap_load = if n_cap > 0.0 { n_cap * cap } else { 0.0 };
    // Which nodes move: 0 free only, 1 all loaded, 2 all.
    let level = if how == Level::All {
        2
    } else if cap_load < target && (n_free + n_cap) * cap >= target && n_free > 0.0 {
        0
    } else if (n_free + n_cap) * cap >= target {
        1
    } else {
        2
    };
    let moves = |v: f64| match level {
        0 => v > 0.0 && v < cap,
        1 => v > 0.0,
        _ => true,
    };
    let eval = |p: &[f64], s: f64| -> (f64, f64) {
        let (mut sum, mut slope) = (0.0, 0.0);
        for &v in p {
            if moves(v) {
                let w = v + s;
                if w >= cap {
                    sum += cap;
                } else if w > 0.0 {
                    sum += w;
                    slope += 1.0;
                }
            } else {
                sum += v;
            }
        }
        (sum - target, slope)
    };
    let count = match level {
        0 => n_free,
        1 => n_free + n_cap,
        _ => p.len() as f64,
    }
    .max(1.0);
    let p_max = p.iter().cloned().fold(0.0, f64::max);
    let (mut lo, mut hi) = (-p_max, if cap.is_finite() { cap } else { target / count });
    let mut s = 0.0;
    for _ in 0..200 {
        let (f, slope) = eval(p, s);
        if f.abs() <= 1e-15 * target {
            break;
        }
        if f < 0.0 {
            lo = s;
        } else {
            hi = s;
        }
        let next = if slope > 0.0 { s - f / slope } else { f64::NAN };
        s = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= f64::EPSILON * (hi.abs() + lo.abs()) {
            break;
        }
    }
    if s != 0.0 {
        for v in p.iter_mut() {
            if moves(*v) {
                *v = (*v + s).clamp(0.0, cap);
            }
        }
    }
}
