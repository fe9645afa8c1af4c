//! The explorer's state and its one mutator, [`update`]. Drawing only reads
//! an [`App`]; every change, including the recomputation of the curves, goes
//! through a [`Message`].

use std::path::PathBuf;
use std::time::SystemTime;

use rough_model::{
    persson_elastic, slopes, Axis, Curves, Scene, SceneSpec, Slopes, Surface, Sweep,
};

use super::theme::Theme;
use super::view;
use crate::presets;
use crate::snapshot::{self, State};

/// Everything that can happen to the explorer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Message {
    SelectPrev,
    SelectNext,
    /// Move the selected slider one step up or down, coarse or fine.
    Step {
        up: bool,
        fine: bool,
    },
    /// Load preset number n (0 = fig1).
    LoadPreset(usize),
    CycleSweep,
    ToggleModel,
    ToggleSizeEffect,
    StartSave,
    ToggleHelp,
    CloseHelp,
    PromptInput(char),
    PromptBackspace,
    PromptCancel,
    PromptAccept,
    Resize(u16, u16),
    Quit,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Main,
    Help,
    /// The save prompt with the name typed so far.
    Prompt(String),
}

/// A line for the status bar.
#[derive(Clone, Debug, PartialEq)]
pub struct Status {
    pub text: String,
    pub error: bool,
}

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
}

/// Everything the readout shows, at the current parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Readout {
    pub surface: Surface,
    /// The index in use (Ψ_P or Ψ*).
    pub psi: f64,
    pub slopes: Slopes,
    /// The other model's slopes at the same ψ.
    pub other: Slopes,
    pub persson: f64,
}

impl Readout {
    pub fn of(state: &State) -> Readout {
        let surface = Surface::of(&state.params, state.moments);
        let psi = surface.indices.psi_in_use(state.size_effect);
        Readout {
            surface,
            psi: psi.to_f64(),
            slopes: slopes(state.model, psi),
            other: slopes(state.model.other(), psi),
            persson: persson_elastic(psi),
        }
    }
}

/// What the curves depend on; they are recomputed only when it changes.
#[derive(Clone, Copy, Debug, PartialEq)]
struct CurveKey {
    spec: SceneSpec,
}

pub struct App {
    pub state: State,
    /// Index into [`Axis::ALL`] of the selected slider.
    pub selected: usize,
    pub mode: Mode,
    pub status: Option<Status>,
    /// Terminal size, columns × rows.
    pub size: (u16, u16),
    pub theme: Theme,
    pub plot: Plot,
    pub readout: Readout,
    /// Where `s` saves.
    pub save_dir: PathBuf,
    /// Whether the parameters differ from the loaded preset or snapshot.
    pub modified: bool,
    pub quit: bool,
    /// How many times the curves were computed (for tests of the cache).
    pub recomputes: usize,
    key: Option<CurveKey>,
}

/// The default range of each parameter, for its slider and when `x` makes it
/// the swept one.
pub fn default_range(axis: Axis) -> (f64, f64) {
    match axis {
        Axis::H0OverE => (1e-4, 1e-1),
        Axis::HRms => (1e-9, 1e-5),
        Axis::Zeta => (1.0, 1e6),
        Axis::Hurst => (0.05, 1.0),
        Axis::RStar => (1e-6, 1e-2),
    }
}

/// Log steps per decade (coarse, fine); Hurst steps (coarse, fine).
pub const LOG_STEPS: (f64, f64) = (4.0, 40.0);
pub const HURST_STEPS: (f64, f64) = (0.05, 0.01);

/// One step from `v` on the grid of the given step, clamped to `[lo, hi]`.
/// Values snap to the grid (10^(k/4), 10^(k/40); multiples of 0.05, 0.01),
/// so repeated steps do not drift and a coarse step from a fine value lands
/// on the next coarse one.
pub fn step_value(axis: Axis, v: f64, (lo, hi): (f64, f64), up: bool, fine: bool) -> f64 {
    const EPS: f64 = 1e-6;
    let next = |t: f64| {
        if up {
            (t + EPS).floor() + 1.0
        } else {
            (t - EPS).ceil() - 1.0
        }
    };
    let out = if axis.is_log() {
        let n = if fine { LOG_STEPS.1 } else { LOG_STEPS.0 };
        if !(v > 0.0 && v.is_finite()) {
            return lo;
        }
        10f64.powf(next(v.log10() * n) / n)
    } else {
        let s = if fine { HURST_STEPS.1 } else { HURST_STEPS.0 };
        if !v.is_finite() {
            return lo;
        }
        // Round to kill 0.15000000000000002.
        (next(v / s) * s * 1e9).round() / 1e9
    };
    out.clamp(lo, hi)
}

impl App {
    /// An app over `state` in a terminal of `size` (columns, rows), saving
    /// into the current directory.
    pub fn new(state: State, theme: Theme, size: (u16, u16)) -> App {
        let readout = Readout::of(&state);
        let mut app = App {
            state,
            selected: 0,
            mode: Mode::Main,
            status: None,
            size,
            theme,
            plot: Plot::default(),
            readout,
            save_dir: std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")),
            modified: false,
            quit: false,
            recomputes: 0,
            key: None,
        };
        app.selected = Axis::ALL
            .iter()
            .position(|a| *a == app.state.sweep.axis())
            .unwrap_or(0);
        app.refresh();
        app
    }

    pub fn selected_axis(&self) -> Axis {
        Axis::ALL[self.selected % Axis::ALL.len()]
    }

    /// The range of a slider: the sweep's for the swept parameter, else the
    /// default one.
    pub fn range(&self, axis: Axis) -> (f64, f64) {
        if axis == self.state.sweep.axis() {
            (self.state.sweep.from(), self.state.sweep.to())
        } else {
            default_range(axis)
        }
    }

    /// Where the marker stands: the swept parameter's value, if inside the sweep.
    pub fn marker(&self) -> Option<f64> {
        let s = &self.state.sweep;
        let v = self.state.params.get(s.axis());
        (v >= s.from() && v <= s.to()).then_some(v)
    }

    fn curve_key(&self, points: usize) -> CurveKey {
        let mut spec = self.state.scene_spec(Curves::ALL, points);
        // The swept value only moves the marker: normalize it out of the key.
        let s = &self.state.sweep;
        spec.base = spec.base.with(s.axis(), s.from()).unwrap_or(spec.base);
        CurveKey { spec }
    }

    /// Recomputes the readout, and the curves when what they depend on changed.
    fn refresh(&mut self) {
        self.readout = Readout::of(&self.state);
        let Some(graph) = view::graph_area(self.size) else {
            return;
        };
        let points = (usize::from(graph.width) * 2).max(2);
        let key = self.curve_key(points);
        if self.key == Some(key) {
            return;
        }
        self.plot = compute_plot(&key.spec);
        self.key = Some(key);
        self.recomputes += 1;
    }

    pub fn set_status(&mut self, text: impl Into<String>, error: bool) {
        self.status = Some(Status {
            text: text.into(),
            error,
        });
    }

    /// Shows `state` with slider `selected` selected, as another session
    /// has it (a followed lecturer's explorer).
    pub fn show(&mut self, state: &State, selected: usize) {
        if self.state != *state || self.selected != selected {
            self.state = state.clone();
            self.selected = selected % Axis::ALL.len();
            self.refresh();
        }
    }

    fn load(&mut self, state: State) {
        let axis = self.selected_axis();
        self.state = state;
        self.modified = false;
        self.selected = Axis::ALL.iter().position(|a| *a == axis).unwrap_or(0);
    }
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

fn compute_plot(spec: &SceneSpec) -> Plot {
    let log_x = spec.sweep.axis().is_log();
    let x_bounds = [
        to_plot(log_x, spec.sweep.from()),
        to_plot(log_x, spec.sweep.to()),
    ];
    let mut plot = Plot {
        x_bounds,
        y_bounds: [Y_DECADES.0, Y_DECADES.1],
        points: spec.points,
        ..Plot::default()
    };
    let Ok(scene) = Scene::compute(spec) else {
        return plot;
    };
    let curve = |ys: &[f64]| -> Vec<(f64, f64)> {
        scene
            .x
            .iter()
            .zip(ys)
            .filter(|(x, y)| x.is_finite() && y.is_finite() && **y > 0.0 && (!log_x || **x > 0.0))
            .map(|(x, y)| (to_plot(log_x, *x), y.log10()))
            .collect()
    };
    plot.elastic = curve(&scene.elastic);
    plot.plastic = curve(&scene.plastic);
    plot.total = curve(&scene.total);
    plot.persson = curve(&scene.persson_elastic);
    let ys = || {
        [&plot.elastic, &plot.plastic, &plot.total, &plot.persson]
            .into_iter()
            .flatten()
            .map(|p| p.1)
    };
    let lo = ys().fold(f64::INFINITY, f64::min);
    let hi = ys().fold(f64::NEG_INFINITY, f64::max);
    if lo.is_finite() && hi.is_finite() {
        let lo = lo.floor().clamp(Y_DECADES.0, Y_DECADES.1 - 1.0);
        let hi = hi.ceil().clamp(lo + 1.0, Y_DECADES.1);
        plot.y_bounds = [lo, hi];
    }
    plot
}

/// The one place that changes an [`App`].
pub fn update(app: &mut App, msg: Message) {
    let n = Axis::ALL.len();
    match msg {
        Message::SelectPrev => app.selected = (app.selected + n - 1) % n,
        Message::SelectNext => app.selected = (app.selected + 1) % n,
        Message::Step { up, fine } => {
            let axis = app.selected_axis();
            let old = app.state.params.get(axis);
            let v = step_value(axis, old, app.range(axis), up, fine);
            match app.state.params.with(axis, v) {
                Ok(p) => {
                    if p != app.state.params {
                        app.state.params = p;
                        app.modified = true;
                    }
                }
                Err(e) => app.set_status(e.to_string(), true),
            }
        }
        Message::LoadPreset(i) => {
            let Some((name, _)) = presets::PRESETS.get(i) else {
                return;
            };
            match presets::load(name) {
                Ok(s) => {
                    app.load(s);
                    app.set_status(format!("loaded {name}"), false);
                }
                Err(e) => app.set_status(format!("{e:#}"), true),
            }
        }
        Message::CycleSweep => {
            let cur = app.state.sweep.axis();
            let i = Axis::ALL.iter().position(|a| *a == cur).unwrap_or(0);
            let axis = Axis::ALL[(i + 1) % n];
            let (lo, hi) = default_range(axis);
            match Sweep::new(axis, lo, hi) {
                Ok(s) => {
                    app.state.sweep = s;
                    app.modified = true;
                    if axis == Axis::RStar && !app.state.size_effect {
                        app.set_status("R* acts only with the size effect: press e", false);
                    }
                }
                Err(e) => app.set_status(e.to_string(), true),
            }
        }
        Message::ToggleModel => {
            app.state.model = app.state.model.other();
            app.modified = true;
        }
        Message::ToggleSizeEffect => {
            app.state.size_effect = !app.state.size_effect;
            app.modified = true;
        }
        Message::StartSave => {
            // The prefill is a file name: no separators or control characters.
            let name: String = app
                .state
                .name
                .chars()
                .map(|c| {
                    if c.is_control() || c == '/' || c == '\\' {
                        '_'
                    } else {
                        c
                    }
                })
                .collect();
            let stem = snapshot::default_stem(&name, SystemTime::now());
            app.mode = Mode::Prompt(stem);
        }
        Message::ToggleHelp => {
            app.mode = match app.mode {
                Mode::Help => Mode::Main,
                _ => Mode::Help,
            }
        }
        Message::CloseHelp => app.mode = Mode::Main,
        Message::PromptInput(c) => {
            if let Mode::Prompt(s) = &mut app.mode {
                if s.chars().count() < 200 {
                    s.push(c);
                }
            }
        }
        Message::PromptBackspace => {
            if let Mode::Prompt(s) = &mut app.mode {
                s.pop();
            }
        }
        Message::PromptCancel => {
            if matches!(app.mode, Mode::Prompt(_)) {
                app.mode = Mode::Main;
                app.set_status("save cancelled", false);
            }
        }
        Message::PromptAccept => {
            let Mode::Prompt(stem) = &app.mode else {
                return;
            };
            let stem = stem.clone();
            if let Err(why) = snapshot::check_stem(&stem) {
                // Stay in the prompt so the name can be fixed.
                app.set_status(format!("cannot save: {why}"), true);
                return;
            }
            app.mode = Mode::Main;
            match snapshot::save_new(&app.save_dir, &stem, &app.state) {
                Ok(path) => app.set_status(format!("saved {}", path.display()), false),
                Err(e) => app.set_status(format!("{e:#}"), true),
            }
        }
        Message::Resize(w, h) => app.size = (w, h),
        Message::Quit => app.quit = true,
    }
    app.refresh();
}
