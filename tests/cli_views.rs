//! `roughtui export --view indices|map|load` and `--format svg`: headers,
//! shapes, overrides and refusals. Accuracy is checked against the mpmath
//! reference in `views_reference.rs`.

use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_roughtui");

fn run(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

fn stdout(args: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    assert!(err.is_empty(), "{err}");
    String::from_utf8(out.stdout).unwrap()
}

fn refused(args: &[&str], words: &[&str]) {
    let out = run(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
}

fn rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect()
}

#[test]
fn indices_header_rows_and_empty_undefined_fields() {
    let t = stdout(&["export", "--view", "indices", "--points", "5"]);
    assert_eq!(
        t.lines().next(),
        Some("x,psi_gw,psi_p,psi_star,psi_star_asymptotic,hardness_ratio")
    );
    let r = rows(&t);
    assert_eq!(r.len(), 5);
    assert_eq!(r[0][0], "1");
    assert_eq!(r[2][0], "100");
    assert_eq!(r[4][0], "10000");
    // fig2 at ζ = 1 with asymptotic moments: Ψ_P = 0.19816636488030044 (mpmath).
    let psi_p: f64 = r[0][2].parse().unwrap();
    assert!((psi_p / 0.19816636488030044 - 1.0).abs() < 1e-13, "{psi_p}");
    // Eq. 13 is undefined without a size-effect length: an empty field.
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("r0.ron");
    std::fs::write(
        &f,
        "(version: 1, name: \"r0\", params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, \
         hurst: 0.8, r_star: 0.0, q0: 100000.0), size_effect: true, \
         sweep: (axis: Zeta, from: 1.0, to: 10000.0), model: Exact)",
    )
    .unwrap();
    let t = stdout(&["export", "--load", f.to_str().unwrap(), "--view", "indices"]);
    let r = rows(&t);
    assert_eq!(r.len(), 200);
    for row in &r {
        assert_eq!(row.len(), 6);
        assert_eq!(row[4], "", "{row:?}");
        assert_eq!(row[5], "1");
        assert_eq!(row[2], row[3], "Ψ* = Ψ_P without R*");
    }
}

#[test]
fn map_header_grid_order_and_ends() {
    let t = stdout(&["export", "--view", "map", "--grid", "4x3"]);
    assert_eq!(
        t.lines().next(),
        Some("x,y,psi,elastic,plastic,total,plastic_share")
    );
    let r = rows(&t);
    assert_eq!(r.len(), 12);
    // x fastest, log-spaced, ends included; y from the bottom up.
    assert_eq!((r[0][0], r[3][0]), ("1", "10000"));
    for (k, row) in r[..4].iter().enumerate() {
        let x: f64 = row[0].parse().unwrap();
        let want = 10f64.powf(4.0 * k as f64 / 3.0);
        assert!((x / want - 1.0).abs() < 1e-15, "{x} vs {want}");
    }
    let ys: Vec<&str> = r.iter().step_by(4).map(|row| row[1]).collect();
    assert_eq!((ys[0], ys[2]), ("0.0001", "0.1"));
    let mid: f64 = ys[1].parse().unwrap();
    assert!((mid / 10f64.powf(-2.5) - 1.0).abs() < 1e-15, "{mid}");
    for row in &r {
        let share: f64 = row[6].parse().unwrap();
        assert!((0.0..=1.0).contains(&share), "{row:?}");
    }
    // The default grid is 50x30; another y axis on request.
    assert_eq!(rows(&stdout(&["export", "--view", "map"])).len(), 1500);
    let t = stdout(&[
        "export", "--view", "map", "--grid", "2x2", "--map-y", "h-rms",
    ]);
    let ys: Vec<&str> = rows(&t).iter().map(|row| row[1]).collect();
    assert_eq!(ys, ["1e-9", "1e-9", "0.00001", "0.00001"]);
}

#[test]
fn load_header_rows_and_ends() {
    let t = stdout(&["export", "--view", "load", "--points", "11"]);
    assert_eq!(t.lines().next(), Some("load,elastic,plastic,total"));
    let r = rows(&t);
    assert_eq!(r.len(), 11);
    assert_eq!(r[0], ["0", "0", "0", "0"]);
    assert_eq!(r[5][0], "0.5");
    assert_eq!(r[10], ["1", "0", "1", "1"]);
    assert_eq!(r[1][0], "0.1");
}

#[test]
fn export_defaults_to_fig2_and_overrides_apply() {
    assert_eq!(
        stdout(&["export", "--points", "7"]),
        stdout(&["export", "--preset", "fig2", "--points", "7"])
    );
    // Size effect on: the hardness ratio column leaves 1.
    let on = stdout(&["export", "--points", "3", "--size-effect", "on"]);
    let hr: f64 = rows(&on)[2][2].parse().unwrap();
    assert!(hr > 1.0, "{hr}");
    let off = stdout(&[
        "export",
        "--preset",
        "fig4",
        "--points",
        "3",
        "--size-effect",
        "off",
    ]);
    assert!(rows(&off).iter().all(|r| r[2] == "1"));
    // Another sweep, printed without rounding noise on exact grids.
    let t = stdout(&["export", "--points", "9", "--sweep", "hurst:0.1:0.9"]);
    let xs: Vec<&str> = rows(&t).iter().map(|r| r[0]).collect();
    assert_eq!(
        xs,
        ["0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9"]
    );
    let t = stdout(&["export", "--points", "4", "--sweep", "zeta:10:1e4"]);
    let xs: Vec<&str> = rows(&t).iter().map(|r| r[0]).collect();
    assert_eq!(xs, ["10", "100", "1000", "10000"]);
}

#[test]
fn options_that_do_not_apply_are_refused() {
    refused(
        &["export", "--view", "map", "--points", "5"],
        &["--points does not apply to --view map", "--grid"],
    );
    for view in ["slopes", "indices", "load"] {
        refused(
            &["export", "--view", view, "--grid", "5x5"],
            &["--grid applies only to --view map", view],
        );
        refused(
            &["export", "--view", view, "--map-y", "zeta"],
            &["--map-y applies only to --view map"],
        );
    }
    refused(
        &["export", "--view", "map", "--map-y", "zeta"],
        &["map y axis zeta is the swept parameter", "h0-over-e"],
    );
    for g in ["1x5", "5x0", "20000x2"] {
        refused(&["export", "--view", "map", "--grid", g], &["out of range"]);
    }
    refused(
        &["export", "--view", "map", "--grid", "5by5"],
        &["COLSxROWS"],
    );
    refused(
        &["export", "--view", "chart"],
        &["'chart'", "slopes, indices, map, load"],
    );
    refused(&["export", "--format", "png"], &["'png'", "csv, svg"]);
    refused(&["export", "--size-effect", "yes"], &["'yes'", "on, off"]);
    refused(&["export", "--sweep", "zeta:1"], &["AXIS:FROM:TO"]);
    refused(
        &["export", "--sweep", "foo:1:2"],
        &["unknown axis 'foo'", "h-rms"],
    );
    refused(&["export", "--sweep", "zeta:1:x"], &["'x' is not a number"]);
    refused(&["export", "--sweep", "zeta:100:10"], &["--sweep", "empty"]);
    refused(&["export", "--sweep", "hurst:0.5:2"], &["--sweep", "hurst"]);
}

#[test]
fn svg_of_every_view_parses_with_labels_legend_and_colours() {
    for (view, words) in [
        (
            "slopes",
            &["elastic", "plastic", "total", "Persson", "ζ"][..],
        ),
        ("indices", &["Ψ_GW", "Ψ_P", "Ψ*", "eq. 13", "ζ"][..]),
        (
            "map",
            &[
                "plastic share",
                "Ψ_P = 1",
                "current point",
                "H0/E",
                "paper sets none",
            ][..],
        ),
        (
            "load",
            &["elastic", "plastic", "total", "initial slope", "p̄/H"][..],
        ),
    ] {
        let svg = stdout(&["export", "--view", view, "--format", "svg"]);
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{view}: {e}"));
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "svg", "{view}");
        let text: String = doc
            .descendants()
            .filter(|n| n.is_text())
            .filter_map(|n| n.text())
            .collect::<Vec<_>>()
            .join("\n");
        for w in words {
            assert!(text.contains(w), "{view}: no {w:?} in the text");
        }
        // The caption and the decade labels of the log axes.
        assert!(text.contains("Fig. 2"), "{view}: caption");
        if view != "load" {
            for d in ["1", "10", "100", "1000", "1e4"] {
                assert!(text.lines().any(|l| l.trim() == d), "{view}: decade {d}");
            }
        }
        let has_colour = |c: &str| svg.contains(c);
        match view {
            "slopes" => {
                for c in ["#000000", "#0000FF", "#FF0000", "#00A000"] {
                    assert!(has_colour(c), "{view}: colour {c}");
                }
            }
            "map" => {
                // Both ends of the scale appear on fig2's map.
                assert!(has_colour("#440154") && has_colour("#FDE725"), "{view}");
                let rects = doc.descendants().filter(|n| n.has_tag_name("rect")).count();
                assert!(rects < 1500, "{rects} rects: runs should merge cells");
            }
            _ => {}
        }
    }
}
