//! The moments of a measured surface as functions of the cutoff q1.
//!
//! A measured surface replaces the power law's moments; everything after
//! them (hardness, indices, slopes, areas, regime) is unchanged. This module
//! only does the arithmetic of truncation, so that the model crate stays
//! pure: reading files, detrending, windowing and the FFT live elsewhere
//! (`rough-surface`), which hands over either
//!
//! - the terms of a discrete spectrum ([`MomentTable::from_discrete`]): one
//!   `(|q|, w)` per FFT wavevector with M_α(q1) = Σ_{0 < |q| ≤ q1} |q|^α w,
//!   i.e. w = C(q)/(Lx Ly) for a map and C1D(q)/L for a line scan in
//!   SurfaceTopography's convention (`integrate_psd`); or
//! - a PSD table ([`MomentTable::from_psd`]): C interpolated as a power law
//!   between neighbouring points (log-log linear) and integrated exactly,
//!   M_α(q1) = (1/2π) ∫ q^(α+1) C^iso dq for an areal (isotropic) PSD and
//!   (1/π) ∫ q^α C1D dq for a profile PSD, from the first q.
//!
//! The paper's profile moments follow by isotropy for areal sums
//! (m0 = M0, m2 = M2/2, m4 = 3M4/8); a profile's sums are its profile
//! moments directly.
//!
//! Every cutoff is cheap: the nodes are sorted once and the sums kept as
//! prefix sums (compensated, so each is within ~1 ulp of the exact sum of
//! its terms), so a moment at any q1 is a binary search plus, for a PSD
//! table, one closed-form partial segment.

use std::fmt;
use std::hash::{Hash, Hasher};

/// Whether a table's sums run over the plane of wavevectors (a map, an
/// isotropic PSD) or along a line (a line scan, a profile PSD).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Dim {
    /// Areal sums M_α; profile moments by isotropy.
    Areal,
    /// Profile sums, which are the profile moments.
    Profile,
}

/// The paper's profile moments at one cutoff, SI units: m0 (m²), m2
/// (dimensionless), m4 (1/m²).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileMoments {
    pub m0: f64,
    pub m2: f64,
    pub m4: f64,
}

/// Why a table was refused. Positions are 0-based indices into the input.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum TableError {
    /// Fewer points than the table needs (2 for a PSD, 1 for a spectrum).
    TooFewPoints { got: usize, need: usize },
    /// A wavevector that is not finite and > 0.
    BadWavevector { index: usize, q: f64 },
    /// A PSD value or spectral term that is not finite and > 0 (≥ 0 for a
    /// discrete term).
    BadValue { index: usize, value: f64 },
    /// A PSD table whose q does not increase strictly at `index`.
    NotIncreasing { index: usize, q: f64, previous: f64 },
    /// The lower cutoff q0 is not finite and > 0.
    BadQ0(f64),
    /// The `q` and `C` columns differ in length.
    Lengths { q: usize, c: usize },
    /// Every term of a discrete spectrum is zero (a flat surface).
    Flat,
}

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TableError::TooFewPoints { got, need } => {
                write!(f, "{got} points: a spectrum needs at least {need}")
            }
            TableError::BadWavevector { index, q } => write!(
                f,
                "wavevector q = {q} at point {} is not finite and > 0",
                index + 1
            ),
            TableError::BadValue { index, value } => write!(
                f,
                "PSD value {value} at point {} must be finite and > 0",
                index + 1
            ),
            TableError::NotIncreasing { index, q, previous } => write!(
                f,
                "q must increase: q = {q} at point {} follows q = {previous}",
                index + 1
            ),
            TableError::BadQ0(q0) => write!(f, "q0 = {q0} is not finite and > 0"),
            TableError::Lengths { q, c } => {
                write!(f, "{q} wavevectors but {c} PSD values")
            }
            TableError::Flat => write!(f, "the surface is flat: every spectral term is zero"),
        }
    }
}

impl std::error::Error for TableError {}

/// A PSD table's segment from node i to i+1: C(q) = C_i (q/q_i)^s.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    /// C_i times the integral's constant (1/2π or 1/π).
    c: f64,
    /// The log-log slope s of C over the segment.
    s: f64,
}

/// The moments M_α (α = 0, 2, 4) of a measured surface at any cutoff q1.
///
/// Immutable once built; share it behind an `Arc`. Equality compares the
/// dimension, q0, the node count and a fingerprint of every input bit, so it
/// is O(1) (cache keys compare tables on every frame).
#[derive(Clone, Debug)]
pub struct MomentTable {
    dim: Dim,
    q0: f64,
    /// Sorted distinct nodes: wavevector magnitudes of the discrete
    /// spectrum, or the PSD table's q.
    q: Vec<f64>,
    /// M_0, M_2, M_4 up to and including node i (discrete), or from the
    /// first node to node i (PSD).
    cum: [Vec<f64>; 3],
    /// For a PSD table: its segments (one fewer than nodes); empty for a
    /// discrete spectrum.
    segments: Vec<Segment>,
    fingerprint: u64,
}

impl PartialEq for MomentTable {
    fn eq(&self, other: &MomentTable) -> bool {
        self.dim == other.dim
            && self.q0.to_bits() == other.q0.to_bits()
            && self.q.len() == other.q.len()
            && self.fingerprint == other.fingerprint
    }
}

/// Σ with Neumaier's compensation: the prefix sums stay within ~1 ulp of
/// the exact sums of their terms however many there are.
#[derive(Clone, Copy, Default)]
struct Compensated {
    sum: f64,
    comp: f64,
}

impl Compensated {
    fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.comp += (self.sum - t) + x;
        } else {
            self.comp += (x - t) + self.sum;
        }
        self.sum = t;
    }

    fn value(self) -> f64 {
        self.sum + self.comp
    }
}

/// Relative distance within which two wavevector magnitudes are the same
/// node: |q|² = qx² + qy² of lattice points at the same distance (3,4) and
/// (5,0) differ by rounding only, and a cutoff that lands on a node within
/// rounding includes it.
const SAME_Q: f64 = 1e-12;

/// The log-log slope of C between two points, ln(c1/c0)/ln(q1/q0), with
/// one correction step: the first quotient carries ln's rounding (up to
/// ~1e-15 here); the residual c1/(c0 (q1/q0)^s) − 1 of that estimate is
/// computed to a few 1e-16 and taken out, leaving ~1e-16.
fn log_slope(q: &[f64], c: &[f64]) -> f64 {
    let (rq, rc) = (q[1] / q[0], c[1] / c[0]);
    let lq = rq.ln();
    let s = rc.ln() / lq;
    let d = c[1] / (c[0] * rq.powf(s)) - 1.0;
    if d.is_finite() {
        s + d.ln_1p() / lq
    } else {
        s
    }
}

/// (e^(e·l) − 1)/e, its limit l at e = 0.
fn g(e: f64, l: f64) -> f64 {
    if e == 0.0 {
        l
    } else {
        (e * l).exp_m1() / e
    }
}

fn fingerprint(dim: Dim, q0: f64, words: impl Iterator<Item = f64>) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    dim.hash(&mut h);
    q0.to_bits().hash(&mut h);
    // Every input word through a multiply–xorshift step (SipHash over the
    // 8.4 million words of a 4096² map took a tenth of a second), then
    // SplitMix64's finaliser.
    let mut acc = h.finish();
    for v in words {
        acc = (acc ^ v.to_bits()).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        acc ^= acc >> 29;
    }
    acc = (acc ^ (acc >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    acc = (acc ^ (acc >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    acc ^ (acc >> 31)
}

impl MomentTable {
    /// A discrete spectrum: `terms` holds one `(|q|, w)` per wavevector with
    /// M_α(q1) = Σ_{|q| ≤ q1} |q|^α w (the q = 0 term, the mean, is not
    /// passed). `q0` is the lower cutoff that ζ = q1/q0 is measured from
    /// (2π/max(Lx, Ly) for a map, 2π/L for a line scan). Terms may come in
    /// any order; magnitudes equal within rounding are merged.
    pub fn from_discrete(
        dim: Dim,
        q0: f64,
        mut terms: Vec<(f64, f64)>,
    ) -> Result<MomentTable, TableError> {
        if !(q0.is_finite() && q0 > 0.0) {
            return Err(TableError::BadQ0(q0));
        }
        if terms.is_empty() {
            return Err(TableError::TooFewPoints { got: 0, need: 1 });
        }
        for (index, &(q, w)) in terms.iter().enumerate() {
            if !(q.is_finite() && q > 0.0) {
                return Err(TableError::BadWavevector { index, q });
            }
            if !(w.is_finite() && w >= 0.0) {
                return Err(TableError::BadValue { index, value: w });
            }
        }
        if terms.iter().all(|&(_, w)| w == 0.0) {
            return Err(TableError::Flat);
        }
        terms.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let fp = fingerprint(
            dim,
            q0,
            terms.iter().map(|t| t.0).chain(terms.iter().map(|t| t.1)),
        );
        let mut q = Vec::new();
        let mut cum: [Vec<f64>; 3] = Default::default();
        let mut acc = [Compensated::default(); 3];
        for (i, &(qi, w)) in terms.iter().enumerate() {
            let q2 = qi * qi;
            acc[0].add(w);
            acc[1].add(q2 * w);
            acc[2].add(q2 * q2 * w);
            let last = i + 1 == terms.len();
            // A node closes where the next magnitude is a different one.
            if last || terms[i + 1].0 > qi * (1.0 + SAME_Q) {
                q.push(qi);
                for (c, a) in cum.iter_mut().zip(&acc) {
                    c.push(a.value());
                }
            }
        }
        Ok(MomentTable {
            dim,
            q0,
            q,
            cum,
            segments: Vec::new(),
            fingerprint: fp,
        })
    }

    /// A PSD table: strictly increasing `q` (1/m) and `c` > 0 (m⁴ for an
    /// areal C^iso, m³ for a profile C1D, SurfaceTopography's convention),
    /// interpolated as a power law between neighbouring points and
    /// integrated exactly. q0 is the first q; the table ends at the last.
    pub fn from_psd(dim: Dim, q: &[f64], c: &[f64]) -> Result<MomentTable, TableError> {
        if q.len() != c.len() {
            return Err(TableError::Lengths {
                q: q.len(),
                c: c.len(),
            });
        }
        if q.len() < 2 {
            return Err(TableError::TooFewPoints {
                got: q.len(),
                need: 2,
            });
        }
        for (index, (&qi, &ci)) in q.iter().zip(c).enumerate() {
            if !(qi.is_finite() && qi > 0.0) {
                return Err(TableError::BadWavevector { index, q: qi });
            }
            if !(ci.is_finite() && ci > 0.0) {
                return Err(TableError::BadValue { index, value: ci });
            }
            if index > 0 && qi <= q[index - 1] {
                return Err(TableError::NotIncreasing {
                    index,
                    q: qi,
                    previous: q[index - 1],
                });
            }
        }
        let constant = match dim {
            Dim::Areal => 1.0 / std::f64::consts::TAU,
            Dim::Profile => std::f64::consts::FRAC_1_PI,
        };
        let segments: Vec<Segment> = q
            .windows(2)
            .zip(c.windows(2))
            .map(|(qw, cw)| Segment {
                c: constant * cw[0],
                s: log_slope(qw, cw),
            })
            .collect();
        let mut table = MomentTable {
            dim,
            q0: q[0],
            q: q.to_vec(),
            cum: Default::default(),
            segments,
            fingerprint: fingerprint(dim, q[0], q.iter().chain(c).copied()),
        };
        table.cum = std::array::from_fn(|k| {
            let mut acc = Compensated::default();
            let mut cum = Vec::with_capacity(q.len());
            cum.push(0.0);
            for i in 0..table.segments.len() {
                acc.add(table.partial(2 * k as u32, i, q[i + 1]));
                cum.push(acc.value());
            }
            cum
        });
        Ok(table)
    }

    /// ∫ from q_i to q1 (inside segment i) of the α-th moment's integrand:
    /// c_i q_i^(k+1) g(k+1+s, ln(q1/q_i)), k = α+1 (areal) or α (profile).
    fn partial(&self, alpha: u32, i: usize, q1: f64) -> f64 {
        let Segment { c, s } = self.segments[i];
        let qi = self.q[i];
        let k = alpha as i32
            + match self.dim {
                Dim::Areal => 1,
                Dim::Profile => 0,
            };
        c * qi.powi(k + 1) * g(f64::from(k + 1) + s, (q1 / qi).ln())
    }

    pub fn dim(&self) -> Dim {
        self.dim
    }

    /// The lower cutoff q0, 1/m: ζ = q1/q0.
    pub fn q0(&self) -> f64 {
        self.q0
    }

    /// The largest wavevector the data holds, 1/m.
    pub fn q_max(&self) -> f64 {
        self.q[self.q.len() - 1]
    }

    /// The largest magnification the data allows, q_max/q0.
    pub fn zeta_max(&self) -> f64 {
        self.q_max() / self.q0
    }

    /// The sorted distinct wavevector magnitudes (discrete) or the table's
    /// q (PSD), 1/m.
    pub fn nodes(&self) -> &[f64] {
        &self.q
    }

    /// Whether the moments are a step function of q1 (a discrete spectrum)
    /// rather than continuous (a PSD table).
    pub fn is_discrete(&self) -> bool {
        self.segments.is_empty()
    }

    /// The sums M_0, M_2, M_4 at cutoff `q1` (1/m): over every node with
    /// |q| ≤ q1 for a discrete spectrum, from q0 to min(q1, q_max) for a PSD
    /// table. Below the first node everything is 0; above the last, the
    /// whole table.
    pub fn sums(&self, q1: f64) -> [f64; 3] {
        if self.is_discrete() {
            let n = self.q.partition_point(|&q| q <= q1 * (1.0 + SAME_Q));
            if n == 0 {
                return [0.0; 3];
            }
            return [self.cum[0][n - 1], self.cum[1][n - 1], self.cum[2][n - 1]];
        }
        // NaN and anything up to q0 hold nothing.
        if q1.partial_cmp(&self.q0) != Some(std::cmp::Ordering::Greater) {
            return [0.0; 3];
        }
        let last = self.q.len() - 1;
        if q1 >= self.q[last] {
            return [self.cum[0][last], self.cum[1][last], self.cum[2][last]];
        }
        // q[i] ≤ q1 < q[i+1].
        let i = self.q.partition_point(|&q| q <= q1) - 1;
        std::array::from_fn(|k| self.cum[k][i] + self.partial(2 * k as u32, i, q1))
    }

    /// The paper's profile moments at cutoff `q1` (1/m): m0 = M0, m2 = M2/2,
    /// m4 = 3M4/8 for areal sums (isotropy), the sums themselves for a
    /// profile.
    pub fn profile_moments(&self, q1: f64) -> ProfileMoments {
        let [m0, m2, m4] = self.sums(q1);
        match self.dim {
            Dim::Areal => ProfileMoments {
                m0,
                m2: 0.5 * m2,
                m4: 0.375 * m4,
            },
            Dim::Profile => ProfileMoments { m0, m2, m4 },
        }
    }

    /// [`MomentTable::profile_moments`] at magnification ζ = q1/q0.
    pub fn at_zeta(&self, zeta: f64) -> ProfileMoments {
        self.profile_moments(zeta * self.q0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// fig2's spectrum in SurfaceTopography's convention: (2π)² Z q^(−2(1+H)).
    fn fig2_psd(n: usize) -> (Vec<f64>, Vec<f64>) {
        let (z, hu, q0) = (1e-8, 0.8, 1e5);
        let q: Vec<f64> = (0..n)
            .map(|i| q0 * 1e4f64.powf(i as f64 / (n - 1) as f64))
            .collect();
        let c = q
            .iter()
            .map(|&q| (2.0 * std::f64::consts::PI).powi(2) * z * q.powf(-2.0 * (1.0 + hu)))
            .collect();
        (q, c)
    }

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn power_law_table_gives_the_truncated_moments() {
        // m2 = πZ q0^(2−2H)(ζ^(2−2H) − 1)/(2−2H) and friends (docs/model.md).
        let (z, hu, q0) = (1e-8f64, 0.8f64, 1e5f64);
        let pi = std::f64::consts::PI;
        for n in [2, 3, 17, 200] {
            let (q, c) = fig2_psd(n);
            let t = MomentTable::from_psd(Dim::Areal, &q, &c).unwrap();
            for zeta in [1.5, 10.0, 128.0, 1e3, 9999.0] {
                let m = t.at_zeta(zeta);
                let gg = |e: f64| (e * zeta.ln()).exp_m1() / e;
                let m0 = pi * z / hu * q0.powf(-2.0 * hu) * -(-2.0 * hu * zeta.ln()).exp_m1();
                let m2 = pi * z * q0.powf(2.0 - 2.0 * hu) * gg(2.0 - 2.0 * hu);
                let m4 = 0.75 * pi * z * q0.powf(4.0 - 2.0 * hu) * gg(4.0 - 2.0 * hu);
                assert!(rel(m.m0, m0) < 2e-15, "n {n} ζ {zeta}: {} {m0}", m.m0);
                assert!(rel(m.m2, m2) < 2e-15, "n {n} ζ {zeta}: {} {m2}", m.m2);
                assert!(rel(m.m4, m4) < 2e-15, "n {n} ζ {zeta}: {} {m4}", m.m4);
            }
        }
    }

    #[test]
    fn psd_ends() {
        let (q, c) = fig2_psd(5);
        let t = MomentTable::from_psd(Dim::Profile, &q, &c).unwrap();
        assert_eq!(t.sums(q[0]), [0.0; 3]);
        assert_eq!(t.sums(0.5 * q[0]), [0.0; 3]);
        assert_eq!(t.sums(q[4]), t.sums(2.0 * q[4]));
        assert_eq!(t.zeta_max(), q[4] / q[0]);
        // Nodes are where the prefix sums are exact.
        let inner = t.sums(q[2]);
        let below = t.sums(q[2] * (1.0 - 1e-15));
        assert!(rel(below[1], inner[1]) < 1e-13);
    }

    #[test]
    fn discrete_sums_merge_equal_magnitudes() {
        // (3,4) and (5,0) lie at the same |q|; each cutoff includes ≤ q1.
        let dq = 0.1;
        let mag = |a: f64, b: f64| ((a * dq).powi(2) + (b * dq).powi(2)).sqrt();
        let terms = vec![
            (mag(3.0, 4.0), 1.0),
            (mag(5.0, 0.0), 2.0),
            (mag(1.0, 0.0), 0.5),
            (mag(0.0, 1.0), 0.5),
        ];
        let t = MomentTable::from_discrete(Dim::Areal, dq, terms).unwrap();
        assert_eq!(t.nodes().len(), 2);
        assert_eq!(t.sums(0.05), [0.0; 3]);
        let s = t.sums(0.1);
        assert_eq!(s[0], 1.0);
        assert!(rel(s[1], 0.01) < 1e-15);
        let s = t.sums(0.5);
        assert_eq!(s[0], 4.0);
        assert!(rel(s[1], 0.01 + 3.0 * 0.25) < 1e-15);
        assert!(rel(s[2], 1e-4 + 3.0 * 0.0625) < 1e-15);
        let m = t.profile_moments(1.0);
        assert_eq!(m.m0, 4.0);
        assert!(rel(m.m2, 0.5 * s[1]) < 1e-15);
        assert!(rel(m.m4, 0.375 * s[2]) < 1e-15);
    }

    #[test]
    fn compensated_prefix_sums() {
        // A million equal terms: the plain running sum drifts, ours does not.
        let terms: Vec<(f64, f64)> = (1..=1_000_000).map(|i| (i as f64, 0.1)).collect();
        let t = MomentTable::from_discrete(Dim::Profile, 1.0, terms).unwrap();
        assert!(rel(t.sums(1e6)[0], 1e5) < 1e-15);
        assert_eq!(t.sums(1e6), t.sums(1e7));
    }

    #[test]
    fn refuses_bad_tables_by_point() {
        let e = |q: &[f64], c: &[f64]| {
            MomentTable::from_psd(Dim::Areal, q, c)
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e(&[1.0, 1.0], &[1.0, 1.0]),
            "q must increase: q = 1 at point 2 follows q = 1"
        );
        assert_eq!(
            e(&[1.0, 2.0], &[1.0, 0.0]),
            "PSD value 0 at point 2 must be finite and > 0"
        );
        assert_eq!(e(&[1.0], &[1.0]), "1 points: a spectrum needs at least 2");
        assert_eq!(e(&[1.0, 2.0], &[1.0]), "2 wavevectors but 1 PSD values");
        assert_eq!(
            MomentTable::from_discrete(Dim::Areal, 1.0, vec![(1.0, 0.0)]).unwrap_err(),
            TableError::Flat
        );
        assert!(matches!(
            MomentTable::from_discrete(Dim::Areal, 1.0, vec![(f64::NAN, 1.0)]),
            Err(TableError::BadWavevector { index: 0, .. })
        ));
    }

    #[test]
    fn equality_is_by_content() {
        let (q, c) = fig2_psd(9);
        let a = MomentTable::from_psd(Dim::Areal, &q, &c).unwrap();
        let b = MomentTable::from_psd(Dim::Areal, &q, &c).unwrap();
        assert_eq!(a, b);
        let mut c2 = c.clone();
        c2[3] *= 1.0 + f64::EPSILON;
        assert_ne!(a, MomentTable::from_psd(Dim::Areal, &q, &c2).unwrap());
        assert_ne!(a, MomentTable::from_psd(Dim::Profile, &q, &c).unwrap());
    }
}
