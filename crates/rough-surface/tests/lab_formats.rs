//! Files in the formats a lab brings (Digital Surf compressed .sur/.pro,
//! WSxM, Image Metrology BCR, Nanonis .sxm, Gwyddion 1, Seiko .xqd) read
//! to the grid, sizes and undefined points independent readers read from
//! them, and to the Sq and Sdq (Rq and RΔq) SurfaceTopography computes on
//! those heights (`scripts/lab_formats_reference.py`,
//! tests/data/lab/lab.txt); files that hold no heights refused with the
//! line naming the format. With ROUGHTUI_SAMPLES=DIR, the same for the
//! real files of tests/data/lab/samples.txt found in DIR (fetched from
//! public repositories, not committed; each checked by its SHA-256 first).

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{parse_named, read, sha256_hex, Kind, Measured, Options, Problem};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lab")
}

/// One file (and channel) as the reference read it.
#[derive(Default, Debug)]
struct Case {
    file: String,
    channel: Option<String>,
    /// The heights' unit to write into a Digital Surf header first.
    patch: Option<String>,
    /// Its SHA-256 (a sample).
    sha256: Option<String>,
    grid: (usize, usize, f64, f64),
    undefined: usize,
    /// Sq, Sdq.
    real: [f64; 2],
    /// The refusal's start, for a file that holds no heights.
    refused: Option<String>,
}

fn cases(name: &str) -> Vec<Case> {
    let text = std::fs::read_to_string(dir().join(name)).unwrap();
    let num = |s: &str| s.parse::<f64>().unwrap();
    let mut out: Vec<Case> = Vec::new();
    let mut sha = None;
    for l in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = l.split_whitespace().collect();
        match w[0] {
            "sample" => sha = Some(w[5].to_string()),
            "file" => out.push(Case {
                file: w[1].to_string(),
                channel: (w[3] != "-").then(|| w[3].to_string()),
                patch: (w.get(4) == Some(&"patch")).then(|| w[5].to_string()),
                sha256: sha.take(),
                ..Case::default()
            }),
            "grid" => {
                let c = out.last_mut().unwrap();
                c.grid = (
                    w[1].parse().unwrap(),
                    w[2].parse().unwrap(),
                    num(w[3]),
                    num(w[4]),
                );
                c.undefined = w[5].parse().unwrap();
            }
            "real" => out.last_mut().unwrap().real = [num(w[1]), num(w[2])],
            "refused" => out.last_mut().unwrap().refused = Some(l[8..].to_string()),
            "readers" => {}
            _ => panic!("{l}"),
        }
    }
    out
}

/// Reads case `c` from folder `at` as a user would (its .gz as it is).
fn read_case(c: &Case, at: &Path) -> Result<Measured, String> {
    let opts = Options {
        channel: c.channel.clone(),
        ..Options::default()
    };
    let path = at.join(&c.file);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    if let Some(want) = &c.sha256 {
        assert_eq!(
            &sha256_hex(&bytes),
            want,
            "{}: not the file the references were made from",
            c.file
        );
    }
    match &c.patch {
        Some(unit) => {
            let mut b = bytes;
            let mut field = unit.as_bytes().to_vec();
            field.resize(16, 0);
            b[212..228].copy_from_slice(&field);
            parse_named(&b, &c.file, &opts).map_err(|(_, p): (_, Problem)| p.to_string())
        }
        None => read(&path, &opts).map_err(|e| e.problem.to_string()),
    }
}

/// Checks every case of `list` read from folder `at`; how many.
fn check(list: &str, at: &Path) -> usize {
    let all = cases(list);
    for c in &all {
        let who = format!("{} channel {:?}", c.file, c.channel);
        let r = read_case(c, at);
        if let Some(start) = &c.refused {
            let e = r
                .err()
                .unwrap_or_else(|| panic!("{who}: read, not refused"));
            assert!(e.starts_with(start.as_str()), "{who}: {e}");
            assert!(!e.contains('\n'), "{who}: {e}");
            println!("{who}: refused: {e}");
            continue;
        }
        let m = r.unwrap_or_else(|e| panic!("{who}: {e}"));
        let (nx, ny, lx, ly) = c.grid;
        let (e_x, e_y) = match m.kind {
            Kind::Map {
                nx: a,
                ny: b,
                lx: x,
                ly: y,
            } => {
                assert_eq!((a, b), (nx, ny), "{who}");
                (rel(x, lx), rel(y, ly))
            }
            Kind::Line { n, l } => {
                assert_eq!((n, 1), (nx, ny), "{who}");
                (rel(l, lx), 0.0)
            }
            k => panic!("{who}: {k:?}"),
        };
        // The sizes to the last bit or two (a float32 spacing times the
        // points, in either order).
        assert!(e_x < 1e-15 && e_y < 1e-15, "{who}: sizes {e_x:e} {e_y:e}");
        agree::undefined_noted(&who, &m.notes, c.undefined);
        let r = m.real.unwrap();
        let (e_sq, e_sdq) = (rel(r.rms_height, c.real[0]), rel(r.rms_slope, c.real[1]));
        assert!(e_sq < 1e-9, "{who}: Sq {} vs {}", r.rms_height, c.real[0]);
        assert!(e_sdq < 1e-9, "{who}: Sdq {} vs {}", r.rms_slope, c.real[1]);
        println!(
            "{who}: {nx} × {ny}, {} undefined; relative to the reference: sizes {:.1e}, \
             Sq {e_sq:.1e}, Sdq {e_sdq:.1e}",
            c.undefined,
            e_x.max(e_y)
        );
    }
    all.len()
}

#[test]
fn lab_formats_match_independent_readers() {
    assert!(check("lab.txt", &dir()) >= 16);
}

#[test]
fn real_samples_match_independent_readers() {
    // Fetched files are not committed: this runs where they are.
    let Ok(at) = std::env::var("ROUGHTUI_SAMPLES") else {
        eprintln!("ROUGHTUI_SAMPLES not set: the real samples are not checked");
        return;
    };
    assert!(check("samples.txt", Path::new(&at)) >= 19);
}
