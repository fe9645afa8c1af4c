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

/// The reference's name of an export column: the export names its grid
/// columns after the parameters (`zeta`, `h0_over_e`, …), the reference,
/// whose cases sweep different parameters in one file, `x` (across) and
/// `y` (up).
fn reference_name(k: usize, name: &str, inputs: &[&str]) -> String {
    // The reference (scripts/gen_views.py) names H_y/H0 `hardness_ratio`;
    // the export calls it `hy_over_h0` (its slopes' `h_use_over_h0` is
    // the hardness in use, another quantity).
    if name == "hy_over_h0" {
        return "hardness_ratio".into();
    }
    match inputs.get(k) {
        Some(&grid) if grid != name && rough_model::Axis::ALL.iter().any(|a| a.field() == name) => {
            grid.to_string()
        }
        _ => name.to_string(),
    }
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
        // The export's first columns are named after the swept parameters.
        let names: Vec<String> = got
            .columns
            .iter()
            .enumerate()
            .map(|(c, n)| reference_name(c, n, inputs))
            .collect();
        assert_eq!(names, reference.columns[1..], "{file} case {k}: columns");
        for (i, (g, w)) in got.rows.iter().zip(&want).enumerate() {
            for (got_name, name) in got.columns.iter().zip(&names) {
                let at = format!("case {k} ({}) row {i}", args.join(" "));
                let (report, limit) = if inputs.contains(&name.as_str()) {
                    (&mut grid, GRID_TOL)
                } else {
                    (&mut outputs, tol::CONTRACT)
                };
                match (got.get(g, got_name), reference.get(w, name)) {
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

/// The preset and overrides of a `# case` line (`--preset`, `--model`,
/// `--moments`), as the explorer would hold them.
fn state_of(args: &[String]) -> roughtui::scene::State {
    use rough_model::{Model, Moments};
    assert_eq!(args[0], "--preset");
    let mut state = roughtui::presets::load(&args[1]).unwrap();
    for pair in args[2..].chunks(2) {
        match (pair[0].as_str(), pair[1].as_str()) {
            ("--model", "exact") => state.model = Model::Exact,
            ("--model", "closed-form") => state.model = Model::ClosedForm,
            ("--moments", "truncated") => state.moments = Moments::Truncated,
            ("--moments", "asymptotic") => state.moments = Moments::Asymptotic,
            other => panic!("unexpected case argument {other:?}"),
        }
    }
    state
}

#[test]
fn claims_match_the_reference() {
    use roughtui::figure::{claims, ClaimKind};
    let text = std::fs::read_to_string(format!("{DATA_DIR}/views_claims.csv")).unwrap();
    let reference = Table::parse("views_claims.csv", &text).unwrap();
    let (mut crossings, mut minima, mut values) =
        (Report::default(), Report::default(), Report::default());
    let all = cases(&text);
    assert!(all.len() >= 6, "{} cases", all.len());
    for (k, args) in all.iter().enumerate() {
        let case = args.join(" ");
        let got = claims(&state_of(args));
        let want: Vec<_> = reference
            .rows
            .iter()
            .filter(|r| reference.get(r, "case") == Some(k as f64))
            .collect();
        assert_eq!(got.len(), want.len(), "{case}: {got:?}");
        for (g, w) in got.iter().zip(want) {
            let kind = match g.kind {
                ClaimKind::ShareHalf => 0.0,
                ClaimKind::IndexOne => 1.0,
                ClaimKind::TotalMinimum => 2.0,
            };
            assert_eq!(reference.get(w, "kind"), Some(kind), "{case}");
            let rising = reference.get(w, "rising") == Some(1.0);
            assert_eq!(g.rising, rising, "{case}: {}", g.text());
            let at = reference.get(w, "at").unwrap();
            let value = reference.get(w, "value").unwrap();
            if g.kind == ClaimKind::TotalMinimum {
                minima.check(&g.text(), &case, g.at, at, tol::MINIMUM_PLACE);
            } else {
                crossings.check(&g.text(), &case, g.at, at, tol::CONTRACT);
            }
            values.check(&g.text(), &case, g.value, value, tol::CONTRACT);
        }
    }
    crossings.finish("views_claims.csv crossings");
    minima.finish("views_claims.csv minima (place)");
    values.finish("views_claims.csv values");
}

/// The numbers docs/model.md and the help quote, against the mpmath reference
/// (`views_quoted.csv`), and quoted as the reference rounds them.
#[test]
fn quoted_numbers_match_the_reference_and_the_docs() {
    use rough_model::{closed_form, persson_elastic, psi_in_use, Axis, Moments};
    let reference = Table::read("views_quoted.csv").unwrap();
    let want = |id: usize| {
        let row = reference
            .rows
            .iter()
            .find(|r| reference.get(r, "id") == Some(id as f64))
            .unwrap();
        reference.get(row, "value").unwrap()
    };
    let fig2 = roughtui::presets::load("fig2").unwrap().params;
    let psi = |zeta: f64, moments| {
        let p = fig2.with(Axis::Zeta, zeta).unwrap();
        psi_in_use(&p, false, moments).0.to_f64()
    };
    let at_1000 = closed_form(psi(1000.0, Moments::Asymptotic));
    let persson = persson_elastic(psi(1000.0, Moments::Asymptotic));
    let got = [
        psi(128.0, Moments::Asymptotic),
        psi(128.0, Moments::Truncated),
        at_1000.plastic_share(),
        (at_1000.total - persson) / at_1000.total,
        // The dip's place is an input here: the claims test checks where
        // the explorer finds it.
        want(4),
        closed_form(want(4)).total,
    ];
    let mut report = Report::default();
    for (id, g) in got.iter().enumerate() {
        report.check(
            &format!("id {id}"),
            "views_quoted.csv",
            *g,
            want(id),
            tol::CONTRACT,
        );
    }
    report.finish("views_quoted.csv");
    // As quoted (three or four digits).
    // The paper's numbers are quoted in the model's page of the manual.
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/model.md"))
        .unwrap()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    let help: String = roughtui::tui::help::SYMBOLS
        .iter()
        .map(|(_, w)| *w)
        .collect::<Vec<_>>()
        .join(" ");
    let r = |v: f64, digits: usize| format!("{v:.digits$}");
    for quote in [
        format!(
            "Ψ_P at ζ = 128 is {} instead of {}",
            r(want(0), 3),
            r(want(1), 3)
        ),
        format!("{} instead of {}", r(want(3), 3), r(want(2), 3)),
        format!("to {} at ψ = {}", r(want(5), 4), r(want(4), 3)),
    ] {
        assert!(
            readme.contains(&quote),
            "docs/model.md does not say {quote:?}"
        );
    }
    let quote = format!("{}, not {}", r(want(3), 3), r(want(2), 3));
    assert!(help.contains(&quote), "the help does not say {quote:?}");
}
