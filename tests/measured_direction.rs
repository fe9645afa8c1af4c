//! `--direction x|y` as a user meets it: the profiles keep the real-space
//! line (Rq and RΔq, and Ra, Rsk, Rku, Rz) in the moments CSV, equal to
//! SurfaceTopography's `Rq` and `Rdq` of the same profiles
//! (`scripts/direction_reference.py`), and ζ, whose largest value is the
//! whole n/2 of a profile, is printed as that number, not with the
//! rounding of q_max/q0 (96, not 96.00000000000001).

mod common;

use std::path::Path;

use common::cli::noted;

/// The `real` rows of direction_reference.txt: x, then y.
fn reference() -> Vec<Vec<f64>> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/direction_reference.txt");
    std::fs::read_to_string(p)
        .unwrap()
        .lines()
        .filter_map(|l| l.strip_prefix("real "))
        .map(|l| l.split_whitespace().map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// The number after `name = ` on the `#` line that starts with `first`.
fn number(csv: &str, first: &str, name: &str) -> f64 {
    let line = csv
        .lines()
        .find(|l| l.starts_with(&format!("# {first} = ")))
        .unwrap_or_else(|| panic!("no {first} line in {csv}"));
    let t = &line[line.find(&format!("{name} = ")).unwrap() + name.len() + 3..];
    let end = t.find([' ', ',']).unwrap_or(t.len());
    t[..end].parse().unwrap()
}

#[test]
fn the_profiles_keep_their_real_space_line() {
    let map =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/rough-surface/tests/data/map_lay.txt");
    let map = map.to_str().unwrap();
    for (d, want) in ["x", "y"].into_iter().zip(reference()) {
        let out = common::cli::run(&[
            "export",
            "--surface",
            map,
            "--direction",
            d,
            "--view",
            "moments",
        ]);
        assert_eq!(out.status.code(), Some(0));
        let csv = String::from_utf8(out.stdout).unwrap();
        let got = [
            number(&csv, "Rq", "Rq"),
            number(&csv, "Rq", "RΔq"),
            number(&csv, "Ra", "Ra"),
            number(&csv, "Ra", "Rsk"),
            number(&csv, "Ra", "Rku"),
            number(&csv, "Ra", "Rz"),
        ];
        for (g, w) in got.iter().zip(&want) {
            assert!(((g - w) / w).abs() < 1e-12, "--direction {d}: {g} vs {w}");
        }
    }
}

#[test]
fn the_largest_zeta_of_profiles_is_printed_whole() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    let out = common::cli::run(&["export", "--surface", example, "--direction", "x"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("\n# zeta = 96  (magnification"), "{text}");
    assert!(
        text.contains("\n# sweep = zeta from 1 to 96, 200 points"),
        "{text}"
    );
    // The last row is at ζ = 96 and holds every profile wavevector: its
    // h_rms is the whole spectrum's.
    let (moments, _) = noted(&[
        "export",
        "--surface",
        example,
        "--direction",
        "x",
        "--view",
        "moments",
        "--points",
        "2",
    ]);
    let last: Vec<&str> = moments.lines().last().unwrap().split(',').collect();
    assert_eq!(last[0], "96");
    let h: f64 = last[6].parse().unwrap();
    let all: f64 = number(&text, "h_rms", "h_rms");
    assert!(((h - all) / all).abs() < 1e-14, "{h} vs {all}");
}
