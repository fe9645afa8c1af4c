//! The speed targets of `roughtui bench`, each measured in the same run as
//! the table above it and printed as a ratio or a time beside its goal.

use std::fmt::Write as _;
use std::hint::black_box;
use std::process::{Command, Stdio};
use std::time::Instant;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

use super::{median, time_call, Row};
use crate::figure::{MapSpec, RegimeMap};
use crate::tui::app::App;
use crate::tui::layout::Regions;
use crate::tui::theme::Theme;
use crate::tui::views::overlap::Cover;

/// The NumPy/SciPy peer of `roughtui export --preset fig2`, as committed
/// under `scripts/`; run with `python3 -c` when python3 has NumPy and SciPy.
const NUMPY_PEER: &str = include_str!("../../scripts/closed_form_numpy.py");

/// Points of the export target.
pub const EXPORT_POINTS: usize = 200_000;

/// Runs of each whole command in the export comparison (the median counts).
const EXPORT_RUNS: usize = 3;

/// One line of the targets table.
struct Target {
    what: String,
    measured: String,
    goal: &'static str,
    /// `None` where nothing was measured.
    met: Option<bool>,
}

/// The targets table: the shipped closed form against the exact series
/// (from `rows`), the regime maps, the slopes view's cover per frame, and,
/// with `whole_commands`, `roughtui export` (this executable) against the
/// NumPy peer.
pub fn table(rows: &[Row], passes: u32, whole_commands: bool) -> anyhow::Result<String> {
    let mut t = Vec::new();
    let row = |name: &str| rows.iter().find(|r| r.name == name);
    if let (Some(c), Some(e)) = (row("closed (shipped)"), row("exact (shipped)")) {
        let ratio = c.ns_per_point / e.ns_per_point;
        t.push(Target {
            what: "closed (shipped) / exact (shipped), ns/point".into(),
            measured: format!(
                "{ratio:.2}× ({:.1} / {:.1} ns), max rel error {}",
                c.ns_per_point,
                e.ns_per_point,
                super::fmt_err(c.err.max)
            ),
            goal: "≤ 1.2×, error ≤ 2e-15",
            met: Some(ratio <= 1.2 && c.err.max <= 2e-15),
        });
    }
    if whole_commands {
        t.push(export_target());
    }
    for (preset, goal, limit) in [("fig2", "≤ 1.0 ms", 1.0), ("fig4", "≤ 1.5 ms", 1.5)] {
        let ms = time_map(preset, passes)? / 1e3;
        t.push(Target {
            what: format!("regime map 200 × 60, {preset} (closed form), median"),
            measured: format!("{ms:.2} ms"),
            goal,
            met: Some(ms <= limit),
        });
    }
    let (trace, cached, uncached) = slopes_frame(passes)?;
    t.push(Target {
        what: "slopes view, which cells each curve covers".into(),
        measured: format!(
            "{trace:.1} µs once per change of the curves; per frame 0 (frame {cached:.0} µs, \
             {uncached:.0} µs when it traced them)"
        ),
        goal: "cached with the curves",
        met: Some(cached < uncached),
    });
    let mut s = String::from("| target | measured | goal | met |\n|---|---|---|---|\n");
    for x in &t {
        let met = match x.met {
            Some(true) => "yes",
            Some(false) => "no",
            None => "-",
        };
        let _ = writeln!(s, "| {} | {} | {} | {met} |", x.what, x.measured, x.goal);
    }
    Ok(s)
}

/// Median µs of one regime map of `preset` at 200 × 60 cells (a
/// 200-column terminal's map), computed afresh each time.
pub fn time_map(preset: &str, passes: u32) -> anyhow::Result<f64> {
    let state = crate::presets::load(preset)?;
    let spec = MapSpec::of(&state, (200, 60), None)?;
    Ok(time_call(passes.max(1), || {
        RegimeMap::compute(black_box(&spec))
    }))
}

/// The slopes view of fig2 in a 200 × 60 terminal: µs to trace which cells
/// each curve covers, and µs per whole frame with the cover kept and with
/// it traced in the frame (as every frame did before it was kept).
fn slopes_frame(passes: u32) -> anyhow::Result<(f64, f64, f64)> {
    let size = (200, 60);
    let mut app = App::new(crate::presets::load("fig2")?, Theme::colored(), size);
    let area = Rect::new(0, 0, size.0, size.1);
    let g = Regions::of(area)
        .ok_or_else(|| anyhow::anyhow!("terminal too small"))?
        .graph;
    let dots = app.theme.glyphs.dots();
    let n = passes.max(1) * 8;
    let trace = time_call(n, || Cover::of(black_box(&app.plot), g, dots));
    let mut buf = Buffer::empty(area);
    let mut frame = |app: &App| {
        time_call(n, || {
            buf.reset();
            black_box(app).render(area, &mut buf);
        })
    };
    let cached = frame(&app);
    app.plot_cover = None;
    let uncached = frame(&app);
    Ok((trace, cached, uncached))
}

/// `roughtui export --preset fig2 --points 200000` (this executable) against
/// the NumPy peer, whole commands with stdout to /dev/null, alternated,
/// median of [`EXPORT_RUNS`] each.
fn export_target() -> Target {
    let what = format!("export fig2 {EXPORT_POINTS} points: NumPy peer / roughtui, median of 3");
    let goal = "≥ 20×";
    let points = EXPORT_POINTS.to_string();
    let ours = std::env::current_exe().map(|exe| {
        let mut c = Command::new(exe);
        c.args(["export", "--preset", "fig2", "--points", &points]);
        c
    });
    let peer = || {
        let mut c = Command::new("python3");
        c.args(["-c", NUMPY_PEER, "--points", &points]);
        c
    };
    let have_peer = Command::new("python3")
        .args(["-c", "import numpy, scipy.special"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    let mut ours = match ours {
        Ok(c) => c,
        Err(e) => {
            return Target {
                what,
                measured: format!("not measured: {e}"),
                goal,
                met: None,
            }
        }
    };
    if !have_peer {
        return Target {
            what,
            measured: "not measured: python3 with NumPy and SciPy not found \
                       (scripts/bench_export.sh runs both)"
                .into(),
            goal,
            met: None,
        };
    }
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for _ in 0..EXPORT_RUNS {
        match (time_command(&mut ours), time_command(&mut peer())) {
            (Ok(x), Ok(y)) => {
                a.push(x);
                b.push(y);
            }
            (Err(e), _) | (_, Err(e)) => {
                return Target {
                    what,
                    measured: format!("not measured: {e}"),
                    goal,
                    met: None,
                }
            }
        }
    }
    let (ms, peer_ms) = (median(&mut a), median(&mut b));
    let ratio = peer_ms / ms;
    Target {
        what,
        measured: format!("{ratio:.1}× ({peer_ms:.0} ms / {ms:.0} ms)"),
        goal,
        met: Some(ratio >= 20.0),
    }
}

/// Wall-clock ms of one run of `c`, stdout to /dev/null.
fn time_command(c: &mut Command) -> anyhow::Result<f64> {
    let t = Instant::now();
    let status = c.stdout(Stdio::null()).stderr(Stdio::null()).status()?;
    let ms = t.elapsed().as_secs_f64() * 1e3;
    anyhow::ensure!(status.success(), "{:?} failed: {status}", c.get_program());
    Ok(ms)
}
