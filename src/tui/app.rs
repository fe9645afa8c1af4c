//! The explorer's state and its one mutator, [`update`]. Drawing only reads
//! an [`App`]; every change, including the recomputation of the curves, goes
//! through a [`Message`].

use std::path::PathBuf;
use std::time::SystemTime;

use rough_model::{Axis, Curves, SceneSpec};

use super::ghost::Ghost;
use super::layout::Regions;
use super::line_edit::LineEdit;
use super::measured;
pub use super::message::Message;
use super::plots::{
    compute_indices, compute_load, compute_plot, compute_spectrum, IndexPlot, LoadPlot, Plot,
    SpectrumPlot,
};
use super::prompt;
pub use super::readout::Readout;
pub use super::status::Hint;
pub use super::steps::{default_range, step_value, HURST_STEPS, LOG_STEPS};
use super::theme::Theme;
use super::views::overlap::Cover;
use crate::class::Classroom;
use crate::figure::{render_svg, shown_claims, Claim, FigureOptions, MapCache, MapSpec, View};
use crate::presets;
use crate::scene::{swept_out, KeptCaption, State};
use crate::snapshot;

mod look;
mod shown;
pub use look::Look;

#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Main,
    Help,
    /// The save prompt with the name typed so far.
    Prompt(LineEdit),
    /// The prompt for a slider's value, with the text typed so far.
    Value(Axis, LineEdit),
    /// The lecturer's prompt for a poll's true value of the swept parameter.
    Truth(Axis, LineEdit),
    /// The lecturer's class list.
    Class,
}

impl Mode {
    /// The open prompt's text field, if a prompt is open.
    pub fn line_mut(&mut self) -> Option<&mut LineEdit> {
        match self {
            Mode::Prompt(l) | Mode::Value(_, l) | Mode::Truth(_, l) => Some(l),
            Mode::Main | Mode::Help | Mode::Class => None,
        }
    }
}

/// The longest text a prompt takes.
pub const PROMPT_MAX_CHARS: usize = 200;

/// A line for the status bar.
#[derive(Clone, Debug, PartialEq)]
pub struct Status {
    pub text: String,
    pub error: bool,
    /// For a hint: the condition it is about; it clears once that no
    /// longer holds.
    pub hint: Option<Hint>,
}

/// What the curves along the sweep depend on; they are recomputed only
/// when it changes.
#[derive(Clone, Debug, PartialEq)]
struct CurveKey {
    spec: SceneSpec,
}

/// What the load view depends on: the state at the marker and the points.
type LoadKey = (rough_model::Params, SceneSpec);

/// What the spectrum view depends on: the surface and the cutoff ζ.
type SpectrumKey = (rough_model::Roughness, f64, usize, Option<(f64, f64)>);

pub struct App {
    pub state: State,
    /// Index into [`Axis::ALL`] of the selected slider.
    pub selected: usize,
    pub mode: Mode,
    /// The help's page (wrapping around the pages the terminal needs).
    pub help_page: usize,
    pub status: Option<Status>,
    /// Terminal size, columns × rows.
    pub size: (u16, u16),
    pub theme: Theme,
    /// The chart on screen.
    pub view: View,
    /// The regime map's y axis (`None`: H0/E, or ζ when H0/E is swept).
    pub map_y: Option<Axis>,
    /// The slopes view's curves.
    pub plot: Plot,
    /// Which of them lie under another on the graph, computed with them.
    pub plot_cover: Option<Cover>,
    pub indices: IndexPlot,
    pub load: LoadPlot,
    /// A measured surface's spectrum, the fit over the band and q1.
    pub spectrum: SpectrumPlot,
    /// The regime map, computed only when something it depends on changes.
    pub map: MapCache,
    /// The figure's checkable claims at the current parameters.
    pub claims: Vec<Claim>,
    pub readout: Readout,
    /// Where `s` saves.
    pub save_dir: PathBuf,
    /// Whether the parameters differ from the loaded preset or snapshot.
    pub modified: bool,
    /// The name of the file the scene was loaded from or last saved to;
    /// `None` for a preset.
    pub file: Option<String>,
    /// Curves pinned with `g`, drawn dim under the current ones.
    pub ghost: Option<Ghost>,
    /// Whether this is a student's explorer in a served class: its keys,
    /// help and footer then include following the lecturer.
    pub student: bool,
    /// Whether the class has a lecturer to follow (`--lecturer-keys`).
    pub lecturer_keys: bool,
    /// Whether a lecturer is connected now (the footer offers `f` then).
    pub lecturer_here: bool,
    /// The measured surface's scene the session started on, which `5`
    /// returns to after a preset; `None` without a surface.
    pub home: Option<State>,
    /// The served class as this explorer sees it (nothing when not served).
    pub class: Classroom,
    /// The contact view's simulation.
    pub contact: super::contact::ContactPane,
    pub quit: bool,
    /// How many times the curves were computed (for tests of the cache).
    pub recomputes: usize,
    key: Option<CurveKey>,
    indices_key: Option<CurveKey>,
    load_key: Option<LoadKey>,
    spectrum_key: Option<SpectrumKey>,
    claims_key: Option<CurveKey>,
    /// The loaded scene's caption and the scene it describes.
    captioned: KeptCaption,
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
            help_page: 0,
            status: None,
            size,
            theme,
            view: View::Slopes,
            map_y: None,
            plot: Plot::default(),
            plot_cover: None,
            indices: IndexPlot::default(),
            load: LoadPlot::default(),
            spectrum: SpectrumPlot::default(),
            map: MapCache::new(),
            claims: Vec::new(),
            readout,
            save_dir: std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")),
            modified: false,
            file: None,
            ghost: None,
            student: false,
            lecturer_keys: false,
            lecturer_here: false,
            home: None,
            class: Classroom::default(),
            contact: Default::default(),
            quit: false,
            recomputes: 0,
            key: None,
            indices_key: None,
            load_key: None,
            spectrum_key: None,
            claims_key: None,
            captioned: KeptCaption::default(),
        };
        app.captioned = KeptCaption::of(&app.state);
        app.selected = Axis::ALL
            .iter()
            .position(|a| *a == app.state.sweep.axis())
            .unwrap_or(0);
        measured::fix_selection(&mut app);
        super::ghost::restore(&mut app);
        if app.state.is_measured() {
            app.home = Some(app.state.clone());
        }
        if let Some(w) = app.state.surface_warning() {
            app.set_status(w, true);
        } else {
            measured::show_notes(&mut app);
        }
        app.refresh();
        app
    }

    /// Whether the terminal is below the smallest size the explorer draws in.
    pub fn too_small(&self) -> bool {
        Regions::of_size(self.size).is_none()
    }

    pub fn selected_axis(&self) -> Axis {
        Axis::ALL[self.selected % Axis::ALL.len()]
    }

    /// The range of a slider: the sweep's for the swept parameter, else the
    /// default one (ζ up to the data's largest on a measured surface).
    pub fn range(&self, axis: Axis) -> (f64, f64) {
        if axis == self.state.sweep.axis() {
            (self.state.sweep.from(), self.state.sweep.to())
        } else {
            measured::range(self, axis)
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
        spec.base = swept_out(&self.state, spec.base);
        CurveKey { spec }
    }

    /// The regime map's spec at the current state on a grid of `graph`'s
    /// cells, two points per cell up (half blocks).
    pub fn map_spec(&self, graph: ratatui::layout::Rect) -> Option<MapSpec> {
        let grid = (usize::from(graph.width), usize::from(graph.height) * 2);
        // A y axis that became the swept one falls back to the default.
        let y = self.map_y.filter(|a| *a != self.state.sweep.axis());
        MapSpec::of(&self.state, grid, y).ok()
    }

    /// Recomputes the readout, and what the chart on screen and the claims
    /// line show when what they depend on changed; clears a hint that no
    /// longer applies.
    fn refresh(&mut self) {
        if let Some(h) = self.status.as_ref().and_then(|s| s.hint) {
            if !h.applies(&self.state) {
                self.status = None;
            }
        }
        if self.ghost.as_ref().is_some_and(|g| !g.fits(&self.state)) {
            self.ghost = None;
            self.set_status("ghost cleared: the sweep changed", false);
        }
        if !self.view.exists(self.state.is_measured()) {
            self.view = View::Slopes;
        }
        self.readout = Readout::of(&self.state);
        let shown = self.view == View::Contact;
        self.contact.refresh(&self.state, shown);
        let Some(regions) = Regions::of_app(self) else {
            return;
        };
        let points = (usize::from(regions.graph.width) * 2).max(2);
        let key = self.curve_key(points);
        let claims_key = self.curve_key(2);
        if self.claims_key.as_ref() != Some(&claims_key) {
            self.claims = shown_claims(&self.state);
            self.claims_key = Some(claims_key);
        }
        match self.view {
            View::Slopes => {
                if self.key.as_ref() != Some(&key) {
                    self.plot = compute_plot(&key.spec);
                    self.key = Some(key);
                    self.recomputes += 1;
                    self.plot_cover = None;
                }
                let dots = self.theme.glyphs.dots();
                let g = regions.slopes_graph();
                Cover::keep(&mut self.plot_cover, &self.plot, g, dots);
            }
            View::Indices if self.indices_key.as_ref() != Some(&key) => {
                self.indices = compute_indices(&self.state, points);
                self.indices_key = Some(key);
            }
            View::Load => {
                let load_key = (self.state.params, key.spec);
                if self.load_key.as_ref() != Some(&load_key) {
                    self.load = compute_load(&self.state, points);
                    self.load_key = Some(load_key);
                }
            }
            View::Map => {
                if let Some(spec) = self.map_spec(regions.graph) {
                    self.map.get(&spec);
                }
            }
            View::Spectrum => {
                let band = self.state.surface.as_ref().and_then(|s| s.fit_band());
                let key = (
                    self.state.roughness(),
                    self.state.params.zeta(),
                    points,
                    band,
                );
                if self.spectrum_key.as_ref() != Some(&key) {
                    self.spectrum = compute_spectrum(&self.state, points);
                    self.spectrum_key = Some(key);
                }
            }
            _ => {}
        }
    }

    /// Writes the current view as an SVG picture into the save folder, under
    /// the snapshot save's rules (never overwriting, written atomically).
    fn save_picture(&mut self) {
        let opts = FigureOptions {
            map_y: self.map_y.filter(|a| *a != self.state.sweep.axis()),
            ..FigureOptions::default()
        };
        let name = format!("{}-{}", self.state.name, self.view.name());
        let stem = snapshot::default_stem(&name, SystemTime::now());
        if self.view == View::Contact {
            return super::contact::save(self, &stem);
        }
        let svg = render_svg(self.view, &self.state, &opts);
        let saved = svg.and_then(|svg| {
            snapshot::save_file_new(&self.save_dir, &stem, "svg", "picture", svg.as_bytes())
        });
        match saved {
            Ok(path) => self.set_status(format!("saved {}", path.display()), false),
            Err(e) => self.set_status(format!("{e:#}"), true),
        }
    }

    pub fn set_status(&mut self, text: impl Into<String>, error: bool) {
        self.status = Some(Status {
            text: text.into(),
            error,
            hint: None,
        });
    }

    pub(super) fn set_hint(&mut self, hint: Hint) {
        self.status = Some(Status {
            text: hint.text().into(),
            error: false,
            hint: Some(hint),
        });
    }

    /// Shows what another session shows (a followed lecturer's explorer):
    /// its scene, selected slider, view and map axis.
    pub fn show(&mut self, state: &State, selected: usize, view: View, map_y: Option<Axis>) {
        let selected = selected % Axis::ALL.len();
        if self.state != *state
            || self.selected != selected
            || self.view != view
            || self.map_y != map_y
        {
            self.state = state.clone();
            self.selected = selected;
            self.view = view;
            self.map_y = map_y;
            self.captioned = KeptCaption::of(&self.state);
            self.refresh();
        }
    }

    /// Shows `state` as freshly loaded (not modified, no file), keeping
    /// the selected slider where the scene has it.
    pub fn load_state(&mut self, state: State) {
        let axis = self.selected_axis();
        self.state = state;
        self.modified = false;
        self.file = None;
        self.captioned = KeptCaption::of(&self.state);
        self.selected = Axis::ALL.iter().position(|a| *a == axis).unwrap_or(0);
        measured::fix_selection(self);
        // A preset or the session's surface: the view stays as it is.
        self.state.shown = Default::default();
    }
}

/// Why H = 1 and the asymptotic moments do not go together, in the
/// explorer's words with the key that helps, within 80 columns (the
/// model's error names the snapshot field).
pub const HURST_ONE_ASYMPTOTIC: &str =
    "H = 1 needs truncated moments (asymptotic m2 is infinite there): press a first";

/// The one place that changes an [`App`].
pub fn update(app: &mut App, msg: Message) {
    super::status::clear_stale(app, msg);
    match msg {
        Message::SelectPrev => app.selected = measured::next_selectable(app, app.selected, false),
        Message::SelectNext => app.selected = measured::next_selectable(app, app.selected, true),
        Message::Step { .. } if measured::refuse_fixed(app, app.selected_axis()) => {}
        Message::Step { up, fine } => {
            let axis = app.selected_axis();
            let old = app.state.params.get(axis);
            let v = step_value(axis, old, app.range(axis), up, fine);
            match app.state.params.with(axis, v) {
                Ok(p) if app.state.moments.check(&p).is_err() => {
                    app.set_status(HURST_ONE_ASYMPTOTIC, true)
                }
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
                    app.load_state(s);
                    app.set_status(format!("loaded {name}"), false);
                }
                Err(e) => app.set_status(format!("{e:#}"), true),
            }
        }
        Message::LoadSurface => measured::load_surface(app),
        Message::CycleSweep => measured::cycle_sweep(app),
        Message::ToggleModel => {
            app.state.model = app.state.model.other();
            app.modified = true;
        }
        Message::ToggleSizeEffect => {
            app.state.size_effect = !app.state.size_effect;
            app.modified = true;
        }
        Message::ToggleMoments if app.state.is_measured() => {
            app.set_status(measured::MOMENTS_DO_NOT_APPLY, true)
        }
        Message::ToggleMoments => {
            let moments = app.state.moments.other();
            if moments.check(&app.state.params).is_ok() {
                app.state.moments = moments;
                app.modified = true;
            } else {
                app.set_status(HURST_ONE_ASYMPTOTIC, true);
            }
        }
        Message::NextView => app.view = app.view.next(app.state.is_measured()),
        Message::PrevView => app.view = app.view.prev(app.state.is_measured()),
        Message::NextMapY => {
            let graph = Regions::of_app(app).map(|r| r.graph);
            if let Some(spec) = graph.and_then(|g| app.map_spec(g)) {
                app.map_y = Some(spec.next_y());
            }
        }
        Message::SavePicture => app.save_picture(),
        Message::ToggleGhost => measured::toggle_ghost(app),
        Message::MoveFitBand { upper, up } => measured::move_fit_band(app, upper, up),
        Message::AutoFitBand => measured::auto_fit_band(app),
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
            app.mode = Mode::Prompt(LineEdit::new(&stem, PROMPT_MAX_CHARS));
        }
        Message::StartValue => {
            let axis = app.selected_axis();
            if !measured::refuse_fixed(app, axis) {
                app.mode = Mode::Value(axis, LineEdit::new("", PROMPT_MAX_CHARS));
            }
        }
        Message::ToggleHelp => {
            app.help_page = 0;
            app.mode = match app.mode {
                Mode::Help => Mode::Main,
                _ => Mode::Help,
            }
        }
        Message::CloseHelp => app.mode = Mode::Main,
        Message::HelpPage { next } => {
            app.help_page = if next {
                app.help_page.wrapping_add(1)
            } else {
                app.help_page.wrapping_sub(1)
            }
        }
        Message::PromptEdit(e) => {
            if let Some(l) = app.mode.line_mut() {
                l.apply(e);
            }
        }
        Message::PromptCancel => match app.mode {
            Mode::Prompt(_) => {
                app.mode = Mode::Main;
                app.set_status("save cancelled", false);
            }
            Mode::Value(..) | Mode::Truth(..) => {
                // The refusal was about the text just dropped.
                app.mode = Mode::Main;
                app.status = None;
            }
            Mode::Main | Mode::Help | Mode::Class => {}
        },
        Message::PromptAccept => prompt::accept(app),
        Message::Resize(w, h) => app.size = (w, h),
        Message::Follow
        | Message::Redraw
        | Message::Poll
        | Message::SavePoll
        | Message::Answer
        | Message::CancelPoll
        | Message::AnswerNowhere
        | Message::ShareAnswers
        | Message::AllFollow => {}
        Message::ShowJoin => {
            app.class.join_shown = !app.class.join_shown && app.class.join_url.is_some();
        }
        Message::Projector | Message::Countdown => super::class::projector(app, msg),
        Message::ClassChoose { down } => super::class::choose(app, down),
        Message::RemoveStudent => super::class::remove(app),
        Message::LessonStep { next } => super::class::step(app, next),
        Message::OpenScenes
        | Message::SceneMove { .. }
        | Message::ScenePick
        | Message::SceneClose => super::scenes::update(app, msg),
        Message::PollTyped => {
            let axis = app.state.sweep.axis();
            app.mode = Mode::Truth(axis, LineEdit::new("", PROMPT_MAX_CHARS));
        }
        Message::ToggleClass => {
            app.help_page = 0;
            app.mode = match app.mode {
                Mode::Class => Mode::Main,
                _ => Mode::Class,
            }
        }
        Message::CycleGlyphs => {
            let g = app.theme.glyphs.next();
            app.theme = app.theme.with_glyphs(g);
            app.set_status(format!("drawing in {} (M: next)", g.describe()), false);
        }
        Message::ToggleColor => {
            app.theme = app.theme.with_color(!app.theme.color);
            let text = if app.theme.color {
                format!("colour on ({}) (c: off)", app.theme.palette.name())
            } else {
                "colour off, as under NO_COLOR (c: on)".to_string()
            };
            app.set_status(text, false);
        }
        Message::ContactLoad { .. }
        | Message::ContactSweep
        | Message::ContactSlopes
        | Message::ContactSeed
        | Message::ContactSeeds
        | Message::ContactTable
        | Message::ContactHardness => super::contact::on_key(app, msg),
        Message::Tick => {}
        Message::Quit => app.quit = true,
    }
    app.captioned.apply(&mut app.state);
    app.refresh();
}
