//! A lay against SurfaceTopography 1.27.1 (`scripts/direction_reference.py`,
//! committed in tests/data/direction_reference.txt): the rms slopes along x
//! and y of the windowed map, and `--direction x|y` — the profiles along
//! one direction — whose moments and spectrum are its
//! `integrate_psd_from_profile` and `power_spectrum_from_profile`.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{read, Direction, Kind, Options};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

#[derive(Default)]
struct Case {
    q0: f64,
    zeta_max: f64,
    /// Rq, RΔq, Ra, Rsk, Rku, Rz of the profiles.
    real: Vec<f64>,
    moments: Vec<[f64; 4]>,
    spectrum: Vec<(f64, f64)>,
}

fn reference() -> ((f64, f64), Vec<Case>) {
    let text = std::fs::read_to_string(data().join("direction_reference.txt")).unwrap();
    let num = |s: &str| s.parse::<f64>().unwrap();
    let (mut slopes, mut cases) = ((0.0, 0.0), Vec::<Case>::new());
    let mut section = "";
    for l in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = l.split_whitespace().collect();
        match w[0] {
            "slopes" => slopes = (num(w[1]), num(w[2])),
            "surface" => cases.push(Case::default()),
            "q0" => cases.last_mut().unwrap().q0 = num(w[1]),
            "zeta_max" => cases.last_mut().unwrap().zeta_max = num(w[1]),
            "real" => cases.last_mut().unwrap().real = w[1..].iter().map(|v| num(v)).collect(),
            "moments" | "spectrum" => section = w[0],
            "end" => section = "",
            _ if section == "moments" => {
                cases
                    .last_mut()
                    .unwrap()
                    .moments
                    .push([num(w[0]), num(w[1]), num(w[2]), num(w[3])])
            }
            _ => cases
                .last_mut()
                .unwrap()
                .spectrum
                .push((num(w[0]), num(w[1]))),
        }
    }
    (slopes, cases)
}

#[test]
fn a_lay_is_noted_and_read_along_each_direction() {
    let ((sx, sy), cases) = reference();
    let file = data().join("map_lay.txt");
    let m = read(&file, &Options::default()).unwrap();
    let s = m.slopes.unwrap();
    assert!(
        rel(s.x, sx) < 1e-12 && rel(s.y, sy) < 1e-12,
        "{s:?} vs {sx} {sy}"
    );
    assert!(s.anisotropic());
    let note = m
        .notes
        .iter()
        .find(|n| n.starts_with("anisotropic"))
        .unwrap();
    let ratio = format!("h′x/h′y = {:.1}", sx / sy);
    assert!(note.contains(&ratio), "{note} lacks {ratio}");
    let (mut worst_m, mut worst_s, mut worst_r) = (0f64, 0f64, 0f64);
    for (d, c) in [Direction::X, Direction::Y].into_iter().zip(&cases) {
        let opts = Options {
            direction: Some(d),
            ..Options::default()
        };
        let m = read(&file, &opts).unwrap();
        assert!(matches!(m.kind, Kind::Profiles { direction, .. } if direction == d));
        assert!(
            m.summary.contains(&format!("profiles along {}", d.name())),
            "{}",
            m.summary
        );
        // The profiles' real-space numbers: Rq and RΔq as SurfaceTopography's
        // Rq and Rdq, the height parameters as NumPy's of its heights.
        let r = m.real.unwrap();
        assert_eq!(r.names(), ("Rq", "RΔq"));
        let [ra, rsk, rku, rz] = r.heights();
        assert_eq!((ra.0, rsk.0, rku.0, rz.0), ("Ra", "Rsk", "Rku", "Rz"));
        let got = [r.rms_height, r.rms_slope, ra.1, rsk.1, rku.1, rz.1];
        for (k, (g, w)) in got.iter().zip(&c.real).enumerate() {
            let e = rel(*g, *w);
            assert!(e < 1e-12, "{d:?} real-space number {k}: {g} vs {w}");
            worst_r = worst_r.max(e);
        }
        assert!(rel(m.table.q0(), c.q0) < 1e-15);
        assert!(rel(m.table.zeta_max(), c.zeta_max) < 1e-14);
        for &[zeta, m0, m2, m4] in &c.moments {
            let got = m.table.at_zeta(zeta);
            for (a, b) in [(got.m0, m0), (got.m2, m2), (got.m4, m4)] {
                let e = rel(a, b);
                assert!(e < 1e-12, "{d:?} ζ {zeta}: {a} vs {b}");
                worst_m = worst_m.max(e);
            }
        }
        assert_eq!(m.spectrum.len(), c.spectrum.len(), "{d:?}");
        for (&(q, p), &(rq, rp)) in m.spectrum.iter().zip(&c.spectrum) {
            assert!(rel(q, rq) < 1e-14, "{d:?} q {q} vs {rq}");
            let e = rel(p, rp);
            assert!(e < 1e-12, "{d:?} at q {q}: {p} vs {rp}");
            worst_s = worst_s.max(e);
        }
    }
    println!(
        "worst relative error along x and y: moments {worst_m:.1e}, spectrum {worst_s:.1e}, \
         Rq, RΔq, Ra, Rsk, Rku, Rz {worst_r:.1e}"
    );
}
