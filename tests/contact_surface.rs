//! `roughtui export --view surface`: the contact views' synthetic surface
//! as a height matrix that other codes read, and the contact view's areas
//! against another code solving that file.
//!
//! The reference (tests/data/contact/surface_tamaas.csv, written by
//! scripts/surface_tamaas_reference.py) is Tamaas 2.9's KatoSaturated on
//! the exported file as SurfaceTopography 1.27's read_topography reads it,
//! solved in cell units. Both codes solve the same discrete problem, so the
//! areas agree node for node but for a node whose pressure each solver
//! leaves within its tolerance of 0 or of the cap: at most
//! [`NODES`] nodes of the 128 × 128 grid. The corrected area also takes
//! Tamaas's perimeter (FloodFill's clusters) and correction
//! (`Statistics2D.contact`): the same within those nodes and their sides.

mod common;
use common::cli::{run, stdout};

/// Nodes the two solvers may place on either side of a bound.
const NODES: f64 = 2.0;

struct Case {
    name: String,
    args: Vec<String>,
    sha256: String,
    /// p̄/H, area, elastic, plastic, corrected area.
    loads: Vec<[f64; 5]>,
}

fn reference() -> Vec<Case> {
    let text = include_str!("data/contact/surface_tamaas.csv");
    let mut cases: Vec<Case> = text
        .lines()
        .filter_map(|l| l.strip_prefix("# case "))
        .map(|l| {
            let (name, args) = l.split_once(": ").unwrap();
            Case {
                name: name.into(),
                args: args.split(' ').map(String::from).collect(),
                sha256: String::new(),
                loads: vec![],
            }
        })
        .collect();
    for l in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = l.split(',').collect();
        let c = cases.iter_mut().find(|c| c.name == f[0]).unwrap();
        c.sha256 = f[1].into();
        let v = |i: usize| f[i].parse::<f64>().unwrap();
        c.loads.push([v(2), v(3), v(4), v(5), v(6)]);
    }
    assert_eq!(cases.len(), 2);
    cases
}

/// SHA-256 of the height lines (the header's words may change).
fn heights_sha256(text: &str) -> String {
    let body: String = text
        .split_inclusive('\n')
        .filter(|l| !l.starts_with('#'))
        .collect();
    rough_surface::sha256_hex(body.as_bytes())
}

fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

#[test]
fn the_exported_surface_gives_tamaas_the_contact_views_areas() {
    for case in reference() {
        let args: Vec<&str> = case.args.iter().map(String::as_str).collect();
        let surface = stdout(&[&["export", "--view", "surface"], &args[..]].concat());
        assert_eq!(
            heights_sha256(&surface),
            case.sha256,
            "{}: the exported heights are not those Tamaas solved",
            case.name
        );
        let csv = stdout(&[&["export", "--view", "contact", "--points", "4"], &args[..]].concat());
        let rows = rows(&csv);
        let n2 = 128.0 * 128.0;
        for (k, want) in case.loads.iter().enumerate() {
            let got = &rows[k];
            assert_eq!(got[0], want[0], "{}: load", case.name);
            // area, elastic, plastic; area_corrected is column 15.
            for (col, w) in [(1, want[1]), (2, want[2]), (3, want[3]), (15, want[4])] {
                let nodes = (got[col] - w).abs() * n2;
                assert!(
                    nodes <= NODES,
                    "{} at p̄/H = {}: column {col} got {} want {w} ({nodes} nodes apart)",
                    case.name,
                    want[0],
                    got[col]
                );
            }
        }
    }
}

/// The file reads back as a measured map (`--surface FILE --periodic`) and
/// solves to the same areas as the scene it came from.
#[test]
fn the_exported_surface_reads_back_as_a_measured_map() {
    let dir = tempfile_dir("surface");
    let path = dir.join("fig2-z8.txt");
    let scene = [
        "--preset", "fig2", "--set", "zeta=8", "--cell", "1", "--seed", "3",
    ];
    let text = stdout(&[&["export", "--view", "surface"], &scene[..]].concat());
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        &lines[..4],
        &[
            "# Channel: Height (roughtui synthetic surface of scene \"fig2\", seed 3)",
            "# Width: 0.00006283185307179586 m",
            "# Height: 0.00006283185307179586 m",
            "# Value units: m",
        ]
    );
    assert!(lines.iter().any(|l| l.starts_with(
        "# surface = the contact views' heights: periodic 64 × 64 grid of side \
         0.00006283185307179586 m (a cell of 1 longest wavelength), 8 nodes per shortest \
         wavelength, seed 3"
    )));
    let data: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| !l.starts_with('#'))
        .collect();
    assert_eq!(data.len(), 64);
    assert!(data.iter().all(|l| l.split(' ').count() == 64));
    std::fs::write(&path, &text).unwrap();
    let p = path.to_str().unwrap();
    let measured = stdout(&[
        "export",
        "--view",
        "contact",
        "--surface",
        p,
        "--periodic",
        "--set",
        "zeta=8",
        "--set",
        "h0-over-e=0.01",
        "--size-effect",
        "off",
        "--points",
        "3",
    ]);
    let synthetic = stdout(
        &[
            &["export", "--view", "contact", "--points", "3"],
            &scene[..],
        ]
        .concat(),
    );
    for (a, b) in rows(&measured).iter().zip(rows(&synthetic)) {
        // The same heights (a Fourier low-pass at ζ q0 that keeps every mode
        // aside): the same nodes in contact and at the hardness.
        assert_eq!(a[0], b[0]);
        assert_eq!(&a[1..4], &b[1..4], "{a:?} {b:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_surface_view_refuses_what_does_not_apply() {
    for (extra, needle) in [
        (
            vec!["--seeds", "2"],
            "--seeds does not apply to --view surface",
        ),
        (
            vec!["--points", "3"],
            "--points does not apply to --view surface",
        ),
        (
            vec!["--hardness", "summit"],
            "--hardness does not apply to --view surface",
        ),
        (vec!["--format", "svg"], "a height matrix: text only"),
        (
            vec!["--surface", "surfaces/example.txt"],
            "--view surface writes the synthetic surface of a power-law scene",
        ),
    ] {
        let mut args = vec!["export", "--view", "surface"];
        args.extend(extra.iter().copied());
        let out = run(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(out.stdout.is_empty());
    }
}

fn tempfile_dir(what: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "roughtui-{what}-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
