//! The index, map and load exports against the mpmath reference
//! (`scripts/gen_views.py` → `crates/rough-study/data/views_*.csv`): every
//! case the reference names is exported with its own arguments, and every
//! value must lie within the contract's 1e-12 (rough_study::rel_err).

use std::process::Command;

use rough_study::{tol, Report, Table, DATA_DIR};

const BIN: &str = env!("CARGO_BIN_EXE_roughtui");

/// Inputs (the grid) must agree to a few ulp: they are rebuilt by the script.
const GRID_TOL: f64 = 1e-14;

/// `# case N: ARGS` lines of a reference file, in order.
fn cases(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .filter_map(|l| l.strip_prefix("# case "))
        .enumerate()
        .map(|(k, l)| {
            let (n, args) = l.split_once(": ").expect("# case N: ARGS");
            assert_eq!(n.parse::<usize>().unwrap(), k);
            args.split(' ').map(String::from).collect()
        })
        .collect()
}

/// Exports every case of `file` and compares it column by column: the
/// grid columns `inputs` to [`GRID_TOL`], the outputs to the contract.
fn check(file: &str, inputs: &[&str]) {
    let path = format!("{DATA_DIR}/{file}");
    let text = std::fs::read_to_string(&path).unwrap();
    let reference = Table::parse(file, &text).unwrap();
    let case_col = reference.col("case").unwrap();
    let (mut grid, mut outputs) = (Report::default(), Report::default());
    let all = cases(&text);
    assert!(all.len() >= 4, "{file}: {} cases", all.len());
    for (k, args) in all.iter().enumerate() {
        let out = Command::new(BIN).arg("export").args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        let got = Table::parse("export", std::str::from_utf8(&out.stdout).unwrap()).unwrap();
        let want: Vec<&Vec<Option<f64>>> = reference
            .rows
            .iter()
            .filter(|r| r[case_col] == Some(k as f64))
            .collect();
        assert_eq!(got.rows.len(), want.len(), "{file} case {k}: rows");
        for (i, (g, w)) in got.rows.iter().zip(&want).enumerate() {
            for name in &got.columns {
                let at = format!("case {k} ({}) row {i}", args.join(" "));
                let (report, limit) = if inputs.contains(&name.as_str()) {
                    (&mut grid, GRID_TOL)
                } else {
                    (&mut outputs, tol::CONTRACT)
                };
                match (got.get(g, name), reference.get(w, name)) {
                    (Some(a), Some(b)) => report.check(name, &at, a, b, limit),
                    (None, None) => {}
                    // An empty field on one side only is a failure.
                    (a, b) => {
                        report.check(name, &at, a.unwrap_or(f64::NAN), b.unwrap_or(0.0), limit)
                    }
                }
            }
        }
    }
    grid.finish(&format!("{file} grid"));
    outputs.finish(file);
}

#[test]
fn indices_match_the_reference() {
    check("views_indices.csv", &["x"]);
}

#[test]
fn map_matches_the_reference() {
    check("views_map.csv", &["x", "y"]);
}

#[test]
fn load_matches_the_reference() {
    check("views_load.csv", &["load"]);
}

#[test]
fn claims_match_the_reference() {
    use roughtui::figure::{claims, ClaimKind};
    let text = std::fs::read_to_string(format!("{DATA_DIR}/views_claims.csv")).unwrap();
    let reference = Table::parse("views_claims.csv", &text).unwrap();
    let mut report = Report::default();
    for (k, args) in cases(&text).iter().enumerate() {
        assert_eq!(args[0], "--preset");
        let state = roughtui::presets::load(&args[1]).unwrap();
        let got = claims(&state);
        let want: Vec<_> = reference
            .rows
            .iter()
            .filter(|r| reference.get(r, "case") == Some(k as f64))
            .collect();
        assert_eq!(got.len(), want.len(), "{}: {got:?}", args[1]);
        for (g, w) in got.iter().zip(want) {
            let kind = match g.kind {
                ClaimKind::ShareHalf => 0.0,
                ClaimKind::IndexOne => 1.0,
            };
            assert_eq!(reference.get(w, "kind"), Some(kind), "{}", args[1]);
            let rising = reference.get(w, "rising") == Some(1.0);
            assert_eq!(g.rising, rising, "{}: {}", args[1], g.text());
            let at = reference.get(w, "at").unwrap();
            report.check(&g.text(), &args[1], g.at, at, tol::CONTRACT);
        }
    }
    report.finish("views_claims.csv");
}
