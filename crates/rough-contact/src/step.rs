//! The conjugate-gradient step on the pressure: the free nodes move along
//! the direction, nodes on the wrong side of a bound are released, and
//! every node is projected on [0, H]. Besides the new pressure the pass
//! returns the nodes whose move differs from the plain step −τt (clipped or
//! released), while they are few, so that u = Kp can follow the step
//! without a transform ([`crate::sparse`]).

// Index loops walk several parallel arrays at once; clearer than zips.
#![allow(clippy::needless_range_loop)]

use rayon::prelude::*;

use crate::cap::{class, Cap, Set};
use crate::load::Count;
use crate::par::{chunk_len, min_len};

/// Nodes off the plain step that u follows node by node (each costs a pass
/// over the grid; a transform costs about as much as a few dozen).
pub(crate) const SPARSE_MAX: usize = 16;

/// What a step did.
pub(crate) struct Step {
    /// Nodes released from a bound.
    pub released: usize,
    /// Whether a free node was clipped at a bound.
    pub clipped: bool,
    pub count: Count,
    /// The nodes off the plain step and how far off (p − (p_old − τt)),
    /// if at most [`SPARSE_MAX`]; `None` if more.
    pub off: Option<Vec<(usize, f64)>>,
}

/// The step of length `tau` along `t` (released nodes by `tau_r` times
/// their gap), u moved by −τ r = −τ K t.
#[allow(clippy::too_many_arguments)]
pub(crate) fn step<C: Cap>(
    p: &mut [f64],
    u: &mut [f64],
    gap: &[f64],
    t: &[f64],
    r: &[f64],
    cap: &C,
    (tau, tau_r): (f64, f64),
) -> Step {
    let n2 = p.len();
    let (c, min) = (chunk_len(n2), min_len(n2));
    let parts: Vec<Step> = p
        .par_chunks_mut(c)
        .zip(u.par_chunks_mut(c))
        .zip(gap.par_chunks(c))
        .zip(t.par_chunks(c))
        .zip(r.par_chunks(c))
        .enumerate()
        .with_min_len(min)
        .map(|(k, ((((p, u), g), t), r))| {
            let (mut released, mut clipped) = (0usize, false);
            let mut count = Count::default();
            let mut off = Some(vec![]);
            let mut note = |i: usize, d: f64| {
                if let Some(v) = off.as_mut() {
                    if v.len() < SPARSE_MAX {
                        v.push((k * c + i, d));
                    } else {
                        off = None;
                    }
                }
            };
            for j in 0..p.len() {
                let (gi, pi, ci) = (g[j], p[j], cap.at(k * c + j));
                let v = match class(pi, ci) {
                    Set::Free => {
                        let v = pi - tau * t[j];
                        if v <= 0.0 || v >= ci {
                            clipped = true;
                            let w = v.clamp(0.0, ci);
                            note(j, w - v);
                            w
                        } else {
                            v
                        }
                    }
                    Set::Zero if gi < 0.0 => {
                        released += 1;
                        let v = (-tau_r * gi).min(ci);
                        note(j, v - pi);
                        v
                    }
                    Set::Cap if gi > 0.0 => {
                        released += 1;
                        let v = (ci - tau_r * gi).max(0.0);
                        note(j, v - pi);
                        v
                    }
                    _ => pi,
                };
                p[j] = v;
                count.add(v, ci);
                u[j] -= tau * r[j];
            }
            Step {
                released,
                clipped,
                count,
                off,
            }
        })
        .collect();
    let mut all = Step {
        released: 0,
        clipped: false,
        count: Count::default(),
        off: Some(vec![]),
    };
    for part in parts {
        all.released += part.released;
        all.clipped |= part.clipped;
        all.count.merge(&part.count);
        all.off = match (all.off, part.off) {
            (Some(mut a), Some(b)) if a.len() + b.len() <= SPARSE_MAX => {
                a.extend(b);
                Some(a)
            }
            _ => None,
        };
    }
    all
}
