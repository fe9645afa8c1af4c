//! What the charts draw, computed in `update` (never while drawing): the
//! curves of each view transformed to the chart's axes, non-finite and
//! non-positive points on log axes dropped.

use rough_model::slopes::{ELASTIC_BELOW, PLASTIC_ABOVE};
use rough_model::{Scene, SceneSpec};

use super::glyphs::Mark;
use crate::figure::{IndexSeries, LoadCurve};
use crate::scene::State;

/// The curves as the chart draws them: transformed to the plot's axes
/// (log10 of both values; Hurst stays linear), non-finite and non-positive
/// points dropped.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plot {
    pub elastic: Vec<(f64, f64)>,
    pub plastic: Vec<(f64, f64)>,
    pub total: Vec<(f64, f64)>,
    pub persson: Vec<(f64, f64)>,
    /// Transformed x range (the sweep's ends).
    pub x_bounds: [f64; 2],
    /// Transformed y range, whole decades.
    pub y_bounds: [f64; 2],
    /// Points sampled per curve: the chart's braille dot columns.
    pub points: usize,
    /// Where along x the regime changes: ψ crosses 1, the plastic share
    /// crosses 10 % or 90 % (transformed x, interpolated between samples).
    pub regime_marks: Vec<(f64, RegimeMark)>,
}

/// A place along the x axis where the regime changes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RegimeMark {
    /// The index in use (Ψ_P or Ψ*) crosses 1.
    PsiOne,
    /// The plastic share crosses [`ELASTIC_BELOW`] (10 %).
    ShareLow,
    /// The plastic share crosses [`PLASTIC_ABOVE`] (90 %).
    ShareHigh,
}

impl RegimeMark {
    /// The mark drawn on the x axis (its character comes from the glyphs).
    pub fn mark(self) -> Mark {
        match self {
            RegimeMark::PsiOne => Mark::PsiOne,
            RegimeMark::ShareLow => Mark::ShareLow,
            RegimeMark::ShareHigh => Mark::ShareHigh,
        }
    }
}

/// Where `ys - level` changes sign between samples, x interpolated linearly.
fn level_crossings(xs: &[f64], ys: &[f64], level: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for i in 1..xs.len().min(ys.len()) {
        let (a, b) = (ys[i - 1] - level, ys[i] - level);
        if a.is_finite() && b.is_finite() && a != b && (a < 0.0) != (b < 0.0) {
            let t = a / (a - b);
            out.push(xs[i - 1] + t * (xs[i] - xs[i - 1]));
        }
    }
    out
}

/// The regime marks of a scene, on the chart's x axis.
fn regime_marks(log_x: bool, scene: &Scene) -> Vec<(f64, RegimeMark)> {
    let xs: Vec<f64> = scene.x.iter().map(|x| to_plot(log_x, *x)).collect();
    let share: Vec<f64> = scene
        .plastic
        .iter()
        .zip(&scene.total)
        .map(|(p, t)| if t.is_infinite() { 0.0 } else { p / t })
        .collect();
    let mut marks: Vec<(f64, RegimeMark)> = Vec::new();
    for (ys, level, mark) in [
        (&scene.psi, 1.0, RegimeMark::PsiOne),
        (&share, ELASTIC_BELOW, RegimeMark::ShareLow),
        (&share, PLASTIC_ABOVE, RegimeMark::ShareHigh),
    ] {
        marks.extend(
            level_crossings(&xs, ys, level)
                .into_iter()
                .map(|x| (x, mark)),
        );
    }
    marks.sort_by(|a, b| a.0.total_cmp(&b.0));
    marks
}

/// Transforms a value for a plot axis: log10 for log axes.
pub fn to_plot(axis_is_log: bool, v: f64) -> f64 {
    if axis_is_log {
        v.log10()
    } else {
        v
    }
}

/// The smallest and largest decade the y axis may show (1e-3 … 1e2, as in
/// the paper's figures).
pub const Y_DECADES: (f64, f64) = (-3.0, 2.0);

/// `(x, y)` pairs on the chart's axes: log10 of y, and of x on log axes;
/// points that cannot be drawn there dropped.
fn log_curve(log_x: bool, xs: &[f64], ys: impl IntoIterator<Item = f64>) -> Vec<(f64, f64)> {
    xs.iter()
        .zip(ys)
        .filter(|(x, y)| x.is_finite() && y.is_finite() && *y > 0.0 && (!log_x || **x > 0.0))
        .map(|(x, y)| (to_plot(log_x, *x), y.log10()))
        .collect()
}

/// Whole decades around every y of `curves`, within `limits`, at least one
/// decade high; `limits` when there is nothing to show.
fn decade_bounds(curves: &[&Vec<(f64, f64)>], limits: (f64, f64)) -> [f64; 2] {
    let ys = || curves.iter().copied().flatten().map(|p| p.1);
    let lo = ys().fold(f64::INFINITY, f64::min);
    let hi = ys().fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite()) {
        return [limits.0, limits.1];
    }
    let lo = lo.floor().clamp(limits.0, limits.1 - 1.0);
    let hi = hi.ceil().clamp(lo + 1.0, limits.1);
    [lo, hi]
}

/// The sweep's ends on the chart's x axis.
fn sweep_bounds(sweep: &rough_model::Sweep) -> [f64; 2] {
    let log_x = sweep.axis().is_log();
    [to_plot(log_x, sweep.from()), to_plot(log_x, sweep.to())]
}

pub fn compute_plot(spec: &SceneSpec) -> Plot {
    let log_x = spec.sweep.axis().is_log();
    let mut plot = Plot {
        x_bounds: sweep_bounds(&spec.sweep),
        y_bounds: [Y_DECADES.0, Y_DECADES.1],
        points: spec.points,
        ..Plot::default()
    };
    let Ok(scene) = Scene::compute(spec) else {
        return plot;
    };
    let curve = |ys: &[f64]| log_curve(log_x, &scene.x, ys.iter().copied());
    plot.elastic = curve(&scene.elastic);
    plot.plastic = curve(&scene.plastic);
    plot.total = curve(&scene.total);
    plot.persson = curve(&scene.persson_elastic);
    plot.regime_marks = regime_marks(log_x, &scene);
    plot.y_bounds = slope_bounds(
        &[&plot.elastic, &plot.total, &plot.persson],
        &[&plot.plastic],
    );
    plot
}

/// The slopes chart's y range, fitted to the data as the picture is: from
/// the largest value of the curves `top` down to the smallest value of
/// those and of `under` within four decades of it (a plastic slope of
/// 1e-33 is no reason for 1e-3). A chart that leaves curves out while a
/// poll's answer waits fits the ones it draws: its range says nothing of
/// the others.
pub fn slope_bounds(top: &[&Vec<(f64, f64)>], under: &[&Vec<(f64, f64)>]) -> [f64; 2] {
    let hi = top
        .iter()
        .copied()
        .flatten()
        .map(|p| p.1)
        .fold(f64::NEG_INFINITY, f64::max);
    let near: Vec<(f64, f64)> = top
        .iter()
        .chain(under)
        .copied()
        .flatten()
        .copied()
        .filter(|p| p.1 >= hi - 4.0)
        .collect();
    decade_bounds(&[&near], Y_DECADES)
}

/// The decades the index view may show (1e-4 … 1e6): wide enough for Ψ_GW
/// of a rough soft surface and Ψ* of a smooth hard one.
pub const INDEX_DECADES: (f64, f64) = (-4.0, 6.0);

/// The index view's curves: Ψ_GW, Ψ_P, Ψ* and eq. 13's Ψ*asy against the
/// swept parameter, log10 of each.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IndexPlot {
    pub psi_gw: Vec<(f64, f64)>,
    pub psi_p: Vec<(f64, f64)>,
    pub psi_star: Vec<(f64, f64)>,
    /// Eq. 13; empty where undefined (R* = 0).
    pub psi_star_asymptotic: Vec<(f64, f64)>,
    pub x_bounds: [f64; 2],
    /// Whole decades, always including Ψ = 1.
    pub y_bounds: [f64; 2],
}

pub fn compute_indices(state: &State, points: usize) -> IndexPlot {
    let log_x = state.sweep.axis().is_log();
    let mut p = IndexPlot {
        x_bounds: sweep_bounds(&state.sweep),
        y_bounds: [-1.0, 1.0],
        ..IndexPlot::default()
    };
    let Ok(s) = IndexSeries::compute(state, points) else {
        return p;
    };
    let curve = |ys: &[f64]| log_curve(log_x, &s.x, ys.iter().copied());
    p.psi_gw = curve(&s.psi_gw);
    p.psi_p = curve(&s.psi_p);
    p.psi_star = curve(&s.psi_star);
    let asy = s.psi_star_asymptotic.iter().map(|v| v.unwrap_or(f64::NAN));
    p.psi_star_asymptotic = log_curve(log_x, &s.x, asy);
    let one = vec![(p.x_bounds[0], 0.0)];
    let curves = [
        &p.psi_gw,
        &p.psi_p,
        &p.psi_star,
        &p.psi_star_asymptotic,
        &one,
    ];
    p.y_bounds = decade_bounds(&curves, INDEX_DECADES);
    p
}

/// The load view's curves: A/A0 against p̄/H on linear axes from 0 to 1,
/// and the initial-slope line S_tot·p̄/H from the origin.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LoadPlot {
    pub elastic: Vec<(f64, f64)>,
    pub plastic: Vec<(f64, f64)>,
    pub total: Vec<(f64, f64)>,
    pub tangent: Vec<(f64, f64)>,
    /// The initial slope of the total area (the tangent's slope).
    pub slope: f64,
}

pub fn compute_load(state: &State, points: usize) -> LoadPlot {
    let Ok(c) = LoadCurve::compute(state, points) else {
        return LoadPlot::default();
    };
    let curve = |ys: &[f64]| -> Vec<(f64, f64)> {
        c.load
            .iter()
            .zip(ys)
            .filter(|(_, y)| y.is_finite())
            .map(|(x, y)| (*x, *y))
            .collect()
    };
    LoadPlot {
        elastic: curve(&c.elastic),
        plastic: curve(&c.plastic),
        total: curve(&c.total),
        tangent: vec![(0.0, 0.0), c.tangent_end()],
        slope: c.slopes.total,
    }
}

/// The spectrum view's curves on log-log axes: the data, the power law
/// fitted over the fit band, the band's ends, and the cutoff q1.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpectrumPlot {
    /// (log10 q, log10 PSD) of the data.
    pub data: Vec<(f64, f64)>,
    /// The fitted power law over the fit band, same axes.
    pub fit: Vec<(f64, f64)>,
    /// log10 of the fit band's ends.
    pub band: Option<[f64; 2]>,
    /// log10 q1, the cutoff (the marker).
    pub q1: f64,
    /// log10 q0.
    pub q0: f64,
    pub x_bounds: [f64; 2],
    pub y_bounds: [f64; 2],
    /// "C^iso (m⁴)" or "C1D (m³)".
    pub label: &'static str,
}

/// Whole decades around the finite values of `v` (at least one).
fn decades_around(v: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = v
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    if !(lo.is_finite() && hi.is_finite()) {
        return [0.0, 1.0];
    }
    let lo = lo.floor();
    [lo, hi.ceil().max(lo + 1.0)]
}

pub fn compute_spectrum(state: &State, points: usize) -> SpectrumPlot {
    let Ok(s) = crate::figure::SpectrumSeries::of(state) else {
        return SpectrumPlot::default();
    };
    let data = log_curve(true, &s.q, s.psd.iter().copied());
    let x_bounds = decades_around(data.iter().map(|p| p.0));
    let y_bounds = decades_around(data.iter().map(|p| p.1));
    let band = s.power_law.map(|f| [f.q_lo.log10(), f.q_hi.log10()]);
    let [a, b] = band.unwrap_or([0.0, 0.0]);
    let n = points.clamp(2, 400);
    let fit = if s.power_law.is_some() && b > a {
        let qs: Vec<f64> = (0..n)
            .map(|i| 10f64.powf(a + (b - a) * i as f64 / (n - 1) as f64))
            .collect();
        let ys = qs.iter().map(|&q| s.fit_at(q).unwrap_or(f64::NAN));
        log_curve(true, &qs, ys)
            .into_iter()
            .filter(|p| p.1 >= y_bounds[0] && p.1 <= y_bounds[1])
            .collect()
    } else {
        Vec::new()
    };
    SpectrumPlot {
        data,
        fit,
        band,
        q1: s.q1.log10(),
        q0: s.q0.log10(),
        x_bounds,
        y_bounds,
        label: s.psd_label(),
    }
}
