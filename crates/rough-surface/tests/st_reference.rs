//! Against SurfaceTopography 1.27.1: surfaces made by its
//! `fourier_synthesis`, written in the formats roughtui reads, and its own
//! moments and spectra of them (`scripts/surface_reference.py`, committed
//! in tests/data/reference.txt). The indices are computed from the
//! moments with docs/model.md's formulas (H0/E = 0.01, R* = 1 mm).

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{read, Kind, Options};

struct Case {
    file: String,
    opts: Options,
    kind: Vec<(String, f64)>,
    q0: f64,
    zeta_max: f64,
    /// ζ, m0, m2, m4.
    moments: Vec<[f64; 4]>,
    spectrum: Vec<(f64, f64)>,
}

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(data().join("reference.txt")).unwrap();
    let mut out = Vec::new();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    while let Some(head) = lines.next() {
        let w: Vec<&str> = head.split_whitespace().collect();
        assert_eq!(w[0], "surface");
        let num = |s: &str| s.parse::<f64>().unwrap();
        let pixel = num(w[5]);
        let kind = w[7..]
            .chunks(2)
            .map(|p| (p[0].to_string(), num(p[1])))
            .collect();
        let mut case = Case {
            file: w[1].to_string(),
            opts: Options {
                periodic: w[3] == "1",
                pixel_size: (pixel > 0.0).then_some(pixel),
                ..Options::default()
            },
            kind,
            q0: 0.0,
            zeta_max: 0.0,
            moments: Vec::new(),
            spectrum: Vec::new(),
        };
        let mut section = "";
        for l in lines.by_ref() {
            let v: Vec<&str> = l.split_whitespace().collect();
            match v[0] {
                "q0" => case.q0 = num(v[1]),
                "zeta_max" => case.zeta_max = num(v[1]),
                "moments" | "spectrum" => section = v[0],
                "end" => break,
                _ if section == "moments" => {
                    case.moments
                        .push([num(v[0]), num(v[1]), num(v[2]), num(v[3])])
                }
                _ => case.spectrum.push((num(v[0]), num(v[1]))),
            }
        }
        out.push(case);
    }
    out
}

/// Ψ_P, Ψ*, Ψ_GW from profile moments (docs/model.md, "Hardness, indices").
fn indices(m0: f64, m2: f64, m4: f64) -> [f64; 3] {
    let (e_over_h0, r_star) = (100.0, 1e-3);
    let rs = 0.375 * (std::f64::consts::PI / m4).sqrt();
    let hy = (1.0 + r_star / (1.2 * rs)).sqrt();
    let psi_p = e_over_h0 * (m2 / 2.0).sqrt();
    [psi_p, psi_p / hy, e_over_h0 * (m0.sqrt() / rs).sqrt()]
}

#[test]
fn moments_indices_and_spectra_match_surfacetopography() {
    let cases = cases();
    assert_eq!(cases.len(), 8);
    let (mut worst_m, mut worst_i, mut worst_s) = (0f64, 0f64, 0f64);
    for c in &cases {
        let m = read(&data().join(&c.file), &c.opts).unwrap_or_else(|e| panic!("{e}"));
        let get = |k: &str| c.kind.iter().find(|p| p.0 == k).unwrap().1;
        match m.kind {
            Kind::Map { nx, ny, lx, ly } => {
                assert_eq!((nx as f64, ny as f64), (get("nx"), get("ny")), "{}", c.file);
                assert!(rel(lx, get("lx")) < 1e-15 && rel(ly, get("ly")) < 1e-15);
            }
            Kind::Line { n, l } => {
                assert_eq!(n as f64, get("n"), "{}", c.file);
                assert!(rel(l, get("l")) < 1e-15, "{}: {l}", c.file);
            }
            Kind::Psd { .. } | Kind::Profiles { .. } => panic!("{} read as {:?}", c.file, m.kind),
        }
        assert!(rel(m.table.q0(), c.q0) < 1e-15, "{}", c.file);
        assert!(rel(m.table.zeta_max(), c.zeta_max) < 1e-14, "{}", c.file);
        for &[zeta, m0, m2, m4] in &c.moments {
            let got = m.table.at_zeta(zeta);
            for (a, b) in [(got.m0, m0), (got.m2, m2), (got.m4, m4)] {
                let e = rel(a, b);
                assert!(e < 1e-10, "{} ζ {zeta}: {a} vs {b}", c.file);
                worst_m = worst_m.max(e);
            }
            let (ours, theirs) = (indices(got.m0, got.m2, got.m4), indices(m0, m2, m4));
            for k in 0..3 {
                let e = rel(ours[k], theirs[k]);
                assert!(
                    e < 1e-9,
                    "{} ζ {zeta} index {k}: {ours:?} vs {theirs:?}",
                    c.file
                );
                worst_i = worst_i.max(e);
            }
        }
        // Beyond a synthesis' short cutoff the PSD is rounding noise, some
        // 1e-30 of its peak: compared to the peak there.
        assert_eq!(m.spectrum.len(), c.spectrum.len(), "{}", c.file);
        let peak = c.spectrum.iter().fold(0f64, |a, p| a.max(p.1));
        for (&(q, s), &(rq, rs)) in m.spectrum.iter().zip(&c.spectrum) {
            assert!(rel(q, rq) < 1e-14, "{} spectrum q {q} vs {rq}", c.file);
            if rs < 1e-20 * peak {
                assert!((s - rs).abs() < 1e-25 * peak, "{} at q {q}", c.file);
                continue;
            }
            let e = rel(s, rs);
            assert!(e < 1e-10, "{} spectrum at q {q}: {s} vs {rs}", c.file);
            worst_s = worst_s.max(e);
        }
    }
    println!(
        "worst relative error against SurfaceTopography: moments {worst_m:.1e}, \
         indices {worst_i:.1e}, spectrum {worst_s:.1e}"
    );
}
