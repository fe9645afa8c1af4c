//! A hardness per node (`solve_capped`, the size effect asperity by asperity)
//! against an exact bounded least-squares solution
//! (scripts/contact_capped_reference.py wrote tests/data/capped/: NumPy's
//! dense compliance, SciPy's BVLS active-set method and brentq on the
//! multiplier, independent of the crate's conjugate gradient): a 32 × 32
//! power-law surface whose left half is twice as hard as its right.

use rough_contact::{Boundary, Contact, Options};
use std::path::PathBuf;

const N: usize = 32;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/capped")
        .join(name)
}

fn read_f64(name: &str) -> Vec<f64> {
    let bytes = std::fs::read(data(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(bytes.len(), 8 * N * N, "{name}");
    bytes
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect()
}

struct Case {
    k: usize,
    p_mean: f64,
    area: f64,
    elastic: f64,
    plastic: f64,
}

fn cases() -> Vec<Case> {
    std::fs::read_to_string(data("cases.csv"))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("k,"))
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
            Case {
                k: f[0] as usize,
                p_mean: f[1],
                area: f[2],
                elastic: f[3],
                plastic: f[4],
            }
        })
        .collect()
}

#[test]
fn hardness_per_node_as_the_exact_bounded_solution() {
    let h = read_f64("surface.f64");
    let caps = read_f64("caps.f64");
    let cases = cases();
    assert_eq!(cases.len(), 3);
    let node = 1.0 / (N * N) as f64;
    let opts = Options {
        tolerance: 1e-12,
        ..Options::default()
    };
    for c in &cases {
        // Each load from a cold start, so that no case leans on another.
        let mut contact = Contact::new(h.clone(), N, 1.0, 1.0, Boundary::Periodic).unwrap();
        let r = contact
            .solve_capped(c.p_mean, &caps, &opts, &mut |_, _| true)
            .unwrap();
        let theirs = read_f64(&format!("{}.pressure.f64", c.k));
        let p = contact.pressure();
        let diff: f64 = p.iter().zip(&theirs).map(|(a, b)| (a - b).powi(2)).sum();
        let norm: f64 = theirs.iter().map(|b| b * b).sum();
        let rel = (diff / norm).sqrt();
        assert!(
            rel < 1e-6,
            "load {}: pressure relative L2 {rel:.3e}",
            c.p_mean
        );
        let mean = p.iter().sum::<f64>() / (N * N) as f64;
        assert!(
            (mean - c.p_mean).abs() <= 1e-12 * c.p_mean,
            "load {}",
            c.p_mean
        );
        // No node above its own hardness, and the two halves' caps both met.
        for (i, (v, cap)) in p.iter().zip(&caps).enumerate() {
            assert!(*v <= cap * (1.0 + 1e-12), "node {i}: {v} above {cap}");
        }
        // Areas to the node (a node exactly at a bound may fall either side
        // of a 1e-13 threshold).
        for (ours, theirs, what) in [
            (r.area, c.area, "area"),
            (r.elastic_area, c.elastic, "elastic"),
            (r.plastic_area, c.plastic, "plastic"),
        ] {
            assert!(
                (ours - theirs).abs() <= node + 1e-12,
                "load {}: {what} {ours} against {theirs}",
                c.p_mean
            );
        }
        assert_eq!(r.hardness, caps.iter().sum::<f64>() / (N * N) as f64);
    }
    // The cases reach the soft half's cap and not only the hard half's.
    let last = cases.last().unwrap();
    assert!(
        last.plastic > 0.0,
        "the reference's highest load reaches no cap"
    );
}
