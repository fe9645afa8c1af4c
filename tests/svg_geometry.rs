//! Every picture of a measured surface drawn across the page, read back
//! from the SVG by its geometry (not only that it parses): the plot at
//! least 60 % of the picture's width, the data spread across it, the
//! legend no wider than 40 % and inside the picture. (A spectrum's legend
//! once carried the whole fit in one 120-character label: the legend was
//! 873 px wide and the plot 15 px.)

mod common;

use std::path::Path;

use common::cli::run;

const WIDTH: f64 = 900.0;

fn points(p: &str) -> Vec<(f64, f64)> {
    p.split_whitespace()
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// Checks the picture `export --format svg ARGS` draws.
fn check(args: &[&str]) {
    let out = run(&[&["export", "--format", "svg"][..], args].concat());
    assert_eq!(out.status.code(), Some(0), "{args:?}");
    let svg = String::from_utf8(out.stdout).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let f = |n: &roxmltree::Node, a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
    // The plot: its widest horizontal line (an axis or a grid line).
    let plot = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .map(|n| points(n.attribute("points").unwrap()))
        .filter(|p| p.len() == 2 && p[0].1 == p[1].1)
        .map(|p| (p[1].0 - p[0].0).abs())
        .fold(0f64, f64::max);
    assert!(plot >= 0.6 * WIDTH, "{args:?}: the plot is {plot} px wide");
    // The data dots (where the view draws them) spread across the plot.
    let dots: Vec<f64> = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .map(|n| f(&n, "cx"))
        .collect();
    if dots.len() > 3 {
        let (lo, hi) = dots
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        assert!(
            hi - lo >= 0.5 * plot,
            "{args:?}: the data span {} px",
            hi - lo
        );
    }
    // The legend box: narrow enough and inside the picture.
    if let Some(r) = doc
        .descendants()
        .find(|n| n.has_tag_name("rect") && n.attribute("opacity") == Some("0.9"))
    {
        let (x, w) = (f(&r, "x"), f(&r, "width"));
        assert!(w <= 0.4 * WIDTH, "{args:?}: the legend is {w} px wide");
        assert!(
            x >= 0.0 && x + w <= WIDTH,
            "{args:?}: the legend at {x}, {w} px wide"
        );
    }
}

fn instruments(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/instruments")
        .join(format!("{name}.gz"))
        .to_str()
        .unwrap()
        .to_string()
}

#[test]
fn the_example_surfaces_pictures() {
    for view in ["spectrum", "slopes", "indices", "load", "map"] {
        check(&["--surface", "surfaces/example.txt", "--view", view]);
    }
    check(&[
        "--surface",
        "surfaces/example.txt",
        "--view",
        "spectrum",
        "--direction",
        "x",
    ]);
}

#[test]
fn instruments_spectra() {
    for (file, more) in [
        ("sur-2.sur", &[][..]),
        ("di-3.di", &[]),
        ("nid-1.nid", &[]),
        ("opdx-3.opdx", &[]),
        ("frt-2.frt", &["--max-undefined", "30"]),
        ("metropro-1.dat", &[]),
    ] {
        let f = instruments(file);
        let mut args = vec!["--surface", f.as_str(), "--view", "spectrum"];
        args.extend_from_slice(more);
        check(&args);
    }
}
