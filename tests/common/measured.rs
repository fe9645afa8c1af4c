//! Measured surfaces for the tests, made in memory: fig2's power law as a
//! PSD table, and a discrete (line-scan-like) spectrum whose moments step.

use std::path::PathBuf;
use std::sync::Arc;

use rough_model::{Dim, MomentTable};
use rough_surface::{Kind, Measured, Options};
use roughtui::scene::State;
use roughtui::surface::SurfaceSource;

/// fig2's spectrum in SurfaceTopography's convention, C^iso = (2π)² Z
/// q^(−2(1+H)), Z = 1e-8, H = 0.8, one point per decade from 1e5 to 1e9.
pub fn fig2_psd_text() -> String {
    let mut text = String::from("# fig2's power law: q (1/m), C^iso (m^4)\n");
    for e in 5..=9 {
        let q = 10f64.powi(e);
        let c = (2.0 * std::f64::consts::PI).powi(2) * 1e-8 * q.powf(-3.6);
        text.push_str(&format!("{q:e} {c:e}\n"));
    }
    text
}

fn source(name: &str, measured: Measured) -> SurfaceSource {
    SurfaceSource {
        path: PathBuf::from("/data").join(name),
        options: Options::default(),
        measured: Arc::new(measured),
        recorded_sha256: None,
        fit_band: None,
    }
}

/// The scene `--surface fig2-psd.txt` opens on.
pub fn fig2_state() -> State {
    let m = rough_surface::parse(fig2_psd_text().as_bytes(), &Options::default()).unwrap();
    State::measured(source("fig2-psd.txt", m)).unwrap()
}

/// A line scan's spectrum as its FFT gives it: wavevectors n·q0 (n = 1 …
/// 64) with terms ∝ n^(−(1+2H)), H = 0.7, so that the moments are a step
/// function of ζ with a step at every integer ζ.
pub fn line_state() -> State {
    let l = 1e-5;
    let q0 = std::f64::consts::TAU / l;
    let terms: Vec<(f64, f64)> = (1..=64)
        .map(|n| (n as f64 * q0, 1e-18 * (n as f64).powf(-2.4)))
        .collect();
    let table = MomentTable::from_discrete(Dim::Profile, q0, terms.clone()).unwrap();
    let spectrum: Vec<(f64, f64)> = terms.iter().map(|&(q, w)| (q, w * l)).collect();
    let m = Measured {
        kind: Kind::Line { n: 128, l },
        table: Arc::new(table),
        sha256: "0".repeat(64),
        summary: "line scan of 128 points".to_string(),
        notes: Vec::new(),
        measurement: None,
        slopes: None,
        real: None,
        band: Measured::find_band(Dim::Profile, &spectrum, &[]),
        modes: Vec::new(),
        heights: None,
        spectrum,
    };
    State::measured(source("line.txt", m)).unwrap()
}
