//! Accuracy against the 50-digit mpmath reference (scripts/gen_reference.py):
//! every output within 1e-12 relative, values below 1e-300 may be 0.

use rough_model::{
    closed_form, exact, persson_elastic, slopes, Model, Moments, ParamValues, Params, Surface,
};
use rough_study::{tol, Report, Table};

#[test]
fn slopes_of_both_models_match_reference() {
    let t = Table::read("slopes.csv").unwrap();
    let mut r = Report::default();
    for row in &t.rows {
        let psi = t.get(row, "psi").unwrap();
        let input = format!("psi={psi:e}");
        let e = exact(psi);
        let c = closed_form(psi);
        for (name, got) in [
            ("exact_elastic", e.elastic),
            ("exact_plastic", e.plastic),
            ("exact_total", e.total),
            ("closed_elastic", c.elastic),
            ("closed_plastic", c.plastic),
            ("closed_total", c.total),
            ("persson_elastic", persson_elastic(psi)),
        ] {
            r.check(name, &input, got, t.get(row, name).unwrap(), tol::CONTRACT);
        }
    }
    r.finish("slopes.csv");
}

/// Both models' slopes at the reference's exact double ψ, from 1e-308 to
/// 1.8e308, within 2e-15 (the closed form's fast path included: its
/// exponential, erfcx table and fits; see `slopes/closed.rs`).
#[test]
fn slopes_within_2e_15_of_reference() {
    let t = Table::read("slopes.csv").unwrap();
    let mut r = Report::default();
    for row in &t.rows {
        let psi = t.get(row, "psi").unwrap();
        let input = format!("psi={psi:e}");
        let (e, c) = (exact(psi), closed_form(psi));
        for (name, got) in [
            ("exact_elastic", e.elastic),
            ("exact_plastic", e.plastic),
            ("exact_total", e.total),
            ("closed_elastic", c.elastic),
            ("closed_plastic", c.plastic),
            ("closed_total", c.total),
        ] {
            r.check(name, &input, got, t.get(row, name).unwrap(), tol::SLOPES);
        }
    }
    r.finish("slopes.csv at 2e-15");
}

#[test]
fn check_values_of_model_md() {
    let mut r = Report::default();
    let e = exact(1.0);
    let c = closed_form(1.0);
    for (name, got, want) in [
        ("exact S_el", e.elastic, 0.0287675334233055),
        ("exact S_pl", e.plastic, 0.985616238638923),
        ("exact S_tot", e.total, 1.01438377206223),
        ("closed S_el", c.elastic, 0.106442719176429),
        ("closed S_pl", c.plastic, 0.900581342322006),
        ("closed S_tot", c.total, 1.00702406149844),
    ] {
        // docs/model.md prints 15 digits.
        r.check(name, "psi=1", got, want, 1e-14);
    }
    let fig2 = Params::new(ParamValues {
        h0_over_e: 1e-2,
        h_rms: 19.816636488030044e-9,
        zeta: 128.0,
        hurst: 0.8,
        r_star: 1e-3,
        q0: 1e5,
    })
    .unwrap();
    let psi_p = Surface::of(&fig2, Moments::Asymptotic).indices.psi_p;
    r.check(
        "asymptotic Psi_P",
        "fig2, zeta=128",
        psi_p,
        0.522964172217328,
        1e-14,
    );
    r.finish("docs/model.md check values");
}

fn params_of(t: &Table, row: &[Option<f64>]) -> Params {
    Params::new(ParamValues {
        h0_over_e: t.get(row, "h0_over_e").unwrap(),
        h_rms: t.get(row, "h_rms").unwrap(),
        zeta: t.get(row, "zeta").unwrap(),
        hurst: t.get(row, "hurst").unwrap(),
        r_star: t.get(row, "r_star").unwrap(),
        q0: t.get(row, "q0").unwrap(),
    })
    .expect("reference inputs are valid")
}

#[test]
fn spectrum_indices_and_slopes_from_parameters_match_reference() {
    check_params_table("params.csv", Moments::Truncated);
}

#[test]
fn asymptotic_moments_match_reference() {
    check_params_table("params_asymptotic.csv", Moments::Asymptotic);
}

/// Every output of `Surface::of` under `moments`, and both models' slopes at
/// Ψ_P and Ψ*, against one table of the reference.
fn check_params_table(file: &str, moments: Moments) {
    let t = Table::read(file).unwrap();
    let mut r = Report::default();
    for row in &t.rows {
        let p = params_of(&t, row);
        let v = p.values();
        let input = format!(
            "(h0_over_e={:e}, h_rms={:e}, zeta={:e}, hurst={}, r_star={:e}, q0={:e})",
            v.h0_over_e, v.h_rms, v.zeta, v.hurst, v.r_star, v.q0
        );
        let s = Surface::of(&p, moments);
        let (sp, ix) = (s.spectrum, s.indices);
        let mut chk = |name: &str, got: f64| {
            r.check(name, &input, got, t.get(row, name).unwrap(), tol::CONTRACT)
        };
        #[rustfmt::skip]
        let outputs = [
            ("z", sp.z), ("m0", sp.m0), ("m2", sp.m2), ("m4", sp.m4), ("r_s", sp.r_s),
            ("lambda1", sp.lambda1), ("h_rms_actual", sp.h_rms_actual),
            ("rms_slope", sp.rms_slope), ("rms_curvature", sp.rms_curvature),
            ("hardness_ratio", ix.hardness_ratio), ("psi_gw", ix.psi_gw),
            ("psi_p", ix.psi_p), ("psi_star", ix.psi_star),
        ];
        for (name, got) in outputs {
            chk(name, got);
        }
        for (size_effect, suffix) in [(false, "p"), (true, "star")] {
            let psi = ix.psi_in_use(size_effect);
            let e = slopes(Model::Exact, psi);
            let c = slopes(Model::ClosedForm, psi);
            for (model, s) in [("exact", e), ("closed", c)] {
                for (part, got) in [("el", s.elastic), ("pl", s.plastic), ("tot", s.total)] {
                    chk(&format!("{model}_{part}_{suffix}"), got);
                }
            }
        }
        match (t.get(row, "psi_star_asym"), ix.psi_star_asymptotic) {
            (Some(want), Some(got)) => r.check("psi_star_asym", &input, got, want, tol::CONTRACT),
            (None, None) => {}
            (want, got) => panic!("psi_star_asym at {input}: got {got:?}, want {want:?}"),
        }
    }
    r.finish(file);
}
