//! Every picture of a measured surface, measured by its geometry as the
//! SVG draws it: the plot spans most of the page, the legend lies within
//! the page and either inside the plot or wholly beside it, no text leaves
//! the page and no two texts overlap (each text's box estimated from its
//! font size, anchor and length), and no drawn line or point enters the
//! legend. The surfaces: the shipped example map, its profiles along x, a
//! line scan, a PSD table and an x3p map; the contact views on a 64² map.

mod common;

use common::cli::{run, stdout};

/// (left, top, right, bottom) in pixels.
type Box4 = (f64, f64, f64, f64);

fn num(n: roxmltree::Node, a: &str) -> f64 {
    n.attribute(a).unwrap().parse().unwrap()
}

fn points(p: &str) -> Vec<(f64, f64)> {
    p.split_whitespace()
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The plot's box: from its axes, the longest black 1-px horizontal line
/// (the q or ζ axis) and the longest black 1-px vertical one (the PSD or
/// moment axis).
fn plot_box(doc: &roxmltree::Document) -> Box4 {
    let mut best_h = (0.0, 0.0, 0.0);
    let mut best_v = (0.0, 0.0, 0.0);
    for n in doc.descendants().filter(|n| {
        n.has_tag_name("polyline")
            && n.attribute("stroke") == Some("#000000")
            && n.attribute("stroke-width") == Some("1")
    }) {
        let p = points(n.attribute("points").unwrap());
        if p.len() != 2 {
            continue;
        }
        let ((x0, y0), (x1, y1)) = (p[0], p[1]);
        if y0 == y1 && (x1 - x0).abs() > best_h.1 - best_h.0 {
            best_h = (x0.min(x1), x0.max(x1), y0);
        }
        if x0 == x1 && (y1 - y0).abs() > best_v.1 - best_v.0 {
            best_v = (y0.min(y1), y0.max(y1), x0);
        }
    }
    (best_h.0, best_v.0, best_h.1, best_h.2)
}

/// The legend's box: the rectangle drawn at 0.9 opacity.
fn legend_box(doc: &roxmltree::Document) -> Option<Box4> {
    let r = doc
        .descendants()
        .find(|n| n.has_tag_name("rect") && n.attribute("opacity") == Some("0.9"))?;
    let (x, y) = (num(r, "x"), num(r, "y"));
    Some((x, y, x + num(r, "width"), y + num(r, "height")))
}

/// A text's box, estimated: 0.6 em a character (a bound for sans-serif
/// digits and lower case), one em high, placed by plotters' anchors
/// (`text-anchor`, `dy` of 0.76em: top, 0.5ex: middle, -0.5ex: bottom) and
/// turned by a `rotate(90, …)` or `rotate(270, …)`.
fn text_box(n: roxmltree::Node) -> (String, Box4) {
    let t = n.text().unwrap_or("").trim().to_string();
    let fs = num(n, "font-size");
    let (x, y) = (num(n, "x"), num(n, "y"));
    let w = t.chars().count() as f64 * 0.6 * fs;
    let (a, b) = match n.attribute("text-anchor") {
        Some("middle") => (-w / 2.0, w / 2.0),
        Some("end") => (-w, 0.0),
        _ => (0.0, w),
    };
    let (top, bottom) = match n.attribute("dy") {
        Some("0.76em") => (0.0, fs),
        Some("0.5ex") => (-fs / 2.0, fs / 2.0),
        Some("-0.5ex") => (-fs, 0.0),
        _ => (-0.8 * fs, 0.2 * fs),
    };
    let turn = n.attribute("transform").unwrap_or("");
    let b4 = if turn.starts_with("rotate(90") {
        // Turned clockwise about (x, y): the text runs down, its top
        // faces right.
        (x - bottom, y + a, x - top, y + b)
    } else if turn.starts_with("rotate(270") {
        // Turned anticlockwise: the text runs up, its top faces left.
        (x + top, y - b, x + bottom, y - a)
    } else {
        (x + a, y + top, x + b, y + bottom)
    };
    (t, b4)
}

fn overlap(a: Box4, b: Box4) -> f64 {
    let w = a.2.min(b.2) - a.0.max(b.0);
    let h = a.3.min(b.3) - a.1.max(b.1);
    if w > 0.0 && h > 0.0 {
        w.min(h)
    } else {
        0.0
    }
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

/// The lines and points drawn, legend samples aside (short horizontal
/// strokes and dots at the legend box's left).
fn drawn(doc: &roxmltree::Document, legend: Option<Box4>) -> Vec<Vec<(f64, f64)>> {
    let sample = |l: &[(f64, f64)]| {
        legend.is_some_and(|b| {
            l.iter()
                .all(|&(x, y)| x >= b.0 && x <= b.0 + 32.0 && y > b.1 && y < b.3 && y == l[0].1)
        })
    };
    doc.descendants()
        .filter_map(|n| {
            if n.has_tag_name("polyline") {
                Some(points(n.attribute("points").unwrap()))
            } else if n.has_tag_name("circle") {
                Some(vec![(num(n, "cx"), num(n, "cy"))])
            } else {
                None
            }
        })
        .filter(|l| !sample(l))
        .collect()
}

/// The picture's geometry: the page, the plot's box, the legend's, the
/// lines drawn and the texts.
struct Geometry {
    page: (f64, f64),
    plot: Box4,
    legend: Option<Box4>,
    lines: Vec<Vec<(f64, f64)>>,
    texts: Vec<(String, Box4)>,
}

fn geometry(svg: &str) -> Geometry {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let legend = legend_box(&doc);
    let root = doc.root_element();
    Geometry {
        page: (num(root, "width"), num(root, "height")),
        plot: plot_box(&doc),
        legend,
        lines: drawn(&doc, legend),
        texts: doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(text_box)
            .filter(|(t, _)| !t.is_empty())
            .collect(),
    }
}

/// Checks one picture; returns its plot width and legend box.
fn check(what: &str, args: &[&str]) -> (f64, Option<Box4>) {
    let out = run(&[&["export", "--format", "svg"][..], args].concat());
    assert_eq!(out.status.code(), Some(0), "{what}: {out:?}");
    let g = geometry(&String::from_utf8(out.stdout).unwrap());
    let page = g.page;
    let (l, t, r, b) = g.plot;
    let width = r - l;
    if width > 0.0 {
        // Across the page: at least half of it where a legend (at most a
        // third of the page) or the map's colour bar stands beside it.
        assert!(width >= 0.5 * page.0, "{what}: the plot is {width} px wide");
        // The moments stand in three panels, one a quantity, each a third
        // of the height (tests/svg_geometry.rs measures them).
        let panels = if what.contains("moments") { 3.0 } else { 1.0 };
        assert!(
            b - t >= 0.5 * page.1 / panels,
            "{what}: the plot is {} px high",
            b - t
        );
    }
    // The moments' legends stand in their panels, which
    // tests/svg_geometry.rs measures one by one.
    if let Some(lg) = g.legend.filter(|_| !what.contains("moments")) {
        assert!(
            lg.0 >= 0.0 && lg.1 >= 0.0 && lg.2 <= page.0 && lg.3 <= b,
            "{what}: the legend {lg:?} leaves the page or goes under the plot {:?}",
            g.plot
        );
        let within = lg.0 >= l && lg.2 <= r && lg.1 >= t && lg.3 <= b;
        let beside = lg.0 >= r;
        assert!(
            within || beside,
            "{what}: the legend {lg:?} straddles the plot {:?}",
            g.plot
        );
        assert!(
            lg.2 - lg.0 <= page.0 / 3.0,
            "{what}: the legend {lg:?} is too wide"
        );
        for line in &g.lines {
            if let Some(p) = inside(line, lg) {
                panic!("{what}: a line passes the legend {lg:?} at {p:?}");
            }
        }
    }
    for (k, (s, a)) in g.texts.iter().enumerate() {
        assert!(
            a.0 >= -0.5 && a.1 >= -0.5 && a.2 <= page.0 + 0.5 && a.3 <= page.1 + 0.5,
            "{what}: {s:?} at {a:?} leaves the page"
        );
        for (u, c) in &g.texts[k + 1..] {
            // A pixel's touch is no overlap (the estimate is a bound).
            assert!(
                overlap(*a, *c) <= 1.5,
                "{what}: {s:?} at {a:?} overlaps {u:?} at {c:?}"
            );
        }
    }
    (width, g.legend)
}

#[test]
fn every_measured_picture_spans_the_page_and_nothing_overlaps() {
    let d = tempfile::tempdir().unwrap();
    let psd = d.path().join("fig2-psd.txt");
    std::fs::write(&psd, common::measured::fig2_psd_text()).unwrap();
    let root = env!("CARGO_MANIFEST_DIR");
    let example = format!("{root}/surfaces/example.txt");
    let line = format!("{root}/crates/rough-surface/tests/data/line_xz.txt");
    let x3p = format!("{root}/crates/rough-surface/tests/data/formats/sur_d.x3p");
    let psd = psd.to_str().unwrap().to_string();
    let surfaces: [(&str, Vec<&str>); 5] = [
        ("example", vec!["--surface", &example]),
        ("profiles", vec!["--surface", &example, "--direction", "x"]),
        ("line", vec!["--surface", &line]),
        ("psd", vec!["--surface", &psd]),
        ("x3p", vec!["--surface", &x3p]),
    ];
    let mut pictures = 0;
    for (name, args) in &surfaces {
        for view in ["spectrum", "moments", "slopes", "indices", "map", "load"] {
            for zeta in [None, Some("zeta=2")] {
                let mut a = args.clone();
                a.extend(["--view", view]);
                if let Some(z) = zeta {
                    a.extend(["--set", z]);
                }
                let (width, legend) = check(&format!("{name} {view} {zeta:?}"), &a);
                if view == "spectrum" {
                    // The spectrum's legend fits inside its plot.
                    let lg = legend.unwrap();
                    assert!(width >= 780.0, "{name}: {width}");
                    assert!(lg.2 - lg.0 <= 300.0, "{name}: {lg:?}");
                }
                pictures += 1;
            }
        }
    }
    assert_eq!(pictures, 60);
    // The contact views of a measured map.
    let map = format!("{root}/tests/data/measured_contact/periodic64.txt");
    for view in ["contact", "contact-sweep", "contact-map"] {
        check(view, &["--surface", &map, "--view", view]);
    }
}

#[test]
fn the_example_spectrum_names_its_fit_in_the_legend_and_in_full_under_it() {
    let root = env!("CARGO_MANIFEST_DIR");
    let example = format!("{root}/surfaces/example.txt");
    let svg = stdout(&[
        "export",
        "--format",
        "svg",
        "--surface",
        &example,
        "--view",
        "spectrum",
    ]);
    let g = geometry(&svg);
    let texts: Vec<&str> = g.texts.iter().map(|(t, _)| t.as_str()).collect();
    // The legend names the fit in short, the caption says it in full.
    assert!(
        texts.contains(&"power law fit: H = 0.7915 ± 0.02313"),
        "{texts:?}"
    );
    assert!(
        texts.contains(&"the fit band 7.658e5…9.777e6 /m"),
        "{texts:?}"
    );
    let caption = texts.join(" ");
    assert!(
        caption.contains(
            "The power law fitted over the fit band 7.658e5…9.777e6 /m: H = 0.7915 ± \
             0.02313, h_rms of the fitted power law 35.82 nm (17 points)."
        ),
        "{caption}"
    );
    // The legend in a corner of the plot (the lower left: the data run
    // from the top left), the plot across the page.
    let (l, _, r, b) = g.plot;
    let lg = g.legend.unwrap();
    assert!(l <= 90.0 && r - l >= 790.0, "{:?}", g.plot);
    assert!(lg.0 < l + 20.0 && lg.3 > b - 20.0, "{lg:?} in {:?}", g.plot);
}
