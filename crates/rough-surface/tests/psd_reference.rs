//! PSD tables against mpmath (`scripts/psd_reference.py`, 50 digits): a
//! power law with a roll-off knee, areal and profile, as a plain table and
//! as contact.engineering downloads; and fig2's spectrum, whose moments are
//! docs/model.md's truncated ones.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_model::Dim;
use rough_surface::{read, Kind, Options};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

#[test]
fn tables_match_mpmath() {
    let text = std::fs::read_to_string(data().join("psd_reference.txt")).unwrap();
    let mut worst = 0f64;
    let mut tables = 0;
    let mut current = None;
    for l in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = l.split_whitespace().collect();
        match w[0] {
            "table" => {
                let m =
                    read(&data().join(w[1]), &Options::default()).unwrap_or_else(|e| panic!("{e}"));
                let dim = if w[2] == "areal" {
                    Dim::Areal
                } else {
                    Dim::Profile
                };
                assert!(
                    matches!(m.kind, Kind::Psd { dim: d, .. } if d == dim),
                    "{}",
                    w[1]
                );
                current = Some((w[1].to_string(), m));
                tables += 1;
            }
            "end" => current = None,
            _ => {
                let (name, m) = current.as_ref().unwrap();
                let v: Vec<f64> = w.iter().map(|s| s.parse().unwrap()).collect();
                let got = m.table.at_zeta(v[0]);
                for (a, b) in [(got.m0, v[1]), (got.m2, v[2]), (got.m4, v[3])] {
                    let e = if b == 0.0 { a.abs() } else { rel(a, b) };
                    assert!(e < 1e-12, "{name} ζ {}: {a} vs {b}", v[0]);
                    worst = worst.max(e);
                }
            }
        }
    }
    assert_eq!(tables, 4);
    println!("worst relative error against mpmath: {worst:.1e}");
}
