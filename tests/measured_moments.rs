//! The numbers behind the indices, as data: `export --view moments` on the
//! reference surfaces gives SurfaceTopography's moments (reference.txt,
//! scripts/surface_reference.py) at every ζ and its Sq, Sdq, Rq, RΔq
//! (realspace.txt, scripts/realspace_reference.py) as comment lines, each
//! within 1e-12, and the height parameters beside them (Sa, Ssk, Sku, Sz;
//! Ra, Rsk, Rku, Rz) within 1e-9; on the paper's power law, its moments in
//! closed form; and the same as an SVG picture.

mod common;

use common::cli::noted;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

const HEADER: &str = "zeta,q1,lambda1,m0,m2,m4,h_rms,h_prime,h_dprime,r_s";

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data")
        .join(name)
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

/// A reference surface: its file, options, q0 and (ζ, m0, m2, m4) rows.
type Case = (String, Vec<String>, f64, Vec<[f64; 4]>);

fn reference() -> Vec<Case> {
    let text = std::fs::read_to_string(data("reference.txt")).unwrap();
    let mut out = Vec::new();
    let mut lines = text.lines().filter(|l| !l.starts_with('#')).peekable();
    while let Some(head) = lines.next() {
        let w: Vec<&str> = head.split_whitespace().collect();
        let mut opts = Vec::new();
        if w[3] == "1" {
            opts.push("--periodic".to_string());
        }
        if w[5] != "0.0" {
            opts.extend(["--pixel-size".to_string(), w[5].to_string()]);
        }
        let (mut q0, mut rows, mut section) = (0.0, Vec::new(), "");
        for l in lines.by_ref() {
            let v: Vec<&str> = l.split_whitespace().collect();
            match v[0] {
                "q0" => q0 = v[1].parse().unwrap(),
                "moments" | "spectrum" | "zeta_max" => section = v[0],
                "end" => break,
                _ if section == "moments" => {
                    let n: Vec<f64> = v.iter().map(|s| s.parse().unwrap()).collect();
                    rows.push([n[0], n[1], n[2], n[3]]);
                }
                _ => {}
            }
        }
        out.push((w[1].to_string(), opts, q0, rows));
    }
    out
}

/// Stdout of a successful run, comments and all.
fn full(args: &[&str]) -> String {
    let out = common::cli::run(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn csv_rows(csv: &str) -> Vec<Vec<f64>> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(lines.next(), Some(HEADER));
    lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect()
}

/// The model's readings of one row, checked against its moments.
fn consistent(r: &[f64], q0: f64) {
    let tau = std::f64::consts::TAU;
    assert!(rel(r[1], r[0] * q0) < 1e-15, "q1 {r:?}");
    assert!(rel(r[2], tau / r[1]) < 1e-15, "λ1 {r:?}");
    assert!(rel(r[6], r[3].sqrt()) < 1e-15, "h_rms {r:?}");
    assert!(rel(r[7], (2.0 * r[4]).sqrt()) < 1e-15, "h′ {r:?}");
    assert!(rel(r[8], (8.0 * r[5] / 3.0).sqrt()) < 1e-15, "h″ {r:?}");
}

#[test]
fn measured_moments_and_real_space_numbers_match_surfacetopography() {
    // file → Sq, Sdq, Sa, Ssk, Sku, Sz (Rq, RΔq, Ra, … for lines).
    let real: HashMap<String, Vec<f64>> = std::fs::read_to_string(data("realspace.txt"))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let v = w[4..10].iter().map(|v| v.parse().unwrap()).collect();
            (w[0].to_string(), v)
        })
        .collect();
    let (mut worst_m, mut worst_r, mut worst_iso) = (0f64, 0f64, 0f64);
    for (file, opts, q0, rows) in reference() {
        let path = data(&file);
        let n = rows.len().to_string();
        let mut a = vec![
            "export",
            "--surface",
            path.to_str().unwrap(),
            "--view",
            "moments",
            "--points",
            &n,
        ];
        a.extend(opts.iter().map(String::as_str));
        let csv = full(&a);
        let got = csv_rows(&csv);
        assert_eq!(got.len(), rows.len(), "{file}");
        for (g, w) in got.iter().zip(&rows) {
            assert!(rel(g[0], w[0]) < 1e-13, "{file}: ζ {} vs {}", g[0], w[0]);
            for k in 0..3 {
                let e = rel(g[3 + k], w[1 + k]);
                assert!(
                    e < 1e-12,
                    "{file} ζ {}: m{} {} vs {}",
                    w[0],
                    2 * k,
                    g[3 + k],
                    w[1 + k]
                );
                worst_m = worst_m.max(e);
            }
            consistent(g, q0);
        }
        // Sq and Sdq (Rq and RΔq) as a comment line, every digit.
        let want = &real[&file];
        let (a, b) = if file.starts_with("map") {
            ("Sq", "Sdq")
        } else {
            ("Rq", "RΔq")
        };
        let comment = |name: &str| {
            csv.lines()
                .find(|l| l.starts_with(&format!("# {name} = ")))
                .unwrap_or_else(|| panic!("{file}: {csv}"))
        };
        let num = |line: &str, after: &str, end: &str| -> f64 {
            let t = &line[line.find(after).unwrap() + after.len()..];
            t[..t.find(end).unwrap()].parse().unwrap()
        };
        let line = comment(a);
        let (gh, gs) = (
            num(line, &format!("{a} = "), " m,"),
            num(line, &format!("{b} = "), " ("),
        );
        for (g, w) in [(gh, want[0]), (gs, want[1])] {
            assert!(rel(g, w) < 1e-12, "{file}: {g} vs {w}");
            worst_r = worst_r.max(rel(g, w));
        }
        // The height parameters on the line after it.
        let names = if file.starts_with("map") {
            ["Sa", "Ssk", "Sku", "Sz"]
        } else {
            ["Ra", "Rsk", "Rku", "Rz"]
        };
        let line = comment(names[0]);
        let ends = [" m,", ",", ",", " m ("];
        for k in 0..4 {
            let g = num(line, &format!("{} = ", names[k]), ends[k]);
            let w = want[2 + k];
            // The skewness's error relative to 1 where it is smaller.
            let e = (g - w).abs() / if k == 1 { w.abs().max(1.0) } else { w.abs() };
            assert!(e < 1e-9, "{file} {}: {g} vs {w}", names[k]);
            worst_iso = worst_iso.max(e);
        }
        assert!(csv.contains("# fit: H = "), "{file}");
    }
    eprintln!(
        "moments view against SurfaceTopography: moments {worst_m:.1e}, real space \
         {worst_r:.1e}, height parameters {worst_iso:.1e}"
    );
}

#[test]
fn the_papers_power_law_has_its_moments_too() {
    // fig2 (H 0.8, h_rms = √(πZ q0^(−2H)/H), q0 = 1e5) with the truncated
    // moments: m0 = πZ q0^(−2H)(1 − ζ^(−2H))/H.
    let (z, h, q0) = (1e-8f64, 0.8f64, 1e5f64);
    let (csv, notes) = noted(&[
        "export",
        "--view",
        "moments",
        "--points",
        "9",
        "--moments",
        "truncated",
    ]);
    assert!(notes.is_empty());
    let text = full(&[
        "export",
        "--view",
        "moments",
        "--points",
        "9",
        "--moments",
        "truncated",
    ]);
    assert!(
        text.contains("# the paper's power law: H = 0.8, h_rms = 1.9816636488030044e-8 m, q0 = 100000.0 /m, truncated moments"),
        "{text}"
    );
    let rows = csv_rows(&csv);
    assert_eq!(rows.len(), 9);
    assert_eq!(rows[0][0], 1.0);
    assert_eq!(rows[8][0], 1e4);
    for r in &rows {
        let m0 = std::f64::consts::PI * z * q0.powf(-2.0 * h) * (1.0 - r[0].powf(-2.0 * h)) / h;
        assert!(
            rel(r[3], m0) < 1e-12 || (r[0] == 1.0 && r[3] < 1e-30),
            "{r:?} {m0}"
        );
        if r[0] > 1.0 {
            consistent(r, q0);
        }
    }
}

#[test]
fn the_moments_view_as_a_picture_and_its_options() {
    let path = data("map_windowed.txt");
    let p = path.to_str().unwrap();
    let (svg, _) = noted(&[
        "export",
        "--surface",
        p,
        "--view",
        "moments",
        "--format",
        "svg",
    ]);
    roxmltree::Document::parse(&svg).unwrap();
    for w in [
        "map_windowed — moments",
        "exact · measured moments · size effect on",
        "h_rms = √m0",
        "summed from the PSD up to ζ",
        "Sq = 70.7 nm (real space)",
        "Sdq = 0.153 (real space)",
    ] {
        assert!(svg.contains(w), "{w}");
    }
    let (svg, _) = noted(&["export", "--view", "moments", "--format", "svg"]);
    assert!(svg.contains("h″ = √(8 m4/3)") && !svg.contains("Sq ="));
    let out = common::cli::run(&[
        "export",
        "--surface",
        p,
        "--view",
        "moments",
        "--grid",
        "5x5",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--grid applies only to --view map"));
}
