//! `roughtui export --view contact` and `--view contact-sweep`: the
//! parameter lines, the header, the loads, the simulation beside the
//! theory, and the refusals (exit status 2, a message naming the problem).
//! The solver's accuracy is tested in crates/rough-contact against Westergaard,
//! Hertz and Tamaas.

mod common;
use common::cli::{run, stdout};

fn parse(csv: &str) -> (Vec<&str>, &str, Vec<Vec<f64>>) {
    let comments: Vec<&str> = csv.lines().filter(|l| l.starts_with('#')).collect();
    let mut rest = csv.lines().filter(|l| !l.starts_with('#'));
    let header = rest.next().unwrap();
    let rows = rest
        .map(|l| l.split(',').map(|v| v.parse::<f64>().unwrap()).collect())
        .collect();
    (comments, header, rows)
}

#[test]
fn contact_view_csv() {
    let csv = stdout(&[
        "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=16", "--cell", "1",
    ]);
    let (comments, header, rows) = parse(&csv);
    // The scene as every view's CSV has it, then what the simulation adds.
    assert_eq!(
        comments[0],
        format!(
            "# roughtui {}: scene \"fig2\", view contact",
            env!("CARGO_PKG_VERSION")
        )
    );
    for want in [
        "# h0_over_e = 0.01  (H0/E: macroscopic hardness over E, the composite modulus E*)",
        "# zeta = 16  (magnification q1/q0; the marker)",
        "# model = closed form",
        "# moments = asymptotic",
        "# size_effect = off",
    ] {
        assert!(comments.contains(&want), "{want} not in {comments:#?}");
    }
    // The span where every view has it (after the parameters), then the
    // simulation's lines after the scene's.
    let at = |line: &str| comments.iter().position(|c| c.starts_with(line));
    let span = at("# contact = p_over_h = pbar/H0 from 0.001 to 1, 13 loads (log-spaced)");
    let sim = at(
        "# simulation = elastic–perfectly-plastic BEM (rough-contact), periodic 128 × 128 \
         grid of side 1 × 2π/q0 (cell: 1 longest wavelength), 8 nodes per shortest wavelength, \
         power-law Gaussian surface, seed 1 (one realisation",
    );
    let model = at("# model = closed form");
    assert!(span.is_some() && sim.is_some(), "{comments:#?}");
    assert!(span < model && model < sim, "{comments:#?}");
    assert!(comments
        .iter()
        .any(|c| c.starts_with("# hardness_in_use_over_e = 0.01 (H0/E*, the pressure cap)")));
    assert!(comments.iter().any(|c| c.starts_with(
        "# theory = the closed form model's finite-load areas at the index in use psi_p = "
    )));
    assert!(comments.iter().any(|c| c.contains("128 × 128 grid")
        && c.contains("cell: 1 longest wavelength")
        && c.contains("8 nodes per shortest wavelength")
        && c.contains("seed 1 (one realisation")));
    assert!(comments.iter().any(
        |c| c.contains("# surface = matched to the scene's rms slope")
            && c.contains("the paper's asymptotic moments")
    ));
    assert!(comments
        .iter()
        .any(|c| c.contains("hardness_in_use_over_e = 0.01")));
    assert_eq!(
        header,
        "p_over_h,area,elastic_area,plastic_area,mean_gap,iterations,residual,\
         theory_area,theory_elastic_area,theory_plastic_area,area_sd,elastic_area_sd,\
         plastic_area_sd,seeds,p_over_h0,area_corrected,area_corrected_sd"
    );
    assert!(
        comments.iter().any(|c| c.starts_with(
            "# load = p_over_h = pbar/H0 (the theory's hardness in use, H0/E* = 0.01)"
        )),
        "{comments:#?}"
    );
    assert!(
        comments
            .iter()
            .any(|c| c.starts_with("# hardness = global: one cap H0/E* = 0.01")),
        "{comments:#?}"
    );
    assert!(
        comments.iter().any(|c| c
            .starts_with("# kappa = A/A0 over pbar/(E* h') at the lightest load")
            && c.contains("Persson's theory: sqrt(8/pi) = 1.5957691216057308")),
        "{comments:#?}"
    );
    assert_eq!(rows.len(), 13);
    assert_eq!(rows[0][0], 1e-3);
    assert_eq!(rows[12][0], 1.0);
    let mut last = 0.0;
    for r in &rows {
        // Parts add up on the grid and in the theory.
        assert!((r[2] + r[3] - r[1]).abs() < 1e-12, "{r:?}");
        assert!((r[8] + r[9] - r[7]).abs() < 1e-9, "{r:?}");
        assert!(r[1] >= last && r[1] <= 1.0);
        assert!(r[6] <= 1e-10, "residual {r:?}");
        assert!(r[10].is_nan() && r[13] == 1.0, "one seed: {r:?}");
        // Without the size effect the load over H0 is the load over H_use;
        // the corrected area is the area less the perimeter's overcount.
        assert_eq!(r[14], r[0]);
        assert!(
            r[15] <= r[1] && (r[15] > 0.9 * r[1] || r[1] < 0.02),
            "{r:?}"
        );
        last = r[1];
    }
    // At p̄ = H everything is at the hardness, in both.
    assert_eq!(&rows[12][1..4], &[1.0, 0.0, 1.0]);
    assert!((rows[12][7] - 1.0).abs() < 1e-12 && (rows[12][9] - 1.0).abs() < 1e-12);
    // Another seed, another surface, same header.
    let other = stdout(&[
        "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=16", "--seed", "7",
        "--points", "3", "--cell", "1",
    ]);
    let (_, _, other) = parse(&other);
    assert_eq!(other.len(), 3);
    assert_ne!(other[0][1], rows[0][1]);
}

/// Three seeds: each column the mean of the three single-seed runs, the
/// `_sd` columns their sample standard deviation.
#[test]
fn contact_over_seeds() {
    let base = [
        "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=8", "--points", "4",
    ];
    let text = stdout(&[&base[..], &["--seed", "4", "--seeds", "3"]].concat());
    let (comments, _, all) = parse(&text);
    assert!(comments
        .iter()
        .any(|c| c.contains("seeds 4–6 (columns: means over 3 realisations")));
    let one: Vec<Vec<Vec<f64>>> = ["4", "5", "6"]
        .iter()
        .map(|s| parse(&stdout(&[&base[..], &["--seed", s]].concat())).2)
        .collect();
    for (k, row) in all.iter().enumerate() {
        for (col, sd_col) in [(1, 10), (2, 11), (3, 12)] {
            let v: Vec<f64> = one.iter().map(|r| r[k][col]).collect();
            let mean = v.iter().sum::<f64>() / 3.0;
            let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 2.0).sqrt();
            assert!((row[col] - mean).abs() <= 1e-15, "{row:?} {v:?}");
            assert!((row[sd_col] - sd).abs() <= 1e-15, "{row:?} {v:?}");
        }
        assert_eq!(row[13], 3.0);
    }
}

/// The cell: K longest wavelengths a side on K times the grid, its
/// spectrum flat below q0; the grid as nodes a side or per wavelength.
#[test]
fn contact_cell_and_grid() {
    let base = [
        "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=8", "--points", "2",
    ];
    for (extra, grid) in [
        (vec![], "128 × 128 grid of side 2 × 2π/q0 (cell: 2 longest wavelengths, the spectrum flat below q0), 8 nodes"),
        (vec!["--cell", "4"], "256 × 256 grid of side 4 × 2π/q0"),
        (vec!["--cell", "1", "--contact-grid", "256"], "256 × 256 grid of side 1 × 2π/q0 (cell: 1 longest wavelength), 32 nodes"),
        (vec!["--cell", "1", "--per-wavelength", "4"], "32 × 32 grid"),
    ] {
        let text = stdout(&[&base[..], &extra].concat());
        let (comments, _, _) = parse(&text);
        assert!(comments.iter().any(|c| c.contains(grid)), "{extra:?}: {comments:?}");
    }
}

#[test]
fn contact_sweep_csv_and_svg() {
    let csv = stdout(&[
        "export",
        "--view",
        "contact-sweep",
        "--preset",
        "fig2",
        "--cell",
        "1",
    ]);
    let (comments, header, rows) = parse(&csv);
    assert_eq!(
        header,
        "zeta,p_over_h0,p_over_h,plastic_share,theory_plastic_share,area,theory_area,grid,\
         iterations,residual,plastic_share_sd,area_sd,seeds,hardness_over_e,\
         theory_hardness_over_e,patches,patch_radius,area_corrected,area_corrected_sd"
    );
    assert!(
        comments.iter().any(|c| c.starts_with(
            "# contact-sweep = zeta = 1, 2, 4, …, 128 (a measured map: those it resolves), each \
             on its own grid, at p_over_h0 = pbar/H0 = 0.01 (the same load at every zeta)"
        )),
        "{comments:#?}"
    );
    assert!(
        comments
            .iter()
            .any(|c| c.starts_with("# load = pbar = 0.01 H0 at every zeta")),
        "{comments:#?}"
    );
    let zetas: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(zetas, [1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0]);
    let grids: Vec<f64> = rows.iter().map(|r| r[7]).collect();
    assert_eq!(grids, [32.0, 32.0, 32.0, 64.0, 128.0, 256.0, 512.0, 1024.0]);
    for r in &rows {
        assert_eq!((r[1], r[2]), (0.01, 0.01));
        assert!(
            (0.0..=1.0).contains(&r[3]) && (0.0..=1.0).contains(&r[4]),
            "{r:?}"
        );
    }
    let svg = stdout(&[
        "export", "--view", "contact", "--preset", "fig3", "--set", "zeta=8", "--format", "svg",
        "--points", "4",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let text: String = doc.descendants().filter_map(|n| n.text()).collect();
    assert!(
        text.contains("simulation") && text.contains("theory"),
        "{text}"
    );
}

#[test]
fn contact_refusals() {
    for (args, needle) in [
        (
            vec!["--set", "zeta=1000"],
            "solves up to 4096 (ζ × cell ≤ 512)",
        ),
        (vec!["--seeds", "0"], "invalid value '0' for '--seeds <N>'"),
        (vec!["--contact-grid", "1000"], "must be a power of two"),
        (
            vec!["--contact-grid", "64"],
            "a grid of 64 nodes a side cannot hold ζ = 128",
        ),
        (
            vec!["--contact-grid", "131072"],
            "of memory to solve (100 bytes a node); this machine has",
        ),
        (
            vec![
                "--cell",
                "2",
                "--contact-grid",
                "1024",
                "--per-wavelength",
                "8",
            ],
            "cannot be used with",
        ),
        (
            vec!["--grid", "3x3"],
            "--grid does not apply to --view contact",
        ),
        (vec!["--points", "100"], "at most 64 loads"),
        (
            vec!["--surface", "surfaces/example.txt", "--direction", "x"],
            "needs heights on a grid",
        ),
    ] {
        let mut all = vec!["export", "--view", "contact", "--preset", "fig2"];
        if args[0] == "--surface" {
            all.truncate(3);
        }
        all.extend(&args);
        let out = run(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains(needle), "{all:?}: {err}");
        assert!(out.stdout.is_empty());
    }
}

/// The map at p̄ = 0.01 H: CSV digits whose counts are the CSV view's
/// areas at that load, and the same map as SVG rectangles.
#[test]
fn contact_map_csv_and_svg() {
    let args = ["--preset", "fig2", "--set", "zeta=16", "--cell", "1"];
    let map = stdout(&[&["export", "--view", "contact-map"][..], &args].concat());
    let lines: Vec<&str> = map.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(lines.len(), 128);
    let nodes: Vec<u8> = lines
        .iter()
        .flat_map(|l| l.split(',').map(|v| v.parse::<u8>().unwrap()))
        .collect();
    assert_eq!(nodes.len(), 128 * 128);
    let count = |k: u8| nodes.iter().filter(|v| **v == k).count() as f64 / (128.0 * 128.0);
    // The contact view's row at p̄/H = 0.01 (the fifth of thirteen).
    let csv = stdout(&[&["export", "--view", "contact"][..], &args].concat());
    let (_, _, rows) = parse(&csv);
    let row = &rows[4];
    assert_eq!(row[0], 0.01);
    assert_eq!(count(1) + count(2), row[1]);
    assert_eq!(count(1), row[2]);
    assert_eq!(count(2), row[3]);
    assert!(
        map.contains(
            "# contact-map = p_over_h = pbar/H0 = 0.01; simulation: 128 × 128 grid of side \
             0.00006283185307179586 m, periodic Gaussian surface, seed 1"
        ),
        "{map}"
    );
    assert!(map.contains("# zeta = 16  (magnification q1/q0; the marker)"));
    let svg = stdout(
        &[
            &["export", "--view", "contact-map", "--format", "svg"][..],
            &args,
        ]
        .concat(),
    );
    assert!(svg.starts_with("<svg"));
    assert!(svg.matches("fill=\"#8C8C8C\"").count() > 10, "{svg}");
    let out = run(&[
        &["export", "--view", "contact-map", "--points", "5"][..],
        &args,
    ]
    .concat());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr)
        .contains("--points does not apply to --view contact-map"));
}

/// The size effect per asperity: the elastic contact's patches give each
/// node its asperity's curvature radius and H_y; refused without the size
/// effect.
#[test]
fn contact_hardness_per_asperity() {
    let base = [
        "export",
        "--view",
        "contact-sweep",
        "--preset",
        "fig2",
        "--set",
        "h0-over-e=0.001",
        "--size-effect",
        "on",
        "--cell",
        "1",
        // Four nodes a wavelength: ζ = 128 on 512², a quick test.
        "--per-wavelength",
        "4",
    ];
    let global = stdout(&base);
    let (_, _, g) = parse(&global);
    for hardness in ["asperity", "summit"] {
        let text = stdout(&[&base[..], &["--hardness", hardness]].concat());
        let (comments, header, rows) = parse(&text);
        assert!(header.contains("hardness_over_e,theory_hardness_over_e,patches,patch_radius"));
        assert!(
            comments
                .iter()
                .any(|c| c.starts_with(&format!("# hardness = {hardness}: each node capped"))),
            "{comments:#?}"
        );
        for (a, g) in rows.iter().zip(&g) {
            // The global cap is the theory's; per node the load-weighted
            // cap is H0 at least and the radii are finite.
            assert_eq!(g[13], g[14], "{g:?}");
            assert!(a[13] >= 0.001 * (1.0 - 1e-12), "{a:?}");
            assert!(a[15] >= 1.0 && a[16] > 0.0, "{a:?}");
            // The same load over H0 at every ζ, over H_y(R_s) the smaller
            // as ζ grows.
            assert_eq!(a[1], 0.01);
            assert!((a[2] * a[14] / 0.001 - 0.01).abs() < 1e-12, "{a:?}");
        }
    }
    // --load-scale in-use: the load a fixed fraction of H_y(R_s) at each ζ
    // (heavier over H0 as ζ grows).
    let scaled = stdout(&[&base[..], &["--load-scale", "in-use"]].concat());
    let (comments, _, rows) = parse(&scaled);
    assert!(
        comments
            .iter()
            .any(|c| c.starts_with("# load = pbar = 0.01 H_y at each zeta (--load-scale in-use")),
        "{comments:#?}"
    );
    for r in &rows {
        assert_eq!(r[2], 0.01);
        assert!((r[1] - 0.01 * r[14] / 0.001).abs() < 1e-12 * r[1], "{r:?}");
    }
    assert!(rows[7][1] > 5.0 * rows[0][1], "{rows:?}");
    let out = common::cli::run(&[
        "export",
        "--view",
        "contact",
        "--preset",
        "fig2",
        "--hardness",
        "asperity",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("switch it on"));
}

/// A seed keeps its surface and its answer: fig2 at ζ = 32, seed 1, on the
/// cell and grid the contact view had before the solver's speed-ups and the
/// cells (one longest wavelength, 256²), gives the thirteen areas that
/// version printed (tests/data/contact/fig2_z32_seed1_before.csv, written
/// by roughtui at 3579ebf, 2026-11) — the bar is 0.2 % on the areas
/// and 1 % on the plastic areas; the solver meets it to the node (at
/// 1024², fig2 ζ = 128, too: docs/accuracy-speed.md).
#[test]
fn a_seed_keeps_its_surface_and_its_answer() {
    let before = include_str!("data/contact/fig2_z32_seed1_before.csv");
    let csv = stdout(&[
        "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=32", "--seed", "1",
        "--cell", "1",
    ]);
    let (_, _, want) = parse(before);
    let (comments, _, got) = parse(&csv);
    assert!(
        comments.iter().any(|c| c.contains("256 × 256")),
        "{comments:?}"
    );
    assert_eq!(got.len(), want.len());
    for (g, w) in got.iter().zip(&want) {
        assert_eq!(g[0], w[0], "load");
        // area, elastic, plastic: fractions of the 256² nodes; equal here
        // to the node, a node's flip allowed on another machine's rounding.
        let node = 1.0 / 65536.0;
        for (k, what) in [(1, "area"), (2, "elastic area"), (3, "plastic area")] {
            assert!(
                (g[k] - w[k]).abs() <= node,
                "{what} at p̄/H = {}: {} against {}",
                w[0],
                g[k],
                w[k]
            );
        }
    }
}

/// The explorer and `serve` take the simulation's options as export does
/// (checked before a terminal is taken or a port opened), and a measured
/// map refuses them in one line with status 2.
#[test]
fn the_explorer_and_serve_take_the_simulations_options() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    for cmd in [&[][..], &["serve"][..]] {
        for (opt, value) in [("--cell", "2"), ("--contact-grid", "256")] {
            let mut args: Vec<&str> = cmd.to_vec();
            args.extend(["--surface", example, opt, value]);
            let out = run(&args);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            assert_eq!(
                err.trim(),
                format!(
                    "roughtui: {opt} does not apply to a measured map: it is solved on its own \
                     heights, its square and grid set by the data and ζ"
                )
            );
        }
        let mut args: Vec<&str> = cmd.to_vec();
        args.extend(["--preset", "fig2", "--cell", "2", "--hardness", "asperity"]);
        let out = std::process::Command::new(common::cli::BIN)
            .args(&args)
            .env("ROUGHTUI_CHECK_ONLY", "1")
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        let out = run(&["--preset", "fig2", "--cell", "65"]);
        assert_eq!(out.status.code(), Some(2));
    }
}

/// With a hardness per asperity the loads above what the asperities can
/// carry have no contact solution (the bulk would yield): they are named
/// in `# not solved` lines and left out, the others solved (the picture
/// draws those and says why the rest are missing).
#[test]
fn loads_beyond_the_asperities_hardness_are_named_not_solved() {
    let args = [
        "export",
        "--view",
        "contact",
        "--preset",
        "fig2",
        "--set",
        "zeta=8",
        "--cell",
        "1",
        "--size-effect",
        "on",
        "--hardness",
        "asperity",
    ];
    let csv = stdout(&args);
    let (comments, _, rows) = parse(&csv);
    let not: Vec<&&str> = comments
        .iter()
        .filter(|c| c.starts_with("# not solved: "))
        .collect();
    assert!(!not.is_empty(), "{comments:?}");
    assert!(
        not.iter()
            .any(|c| c.starts_with("# not solved: p̄/H = 1, seed 1: the mean pressure")),
        "{not:?}"
    );
    assert!(
        not.iter().all(|c| c.ends_with("the bulk would yield")),
        "{not:?}"
    );
    assert_eq!(rows.len() + not.len(), 13);
    assert_eq!(rows[0][0], 0.001);
    for r in &rows {
        assert!(r[1] > 0.0 && r[3] <= r[1], "{r:?}");
    }
    let mut svg_args = args.to_vec();
    svg_args.extend(["--format", "svg"]);
    let svg = stdout(&svg_args);
    assert!(svg.contains("loads beyond what the asperities carry are not solved"));
}
