//! Real files through the command line, end to end: Gwyddion-style height
//! maps and a line scan (SurfaceTopography's own `fourier_synthesis`
//! surfaces, rough-surface's test data) give, through `roughtui export`,
//! the indices that SurfaceTopography 1.27.1's moments give (within 1e-9 at
//! every swept ζ); a contact.engineering download gives those of mpmath's
//! moments (within 1e-12); every view of both exports as CSV and SVG; and
//! every bad input of the list is one message with file, line and problem
//! and status 2, from `export`, the explorer and `serve` alike.

mod common;

use common::cli::{noted, run, BIN};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

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

/// Ψ_GW, Ψ_P, Ψ* from profile moments with docs/model.md's formulas, written
/// out here (H0/E = 0.01, R* = 1 mm: the material a surface opens with).
fn indices(m0: f64, m2: f64, m4: f64) -> [f64; 3] {
    let (e_over_h0, r_star) = (100.0, 1e-3);
    let rs = 0.375 * (std::f64::consts::PI / m4).sqrt();
    let hy = (1.0 + r_star / (1.2 * rs)).sqrt();
    let psi_p = e_over_h0 * (m2 / 2.0).sqrt();
    [e_over_h0 * (m0.sqrt() / rs).sqrt(), psi_p, psi_p / hy]
}

/// The rows (ζ, m0, m2, m4) a reference file gives for `name`: blocks
/// headed by `head` words, the rows after `rows_after` (or at once).
fn reference(file: &str, name: &str, rows_after: Option<&str>) -> Vec<[f64; 4]> {
    let text = std::fs::read_to_string(data(file)).unwrap();
    let mut lines = text.lines().skip_while(|l| {
        let w: Vec<&str> = l.split_whitespace().collect();
        !(w.len() > 1 && (w[0] == "surface" || w[0] == "table") && w[1] == name)
    });
    lines.next().expect(name);
    if let Some(after) = rows_after {
        lines.by_ref().find(|l| l.trim() == after).unwrap();
    }
    lines
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .take_while(|w| w.len() == 4 && w[0].parse::<f64>().is_ok())
        .map(|w| {
            let v: Vec<f64> = w.iter().map(|s| s.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// The largest relative deviation of `export --view indices` from the
/// indices of `rows`, sampled at the same ζ.
fn deviation(args: &[&str], rows: &[[f64; 4]], tol: f64) -> f64 {
    let n = rows.len().to_string();
    let mut a = vec!["export", "--view", "indices", "--points", &n];
    a.extend_from_slice(args);
    let (csv, _) = noted(&a);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("zeta,psi_gw,psi_p,psi_star,psi_star_asymptotic,hy_over_h0")
    );
    let mut worst = 0f64;
    let mut count = 0;
    for (line, &[zeta, m0, m2, m4]) in lines.zip(rows) {
        let f: Vec<&str> = line.split(',').collect();
        let x: f64 = f[0].parse().unwrap();
        assert!(rel(x, zeta) < 1e-13, "{args:?}: ζ {x} vs {zeta}");
        // Eq. 13 is a power law's: empty on a measured surface.
        assert_eq!(f[4], "", "{line}");
        let want = indices(m0, m2, m4);
        for k in 0..3 {
            let got: f64 = f[k + 1].parse().unwrap();
            let e = rel(got, want[k]);
            assert!(
                e < tol,
                "{args:?} ζ {zeta} column {}: {got} vs {}",
                k + 1,
                want[k]
            );
            worst = worst.max(e);
        }
        count += 1;
    }
    assert_eq!(count, rows.len(), "{args:?}");
    worst
}

#[test]
fn maps_and_a_line_scan_give_surfacetopographys_indices() {
    let mut worst = 0f64;
    for (name, opts) in [
        ("map_windowed.txt", &[][..]),
        ("map_periodic.txt", &["--periodic"][..]),
        ("map_odd.txt", &[][..]),
        ("map_pixel.txt", &["--pixel-size", "50nm"][..]),
        ("line_xz.txt", &[][..]),
        ("line_column.txt", &[][..]),
    ] {
        let rows = reference("reference.txt", name, Some("moments"));
        assert_eq!(rows.len(), 41, "{name}");
        let path = data(name);
        let mut args = vec!["--surface", path.to_str().unwrap()];
        args.extend_from_slice(opts);
        worst = worst.max(deviation(&args, &rows, 1e-9));
    }
    eprintln!("export against SurfaceTopography 1.27.1's moments: worst {worst:.1e}");
}

#[test]
fn a_contact_engineering_download_gives_mpmaths_indices() {
    let mut worst = 0f64;
    for name in ["psd_knee_ce.txt", "psd_profile_ce.txt"] {
        let rows = reference("psd_reference.txt", name, None);
        assert_eq!(rows.len(), 31, "{name}");
        let path = data(name);
        let args = ["--surface", path.to_str().unwrap(), "--sweep", "zeta:1:1e4"];
        worst = worst.max(deviation(&args, &rows, 1e-12));
    }
    eprintln!("export of contact.engineering downloads against mpmath: worst {worst:.1e}");
}

#[test]
fn every_view_of_a_map_and_a_download_exports() {
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("surfaces/example.txt");
    let ce = data("psd_knee_ce.txt");
    for file in [example, ce] {
        let f = file.to_str().unwrap();
        for (view, header) in [
            (
                "slopes",
                "zeta,psi,h_use_over_h0,elastic,plastic,total,persson_elastic",
            ),
            (
                "indices",
                "zeta,psi_gw,psi_p,psi_star,psi_star_asymptotic,hy_over_h0",
            ),
            (
                "map",
                "zeta,h0_over_e,psi,elastic,plastic,total,plastic_share",
            ),
            ("load", "load,elastic,plastic,total"),
            ("spectrum", "q,psd,fit"),
        ] {
            let out = run(&["export", "--surface", f, "--view", view]);
            assert_eq!(out.status.code(), Some(0), "{f} {view}");
            let csv = String::from_utf8(out.stdout).unwrap();
            // The scene first: the file and its SHA-256 among the `#` lines.
            let name = file.file_name().unwrap().to_str().unwrap();
            let comments: Vec<&str> = csv.lines().take_while(|l| l.starts_with('#')).collect();
            assert!(
                comments.contains(&format!("# surface = {name}").as_str()),
                "{f} {view}"
            );
            assert!(
                comments.iter().any(|l| l.starts_with("# sha256 = ")),
                "{f} {view}"
            );
            let header_line = csv.lines().find(|l| !l.starts_with('#'));
            assert_eq!(header_line, Some(header), "{f} {view}");
            assert!(csv.lines().count() > 10, "{f} {view}: {csv}");
            let (svg, _) = noted(&["export", "--surface", f, "--view", view, "--format", "svg"]);
            assert!(
                svg.contains("<svg") && svg.trim_end().ends_with("</svg>"),
                "{f} {view}"
            );
        }
    }
}

/// A 4 × 4 map with the size header, rows `rows`.
fn map(header: &str, rows: &[&str]) -> String {
    let mut t = String::from(header);
    for r in rows {
        t.push_str(r);
        t.push('\n');
    }
    t
}

const SIZE: &str = "# Width: 4 µm\n# Height: 4 µm\n# Value units: nm\n";
const GOOD: [&str; 4] = ["1 2 3 4", "2 1 4 3", "0 5 1 2", "3 3 0 1"];

#[test]
fn every_bad_input_is_status_2_with_file_line_and_problem() {
    let dir = tempfile::tempdir().unwrap();
    let psd = |c: &dyn Fn(usize, f64) -> (f64, f64)| {
        let mut t = String::from("# q C\n");
        for (i, q) in [1e5, 2e5, 4e5, 8e5, 1.6e6].into_iter().enumerate() {
            let (q, c) = c(i, q);
            t.push_str(&format!("{q:e} {c:e}\n"));
        }
        t
    };
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "ragged",
            map(SIZE, &["1 2 3 4", "1 2 3", "1 2 3 4", "1 2 3 4"]),
            "line 5: 3 columns where the first row has 4",
        ),
        (
            "word",
            map(SIZE, &["1 2 3 4", "1 2 3 4", "1 2 x 4", "1 2 3 4"]),
            "line 6: 'x' is not a number",
        ),
        (
            "nan",
            map(SIZE, &["1 2 3 4", "1 NaN 3 4", "1 2 nan 4", "1 2 3 4"]),
            "2 of 16 points (12.5 %) are undefined",
        ),
        (
            "inf",
            map(SIZE, &["1 2 3 4", "1 2 3 4", "1 2 3 4", "1 2 3 -inf"]),
            "line 7: -inf is not a finite number",
        ),
        ("nosize", map("", &GOOD), "no size: add header lines"),
        (
            "unit",
            map("# Width: 4 furlong\n# Height: 4 µm\n", &GOOD),
            "line 1: unknown unit 'furlong'",
        ),
        (
            "few",
            map(SIZE, &["1 2 3", "1 2 3", "3 2 1", "0 0 1"]),
            "3 points along x: at least 4 are needed",
        ),
        (
            "flat",
            map(SIZE, &["2 2 2 2"; 4]),
            "the surface is flat: every height is the same",
        ),
        (
            "uneven",
            "# x z\n0 1e-9\n1e-6 -2e-9\n2e-6 3e-9\n3.5e-6 0\n4e-6 1e-9\n".to_string(),
            "line 5: x is not uniformly spaced",
        ),
        (
            "validity",
            "X;Y;valid\r\n[mm];[mm];[1/0]\r\n0;1.5;1\r\n0.5;1.2;1\r\n1;1.7;2\r\n1.5;1.1;1\r\n"
                .to_string(),
            "line 5: the validity column holds 2: 1 marks a measured point, 0 one not measured",
        ),
        (
            "q-order",
            psd(&|i, q| (if i == 3 { 4e5 } else { q }, q.powf(-3.6))),
            "line 5: q must increase",
        ),
        (
            "c-zero",
            psd(&|i, q| (q, if i == 2 { 0.0 } else { q.powf(-3.6) })),
            "line 4: PSD value 0 at point 3 must be finite and > 0",
        ),
    ];
    let big = dir.path().join("big.txt");
    // Sparse: no disk used.
    std::fs::File::create(&big)
        .unwrap()
        .set_len(rough_surface::MAX_BYTES + 1)
        .unwrap();
    let mut files = vec![(big, "536870913 bytes is too large".to_string())];
    for (name, text, problem) in cases {
        let p = dir.path().join(format!("{name}.txt"));
        std::fs::write(&p, text).unwrap();
        files.push((p, problem.to_string()));
    }
    for (path, problem) in &files {
        let before = std::fs::metadata(path).unwrap().len();
        for cmd in [
            &["export"][..],
            &[][..],
            &["serve", "--listen", "127.0.0.1:0"][..],
        ] {
            let out = Command::new(BIN)
                .args(cmd)
                .arg("--surface")
                .arg(path)
                .stdin(Stdio::null())
                .output()
                .unwrap();
            let err = String::from_utf8(out.stderr).unwrap();
            assert_eq!(
                out.status.code(),
                Some(2),
                "{cmd:?} {}: {err}",
                path.display()
            );
            assert!(out.stdout.is_empty());
            // One line: the file, the line where there is one, the problem.
            let want = format!("roughtui: bad surface {}", path.display());
            assert!(err.starts_with(&want), "{err}");
            assert!(err.contains(problem.as_str()), "wants {problem:?} in {err}");
            assert_eq!(err.lines().count(), 1, "{err}");
        }
        // The file is left as it was.
        assert_eq!(std::fs::metadata(path).unwrap().len(), before);
    }
}

/// A Dektak CSV export and an .hfm profile (three columns a row: empty
/// trailing cells, a validity column) read as line scans through the
/// command line: Rq and RΔq in the moments CSV are SurfaceTopography's on
/// the same values (scripts/profile_columns_reference.py), the .hfm's 33
/// points not measured filled and said.
#[test]
fn three_column_profiles_export_surfacetopographys_numbers() {
    let reference = std::fs::read_to_string(data("profile_columns_reference.txt")).unwrap();
    for (file, tol, note) in [
        (
            "dektak_profile.csv",
            1e-12,
            "read as Windows-1252 (Latin-1) text: line 4 is not UTF-8",
        ),
        (
            "hfm_profile.hfm",
            1e-11,
            "33 points not measured (validity 0) read as undefined",
        ),
    ] {
        let want: Vec<f64> = reference
            .lines()
            .find(|l| l.starts_with(&format!("real {file} ")))
            .unwrap()
            .split_whitespace()
            .skip(2)
            .map(|w| w.parse().unwrap())
            .collect();
        let out = run(&[
            "export",
            "--surface",
            data(file).to_str().unwrap(),
            "--view",
            "moments",
        ]);
        assert_eq!(out.status.code(), Some(0));
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(
            err.starts_with(&format!("roughtui: note: {note}\n")),
            "{file}: {err}"
        );
        let csv = String::from_utf8(out.stdout).unwrap();
        assert!(csv.lines().any(|l| l == format!("# {note}")), "{file}");
        // "# Rq = 1.74e-8 m, RΔq = 0.0081 (real space, …)"
        let line = csv.lines().find(|l| l.starts_with("# Rq = ")).unwrap();
        let rq: f64 = line[7..].split(' ').next().unwrap().parse().unwrap();
        let rdq: f64 = line
            .split("RΔq = ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(
            rel(rq, want[0]) < tol && rel(rdq, want[1]) < tol,
            "{file}: {line} vs {want:?}"
        );
    }
}
