//! Undefined points against SurfaceTopography 1.27.1: maps and a line
//! scan with `nan` and empty cells (scattered points, a blob, a broken scan
//! line, corners, an edge), filled by its `interpolate_undefined_data()`
//! (harmonic), then detrended and transformed as for every surface
//! (`scripts/fill_reference.py`, committed in tests/data/
//! fill_reference.txt): the moments and spectra of our filled surface
//! match its, and the note counts the points.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{read, Options, Problem};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

struct Case {
    file: String,
    periodic: bool,
    undefined: usize,
    total: usize,
    moments: Vec<[f64; 4]>,
    spectrum: Vec<(f64, f64)>,
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(data().join("fill_reference.txt")).unwrap();
    let num = |s: &str| s.parse::<f64>().unwrap();
    let mut out: Vec<Case> = Vec::new();
    let mut counts = (0, 0);
    let mut section = "";
    for l in text.lines() {
        let w: Vec<&str> = l.split_whitespace().collect();
        match w[0] {
            // "# map_nan.txt: 208 undefined of 7680"
            "#" if w.get(3) == Some(&"undefined") => {
                counts = (w[2].parse().unwrap(), w[5].parse().unwrap())
            }
            "#" => {}
            "surface" => out.push(Case {
                file: w[1].to_string(),
                periodic: w[3] == "1",
                undefined: counts.0,
                total: counts.1,
                moments: Vec::new(),
                spectrum: Vec::new(),
            }),
            "moments" | "spectrum" => section = w[0],
            "q0" | "zeta_max" | "end" => section = "",
            _ if section == "moments" => {
                out.last_mut()
                    .unwrap()
                    .moments
                    .push([num(w[0]), num(w[1]), num(w[2]), num(w[3])])
            }
            _ if section == "spectrum" => out
                .last_mut()
                .unwrap()
                .spectrum
                .push((num(w[0]), num(w[1]))),
            _ => panic!("{l}"),
        }
    }
    out
}

#[test]
fn filled_surfaces_match_surfacetopography() {
    let cases = cases();
    assert_eq!(cases.len(), 3);
    let (mut worst_m, mut worst_s) = (0f64, 0f64);
    for c in &cases {
        let opts = Options {
            periodic: c.periodic,
            ..Options::default()
        };
        let m = read(&data().join(&c.file), &opts).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.notes.len(), 1, "{}: {:?}", c.file, m.notes);
        assert!(
            m.notes[0].starts_with(&format!("{} undefined points (", c.undefined)),
            "{}: {:?}",
            c.file,
            m.notes
        );
        assert!(m.notes[0].ends_with(" %) filled"), "{:?}", m.notes);
        assert!(c.total > 0);
        for &[zeta, m0, m2, m4] in &c.moments {
            let got = m.table.at_zeta(zeta);
            for (a, b) in [(got.m0, m0), (got.m2, m2), (got.m4, m4)] {
                let e = rel(a, b);
                assert!(e < 1e-12, "{} ζ {zeta}: {a} vs {b}", c.file);
                worst_m = worst_m.max(e);
            }
        }
        assert_eq!(m.spectrum.len(), c.spectrum.len(), "{}", c.file);
        let peak = c.spectrum.iter().fold(0f64, |a, p| a.max(p.1));
        for (&(q, s), &(rq, rs)) in m.spectrum.iter().zip(&c.spectrum) {
            assert!(rel(q, rq) < 1e-14, "{} spectrum q {q} vs {rq}", c.file);
            let e = (s - rs).abs() / rs.max(1e-12 * peak);
            assert!(e < 1e-12, "{} spectrum at q {q}: {s} vs {rs}", c.file);
            worst_s = worst_s.max(e);
        }
    }
    println!(
        "worst relative error of the filled surfaces against SurfaceTopography: \
         moments {worst_m:.1e}, spectrum {worst_s:.1e}"
    );
}

#[test]
fn too_many_undefined_points_are_refused_with_their_share() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path().join("holes.txt");
    let mut text = String::from("# Width: 1 µm\n# Height: 1 µm\n");
    for j in 0..10 {
        let row: Vec<String> = (0..10)
            .map(|i| {
                if j == 3 && i < 9 || j == 7 && i < 3 {
                    "nan".to_string()
                } else {
                    format!("{}", ((i * 7 + j * 3) % 5) as f64)
                }
            })
            .collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    std::fs::write(&p, &text).unwrap();
    let e = read(&p, &Options::default()).unwrap_err();
    assert_eq!(
        e.problem,
        Problem::Undefined {
            count: 12,
            total: 100,
            allowed: 0.1
        }
    );
    let msg = e.to_string();
    assert!(
        msg.contains("12 of 100 points (12 %) are undefined")
            && msg.contains("up to 10 % are filled")
            && msg.contains("crop"),
        "{msg}"
    );
    // --max-undefined 12 fills them, saying so.
    let twelve = Options {
        max_undefined: Some(0.12),
        ..Options::default()
    };
    let m = read(&p, &twelve).unwrap();
    assert_eq!(
        m.notes[0],
        "12 undefined points (12 %) filled (--max-undefined 12 %)"
    );
    // Ten are filled.
    std::fs::write(&p, text.replacen("nan", "1", 2)).unwrap();
    let m = read(&p, &Options::default()).unwrap();
    // The fill's note first (the units' and the plausibility line follow).
    assert_eq!(m.notes[0], "10 undefined points (10 %) filled");
    // Infinity is still refused, with its line.
    std::fs::write(&p, text.replacen("nan", "inf", 1)).unwrap();
    let e = read(&p, &Options::default()).unwrap_err();
    assert_eq!(
        (e.line, e.problem),
        (Some(6), Problem::NotFinite("inf".into()))
    );
}
