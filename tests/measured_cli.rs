//! `--surface`, `--periodic`, `--pixel-size` and `--set` on the command
//! line: a power-law PSD table equal to fig2's spectrum reproduces
//! `--preset fig2 --moments truncated` within 1e-12 in every column; the
//! spectrum view's CSV and SVG; every refusal exits 2 with one message.

mod common;

use common::cli::{stdout, BIN};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Exit 2, nothing on stdout, and each of `words` in the one message.
fn refused<S: AsRef<std::ffi::OsStr> + std::fmt::Debug>(args: &[S], words: &[&str]) {
    let out = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
    assert!(!err.contains("panicked"), "{err}");
}

/// fig2's spectrum as a PSD table in SurfaceTopography's convention,
/// C^iso = (2π)² Z q^(−2(1+H)) with Z = 1e-8, H = 0.8, one point per decade
/// from q0 = 1e5 to 1e9 (so ζ runs to 1e4, fig2's sweep).
fn fig2_table(dir: &Path) -> PathBuf {
    let mut text = String::from("# fig2's power law: q (1/m), C^iso (m^4)\n");
    for e in 5..=9 {
        let q = 10f64.powi(e);
        let c = (2.0 * std::f64::consts::PI).powi(2) * 1e-8 * q.powf(-2.0 * (1.0 + 0.8));
        text.push_str(&format!("{q:e} {c:e}\n"));
    }
    let p = dir.join("fig2-psd.txt");
    std::fs::write(&p, text).unwrap();
    p
}

/// A CSV export's header and rows; the `#` lines (the scene) skipped.
fn table(csv: &str) -> (Vec<String>, Vec<Vec<Option<f64>>>) {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|f| (!f.is_empty()).then(|| f.parse::<f64>().unwrap()))
                .collect()
        })
        .collect();
    (header, rows)
}

/// Every field of `got` within `tol` relative of `want` (equal when either
/// is 0 or infinite); returns the largest deviation.
fn agree(got: &str, want: &str, skip: &[&str], tol: f64) -> f64 {
    let (hg, rg) = table(got);
    let (hw, rw) = table(want);
    assert_eq!(hg, hw);
    assert_eq!(rg.len(), rw.len());
    let mut worst = 0.0f64;
    for (i, (a, b)) in rg.iter().zip(&rw).enumerate() {
        for (k, name) in hg.iter().enumerate() {
            if skip.contains(&name.as_str()) {
                continue;
            }
            let (x, y) = (a[k].unwrap(), b[k].unwrap());
            let d = if x == y { 0.0 } else { ((x - y) / y).abs() };
            assert!(
                d <= tol,
                "row {i} {name}: got {x:e}, want {y:e}, rel {d:e} > {tol:e}"
            );
            worst = worst.max(d);
        }
    }
    worst
}

#[test]
fn a_power_law_table_reproduces_fig2_truncated_in_every_column() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let t = t.to_str().unwrap();
    // fig2 is closed form without size effect: the same on the surface
    // (which opens with the paper's material, exact model, size effect on).
    let fig2 = |extra: &[&str]| {
        let mut a = vec!["export", "--preset", "fig2", "--moments", "truncated"];
        a.extend_from_slice(extra);
        stdout(&a)
    };
    let surface = |extra: &[&str]| {
        let mut a = vec!["export", "--surface", t];
        a.extend_from_slice(extra);
        stdout(&a)
    };
    let mut worst = 0.0f64;
    for (model, se) in [
        ("closed-form", "off"),
        ("closed-form", "on"),
        ("exact", "off"),
        ("exact", "on"),
    ] {
        let o = ["--model", model, "--size-effect", se];
        worst = worst.max(agree(&surface(&o), &fig2(&o), &[], 1e-12));
        let mut v = o.to_vec();
        v.extend(["--view", "indices"]);
        // Eq. 13 is a power law's: empty on a measured surface.
        let s = surface(&v);
        let rows = s.lines().filter(|l| !l.starts_with('#')).skip(1);
        assert!(rows.clone().count() > 2);
        assert!(rows.into_iter().all(|l| l.split(',').nth(4) == Some("")));
        worst = worst.max(agree(&s, &fig2(&v), &["psi_star_asymptotic"], 1e-12));
        let mut v = o.to_vec();
        v.extend(["--view", "map", "--grid", "20x12"]);
        worst = worst.max(agree(&surface(&v), &fig2(&v), &[], 1e-12));
    }
    // The load view at ζ = 128, the preset's marker.
    let o = ["--model", "exact", "--size-effect", "on", "--view", "load"];
    let mut s = o.to_vec();
    s.extend(["--set", "zeta=128"]);
    worst = worst.max(agree(&surface(&s), &fig2(&o), &[], 1e-12));
    eprintln!("fig2 table against fig2 truncated: largest deviation {worst:e}");
}

#[test]
fn the_spectrum_view_as_csv_and_svg() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let t = t.to_str().unwrap();
    let csv = stdout(&[
        "export",
        "--surface",
        t,
        "--view",
        "spectrum",
        "--set",
        "zeta=100",
    ]);
    let (h, rows) = table(&csv);
    assert_eq!(h, ["q", "psd", "fit"]);
    assert_eq!(rows.len(), 5);
    // The fit band found is the whole table (a power law throughout), and
    // the fit over it is fig2's power law, whatever the cutoff.
    for r in &rows {
        let (q, psd, fit) = (r[0].unwrap(), r[1].unwrap(), r[2].unwrap());
        assert!((fit / psd - 1.0).abs() < 1e-12, "{q}: {fit} {psd}");
    }
    let svg = stdout(&[
        "export",
        "--surface",
        t,
        "--view",
        "spectrum",
        "--format",
        "svg",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    // The picture's texts, a caption's wrapped lines joined again.
    let texts = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ");
    for w in [
        "fig2-psd — spectrum",
        "exact · measured moments · size effect on",
        "C^iso (m⁴)",
        "power law fitted over the fit band 1e5…1e9 /m: H = 0.8 ± ",
        "h_rms of the fitted power law 19.82 nm (5 points)",
        "cutoff q1 = ζ q0 = 1e9 /m (ζ = 1e4)",
    ] {
        assert!(texts.contains(w), "{w}: {texts}");
    }
    for view in ["slopes", "indices", "map", "load"] {
        let svg = stdout(&["export", "--surface", t, "--view", view, "--format", "svg"]);
        roxmltree::Document::parse(&svg).unwrap();
        assert!(svg.contains("measured moments"), "{view}");
    }
}

#[test]
fn set_takes_units_on_presets_and_surfaces() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let t = t.to_str().unwrap();
    // --set gives what a snapshot with those values gives.
    let snap = d.path().join("s.ron");
    std::fs::write(
        &snap,
        "(version: 1, name: \"s\", params: (h0_over_e: 0.001, h_rms: 2e-8, zeta: 128.0, \
         hurst: 0.8, r_star: 0.0005, q0: 100000.0), size_effect: true, \
         sweep: (axis: Zeta, from: 1.0, to: 10000.0), model: Exact)",
    )
    .unwrap();
    let want = stdout(&["export", "--load", snap.to_str().unwrap(), "--points", "7"]);
    let got = stdout(&[
        "export",
        "--preset",
        "fig4",
        "--set",
        "h0-over-e=0.001",
        "--set",
        "r-star=0.5mm",
        "--set",
        "h-rms=20 nm",
        "--set",
        "hurst=0.8",
        "--sweep",
        "zeta:1:1e4",
        "--set",
        "zeta=128",
        "--model",
        "exact",
        "--moments",
        "truncated",
        "--points",
        "7",
    ]);
    // The same scene line for line, but for its name (the first line).
    assert_eq!(
        got.lines().nth(1),
        Some("# h0_over_e = 0.001  (H0/E: macroscopic hardness over E, the composite modulus E*)")
    );
    assert!(
        got.lines().skip(1).eq(want.lines().skip(1)),
        "{got}\n{want}"
    );
    // On a surface: H0/E and R* move the curves, ζ the marker.
    let base = stdout(&["export", "--surface", t, "--points", "5"]);
    let soft = stdout(&[
        "export",
        "--surface",
        t,
        "--points",
        "5",
        "--set",
        "h0-over-e=1e-3",
    ]);
    assert_ne!(base, soft);
    let (_, b) = table(&base);
    let (_, s) = table(&soft);
    // Without the size effect Ψ ∝ 1/(H0/E): ten times larger.
    let (_, b0) = table(&stdout(&[
        "export",
        "--surface",
        t,
        "--points",
        "5",
        "--size-effect",
        "off",
    ]));
    let (_, s0) = table(&stdout(&[
        "export",
        "--surface",
        t,
        "--points",
        "5",
        "--size-effect",
        "off",
        "--set",
        "h0-over-e=0.001",
    ]));
    let r = s0[3][1].unwrap() / b0[3][1].unwrap();
    assert!((r - 10.0).abs() < 1e-12, "{r}");
    assert!(s[3][1].unwrap() > b[3][1].unwrap());
    // The explorer and serve take --set too (refusals checked below).
    refused(
        &["--preset", "fig2", "--set", "zeta=0.5"],
        &["--set zeta=0.5", "out of range"],
    );
}

#[test]
fn every_refusal_exits_2_with_one_message() {
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let t = t.to_str().unwrap();
    let bad = d.path().join("bad.txt");
    std::fs::write(&bad, "1e5 1e-20\n1e6 x\n").unwrap();
    let bad = bad.to_str().unwrap();
    let missing = d.path().join("nope.txt");
    let missing = missing.to_str().unwrap();
    for cmd in [
        &["export"][..],
        &[][..],
        &["serve", "--listen", "127.0.0.1:0"][..],
    ] {
        let with = |rest: &[&str]| -> Vec<String> {
            cmd.iter().chain(rest).map(|s| s.to_string()).collect()
        };
        refused(
            &with(&["--surface", bad]),
            &["bad surface", "bad.txt", "line 2", "'x' is not a number"],
        );
        refused(&with(&["--surface", missing]), &["nope.txt", "cannot read"]);
        refused(
            &with(&["--surface", t, "--set", "h-rms=20nm"]),
            &["--set h-rms=20nm", "not a parameter of a measured surface"],
        );
        refused(
            &with(&["--surface", t, "--set", "hurst=0.5"]),
            &["--set hurst=0.5", "H is not a parameter"],
        );
        refused(
            &with(&["--surface", t, "--set", "zeta=2e4"]),
            &["ζ = 20000 is beyond the data", "largest ζ is 10000"],
        );
        refused(
            &with(&["--preset", "fig2", "--set", "hurst=1.5"]),
            &["--set hurst=1.5", "H = 1.5 is out of range"],
        );
        refused(
            &with(&["--preset", "fig2", "--set", "hurst=1"]),
            &["--set hurst=1", "H = 1 needs truncated moments"],
        );
        refused(&with(&["--set", "zeta=3nm"]), &["--set", "ζ takes no unit"]);
        refused(&with(&["--set", "eta=3"]), &["unknown parameter 'eta'"]);
        refused(&with(&["--set", "zeta"]), &["must be AXIS=VALUE"]);
        refused(&with(&["--periodic"]), &["--surface"]);
        refused(
            &with(&["--surface", t, "--pixel-size", "3ft"]),
            &["--pixel-size", "unknown unit \"ft\""],
        );
        refused(
            &with(&["--surface", t, "--pixel-size", "-1nm"]),
            &["--pixel-size", "not a length > 0"],
        );
        refused(
            &with(&["--surface", t, "--preset", "fig2"]),
            &["cannot be used with"],
        );
    }
    refused(
        &["export", "--surface", t, "--moments", "asymptotic"],
        &["--moments does not apply to a measured surface"],
    );
    refused(
        &["export", "--preset", "fig2", "--view", "spectrum"],
        &["spectrum view shows a measured surface's data", "--surface"],
    );
    refused(
        &[
            "export",
            "--surface",
            t,
            "--view",
            "spectrum",
            "--points",
            "9",
        ],
        &["--points does not apply to --view spectrum"],
    );
    refused(
        &["export", "--surface", t, "--sweep", "hurst:0.1:0.9"],
        &["H is not a parameter of a measured surface"],
    );
    refused(
        &["export", "--surface", t, "--sweep", "zeta:1:1e5"],
        &["ζ = 100000 is beyond the data"],
    );
    refused(
        &[
            "export",
            "--surface",
            t,
            "--view",
            "map",
            "--map-y",
            "h-rms",
        ],
        &["map y axis h-rms is not a parameter of a measured surface"],
    );
}

/// A file of rough-surface's test data (SurfaceTopography's
/// fourier_synthesis surfaces).
fn data(name: &str) -> String {
    format!(
        "{}/crates/rough-surface/tests/data/{name}",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn options_that_read_a_surface_apply_to_samples_only() {
    // A windowed map read as periodic has other moments.
    let map = data("map_windowed.txt");
    let plain = stdout(&["export", "--surface", &map, "--points", "3"]);
    let periodic = stdout(&["export", "--surface", &map, "--points", "3", "--periodic"]);
    assert_ne!(plain, periodic);
    // A header-less map needs its spacing, and takes it.
    let bare = data("map_pixel.txt");
    refused(
        &["export", "--surface", &bare],
        &["map_pixel.txt", "no size", "--pixel-size"],
    );
    stdout(&[
        "export",
        "--surface",
        &bare,
        "--pixel-size",
        "50nm",
        "--height-unit",
        "m",
    ]);
    // A PSD table has no samples to window or space: refused with them.
    let d = tempfile::tempdir().unwrap();
    let t = fig2_table(d.path());
    let t = t.to_str().unwrap();
    for opt in [&["--periodic"][..], &["--pixel-size", "50nm"][..]] {
        let args: Vec<&str> = ["export", "--surface", t]
            .iter()
            .chain(opt)
            .copied()
            .collect();
        refused(&args, &["fig2-psd.txt", "do not apply to a PSD table"]);
    }
}
