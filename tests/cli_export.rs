//! `roughtui export`: the CSV contract of every view, the SVG pictures and
//! the usage errors. Accuracy against the mpmath reference is checked in
//! `views_reference.rs`.

mod common;

use common::cli::{run, stdout, BIN};
use std::io::Read;
use std::process::{Command, Output, Stdio};

const HEADER: &str = "zeta,psi,h_use_over_h0,elastic,plastic,total,persson_elastic";

/// A CSV export without its `#` lines (the scene), header first.
fn body(text: &str) -> String {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect()
}

/// The header: the first line that is not a `#` line.
fn header(text: &str) -> Option<&str> {
    text.lines().find(|l| !l.starts_with('#'))
}

/// A snapshot file `name.ron` in `dir` with fig2's surface and these
/// fields changed: (hurst, r_star, size_effect).
fn snapshot_file(dir: &std::path::Path, name: &str, hurst: f64, r_star: f64, se: bool) -> String {
    let path = dir.join(format!("{name}.ron"));
    std::fs::write(
        &path,
        format!(
            "(version: 1, name: \"{name}\", params: (h0_over_e: 0.01, h_rms: 2e-8, \
             zeta: 128.0, hurst: {hurst:?}, r_star: {r_star:?}, q0: 100000.0), \
             size_effect: {se}, sweep: (axis: Zeta, from: 1.0, to: 10000.0), model: Exact)"
        ),
    )
    .unwrap();
    path.to_str().unwrap().to_string()
}

fn usage_error(args: &[&str], words: &[&str]) {
    let out = run(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line, {err}");
    assert!(out.stdout.is_empty());
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
}

#[test]
fn default_is_200_points_with_both_ends() {
    let out = run(&["export", "--preset", "fig2"]);
    assert_eq!(out.status.code(), Some(0));
    let text = body(&String::from_utf8(out.stdout).unwrap());
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], HEADER);
    assert_eq!(lines.len(), 201);
    // fig2 sweeps ζ from 1 to 1e4 with the paper's asymptotic moments, so
    // ψ stays finite at ζ = 1: (E/H0)·√(m2/2) = 0.19816636488030044 (mpmath).
    let first: Vec<f64> = lines[1].split(',').map(|f| f.parse().unwrap()).collect();
    assert_eq!(first[0], 1.0);
    assert!(
        (first[1] / 0.19816636488030044 - 1.0).abs() < 1e-13,
        "{}",
        lines[1]
    );
    assert_eq!(first[2], 1.0);
    assert!(lines[200].starts_with("10000,"), "{}", lines[200]);
    for l in &lines[1..] {
        assert_eq!(l.split(',').count(), 7, "{l}");
        for f in l.split(',') {
            let v: f64 = f.parse().unwrap();
            assert!(!v.is_nan(), "{l}");
        }
    }
}

#[test]
fn model_override_changes_the_slopes() {
    let base = ["export", "--preset", "fig2", "--points", "3"];
    let closed = run(&base);
    let exact = run(&[&base[..], &["--model", "exact"]].concat());
    assert_eq!(exact.status.code(), Some(0));
    let (e, c) = (
        body(&String::from_utf8(exact.stdout).unwrap()),
        body(&String::from_utf8(closed.stdout).unwrap()),
    );
    assert_eq!(e.lines().count(), 4);
    // Same moments, so the same ψ; another model, other slopes.
    let psi = |t: &str| {
        t.lines()
            .nth(2)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .to_owned()
    };
    assert_eq!(psi(&e), psi(&c));
    assert_ne!(e.lines().nth(2), c.lines().nth(2));
}

#[test]
fn moments_override_changes_psi() {
    // At ζ = 100 the paper's asymptotic moments give Ψ_P = 0.49777140312440325
    // (mpmath); the truncated spectrum's exact moments give less, and ψ = 0
    // at ζ = 1 where there is no roughness left.
    let base = ["export", "--preset", "fig2", "--points", "3"];
    let field = |out: Output, row: usize| -> f64 {
        assert_eq!(out.status.code(), Some(0));
        let text = body(&String::from_utf8(out.stdout).unwrap());
        text.lines()
            .nth(row)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse()
            .unwrap()
    };
    let asymptotic = field(run(&base), 2);
    assert!(
        (asymptotic / 0.49777140312440325 - 1.0).abs() < 1e-13,
        "{asymptotic}"
    );
    let truncated = run(&[&base[..], &["--moments", "truncated"]].concat());
    assert_eq!(field(truncated, 1), 0.0);
    let truncated = field(run(&[&base[..], &["--moments", "truncated"]].concat()), 2);
    assert!(truncated < asymptotic && truncated > 0.4, "{truncated}");
}

#[test]
fn usage_errors_exit_2_with_a_message() {
    usage_error(
        &["export", "--preset", "fig2", "--moments", "asimptotic"],
        &["--moments", "asimptotic", "asymptotic"],
    );
    // Every bad count gets the same message, negative and huge ones too.
    for bad in ["0", "1", "-5", "1e9", "abc", "10000001"] {
        usage_error(
            &["export", "--preset", "fig2", "--points", bad],
            &[
                &format!("invalid value '{bad}' for '--points <N>'"),
                "must be a whole number from 2 to 10000000",
            ],
        );
    }
    usage_error(
        &["export", "--preset", "fig2", "--model", "foo"],
        &["'foo'", "exact, closed-form"],
    );
    usage_error(
        &["export", "--preset", "fig2", "--load", "x.ron"],
        &["cannot be used with"],
    );
    usage_error(
        &["export", "--preset", "fig9"],
        &["unknown preset 'fig9'", "fig1, fig2, fig3, fig4"],
    );
}

#[test]
fn a_closed_stdout_is_not_a_crash() {
    // Like `roughtui export … | head -1`: the reader goes away early.
    let mut child = Command::new(BIN)
        .args(["export", "--preset", "fig4", "--points", "200000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 10];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    assert_eq!(&first, b"# roughtui");
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert_eq!(err, "");
}

#[test]
fn asymptotic_moments_at_hurst_one_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = &snapshot_file(dir.path(), "h1", 1.0, 0.001, false);
    assert_eq!(
        run(&["export", "--load", file, "--points", "2"])
            .status
            .code(),
        Some(0)
    );
    usage_error(
        &[
            "export",
            "--load",
            file,
            "--points",
            "2",
            "--moments",
            "asymptotic",
        ],
        &["hurst = 1", "moments", "Truncated"],
    );
}

fn rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect()
}

#[test]
fn indices_header_rows_and_empty_undefined_fields() {
    let t = stdout(&["export", "--view", "indices", "--points", "5"]);
    assert_eq!(
        header(&t),
        Some("zeta,psi_gw,psi_p,psi_star,psi_star_asymptotic,hy_over_h0")
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
    let f = snapshot_file(dir.path(), "r0", 0.8, 0.0, true);
    let t = stdout(&["export", "--load", &f, "--view", "indices"]);
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
        header(&t),
        Some("zeta,h0_over_e,psi,elastic,plastic,total,plastic_share")
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
    assert_eq!(header(&t), Some("load,elastic,plastic,total"));
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
fn a_picture_of_a_changed_scene_drops_the_saved_caption() {
    let svg = |args: &[&str]| stdout(&[&["export", "--format", "svg"][..], args].concat());
    assert!(svg(&[]).contains("Fig. 2: slopes against magnification"));
    for changed in [
        &["--size-effect", "on"][..],
        &["--sweep", "zeta:1:1e6"],
        &["--model", "exact"],
        &["--moments", "truncated"],
    ] {
        let t = svg(changed);
        assert!(!t.contains("Fig. 2:"), "{changed:?}");
        assert!(t.contains("fig2 — initial slopes"), "{changed:?}");
    }
    // Setting what the preset already has changes nothing.
    assert!(svg(&["--size-effect", "off"]).contains("Fig. 2:"));
}

#[test]
fn a_picture_carries_the_claims_under_its_caption() {
    // Text lines of an SVG with their y, in document order.
    let texts = |svg: &str| -> Vec<(String, f64)> {
        let doc = roxmltree::Document::parse(svg).unwrap();
        doc.descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(|n| {
                let y = n
                    .attribute("y")
                    .and_then(|y| y.parse().ok())
                    .unwrap_or(-1.0);
                (n.text().unwrap_or("").to_string(), y)
            })
            .collect()
    };
    let fig1 = texts(&stdout(&["export", "--preset", "fig1", "--format", "svg"]));
    let at = |t: &[(String, f64)], what: &str| {
        t.iter()
            .find(|(s, _)| s.contains(what))
            .unwrap_or_else(|| panic!("no {what:?} in {t:?}"))
            .1
    };
    let caption = at(&fig1, "Fig. 1: the paper calls realistic hardness");
    let share = at(
        &fig1,
        "plastic share falls below ½ at H0/E = 0.008318 (E/H0 = 120.2)",
    );
    let minimum = at(&fig1, "total slope's minimum 0.9796 at H0/E = 0.003678");
    assert!(caption < share && share < minimum);
    // Each picture its own claims: the index's crossing under the
    // indices, not under the slopes; the share and the crossing under the
    // map, along the current parameters' row.
    let psi = "Ψ_P falls below 1 at H0/E = 0.00523 (E/H0 = 191.2)";
    assert!(!fig1.iter().any(|(s, _)| s.contains(psi)));
    let indices = texts(&stdout(&[
        "export", "--preset", "fig1", "--view", "indices", "--format", "svg",
    ]));
    at(&indices, psi);
    assert!(!indices
        .iter()
        .any(|(s, _)| s.contains("plastic share") && !s.starts_with("Plasticity")));
    let map = texts(&stdout(&[
        "export", "--preset", "fig1", "--view", "map", "--format", "svg",
    ]));
    at(
        &map,
        "along ζ = 128: plastic share falls below ½ at H0/E = 0.008318",
    );
    at(&map, psi);
    assert!(!map.iter().any(|(s, _)| s.contains("total slope's minimum")));
    // Every line inside the picture (the caption area grows to hold them).
    assert!(fig1.iter().all(|(_, y)| *y < 600.0), "{fig1:?}");
    let fig3 = texts(&stdout(&["export", "--preset", "fig3", "--format", "svg"]));
    at(&fig3, "total slope's minimum 3.91 at ζ = 3.191");
    // Claims hold for the scene drawn: truncated moments move fig3's
    // minimum to ζ = 7.763, within the first decade where the truncation
    // of the moments, not the model, makes it: not claimed.
    let truncated = stdout(&[
        "export",
        "--preset",
        "fig3",
        "--format",
        "svg",
        "--moments",
        "truncated",
    ]);
    let t = texts(&truncated);
    assert!(!t.iter().any(|(s, _)| s.contains("minimum")), "{t:?}");
}

#[test]
fn options_that_do_not_apply_are_refused() {
    usage_error(
        &["export", "--view", "map", "--points", "5"],
        &["--points does not apply to --view map", "--grid"],
    );
    for view in ["slopes", "indices", "load"] {
        usage_error(
            &["export", "--view", view, "--grid", "5x5"],
            &["--grid applies only to --view map", view],
        );
        usage_error(
            &["export", "--view", view, "--map-y", "zeta"],
            &["--map-y applies only to --view map"],
        );
    }
    usage_error(
        &["export", "--view", "map", "--map-y", "zeta"],
        &["map y axis zeta is the swept parameter", "h0-over-e"],
    );
    for g in ["1x5", "5x0", "20000x2"] {
        usage_error(&["export", "--view", "map", "--grid", g], &["out of range"]);
    }
    usage_error(
        &["export", "--view", "map", "--grid", "5by5"],
        &["COLSxROWS"],
    );
    usage_error(
        &["export", "--view", "chart"],
        &["'chart'", "slopes, indices, map, load"],
    );
    usage_error(&["export", "--format", "png"], &["'png'", "csv, svg"]);
    usage_error(
        &["export", "--view", "load", "--sweep", "zeta:1:10"],
        &["--sweep does not apply to --view load"],
    );
    usage_error(
        &["export", "--format", "svg", "--points", "20001"],
        &["--points 20001 is too many for --format svg: at most 20000"],
    );
    usage_error(&["export", "--size-effect", "yes"], &["'yes'", "on, off"]);
    usage_error(&["export", "--sweep", "zeta:1"], &["AXIS:FROM:TO"]);
    usage_error(
        &["export", "--sweep", "foo:1:2"],
        &["unknown axis 'foo'", "h-rms"],
    );
    usage_error(
        &["export", "--sweep", "zeta:1:x"],
        &["\"x\" is not a number"],
    );
    usage_error(&["export", "--sweep", "zeta:100:10"], &["--sweep", "empty"]);
    usage_error(
        &["export", "--sweep", "hurst:0.5:2"],
        &["--sweep", "H = 2", "0.05 … 1"],
    );
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
        // The scene under every picture; the preset's caption (about its
        // slopes) only under the slopes, each other view its own; and the
        // decade labels of the log axes.
        assert!(
            text.contains("H0/E = 0.01 · h_rms = 19.82 nm"),
            "{view}: scene"
        );
        assert_eq!(text.contains("Fig. 2"), view == "slopes", "{view}: caption");
        if view != "load" {
            // ζ 1 … 1e4: one style for the whole axis, powers of ten.
            for d in ["10⁰", "10¹", "10²", "10³", "10⁴"] {
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

#[test]
fn every_csv_and_picture_names_its_scene() {
    let set = ["--set", "h-rms=25nm"];
    for (view, first) in [
        ("slopes", "zeta"),
        ("indices", "zeta"),
        ("map", "zeta,h0_over_e"),
        ("load", "load"),
    ] {
        let args = [&["export", "--view", view][..], &set].concat();
        let csv = stdout(&args);
        let comments: Vec<&str> = csv.lines().take_while(|l| l.starts_with("# ")).collect();
        for want in [
            format!(
                "# roughtui {}: scene \"fig2\", view {view}",
                env!("CARGO_PKG_VERSION")
            ),
            "# h_rms = 2.5e-8 m".into(),
            "# h0_over_e = 0.01".into(),
            "# zeta = 128".into(),
            "# hurst = 0.8".into(),
            "# r_star = 0.001 m".into(),
            "# q0 = 100000 1/m".into(),
            "# model = closed form".into(),
            "# moments = asymptotic".into(),
            "# size_effect = off".into(),
        ] {
            assert!(
                comments.iter().any(|l| l.starts_with(&want)),
                "{view}: no {want:?} in {comments:#?}"
            );
        }
        let h = header(&csv).unwrap();
        assert!(h.starts_with(&format!("{first},")), "{view}: {h}");
        let svg = stdout(&[&args[..], &["--format", "svg"]].concat());
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let desc = doc
            .descendants()
            .find(|n| n.has_tag_name("desc"))
            .and_then(|n| n.text())
            .unwrap();
        // The description holds the CSV's `#` lines, word for word (the
        // columns' meanings aside: the picture has no columns).
        for c in comments.iter().filter(|c| !c.starts_with("# columns:")) {
            assert!(
                desc.lines().any(|l| l == &c[2..]),
                "{view}: {c:?} not in <desc>"
            );
        }
        let title = doc.descendants().find(|n| n.has_tag_name("title")).unwrap();
        assert_eq!(title.text(), Some(&*format!("fig2 — {view} view")));
        // The caption line under the plot, in short.
        assert!(
            svg.contains("H0/E = 0.01 · h_rms = 25 nm · ζ = 128 · Hurst H = 0.8 · R* = 1 mm"),
            "{view}"
        );
    }
    // The sweep's other axes name the column.
    for (sweep, first) in [
        ("h0-over-e:1e-4:0.1", "h0_over_e"),
        ("h-rms:1e-9:1e-6", "h_rms"),
        ("hurst:0.2:0.9", "hurst"),
        ("r-star:1e-6:1e-2", "r_star"),
    ] {
        let csv = stdout(&["export", "--points", "3", "--sweep", sweep]);
        assert!(
            header(&csv).unwrap().starts_with(&format!("{first},psi,")),
            "{sweep}"
        );
    }
}

/// pandas reads an export as it is (`comment='#'`), column names and all,
/// when python3 with pandas is installed (else the test says so and passes).
#[test]
fn pandas_reads_an_export_as_it_is() {
    let ok = Command::new("python3")
        .args(["-c", "import pandas"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        eprintln!("python3 with pandas not found: not checked");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("fig2.csv");
    std::fs::write(
        &f,
        stdout(&["export", "--view", "indices", "--points", "5"]),
    )
    .unwrap();
    let out = Command::new("python3")
        .args([
            "-c",
            "import sys, pandas as pd; d = pd.read_csv(sys.argv[1], comment='#'); \
             print(list(d.columns)[0], len(d), repr(float(d['zeta'].iloc[-1])))",
            f.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8(out.stdout).unwrap().trim(),
        "zeta 5 10000.0"
    );
}
