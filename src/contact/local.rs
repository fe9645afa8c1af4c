//! The size effect node by node: each node capped at the hardness of the
//! asperity it belongs to, H_y = H0 √(1 + R*/(1.2 R)) — the law the theory
//! uses with the mean summit radius R_s — with R that asperity's curvature
//! radius.
//!
//! Which asperities carry the load, and how curved they are, is read from
//! the purely elastic contact at the same mean pressure: its patches are
//! where the undeformed asperities touch, each patch's R the curvature
//! radius of the paraboloid fitted to the undeformed surface over it
//! ([`rough_contact::asperity`]; exact for a Hertzian asperity). A big
//! asperity's patch sees its own curvature and the bulk-like hardness that
//! goes with it; a small one the fine scale's, and its high hardness. A node
//! outside every patch takes its nearest patch's hardness; a patch that
//! spans the cell (percolation) is the bulk, H0. The elastic–plastic
//! contact is then solved once under these caps, from the elastic
//! pressure.
//!
//! Reading the asperities from the elastic contact, not from the plastic
//! one, keeps the hardness a property of the surface: plastic flow that
//! spreads a small asperity's patch does not make it a big asperity (a
//! feedback that, tried, lowered every cap round after round without
//! settling).
//!
//! The patch's fitted paraboloid returns the curvature of the large-scale
//! envelope a patch spans. The other reading, [`Radius::Summit`], gives
//! each node the radius of its own finest-scale summit: steepest ascent on
//! the heights to the local maximum, R = 1/(−∇²h/2) there
//! ([`rough_contact::asperity::summit_radii`]). It needs no elastic solve:
//! the caps are the surface's alone.

use rough_contact::asperity::{patch_radii, summit_radii, summits, Patches};
use rough_contact::{Contact, ContactError, LoadResult, Options};

/// Which radius a node's hardness takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Radius {
    /// The paraboloid fitted under the node's patch of the elastic
    /// contact at the same load.
    Asperity,
    /// The curvature at the summit steepest ascent takes the node to.
    Summit,
}

/// The law H_y(R) with the material's numbers (H0 in units of E*, R* in m)
/// and the radius it is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Law {
    pub h0: f64,
    pub r_star: f64,
    pub radius: Radius,
}

/// R_p/R of the hardness law (the paper's 1.2).
pub const RP_OVER_R: f64 = 1.2;

impl Law {
    /// H_y/E* for an asperity of curvature radius `r` (m; ∞: H0).
    pub fn hardness(&self, r: f64) -> f64 {
        if r.is_infinite() {
            self.h0
        } else {
            self.h0 * (1.0 + self.r_star / (RP_OVER_R * r)).sqrt()
        }
    }
}

/// What a solve with a hardness per node found besides the areas.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Local {
    /// Patches of the elastic contact (the asperities in contact); with
    /// summit radii, the summits the contact's nodes climb to.
    pub patches: usize,
    /// The load-weighted mean of the caps, H/E*.
    pub mean_hardness: f64,
    /// The patches' (summits') curvature radii, m: median, smallest,
    /// largest of the finite ones.
    pub radius: [f64; 3],
    /// Iterations of the elastic solve (in the result's count too; none
    /// with summit radii).
    pub elastic_iterations: usize,
    /// The caps' load-weighted spread, H/E*: the smallest and the largest
    /// cap a loaded node has.
    pub caps: [f64; 2],
}

/// How [`solve`]'s refusal of a load beyond the asperities' hardness
/// begins ([`Beyond::of`] knows it by that).
const BEYOND: &str = "the mean pressure ";

/// A load above what the asperities' hardness can carry: no contact
/// solution exists (the bulk would yield), so the load is not solved —
/// the physics' limit, not a failure.
#[derive(Clone, Debug, PartialEq)]
pub struct Beyond(pub String);

impl Beyond {
    /// The refusal of [`solve`] for a load beyond the asperities' hardness.
    pub fn of(e: &ContactError) -> Option<Beyond> {
        match e {
            ContactError::Input(s) if s.starts_with(BEYOND) => Some(Beyond(s.clone())),
            _ => None,
        }
    }
}

impl std::fmt::Display for Beyond {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Beyond {}

/// Solves `contact` at mean pressure `p_mean` with a cap per asperity
/// (`global`, the theory's cap, bounds the load: p̄ ≤ the caps' mean is
/// checked). Returns the result, the caps and what the asperities were.
pub fn solve(
    contact: &mut Contact,
    p_mean: f64,
    law: &Law,
    opts: &Options,
    progress: &mut dyn FnMut(usize, f64) -> bool,
) -> Result<(LoadResult, Vec<f64>, Local), ContactError> {
    if law.radius == Radius::Summit {
        return solve_summits(contact, p_mean, law, opts, progress);
    }
    let (n, length) = (contact.n(), contact.length());
    let elastic = contact.solve_with_progress(p_mean, f64::INFINITY, opts, progress)?;
    let patches = Patches::of(contact.pressure(), n);
    let radii = patch_radii(contact.heights(), n, length, &patches);
    let owner = patches.nearest(n);
    let caps: Vec<f64> = owner
        .iter()
        .map(|&id| match id {
            u32::MAX => law.h0,
            id => law.hardness(radii[id as usize]),
        })
        .collect();
    check_load(p_mean, &caps)?;
    let offset = elastic.iterations;
    let mut r = contact.solve_capped(p_mean, &caps, opts, &mut |it, res| {
        progress(offset + it, res)
    })?;
    r.iterations += elastic.iterations;
    let (mean_hardness, loaded) = weighted(contact.pressure(), &caps);
    let info = Local {
        patches: patches.count(),
        mean_hardness,
        radius: spread(&radii),
        elastic_iterations: elastic.iterations,
        caps: loaded,
    };
    Ok((r, caps, info))
}

/// A load above the caps' mean has no solution.
fn check_load(p_mean: f64, caps: &[f64]) -> Result<(), ContactError> {
    let mean = caps.iter().sum::<f64>() / caps.len() as f64;
    if p_mean > mean {
        return Err(ContactError::Input(format!(
            "{BEYOND}{p_mean:.4e} E* is above what the asperities' hardness can carry \
             (their mean {mean:.4e} E*): the bulk would yield"
        )));
    }
    Ok(())
}

/// The caps' mean weighted by the pressure, and the least and largest cap
/// of a loaded node.
fn weighted(p: &[f64], caps: &[f64]) -> (f64, [f64; 2]) {
    let load: f64 = p.iter().sum();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for (&p, &c) in p.iter().zip(caps) {
        if p > 0.0 {
            lo = lo.min(c);
            hi = hi.max(c);
        }
    }
    let mean = if load > 0.0 {
        p.iter().zip(caps).map(|(p, c)| p * c).sum::<f64>() / load
    } else {
        caps.iter().sum::<f64>() / caps.len() as f64
    };
    (mean, [lo, hi])
}

/// The caps of the summit reading: each node H_y at the radius of the
/// summit it climbs to (H0 where that summit is not convex).
pub fn summit_caps(contact: &Contact, law: &Law) -> Vec<f64> {
    let (n, length) = (contact.n(), contact.length());
    summit_radii(contact.heights(), n, length)
        .into_iter()
        .map(|r| law.hardness(r))
        .collect()
}

/// [`solve`] with summit radii: the caps from the heights alone, one
/// capped solve (from the contact's last answer).
fn solve_summits(
    contact: &mut Contact,
    p_mean: f64,
    law: &Law,
    opts: &Options,
    progress: &mut dyn FnMut(usize, f64) -> bool,
) -> Result<(LoadResult, Vec<f64>, Local), ContactError> {
    let caps = summit_caps(contact, law);
    check_load(p_mean, &caps)?;
    let r = contact.solve_capped(p_mean, &caps, opts, progress)?;
    let n = contact.n();
    let top = summits(contact.heights(), n);
    let radii = summit_radii(contact.heights(), n, contact.length());
    let p = contact.pressure();
    let mut tops: Vec<u32> = (0..n * n).filter(|&i| p[i] > 0.0).map(|i| top[i]).collect();
    tops.sort_unstable();
    tops.dedup();
    let top_radii: Vec<f64> = tops.iter().map(|&t| radii[t as usize]).collect();
    let (mean_hardness, loaded) = weighted(p, &caps);
    let info = Local {
        patches: tops.len(),
        mean_hardness,
        radius: spread(&top_radii),
        elastic_iterations: 0,
        caps: loaded,
    };
    Ok((r, caps, info))
}

/// Median, smallest and largest of the finite `v`.
fn spread(v: &[f64]) -> [f64; 3] {
    let mut f: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
    if f.is_empty() {
        return [f64::INFINITY; 3];
    }
    f.sort_by(f64::total_cmp);
    [f[f.len() / 2], f[0], f[f.len() - 1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_law_is_the_theorys() {
        let law = Law {
            h0: 0.01,
            r_star: 1e-3,
            radius: Radius::Summit,
        };
        assert_eq!(law.hardness(f64::INFINITY), 0.01);
        // R*/(1.2 R) = 3 at R = R*/3.6: twice H0.
        assert!((law.hardness(1e-3 / 3.6) / 0.02 - 1.0).abs() < 1e-15);
    }
}
