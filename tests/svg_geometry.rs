//! The pictures measured as a person looks at them: curves that are
//! straight on the paper's log axes are straight in the picture (drawn
//! with sub-pixel coordinates, not on whole pixels), texts do not overlap
//! or leave the picture, axes end at the data and carry every decade in
//! range labelled in one style, points are drawn whole inside the axes and
//! the legend stays clear of them, the contact map has a scale bar of the
//! length it says.

mod common;

use common::svg::{off_straight, Picture};
use roughtui::figure::{
    render_contact, render_contact_map, render_contact_sweep, ContactLoads, ContactMap,
    ContactSweep,
};

const EXAMPLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");

/// fig1's Persson line is √(2/π)/ψ with ψ ∝ E/H0: a straight line on
/// log-log axes. Drawn on whole pixels it stepped by up to 0.9 px (a kink
/// near H0/E = 5e-4); drawn exactly it is straight to rounding. So are
/// fig2's Ψ_P ∝ ζ^(1−H) and the power law's h′(ζ) ∝ ζ^(1−H) (a staircase
/// on whole pixels).
#[test]
fn power_laws_are_straight_lines() {
    let p = Picture::export(&["--preset", "fig1", "--view", "slopes"]);
    let persson = p.curves("#00A000");
    assert_eq!(persson.len(), 1);
    let off = off_straight(&persson[0].points);
    assert!(off < 0.02, "Persson's line is {off} px off straight");
    // Coordinates with decimals: not rounded to whole pixels.
    assert!(persson[0].points.iter().any(|p| p.1.fract() != 0.0));
    let p = Picture::export(&["--preset", "fig2", "--view", "indices"]);
    let psi_p = p.curves("#0000FF");
    assert_eq!(psi_p.len(), 1);
    let off = off_straight(&psi_p[0].points);
    assert!(off < 0.02, "Ψ_P is {off} px off straight");
    let p = Picture::export(&["--preset", "fig2", "--view", "moments"]);
    for colour in ["#0000FF", "#FF0000"] {
        let c = p.curves(colour);
        assert_eq!(c.len(), 1, "{colour}");
        let off = off_straight(&c[0].points);
        assert!(off < 0.02, "{colour} is {off} px off straight");
    }
}

/// Every picture but the measured spectrum's (whose layout issue 36
/// mends): every preset's five views and the example surface's.
fn pictures() -> Vec<(String, Picture)> {
    let mut out = vec![];
    for preset in ["fig1", "fig2", "fig3", "fig4"] {
        for view in ["slopes", "indices", "map", "load", "moments"] {
            let p = Picture::export(&["--preset", preset, "--view", view]);
            out.push((format!("{preset} {view}"), p));
        }
    }
    for view in ["slopes", "indices", "map", "load", "moments"] {
        let svg = common::cli::noted(&[
            "export",
            "--format",
            "svg",
            "--surface",
            EXAMPLE,
            "--view",
            view,
        ])
        .0;
        out.push((format!("example {view}"), Picture::parse(&svg)));
    }
    out
}

/// No text overlaps another or leaves the picture, on any of them.
#[test]
fn texts_neither_overlap_nor_leave_the_picture() {
    let all = pictures();
    assert_eq!(all.len(), 25);
    for (name, p) in &all {
        let o = p.overlapping_texts();
        assert!(o.is_empty(), "{name}: overlapping texts {o:?}");
        let c: Vec<&str> = p.clipped_texts().iter().map(|t| t.text.as_str()).collect();
        assert!(c.is_empty(), "{name}: texts outside the picture {c:?}");
    }
}

/// One label per whole decade of a log axis, in one style: powers of ten
/// (10⁻⁴) or plain numbers (0.01 … 1000), never "1e0" or "1.0".
#[test]
fn log_axes_label_every_decade_in_one_style() {
    for (name, p) in pictures() {
        let (ys, xs) = p.tick_labels();
        // The moments' three y axes each have their own style: the x
        // axis alone is checked there.
        let axes = if name.ends_with("moments") {
            vec![&xs]
        } else {
            vec![&ys, &xs]
        };
        for labels in axes {
            let texts: Vec<&str> = labels.iter().map(|t| t.text.as_str()).collect();
            for t in &texts {
                assert!(
                    !t.contains('e') || t.chars().all(|c| !c.is_ascii_digit()),
                    "{name}: label {t:?} in {texts:?}"
                );
                assert!(!t.ends_with(".0"), "{name}: label {t:?}");
            }
            let powers = texts
                .iter()
                .filter(|t| {
                    t.starts_with("10")
                        && t.chars().count() > 2
                        && !t.chars().nth(2).unwrap().is_ascii_digit()
                })
                .count();
            assert!(
                powers == 0 || powers == texts.len(),
                "{name}: two styles on one axis: {texts:?}"
            );
        }
    }
}

/// The moments' ζ axis ends where the data do (fig2: 1 … 1e4; the
/// example: 1 … 135.8, not 1000), each quantity on its own axis.
#[test]
fn the_moments_axis_ends_at_the_data_one_panel_a_quantity() {
    for args in [
        &["--preset", "fig2", "--view", "moments"][..],
        &[
            "--set",
            "zeta=128",
            "--sweep",
            "h-rms:1e-9:1e-6",
            "--view",
            "moments",
        ],
    ] {
        let p = Picture::export(args);
        let (x0, _, x1, _) = p.frame();
        for colour in ["#000000", "#0000FF", "#FF0000"] {
            let c = p.curves(colour);
            assert_eq!(c.len(), 1, "{args:?} {colour}");
            let pts = &c[0].points;
            let (a, b) = (pts[0].0, pts[pts.len() - 1].0);
            assert!(
                (a - x0).abs() <= 1.5,
                "{args:?} {colour}: starts at {a}, frame {x0}"
            );
            assert!(
                (b - x1).abs() <= 1.5,
                "{args:?} {colour}: ends at {b}, frame {x1}"
            );
        }
        // Three y axes, one a quantity, each with its unit.
        for d in ["h_rms (m)", "h′ (1)", "h″ (1/m)"] {
            assert_eq!(p.text(d).len(), 1, "{args:?}: {d}");
        }
    }
    let svg = common::cli::noted(&[
        "export",
        "--format",
        "svg",
        "--surface",
        EXAMPLE,
        "--view",
        "moments",
    ])
    .0;
    let p = Picture::parse(&svg);
    let (x0, _, x1, _) = p.frame();
    let c = p.curves("#0000FF");
    let pts = &c[0].points;
    assert!((pts[0].0 - x0).abs() <= 1.5 && (pts[pts.len() - 1].0 - x1).abs() <= 1.5);
    // The last decade label is 100: the axis does not run on to 1000.
    let (_, xs) = p.tick_labels();
    let labels: Vec<&str> = xs.iter().map(|t| t.text.as_str()).collect();
    assert_eq!(labels, ["1", "10", "100"]);
}

fn fig2() -> roughtui::scene::State {
    roughtui::presets::load("fig2").unwrap()
}

/// Dots drawn whole inside the frame, the legend box clear of every dot
/// and curve (dots by their radius): what the contact pictures showed cut
/// in half at the axes' ends, and under fig3's and fig4's legends.
fn check_points_and_legend(name: &str, p: &Picture) {
    let (x0, y0, x1, y1) = p.frame();
    let lg = p.legend().unwrap_or_else(|| panic!("{name}: no legend"));
    let in_legend = |x: f64, y: f64| x >= lg.0 && x <= lg.2 && y >= lg.1 && y <= lg.3;
    let mut dots = 0;
    for d in &p.dots {
        if in_legend(d.x, d.y) {
            // The legend's own sample.
            continue;
        }
        dots += 1;
        assert!(
            d.x - d.r >= x0 - 0.5
                && d.x + d.r <= x1 + 0.5
                && d.y - d.r >= y0 - 0.5
                && d.y + d.r <= y1 + 0.5,
            "{name}: a dot at ({}, {}) r {} is cut by the frame {:?}",
            d.x,
            d.y,
            d.r,
            (x0, y0, x1, y1)
        );
        let clear = d.x + d.r < lg.0 - 2.0
            || d.x - d.r > lg.2 + 2.0
            || d.y + d.r < lg.1 - 2.0
            || d.y - d.r > lg.3 + 2.0;
        assert!(
            clear,
            "{name}: the legend {lg:?} touches the dot at ({}, {})",
            d.x, d.y
        );
    }
    assert!(dots > 0, "{name}: no dots");
    for l in p
        .lines
        .iter()
        .filter(|l| l.width >= 2.0 && l.points.len() > 2)
    {
        for w in l.points.windows(2) {
            for k in 0..=20 {
                let t = f64::from(k) / 20.0;
                let (x, y) = (
                    w[0].0 + (w[1].0 - w[0].0) * t,
                    w[0].1 + (w[1].1 - w[0].1) * t,
                );
                assert!(
                    !in_legend(x, y),
                    "{name}: a curve passes the legend at ({x}, {y})"
                );
            }
        }
    }
}

/// The contact view's picture from its data: theory lines, simulation dots
/// at the axes' ends (1e-3 and 1, A/A0 = 1), the 1e-3 tick labelled, the
/// legend clear, the scene under it and in `<desc>`.
#[test]
fn the_contact_picture_keeps_its_points_whole_and_its_legend_clear() {
    let loads: Vec<f64> = (0..13)
        .map(|i| 10f64.powf(-3.0 + 0.25 * f64::from(i)))
        .collect();
    // fig3's shape: elastic up to p̄ ≈ 0.3 H_y, plastic near p̄ = H_y.
    let area: Vec<f64> = loads.iter().map(|&p| (3.0 * p).min(1.0)).collect();
    let plastic: Vec<f64> = loads
        .iter()
        .map(|&p| if p > 0.5 { p } else { 0.0 })
        .collect();
    let elastic: Vec<f64> = area.iter().zip(&plastic).map(|(a, b)| a - b).collect();
    let theory_p: Vec<f64> = (0..120)
        .map(|i| 10f64.powf(-3.0 + 3.0 * f64::from(i) / 119.0))
        .collect();
    let th_total: Vec<f64> = theory_p.iter().map(|&p| (2.5 * p).min(1.0)).collect();
    let th_plastic: Vec<f64> = theory_p
        .iter()
        .map(|&p| if p > 0.4 { p.powi(3) } else { 0.0 })
        .collect();
    let th_elastic: Vec<f64> = th_total
        .iter()
        .zip(&th_plastic)
        .map(|(a, b)| a - b)
        .collect();
    for state in [fig2(), roughtui::presets::load("fig3").unwrap()] {
        let d = ContactLoads {
            per_asperity: false,
            surface: "128×128 nodes, seed 1".into(),
            psi: 0.49,
            p_over_h: loads.clone(),
            area: [area.clone(), elastic.clone(), plastic.clone()],
            sd: None,
            theory_p: theory_p.clone(),
            theory: [th_total.clone(), th_elastic.clone(), th_plastic.clone()],
        };
        let p = Picture::parse(&render_contact(&state, &d).unwrap());
        let name = format!("{} contact", state.name);
        check_points_and_legend(&name, &p);
        let (_, xs) = p.tick_labels();
        let labels: Vec<&str> = xs.iter().map(|t| t.text.as_str()).collect();
        assert_eq!(labels, ["10⁻³", "10⁻²", "10⁻¹", "10⁰"], "{name}");
        assert!(
            p.overlapping_texts().is_empty(),
            "{name}: {:?}",
            p.overlapping_texts()
        );
        let h = if state.size_effect { "H_y" } else { "H0" };
        assert_eq!(p.text(&format!("load p̄/{h}")).len(), 1, "{name}");
        assert!(!p.svg.contains("p̄/H "), "{name}: H alone");
        assert!(
            p.desc.contains("h0_over_e = 0.01") && p.desc.contains("view contact"),
            "{}",
            p.desc
        );
        assert!(
            p.texts
                .iter()
                .any(|t| t.text.starts_with("H0/E = 0.01 · h_rms = 19.82 nm")),
            "{name}"
        );
    }
    // With standard deviations (several seeds): error bars, still clear.
    let sd: Vec<f64> = area.iter().map(|a| 0.1 * a).collect();
    let d = ContactLoads {
        per_asperity: false,
        surface: "128×128 nodes, 4 seeds".into(),
        psi: 0.49,
        p_over_h: loads.clone(),
        area: [area.clone(), elastic.clone(), plastic.clone()],
        sd: Some([sd.clone(), sd.clone(), sd]),
        theory_p,
        theory: [th_total, th_elastic, th_plastic],
    };
    let p = Picture::parse(&render_contact(&fig2(), &d).unwrap());
    assert!(p
        .texts
        .iter()
        .any(|t| t.text == "total: simulation (mean ± sd)"));
    check_points_and_legend("fig2 contact ± sd", &p);
}

/// fig4's sweep: shares near 1 at every ζ, the legend once touched the
/// ζ = 64 point.
#[test]
fn the_sweep_picture_keeps_its_points_whole_and_its_legend_clear() {
    let zeta: Vec<f64> = (0..8).map(|k| 2f64.powi(k)).collect();
    let share = vec![0.91, 0.91, 0.91, 0.93, 0.93, 0.976, 0.988, 0.966];
    let theory_zeta: Vec<f64> = (0..100).map(|i| 128f64.powf(f64::from(i) / 99.0)).collect();
    let theory_share = vec![0.9999; 100];
    let state = roughtui::presets::load("fig4").unwrap();
    let d = ContactSweep {
        surface: "seed 1".into(),
        load: 0.01,
        load_in_h0: false,
        hardness: "H_y(R_s) at every node".into(),
        zeta,
        share,
        sd: None,
        theory_zeta,
        theory_share,
    };
    let p = Picture::parse(&render_contact_sweep(&state, &d).unwrap());
    check_points_and_legend("fig4 sweep", &p);
    let (ys, xs) = p.tick_labels();
    let x: Vec<&str> = xs.iter().map(|t| t.text.as_str()).collect();
    assert_eq!(x, ["1", "10", "100"]);
    let y: Vec<&str> = ys.iter().map(|t| t.text.as_str()).collect();
    assert!(y.contains(&"0") && y.contains(&"1"), "{y:?}");
    assert!(p.texts.iter().any(|t| t.text.contains("p̄ = 0.01 H_y")));
}

/// The contact map: the nodes at exact coordinates inside the square, a
/// scale bar as long as it says, the hardness by its name, the scene.
#[test]
fn the_contact_map_has_a_true_scale_bar() {
    let n = 64;
    let nodes: Vec<u8> = (0..n * n)
        .map(|k| ((k % 7 == 0) as u8) + ((k % 23 == 0) as u8))
        .collect();
    let side = std::f64::consts::TAU / 1e5;
    let m = ContactMap {
        seed: Some(1),
        nodes: &nodes,
        n,
        side,
        load: 0.01,
        area: 0.2,
        plastic: 0.01,
    };
    let p = Picture::parse(&render_contact_map(&fig2(), &m, "contact-map = test".into()).unwrap());
    assert!(p.desc.contains("view contact-map") && p.desc.contains("contact-map = test"));
    assert!(
        p.title.starts_with("fig2 — contact map at p̄ = 0.01 H0"),
        "{}",
        p.title
    );
    // The square: the frame drawn around the nodes.
    let frame = p
        .rects
        .iter()
        .find(|r| r.4 == "none" && (r.2 - r.0) > 200.0 && ((r.2 - r.0) - (r.3 - r.1)).abs() < 0.5)
        .expect("the map's frame");
    let side_px = frame.2 - frame.0;
    // The bar: a black filled rectangle under the square, 20 µm of 62.83.
    let bar = p
        .rects
        .iter()
        .find(|r| r.4 == "#000000" && r.1 > frame.3 && (r.3 - r.1) < 10.0)
        .expect("the scale bar");
    let want = side_px * 20e-6 / side;
    assert!(
        ((bar.2 - bar.0) - want).abs() <= 1.0,
        "bar {} px, want {want}",
        bar.2 - bar.0
    );
    assert_eq!(p.text("20 µm").len(), 1);
    // Elastic and plastic nodes, sub-pixel, inside the square.
    let cells: Vec<_> = p
        .rects
        .iter()
        // The nodes: written without plotters (no opacity), unlike the
        // legend's swatches.
        .filter(|r| (r.4 == "#8C8C8C" || r.4 == "#0000FF") && r.5.is_empty())
        .collect();
    assert!(cells.len() > 100);
    for c in &cells {
        assert!(
            c.0 >= frame.0 - 0.01
                && c.2 <= frame.2 + 0.01
                && c.1 >= frame.1 - 0.01
                && c.3 <= frame.3 + 0.01,
            "{c:?} outside {frame:?}"
        );
    }
    assert!(cells.iter().any(|c| c.0.fract() != 0.0));
    assert!(p.texts.iter().any(|t| t.text == "elastic (0 < p < H0)"));
    assert!(p.texts.iter().any(|t| t.text == "at the hardness (p = H0)"));
    assert!(
        p.overlapping_texts().is_empty(),
        "{:?}",
        p.overlapping_texts()
    );
    assert!(p.clipped_texts().is_empty());
}
