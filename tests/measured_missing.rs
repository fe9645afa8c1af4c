//! Undefined points, contact.engineering's real downloads and anisotropy,
//! through the binary on files written here: a map with `nan` or empty
//! cells reads as the same map with the point filled; more than 10 %
//! undefined is refused with the share; a download with a `nan`
//! standard-error column and several measurements reads its first (named
//! in the caption) or the one `--series` names; a `# Columns:` table
//! without a series name reads by its units; `--direction x` reads a
//! map's profiles as line scans. The numbers themselves are checked
//! against SurfaceTopography in crates/rough-surface/tests
//! (fill_reference.rs, direction_reference.rs).

mod common;

use common::cli::{run, BIN};
use std::path::{Path, PathBuf};

/// Stdout of a successful run (status 0); stderr may carry notes.
fn ok(args: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
    String::from_utf8(out.stdout).unwrap()
}

/// Exit 2, nothing on stdout, each of `words` in the message.
fn refused(args: &[&str], words: &[&str]) {
    let out = run(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
    assert!(!err.contains("panicked"), "{err}");
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p: PathBuf = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

/// The spectrum's table without its `#` lines (they name the file and
/// carry its notes, which differ between the files compared here).
fn spectrum(file: &str, extra: &[&str]) -> String {
    let mut a = vec!["export", "--surface", file, "--view", "spectrum"];
    a.extend_from_slice(extra);
    ok(&a)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect()
}

/// Every number of two CSV texts within `tol` relative (same shape).
fn close(a: &str, b: &str, tol: f64) {
    let (la, lb): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    assert_eq!(la.len(), lb.len());
    assert_eq!(la[0], lb[0]);
    for (x, y) in la.iter().zip(&lb).skip(1) {
        for (u, v) in x.split(',').zip(y.split(',')) {
            // An empty field (the fit outside its band) is empty in both.
            if u.is_empty() || v.is_empty() {
                assert_eq!(u, v, "{x} vs {y}");
                continue;
            }
            let (u, v): (f64, f64) = (u.parse().unwrap(), v.parse().unwrap());
            assert!((u - v).abs() <= tol * v.abs(), "{x} vs {y}");
        }
    }
}

/// A rough 16 × 12 map, heights in nm, `hole` replacing the point (5, 4).
fn map(hole: Option<&str>) -> (String, f64) {
    let h = |i: usize, j: usize| ((i * 7 + j * 13) % 11) as f64 + 0.1 * (i * j) as f64;
    let mut t = String::from("# Width: 16 µm\n# Height: 12 µm\n# Value units: nm\n");
    for j in 0..12 {
        let row: Vec<String> = (0..16)
            .map(|i| match (i, j, hole) {
                (5, 4, Some(s)) => s.to_string(),
                _ => format!("{}", h(i, j)),
            })
            .collect();
        t.push_str(&row.join(","));
        t.push('\n');
    }
    // The harmonic fill of an interior point: its neighbours' mean.
    let mean = (h(4, 4) + h(6, 4) + h(5, 3) + h(5, 5)) / 4.0;
    (t, mean)
}

#[test]
fn undefined_points_are_filled_or_refused() {
    let d = tempfile::tempdir().unwrap();
    let (_, mean) = map(None);
    let (filled, _) = map(Some(&format!("{mean}")));
    let want = spectrum(&write(d.path(), "filled.csv", &filled), &[]);
    for (name, hole) in [("nan.csv", "nan"), ("NaN.csv", "NaN"), ("empty.csv", "")] {
        let (t, _) = map(Some(hole));
        let f = write(d.path(), name, &t);
        close(&spectrum(&f, &[]), &want, 1e-12);
        // Every view reads it.
        ok(&[
            "export",
            "--surface",
            &f,
            "--view",
            "indices",
            "--points",
            "5",
        ]);
    }
    // 20 of 192 undefined: refused with the count and the share.
    let (t, _) = map(None);
    let mut lines: Vec<String> = t.lines().map(String::from).collect();
    lines[4] = vec!["nan"; 16].join(",");
    lines[5] = format!("1,2,3,4{}", ",".repeat(12));
    let f = write(d.path(), "holes.csv", &(lines.join("\n") + "\n"));
    refused(
        &["export", "--surface", &f],
        &[
            "holes.csv",
            "28 of 192 points (14.6 %) are undefined",
            "up to 10 % are filled",
        ],
    );
    // x and PSD values are never undefined.
    let f = write(
        d.path(),
        "psd.txt",
        "# q C\n1e5 1e-20\n1e6 nan\n1e7 1e-26\n1e8 1e-30\n",
    );
    refused(
        &["export", "--surface", &f],
        &["psd.txt, line 3", "an undefined PSD value"],
    );
}

/// A contact.engineering download: a `q/π × 2D PSD` block per measurement,
/// with the standard-error column `nan` as a single measurement writes it.
fn download(names: &[(&str, f64)]) -> String {
    let mut t = String::from("# Power spectrum\n# ==============\n\n");
    for (name, k) in names {
        t.push_str(&format!("# Topography: {name}\n# ==============\n\n"));
        t.push_str("# q/π × 2D PSD\n# ------------\n");
        t.push_str("# Columns: Wavevector (1/m), PSD (m³), standard error of average PSD (m³)\n");
        for e in 0..8 {
            let q = 1e5 * 10f64.powf(0.5 * e as f64);
            let v = k * 1e-20 * (q / 1e5).powf(-2.6);
            t.push_str(&format!("{q:e} {v:e} nan\n"));
        }
        t.push('\n');
    }
    t
}

#[test]
fn contact_engineering_downloads_of_several_measurements() {
    let d = tempfile::tempdir().unwrap();
    let both = write(
        d.path(),
        "both.txt",
        &download(&[("steel", 1.0), ("glass", 2.0)]),
    );
    let steel = write(d.path(), "steel.txt", &download(&[("steel", 1.0)]));
    let glass = write(d.path(), "glass.txt", &download(&[("glass", 2.0)]));
    // The nan column is read past; the first measurement by default.
    let first = spectrum(&both, &[]);
    assert_eq!(first, spectrum(&steel, &[]));
    assert_eq!(
        spectrum(&both, &["--series", "glass"]),
        spectrum(&glass, &[])
    );
    assert_ne!(first, spectrum(&glass, &[]));
    // The caption names the measurement read.
    let svg = ok(&["export", "--surface", &both, "--format", "svg"]);
    assert!(
        svg.contains("(measurement &apos;steel&apos;)"),
        "caption lacks the measurement"
    );
    refused(
        &["export", "--surface", &both, "--series", "brass"],
        &[
            "both.txt",
            "--series 'brass' is not in this download",
            "'steel', 'glass'",
        ],
    );
    let (m, _) = map(None);
    let m = write(d.path(), "map.csv", &m);
    refused(
        &["export", "--surface", &m, "--series", "steel"],
        &[
            "map.csv",
            "--series 'steel' applies to a contact.engineering download",
        ],
    );
}

#[test]
fn a_columns_table_reads_by_its_units() {
    let d = tempfile::tempdir().unwrap();
    let rows: Vec<(f64, f64)> = (0..8)
        .map(|e| {
            let q = 1e5 * 10f64.powf(0.5 * e as f64);
            (q, 1e-30 * (q / 1e5).powf(-3.6))
        })
        .collect();
    let body: String = rows.iter().map(|(q, c)| format!("{q:e} {c:e}\n")).collect();
    let m4 = write(
        d.path(),
        "m4.txt",
        &format!("# Columns: Wavevector (1/m), PSD (m^4)\n{body}"),
    );
    let plain = write(d.path(), "plain.txt", &format!("# q C\n{body}"));
    assert_eq!(spectrum(&m4, &[]), spectrum(&plain, &[]));
    // m³: a profile's C1D, as contact.engineering's "1D PSD along x".
    let m3 = write(
        d.path(),
        "m3.txt",
        &format!("# Columns: Wavevector (1/m), PSD (m³)\n{body}"),
    );
    let along = write(
        d.path(),
        "along.txt",
        &format!("# 1D PSD along x\n# Columns: Wavevector (1/m), PSD (m³)\n{body}"),
    );
    assert_eq!(spectrum(&m3, &[]), spectrum(&along, &[]));
    // The same numbers, areal or profile: other moments, other slopes.
    let slopes = |f: &str| {
        ok(&["export", "--surface", f, "--points", "5"])
            .lines()
            .filter(|l| !l.starts_with('#'))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(slopes(&m3), slopes(&along));
    assert_ne!(slopes(&m3), slopes(&m4));
    let bad = write(
        d.path(),
        "bad.txt",
        &format!("# Columns: Wavevector (1/m), PSD (m^2)\n{body}"),
    );
    refused(
        &["export", "--surface", &bad],
        &["bad.txt, line 1", "m⁴ (areal C^iso) or m³ (profile C1D)"],
    );
}

#[test]
fn direction_reads_a_maps_profiles_as_line_scans() {
    let d = tempfile::tempdir().unwrap();
    // Every row the same profile f(x), plus a tilt along y: its profiles
    // along x are the line scan of f.
    let f = |i: usize| ((i * 7) % 11) as f64 + (0.3 * i as f64).sin();
    let (n, rows) = (64, 12);
    let mut map = String::from("# Width: 6.4 µm\n# Height: 1.2 µm\n# Value units: nm\n");
    let mut line = String::from("# Width: 6.4 µm\n# Value units: nm\n");
    for j in 0..rows {
        let r: Vec<String> = (0..n)
            .map(|i| format!("{}", f(i) + 0.5 * j as f64))
            .collect();
        map.push_str(&(r.join(" ") + "\n"));
    }
    let r: Vec<String> = (0..n).map(|i| format!("{}", f(i))).collect();
    line.push_str(&(r.join(" ") + "\n"));
    let map = write(d.path(), "lay.txt", &map);
    let line = write(d.path(), "line.txt", &line);
    close(
        &spectrum(&map, &["--direction", "x"]),
        &spectrum(&line, &[]),
        1e-10,
    );
    let svg = ok(&[
        "export",
        "--surface",
        &map,
        "--direction",
        "x",
        "--format",
        "svg",
    ]);
    assert!(
        svg.contains("profiles along x"),
        "caption lacks the direction"
    );
    refused(
        &["export", "--surface", &line, "--direction", "y"],
        &[
            "line.txt",
            "--direction y applies to a map, not to a line scan",
        ],
    );
    refused(&["export", "--direction", "x"], &["--surface"]);
    assert!(Path::new(BIN).exists());
}
