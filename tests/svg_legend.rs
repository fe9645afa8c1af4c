//! The pictures' legend never covers data: for every preset, every view
//! with a legend in the plot and a marker at either end of the sweep, in
//! its middle and where the preset has it (and the measured example
//! surface's views), no point or segment of a drawn line or data dot lies
//! inside the legend box, read back from the SVG itself.

mod common;

use common::cli::stdout;

type Box4 = (f64, f64, f64, f64);

/// The legend box: the rectangle drawn at 0.9 opacity.
fn legend_box(doc: &roxmltree::Document) -> Option<Box4> {
    let r = doc
        .descendants()
        .find(|n| n.has_tag_name("rect") && n.attribute("opacity") == Some("0.9"))?;
    let f = |a: &str| r.attribute(a).unwrap().parse::<f64>().unwrap();
    let (x, y) = (f("x"), f("y"));
    Some((x, y, x + f("width"), y + f("height")))
}

fn points(p: &str) -> Vec<(f64, f64)> {
    p.split_whitespace()
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// Points of `line` inside `b`, its segments sampled every half pixel.
fn inside(line: &[(f64, f64)], b: Box4) -> Option<(f64, f64)> {
    let hit = |(x, y): (f64, f64)| x >= b.0 && x <= b.2 && y >= b.1 && y <= b.3;
    if line.len() == 1 {
        return hit(line[0]).then_some(line[0]);
    }
    line.windows(2).find_map(|s| {
        let (a, c) = (s[0], s[1]);
        let n = ((c.0 - a.0).abs().max((c.1 - a.1).abs()) * 2.0)
            .ceil()
            .max(1.0) as usize;
        (0..=n)
            .map(|k| {
                let t = k as f64 / n as f64;
                (a.0 + (c.0 - a.0) * t, a.1 + (c.1 - a.1) * t)
            })
            .find(|p| hit(*p))
    })
}

/// Checks one picture; returns whether it has a legend box.
fn check(args: &[&str]) -> bool {
    let svg = stdout(&[&["export", "--format", "svg"][..], args].concat());
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let Some(b) = legend_box(&doc) else {
        return false;
    };
    // The legend's own samples: short horizontal strokes at its left.
    let sample = |l: &[(f64, f64)]| {
        l.iter()
            .all(|&(x, y)| x >= b.0 + 4.0 && x <= b.0 + 30.0 && y > b.1 && y < b.3 && y == l[0].1)
    };
    for n in doc.descendants() {
        let line = if n.has_tag_name("polyline") {
            points(n.attribute("points").unwrap())
        } else if n.has_tag_name("circle") {
            let f = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
            vec![(f("cx"), f("cy"))]
        } else {
            continue;
        };
        if sample(&line) {
            continue;
        }
        if let Some(p) = inside(&line, b) {
            panic!("{args:?}: a line passes the legend box {b:?} at {p:?}");
        }
    }
    true
}

#[test]
fn the_legend_never_covers_a_curve() {
    let mut pictures = 0;
    for (preset, axis, from, to) in [
        ("fig1", "h0-over-e", 1e-4, 1e-1),
        ("fig2", "zeta", 1.0, 1e4),
        ("fig3", "zeta", 1.0, 1e4),
        ("fig4", "zeta", 1.0, 1e6),
    ] {
        let middle = f64::sqrt(from * to);
        let markers = [None, Some(from), Some(middle), Some(to)];
        for view in ["slopes", "indices", "load"] {
            for m in markers {
                let set = m.map(|v| format!("{axis}={v}"));
                let mut args = vec!["--preset", preset, "--view", view];
                if let Some(s) = &set {
                    args.extend(["--set", s]);
                }
                // Both models: their curves differ.
                for model in ["closed-form", "exact"] {
                    let mut a = args.clone();
                    a.extend(["--model", model]);
                    assert!(check(&a), "{a:?}: no legend");
                    pictures += 1;
                }
            }
        }
    }
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    for view in ["slopes", "indices", "load", "spectrum"] {
        for zeta in ["2", "30", "130"] {
            let set = format!("zeta={zeta}");
            let a = ["--surface", example, "--view", view, "--set", &set];
            if check(&a) {
                pictures += 1;
            }
        }
    }
    assert!(pictures >= 100, "{pictures}");
}

#[test]
fn the_legend_lists_only_what_is_drawn() {
    let svg = |args: &[&str]| stdout(&[&["export", "--format", "svg"][..], args].concat());
    // The marker named where it is drawn, absent where it is off the sweep.
    let on = svg(&["--preset", "fig2"]);
    assert!(on.contains("ζ = 128, the marker"), "{on}");
    let off = svg(&["--preset", "fig2", "--sweep", "zeta:1000:1e4"]);
    assert!(!off.contains(", the marker"));
    // The indices name the Ψ = 1 line.
    assert!(svg(&["--view", "indices"]).contains("Ψ = 1: plastic above"));
    // The map's current point only where it lies on the map.
    let map = svg(&["--view", "map"]);
    assert!(map.contains("current point"));
    let map = svg(&["--view", "map", "--sweep", "zeta:1000:1e4"]);
    assert!(!map.contains("current point"));
    // The load axis names the hardness by its own symbol.
    assert!(svg(&["--view", "load"]).contains("load p̄/H0"));
}

#[test]
fn the_spectrum_ends_at_the_data_with_a_wavelength_axis() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    let svg = stdout(&[
        "export",
        "--format",
        "svg",
        "--surface",
        example,
        "--view",
        "spectrum",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts: Vec<String> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(|t| t.trim().to_string())
        .collect();
    assert!(
        texts.iter().any(|t| t == "wavelength λ = 2π/q"),
        "{texts:?}"
    );
    assert!(
        texts.iter().any(|t| t == "1 µm" || t == "10 µm"),
        "{texts:?}"
    );
    // The data span q ≈ 1.3e5 … 1.7e7 1/m: no decade label below or above.
    assert!(!texts.iter().any(|t| t == "10⁵" || t == "10⁸"), "{texts:?}");
    assert!(
        svg.contains("cutoff q1 = ζ q0"),
        "the cutoff at the data's end is drawn"
    );
}

#[test]
fn a_long_title_is_cut_at_the_name_never_clipped() {
    let dir = tempfile::tempdir().unwrap();
    let name = "a-rather-long-scene-name-20261125-094445-for-the-projector-slide";
    assert_eq!(name.chars().count(), 64);
    let p = dir.path().join("long.ron");
    std::fs::write(
        &p,
        common::GOOD.replace("name: \"fig2\"", &format!("name: \"{name}\"")),
    )
    .unwrap();
    for view in ["slopes", "map"] {
        let args = [
            "export",
            "--format",
            "svg",
            "--load",
            p.to_str().unwrap(),
            "--view",
            view,
        ];
        let svg = stdout(&args);
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let title = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .filter_map(|n| n.text())
            .map(str::trim)
            .find(|t| t.contains(" — "))
            .unwrap();
        // 10.5 px per character bounds plotters' 16.1 px title font.
        let width = title.chars().count() as f64 * 10.5;
        let plot_w = if view == "map" { 670.0 } else { 900.0 };
        assert!(width <= plot_w - 30.0, "{view}: {title:?} is {width} px");
        assert!(title.ends_with(if view == "map" {
            "regime map"
        } else {
            "initial slopes"
        }));
        assert!(title.starts_with("a-rather-long"), "{title}");
    }
}

#[test]
fn dashed_curves_are_dashed_by_the_viewer_not_cut_in_pixels() {
    let svg = stdout(&["export", "--format", "svg", "--preset", "fig2"]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let green: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#00A000"))
        .collect();
    // Persson's line and its legend sample, each one dashed path.
    assert_eq!(green.len(), 2, "{green:?}");
    for n in green {
        assert_eq!(n.attribute("stroke-dasharray"), Some("9 6"));
    }
    assert!(
        points(
            doc.descendants()
                .find(|n| n.attribute("stroke-dasharray").is_some())
                .unwrap()
                .attribute("points")
                .unwrap()
        )
        .len()
            > 100
    );
}
