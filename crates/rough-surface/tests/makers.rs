//! Instrument makers' files read natively (Keyence .vk4/.vk6/.vk7/.zon,
//! JPK .jpk/.jpk-qi-image/.h5-jpk, Park Systems TIFF, Sensofar .plux,
//! Zygo .datx) to the numbers independent readers read and compute on
//! them (`scripts/makers_reference.py`: SurfaceTopography 1.27.1, and
//! AFMReader 0.0.7 for .h5-jpk): the grid exactly, its size and Sq and
//! Sdq within 1e-6 (relative), the undefined points as the file marks
//! them. tests/data/makers/ holds JPK's real files (AFMReader's sdist) and
//! synthetic files of the other formats (`scripts/makers_synthetic.py`);
//! with `ROUGHTUI_SAMPLES=DIR` the real files samples.txt names (fetched
//! from public repositories, not committed) are checked too, each against
//! its SHA-256 first.

mod agree;
use agree::rel;

use std::io::Read;
use std::path::{Path, PathBuf};

use rough_surface::{parse_named, sha256_hex, Kind, Measured, Options};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/makers")
}

/// One file (and channel) as the independent reader read it.
struct Case {
    /// The file, as makers.txt or samples.txt names it.
    file: String,
    channel: Option<String>,
    /// A sample's repository and SHA-256.
    sample: Option<(String, String)>,
    grid: (usize, usize, f64, f64),
    undefined: usize,
    sq: f64,
    sdq: f64,
}

fn cases(name: &str) -> Vec<Case> {
    let text = std::fs::read_to_string(dir().join(name)).unwrap();
    let num = |s: &str| s.parse::<f64>().unwrap();
    let mut out: Vec<Case> = Vec::new();
    for l in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = l.split_whitespace().collect();
        let last = out.last_mut();
        let channel = |s: &str| (s != "-").then(|| s.to_string());
        match w[0] {
            "file" => out.push(Case {
                file: w[1].into(),
                channel: channel(w[3]),
                sample: None,
                grid: (0, 0, 0.0, 0.0),
                undefined: 0,
                sq: 0.0,
                sdq: 0.0,
            }),
            "sample" => out.push(Case {
                file: w[3].into(),
                channel: channel(w[6]),
                sample: Some((w[1].into(), w[4].into())),
                grid: (0, 0, 0.0, 0.0),
                undefined: 0,
                sq: 0.0,
                sdq: 0.0,
            }),
            "grid" => {
                let c = last.unwrap();
                c.grid = (
                    w[1].parse().unwrap(),
                    w[2].parse().unwrap(),
                    num(w[3]),
                    num(w[4]),
                );
                c.undefined = w[5].parse().unwrap();
            }
            "real" => {
                let c = last.unwrap();
                (c.sq, c.sdq) = (num(w[1]), num(w[2]));
            }
            _ => panic!("{l}"),
        }
    }
    out
}

/// `bytes` of a file named `name` read as a user reads it, checked
/// against `c`; the relative differences of Sq and Sdq.
fn check(c: &Case, name: &str, bytes: &[u8]) -> (f64, f64) {
    let opts = Options {
        channel: c.channel.clone(),
        ..Options::default()
    };
    let m: Measured = parse_named(bytes, name, &opts).unwrap_or_else(|e| panic!("{name}: {e:?}"));
    let who = format!("{} channel {:?}", c.file, c.channel);
    let (nx, ny, lx, ly) = c.grid;
    match m.kind {
        Kind::Map {
            nx: a,
            ny: b,
            lx: x,
            ly: y,
        } => {
            assert_eq!((a, b), (nx, ny), "{who}");
            assert!(rel(x, lx) < 1e-12 && rel(y, ly) < 1e-12, "{who}: {x} {y}");
        }
        k => panic!("{who}: {k:?}"),
    }
    agree::undefined_noted(&who, &m.notes, c.undefined);
    let r = m.real.unwrap();
    let (e_sq, e_sdq) = (rel(r.rms_height, c.sq), rel(r.rms_slope, c.sdq));
    assert!(e_sq < 1e-6, "{who}: Sq {} vs {}", r.rms_height, c.sq);
    assert!(e_sdq < 1e-6, "{who}: Sdq {} vs {}", r.rms_slope, c.sdq);
    println!(
        "{who}: {nx} × {ny}, {} undefined; relative to the independent reader: Sq {e_sq:.1e}, \
         Sdq {e_sdq:.1e}",
        c.undefined
    );
    (e_sq, e_sdq)
}

fn gunzip(b: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    flate2::read::GzDecoder::new(b)
        .read_to_end(&mut out)
        .unwrap();
    out
}

#[test]
fn makers_files_read_as_independent_readers_read_them() {
    let all = cases("makers.txt");
    assert_eq!(all.len(), 11);
    for c in &all {
        let bytes = std::fs::read(dir().join(&c.file)).unwrap();
        // Each as it is named, a .gz as the file it holds.
        check(c, &c.file, &bytes);
        if let Some(inner) = c.file.strip_suffix(".gz") {
            check(c, inner, &gunzip(&bytes));
        }
    }
}

/// The real files named in samples.txt, when `ROUGHTUI_SAMPLES` names
/// the folder that holds them (`DIR/owner+name/path`).
#[test]
fn real_samples_when_present() {
    let Some(root) = std::env::var_os("ROUGHTUI_SAMPLES") else {
        eprintln!("ROUGHTUI_SAMPLES not set: the real samples are not checked");
        return;
    };
    let all = cases("samples.txt");
    for c in &all {
        let (repo, sha) = c.sample.clone().unwrap();
        let (outer, member) = match c.file.split_once('!') {
            Some((o, m)) => (o, Some(m)),
            None => (c.file.as_str(), None),
        };
        let path = Path::new(&root).join(&repo).join(outer);
        let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(sha256_hex(&bytes), sha, "{}: another file", path.display());
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        match member {
            None => {
                check(c, &name, &bytes);
            }
            Some(m) => {
                let mut z = zip::ZipArchive::new(std::io::Cursor::new(&bytes)).unwrap();
                let mut inner = Vec::new();
                z.by_name(m).unwrap().read_to_end(&mut inner).unwrap();
                check(c, "inner.vk4", &inner);
            }
        }
    }
}
