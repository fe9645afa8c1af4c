//! Units are never guessed silently: heights without a value unit take
//! the lateral unit and say so (on stderr and as a CSV comment), column
//! headers with units are read, `--height-unit` overrides the file, and
//! numbers that look like a unit mistake earn a warning — never a refusal.

mod common;

use common::cli::{noted, run};
use std::path::Path;

/// Heights of a small rough map, rows of `nx` (a fixed pseudo-random walk,
/// about unit size).
fn heights(nx: usize, ny: usize) -> Vec<f64> {
    let mut s = 12345u64;
    let mut h = Vec::with_capacity(nx * ny);
    for _ in 0..ny {
        let mut v = 0.0;
        for _ in 0..nx {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            v += (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            h.push(v);
        }
    }
    h
}

fn write_map(dir: &Path, name: &str, header: &str, scale: f64) -> String {
    let (nx, ny) = (16, 12);
    let h = heights(nx, ny);
    let mut t = String::from(header);
    for row in h.chunks(nx) {
        let r: Vec<String> = row.iter().map(|v| format!("{:e}", v * scale)).collect();
        t.push_str(&r.join(" "));
        t.push('\n');
    }
    let p = dir.join(name);
    std::fs::write(&p, t).unwrap();
    p.to_str().unwrap().to_string()
}

/// The moments CSV's rows (ζ … r_s), comments dropped.
fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect()
}

fn close(a: &[Vec<f64>], b: &[Vec<f64>], tol: f64) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        for (u, v) in x.iter().zip(y) {
            assert!((u - v).abs() <= tol * v.abs(), "{u} vs {v}");
        }
    }
}

fn moments(file: &str, more: &[&str]) -> (String, Vec<String>) {
    let mut a = vec![
        "export",
        "--surface",
        file,
        "--view",
        "moments",
        "--points",
        "5",
    ];
    a.extend_from_slice(more);
    let (csv, mut notes) = noted(&a);
    // The small maps written here are not isotropic; their anisotropy note
    // is tested with the lay in measured_missing.rs.
    notes.retain(|n| !n.starts_with("anisotropic"));
    (csv, notes)
}

#[test]
fn heights_without_a_value_unit_take_the_widths_and_say_so() {
    let d = tempfile::tempdir().unwrap();
    let size = "# Width: 5 um\n# Height: 3.75 um\n";
    let bare = write_map(d.path(), "bare.txt", size, 1.0);
    let said = write_map(
        d.path(),
        "said.txt",
        &format!("{size}# Value units: um\n"),
        1.0,
    );
    let (a, notes) = moments(&bare, &[]);
    assert_eq!(
        notes,
        ["heights read in µm (the width's unit; --height-unit to change)"]
    );
    let (b, none) = moments(&said, &[]);
    assert!(none.is_empty(), "{none:?}");
    assert_eq!(rows(&a), rows(&b));
    // h_rms in µm, not metres: SurfaceTopography's one unit per topography.
    let h = rows(&a).last().unwrap()[6];
    assert!(h > 1e-7 && h < 1e-5, "{h}");
    // --height-unit overrides the file; where it overrules a value unit,
    // that is said.
    let (c, quiet) = moments(&bare, &["--height-unit", "nm"]);
    assert!(quiet.is_empty(), "{quiet:?}");
    let (hc, ha) = (rows(&c).last().unwrap()[3], rows(&a).last().unwrap()[3]);
    assert!((hc / ha / 1e-6 - 1.0).abs() < 1e-12, "m0 {hc} vs {ha}");
    let (_, over) = moments(&said, &["--height-unit", "nm"]);
    assert_eq!(
        over,
        ["heights read in nm (--height-unit; the file says µm)"]
    );
    // The explorer and serve take it too; an unknown unit is refused.
    let out = run(&["export", "--surface", &bare, "--height-unit", "furlong"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("\"furlong\" is not a length unit"), "{err}");
    let out = run(&["--surface", &bare, "--height-unit", "parsec"]);
    assert_eq!(out.status.code(), Some(2));
    // A PSD table holds no heights.
    let psd = d.path().join("psd.txt");
    std::fs::write(&psd, "# q C\n1e5 1e-20\n1e6 1e-24\n1e7 1e-28\n1e8 1e-32\n").unwrap();
    let out = run(&[
        "export",
        "--surface",
        psd.to_str().unwrap(),
        "--height-unit",
        "nm",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("does not apply to a PSD table"));
}

#[test]
fn column_headers_with_units_are_read() {
    let d = tempfile::tempdir().unwrap();
    let n = 64;
    let z: Vec<f64> = heights(n, 1).iter().map(|v| v * 1e-8).collect();
    let dx = 2e-7;
    let write = |name: &str, header: &str, sx: f64, sz: f64| {
        let mut t = format!("{header}\n");
        let sep = if header.contains(',') { "," } else { " " };
        for (i, v) in z.iter().enumerate() {
            t.push_str(&format!("{:e}{sep}{:e}\n", i as f64 * dx * sx, v * sz));
        }
        let p = d.path().join(name);
        std::fs::write(&p, t).unwrap();
        p.to_str().unwrap().to_string()
    };
    let metres = write("m.txt", "# x z", 1.0, 1.0);
    let (want, notes) = moments(&metres, &[]);
    assert_eq!(
        notes,
        [
            "x read in m (the file names no unit; --lateral-unit to change)",
            "heights read in m (the file names no unit; --height-unit to change)"
        ]
    );
    // x and z written in µm without a unit: --lateral-unit says x's, and
    // the heights follow it (--height-unit alone would change the slope
    // a millionfold).
    let microns = write("um.txt", "# x z", 1e6, 1e6);
    let (got, notes) = moments(&microns, &["--lateral-unit", "um"]);
    assert_eq!(
        notes,
        [
            "x read in µm (--lateral-unit)",
            "heights read in µm (the x column's unit; --height-unit to change)"
        ]
    );
    close(&rows(&got), &rows(&want), 1e-12);
    let (got, _) = moments(
        &microns,
        &["--lateral-unit", "microns", "--height-unit", "um"],
    );
    close(&rows(&got), &rows(&want), 1e-12);
    // On a height matrix its header says the sizes' unit.
    let map = write_map(
        d.path(),
        "map.txt",
        "# Width: 5 um\n# Height: 3.75 um\n",
        1.0,
    );
    let out = run(&["export", "--surface", &map, "--lateral-unit", "nm"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--lateral-unit nm applies to an x z line scan and to files that give no lateral unit, not to a height matrix"),
        "{err}"
    );
    for (name, header) in [
        ("paren.txt", "x (mm),z (um)"),
        ("bracket.txt", "x [mm]  z [µm]"),
        ("slash.txt", "# x/mm z/um"),
    ] {
        let f = write(name, header, 1e3, 1e6);
        let (got, notes) = moments(&f, &[]);
        assert!(notes.is_empty(), "{header}: {notes:?}");
        close(&rows(&got), &rows(&want), 1e-12);
    }
    // A unit for x only: the heights take it, and say so.
    let f = write("xonly.txt", "x (um),z", 1e6, 1e6);
    let (got, notes) = moments(&f, &[]);
    assert_eq!(
        notes,
        ["heights read in µm (the x column's unit; --height-unit to change)"]
    );
    close(&rows(&got), &rows(&want), 1e-12);
    // An unknown unit in the header is refused with its line.
    let f = write("bad.txt", "x (mm),z (furlong)", 1e3, 1.0);
    let out = run(&["export", "--surface", &f]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 1: unknown unit 'furlong'"), "{err}");
}

#[test]
fn a_likely_unit_mistake_is_a_warning_not_a_refusal() {
    let d = tempfile::tempdir().unwrap();
    let size = "# Width: 5 um\n# Height: 3.75 um\n# Value units: m\n";
    // Heights written in nm but labelled metres: h_rms of metres.
    let big = write_map(d.path(), "big.txt", size, 50.0);
    let (csv, notes) = moments(&big, &[]);
    assert!(!rows(&csv).is_empty());
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(
        notes[0].starts_with("warning: rms slope") && notes[0].contains("above 10"),
        "{notes:?}"
    );
    // Heights of picometres over micrometres: the slope is below 1e-5.
    let small = write_map(d.path(), "small.txt", size, 1e-14);
    let (_, notes) = moments(&small, &[]);
    assert!(notes[0].contains("below 1e-5"), "{notes:?}");
    // h_rms above 1 mm with a moderate slope (a 5 m wide map).
    let wide = "# Width: 5 m\n# Height: 3.75 m\n# Value units: mm\n";
    let f = write_map(d.path(), "wide.txt", wide, 1e3);
    let (_, notes) = moments(&f, &[]);
    assert!(notes[0].contains("mm is above 1 mm"), "{notes:?}");
}
