//! Against Tamaas's `KatoSaturated` on the same surfaces and loads
//! (scripts/contact_reference.py wrote tests/data/tamaas/): contact area and
//! its elastic and plastic parts within 0.5 %, pressure fields within 1e-6
//! relative L2, mean pressure exact to 1e-12.

use rough_contact::{Boundary, Contact, Options};
use std::path::PathBuf;

const N: usize = 256;
const MIN_CASES: usize = 9;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/tamaas")
        .join(name)
}

fn read_f32(name: &str) -> Vec<f64> {
    let bytes = std::fs::read(data(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(bytes.len(), 4 * N * N, "{name}");
    bytes
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
        .collect()
}

struct Case {
    name: String,
    k: usize,
    hardness: f64,
    p_over_h: f64,
    area: f64,
    elastic: f64,
    plastic: f64,
}

fn cases() -> Vec<Case> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(data(""))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            name.starts_with("cases") && name.ends_with(".csv")
        })
        .collect();
    files.sort();
    let text: String = files
        .iter()
        .map(|f| std::fs::read_to_string(f).unwrap())
        .collect();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("case,"))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let num = |i: usize| f[i].parse::<f64>().unwrap();
            Case {
                name: f[0].to_string(),
                k: f[1].parse().unwrap(),
                hardness: num(2),
                p_over_h: num(3),
                area: num(4),
                elastic: num(5),
                plastic: num(6),
            }
        })
        .collect()
}

fn within(ours: f64, theirs: f64, rel: f64, cell: f64) -> bool {
    // 0.5 % of the area, but never finer than one grid cell.
    (ours - theirs).abs() <= (rel * theirs).max(cell)
}

#[test]
fn same_areas_and_pressures_as_tamaas() {
    let cases = cases();
    assert!(cases.len() >= MIN_CASES, "{} cases", cases.len());
    let opts = Options {
        tolerance: 1e-12,
        ..Options::default()
    };
    let cell = 1.0 / (N * N) as f64;
    let mut report = String::new();
    for c in &cases {
        let h = read_f32(&format!("{}.surface.f32", c.name));
        let theirs = read_f32(&format!("{}.{}.pressure.f32", c.name, c.k));
        let mut contact = Contact::new(h, N, 1.0, 1.0, Boundary::Periodic).unwrap();
        let p_mean = c.p_over_h * c.hardness;
        let r = contact.solve(p_mean, c.hardness, &opts).unwrap();
        let p = contact.pressure();
        let mean = p.iter().sum::<f64>() / p.len() as f64;
        let (mut d2, mut t2) = (0.0, 0.0);
        for (a, b) in p.iter().zip(&theirs) {
            d2 += (a - b) * (a - b);
            t2 += b * b;
        }
        let l2 = (d2 / t2).sqrt();
        report += &format!(
            "{} p/H {:e}: area {:.6} vs {:.6}, plastic {:.6} vs {:.6}, L2 {:.2e}, {} it, residual {:.1e}\n",
            c.name, c.p_over_h, r.area, c.area, r.plastic_area, c.plastic, l2, r.iterations, r.residual
        );
        assert!(
            ((mean - p_mean) / p_mean).abs() < 1e-12,
            "{report}mean {mean}"
        );
        assert!(within(r.area, c.area, 0.005, cell), "{report}");
        assert!(within(r.elastic_area, c.elastic, 0.005, cell), "{report}");
        assert!(within(r.plastic_area, c.plastic, 0.005, cell), "{report}");
        assert!(l2 < 1e-6, "{report}");
    }
    println!("{report}");
}
