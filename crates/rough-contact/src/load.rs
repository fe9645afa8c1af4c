//! Imposing the mean pressure exactly: a uniform shift of the loaded nodes,
//! clipped to their bounds, and the Euclidean projection on the
//! constraints.

// Index loops walk several parallel arrays at once; clearer than zips.
#![allow(clippy::needless_range_loop)]

use rayon::prelude::*;

use crate::cap::{class, Cap, Set};
use crate::par::{chunk_len, min_len};

/// The load is taken as imposed when the pressures sum to the target within
/// this (relative).
const LOAD_SLACK: f64 = 1e-14;

/// What a pass over the pressures counted for [`impose_mean`].
#[derive(Clone, Copy, Default)]
pub(crate) struct Count {
    /// Σ p.
    sum: f64,
    /// Nodes with 0 < p < H.
    free: f64,
    /// Σ H over the nodes at the cap, and over the loaded nodes.
    cap_load: f64,
    loaded_cap: f64,
    /// Nodes with p > 0.
    loaded: f64,
    /// The largest p.
    p_max: f64,
}

impl Count {
    #[inline(always)]
    pub(crate) fn add(&mut self, v: f64, cap: f64) {
        self.sum += v;
        self.p_max = self.p_max.max(v);
        match class(v, cap) {
            Set::Free => {
                self.free += 1.0;
                self.loaded += 1.0;
                self.loaded_cap += cap;
            }
            Set::Cap => {
                self.loaded += 1.0;
                self.cap_load += cap;
                self.loaded_cap += cap;
            }
            Set::Zero => {}
        }
    }

    pub(crate) fn merge(&mut self, o: &Count) {
        self.sum += o.sum;
        self.free += o.free;
        self.cap_load += o.cap_load;
        self.loaded_cap += o.loaded_cap;
        self.loaded += o.loaded;
        self.p_max = self.p_max.max(o.p_max);
    }

    fn of<C: Cap>(p: &[f64], cap: &C) -> Count {
        let (c, min) = (chunk_len(p.len()), min_len(p.len()));
        let parts: Vec<Count> = p
            .par_chunks(c)
            .enumerate()
            .with_min_len(min)
            .map(|(k, p)| {
                let mut count = Count::default();
                for (j, &v) in p.iter().enumerate() {
                    count.add(v, cap.at(k * c + j));
                }
                count
            })
            .collect();
        let mut all = Count::default();
        for part in &parts {
            all.merge(part);
        }
        all
    }
}

/// Make mean(p) exact by a uniform shift s of the free nodes (0 < p < H),
/// clipped to [0, H]: the root of the monotone piecewise-linear
/// Σ clip(pᵢ + s) = target, by Newton's method kept inside a bracket. Nodes
/// at the cap stay there unless the free nodes cannot make up the load
/// alone; nodes out of contact stay out unless the loaded ones cannot carry
/// it even at the cap. `count`: the pass over `p` already made, if any.
/// Whether it moved any node.
pub(crate) fn impose_mean<C: Cap>(
    p: &mut [f64],
    cap: &C,
    target: f64,
    count: Option<Count>,
) -> bool {
    let c = count.unwrap_or_else(|| Count::of(p, cap));
    if (c.sum - target).abs() <= LOAD_SLACK * target {
        return false;
    }
    // Which nodes move: 0 free only, 1 all loaded, 2 all.
    let (level, moving) = if c.cap_load < target && c.loaded_cap >= target && c.free > 0.0 {
        (0, c.free)
    } else if c.loaded_cap >= target {
        (1, c.loaded)
    } else {
        (2, p.len() as f64)
    };
    shift(p, cap, target, level, c.p_max, moving)
}

/// The exact Euclidean projection on {0 ≤ p ≤ H, Σ p = target}: a uniform
/// shift of every node, clipped.
pub(crate) fn project<C: Cap>(p: &mut [f64], cap: &C, target: f64) {
    let p_max = p.iter().cloned().fold(0.0, f64::max);
    let _ = shift(p, cap, target, 2, p_max, p.len() as f64);
}

/// The shift of the nodes `level` says (see [`impose_mean`]), `moving` of
/// them, the largest p being `p_max`.
fn shift<C: Cap>(p: &mut [f64], cap: &C, target: f64, level: u8, p_max: f64, moving: f64) -> bool {
    let moves = |v: f64, c: f64| match level {
        0 => v > 0.0 && v < c,
        1 => v > 0.0,
        _ => true,
    };
    let (c, min) = (chunk_len(p.len()), min_len(p.len()));
    let eval = |p: &[f64], s: f64| -> (f64, f64) {
        let parts: Vec<(f64, f64)> = p
            .par_chunks(c)
            .enumerate()
            .with_min_len(min)
            .map(|(k, p)| {
                let (mut sum, mut slope) = (0.0, 0.0);
                for (j, &v) in p.iter().enumerate() {
                    let c = cap.at(k * c + j);
                    if moves(v, c) {
                        let w = v + s;
                        if w >= c {
                            sum += c;
                        } else if w > 0.0 {
                            sum += w;
                            slope += 1.0;
                        }
                    } else {
                        sum += v;
                    }
                }
                (sum, slope)
            })
            .collect();
        let (sum, slope) = parts.iter().fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        (sum - target, slope)
    };
    // The moving nodes alone carry the target once shifted by target/moving.
    let top = cap.max();
    let (mut lo, mut hi) = (
        -p_max.max(0.0),
        if top.is_finite() {
            top
        } else {
            target / moving.max(1.0)
        },
    );
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
        p.par_chunks_mut(c)
            .enumerate()
            .with_min_len(min)
            .for_each(|(k, p)| {
                for (j, v) in p.iter_mut().enumerate() {
                    let cj = cap.at(k * c + j);
                    if moves(*v, cj) {
                        *v = (*v + s).clamp(0.0, cj);
                    }
                }
            });
    }
    s != 0.0
}
