//! `roughtui export --view contact-slopes`: the simulation's initial slopes
//! against ζ beside the theory's, whose columns are the slopes view's
//! elastic, plastic and total for the same scene; the picture; the
//! refusals.

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

/// The columns by name.
fn col(header: &str, name: &str) -> usize {
    header
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("{name} not in {header}"))
}

#[test]
fn the_theory_columns_are_the_slopes_views() {
    // fig3: the size effect on, the slopes normalised by H_y (a coarse grid
    // keeps the test quick: 4 nodes per wavelength, at least 256²).
    for preset in ["fig2", "fig3"] {
        let csv = stdout(&[
            "export",
            "--view",
            "contact-slopes",
            "--preset",
            preset,
            "--cell",
            "1",
            "--per-wavelength",
            "4",
        ]);
        let (comments, header, rows) = parse(&csv);
        assert!(header.starts_with(
            "zeta,sim_elastic_slope,sim_elastic_slope_sd,sim_plastic_slope,sim_plastic_slope_sd,\
             sim_total_slope,sim_total_slope_sd,theory_elastic_slope,theory_plastic_slope,\
             theory_total_slope,seeds"
        ));
        assert!(
            comments
                .iter()
                .any(|c| c.starts_with("# slopes = initial slopes")
                    && c.contains(
                        "fitted by A = s x + c x^2 through the origin over the 4 lightest"
                    )),
            "{comments:#?}"
        );
        let slopes = stdout(&[
            "export",
            "--view",
            "slopes",
            "--preset",
            preset,
            "--sweep",
            "zeta:1:128",
            "--points",
            "8",
        ]);
        let (_, sh, srows) = parse(&slopes);
        assert_eq!(rows.len(), 8);
        for (r, s) in rows.iter().zip(&srows) {
            assert!((r[0] / s[0] - 1.0).abs() < 1e-14, "ζ {} {}", r[0], s[0]);
            for (mine, theirs) in [
                ("theory_elastic_slope", "elastic"),
                ("theory_plastic_slope", "plastic"),
                ("theory_total_slope", "total"),
            ] {
                let (a, b) = (r[col(header, mine)], s[col(sh, theirs)]);
                assert!(
                    (a - b).abs() <= 1e-12 * b.abs(),
                    "{preset} ζ = {}: {mine} {a} against the slopes view's {b}",
                    r[0]
                );
            }
            // One seed: its slopes, no spread; the parts non-negative.
            assert_eq!(r[col(header, "seeds")], 1.0);
            assert!(r[col(header, "sim_total_slope_sd")].is_nan());
            for c in ["sim_elastic_slope", "sim_plastic_slope", "sim_total_slope"] {
                assert!(r[col(header, c)] >= 0.0, "{c} {r:?}");
            }
            // The loads: p̄/(E* h′) = 0.5e-3 … 8e-3, at least 256² a side.
            assert!(r[col(header, "grid")] >= 256.0);
            let (lo, hi) = (
                r[col(header, "p_over_h_lightest")],
                r[col(header, "p_over_h_heaviest")],
            );
            assert!((hi / lo - 16.0).abs() < 1e-9, "{lo} {hi}");
        }
    }
}

#[test]
fn the_slopes_picture_and_refusals() {
    // A measured map: its own grid at each ζ it resolves (quick).
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/surfaces/example.txt");
    let svg = stdout(&[
        "export",
        "--view",
        "contact-slopes",
        "--surface",
        example,
        "--format",
        "svg",
    ]);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let text: String = doc.descendants().filter_map(|n| n.text()).collect();
    for want in [
        "total: theory",
        "total: simulation",
        "Initial slopes H_y·dA/(A0·dp̄)",
    ] {
        assert!(text.contains(want), "{want} not in {text}");
    }
    for (extra, needle) in [
        (
            vec!["--points", "3"],
            "--points does not apply to --view contact-slopes",
        ),
        (
            vec!["--load-scale", "in-use"],
            "--load-scale does not apply to --view contact-slopes",
        ),
    ] {
        let mut args = vec!["export", "--view", "contact-slopes", "--preset", "fig2"];
        args.extend(extra.iter().copied());
        let out = run(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{err}");
    }
}
