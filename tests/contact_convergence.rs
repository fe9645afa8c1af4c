//! `roughtui export --view contact-convergence`: the scene's load solved on
//! 4, 8 and 16 nodes per shortest wavelength and cells of 1, 2 and 4 longest
//! wavelengths over the seeds. A seed is one surface on every grid, so at a
//! given cell the area falls as the grid refines (a sampled contact patch
//! counts every node it touches), less with each halving; the refusals name
//! the problem.

mod common;
use common::cli::{run, stdout};

#[test]
fn convergence_csv() {
    let csv = stdout(&[
        "export",
        "--view",
        "contact-convergence",
        "--preset",
        "fig2",
        "--set",
        "zeta=8",
        "--seeds",
        "2",
    ]);
    let comments: Vec<&str> = csv.lines().filter(|l| l.starts_with('#')).collect();
    assert!(comments.iter().any(|c| c.contains("p_over_h = 0.01")
        && c.contains("4, 8, 16 nodes per shortest wavelength")
        && c.contains("cells of 1, 2, 4 longest wavelengths")
        && c.contains("seeds 1–2")));
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next().unwrap(),
        "per_wavelength,cell,grid,area,area_sd,elastic_area,plastic_area,plastic_area_sd,\
         plastic_share,plastic_share_sd,iterations,seeds,area_corrected,area_corrected_sd"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 9);
    let row = |k: f64, cell: f64| {
        rows.iter()
            .find(|r| r[0] == k && r[1] == cell)
            .unwrap_or_else(|| panic!("{k} per wavelength, cell {cell}: {rows:?}"))
    };
    for cell in [1.0, 2.0, 4.0] {
        for k in [4.0, 8.0, 16.0] {
            let r = row(k, cell);
            // The power of two with at least k nodes per shortest wavelength
            // (32 at least).
            let need = (k * 8.0 * cell) as usize;
            assert_eq!(r[2] as usize, need.next_power_of_two().max(32), "{r:?}");
            assert!((r[5] + r[6] - r[3]).abs() < 1e-12, "{r:?}");
            assert!(r[3] > 0.0 && r[3] < 0.2 && r[4] > 0.0, "{r:?}");
            assert_eq!(r[11], 2.0);
            // The corrected area: less the overcount along the edge.
            assert!(r[12] < r[3] && r[12] > 0.8 * r[3], "{r:?}");
        }
        let (a4, a8, a16) = (row(4.0, cell)[3], row(8.0, cell)[3], row(16.0, cell)[3]);
        if row(4.0, cell)[2] < row(8.0, cell)[2] {
            assert!(a4 > a8, "cell {cell}: {a4} {a8}");
        }
        assert!(a8 > a16, "cell {cell}: {a8} {a16}");
    }
}

#[test]
fn convergence_refusals() {
    for (extra, needle) in [
        (
            vec!["--cell", "2"],
            "--cell does not apply to --view contact-convergence",
        ),
        (
            vec!["--per-wavelength", "8"],
            "--per-wavelength does not apply",
        ),
        (vec!["--format", "svg"], "a table: CSV only"),
        (vec!["--seeds", "0"], "invalid value '0' for '--seeds <N>'"),
    ] {
        let mut all = vec![
            "export",
            "--view",
            "contact-convergence",
            "--preset",
            "fig2",
            "--set",
            "zeta=8",
        ];
        all.extend(&extra);
        let out = run(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains(needle), "{all:?}: {err}");
        if extra[0] != "--seeds" {
            // One line (clap adds its "--help" hint to its own).
            assert_eq!(err.lines().count(), 1, "{err}");
        }
        assert!(out.stdout.is_empty());
    }
}
