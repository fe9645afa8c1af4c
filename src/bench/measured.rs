//! Speed on a measured surface: reading the file to the first screen, a ζ
//! step and an H0/E step (update and a 160×48 frame, the terminal's own
//! output left out), and the process's peak memory.
//!
//! `roughtui bench --surface FILE` times a file; without one, a synthetic
//! 1024 × 1024 FFT grid (a power law over 1,048,575 wavevectors, built in
//! memory: the moment table's share of the work, no reading or FFT).

use std::fmt::Write as _;
use std::time::Instant;

use ratatui::backend::TestBackend;
use ratatui::Terminal;

use rough_surface::Options;

use crate::scene::State;
use crate::surface::SurfaceSource;
use crate::tui::app::{update, App, Message};
use crate::tui::theme::Theme;

/// The terminal the frames are drawn for.
pub const SIZE: (u16, u16) = (160, 48);

/// What one run measured, in ms and µs.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceTimes {
    /// The state ready: file read and moments tabulated (ms).
    pub read_ms: f64,
    /// From there to the first frame drawn: curves, claims, readout (ms).
    pub first_frame_ms: f64,
    /// Median of ζ steps, each update + frame (µs).
    pub zeta_step_us: f64,
    /// Median of H0/E steps, each update + frame, curves recomputed (µs).
    pub h0_step_us: f64,
    /// Distinct wavevectors (or PSD points) in the table.
    pub nodes: usize,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The explorer on `state` at [`SIZE`]: the first frame, then `steps`
/// steps of ζ and of H0/E (down and up in turn), each drawn.
pub fn time_frames(state: State, steps: usize) -> anyhow::Result<(f64, f64, f64)> {
    let t = Instant::now();
    let mut app = App::new(state, Theme::colored(), SIZE);
    let mut term = Terminal::new(TestBackend::new(SIZE.0, SIZE.1))?;
    term.draw(|f| f.render_widget(&app, f.area()))?;
    let first = t.elapsed().as_secs_f64() * 1e3;
    let mut step = |app: &mut App, axis: usize| -> anyhow::Result<f64> {
        app.selected = axis;
        let mut v = Vec::with_capacity(steps);
        for k in 0..steps.max(1) {
            let t = Instant::now();
            update(
                app,
                Message::Step {
                    up: k % 2 == 1,
                    fine: false,
                },
            );
            term.draw(|f| f.render_widget(&*app, f.area()))?;
            v.push(t.elapsed().as_secs_f64() * 1e6);
        }
        Ok(median(v))
    };
    let zeta = step(&mut app, 2)?;
    let h0 = step(&mut app, 0)?;
    Ok((first, zeta, h0))
}

/// Times `path` read with `options`.
pub fn time_file(
    path: &std::path::Path,
    options: Options,
    steps: usize,
) -> anyhow::Result<SurfaceTimes> {
    let t = Instant::now();
    let state = State::measured(SurfaceSource::read(path, options)?)?;
    let read_ms = t.elapsed().as_secs_f64() * 1e3;
    let nodes = nodes(&state);
    let (first_frame_ms, zeta_step_us, h0_step_us) = time_frames(state, steps)?;
    Ok(SurfaceTimes {
        read_ms,
        first_frame_ms,
        zeta_step_us,
        h0_step_us,
        nodes,
    })
}

fn nodes(state: &State) -> usize {
    state
        .surface
        .as_ref()
        .map_or(0, |s| s.measured.table.nodes().len())
}

/// Times the synthetic n × n grid.
pub fn time_synthetic(n: usize, steps: usize) -> anyhow::Result<SurfaceTimes> {
    let t = Instant::now();
    let state = crate::scene::synthetic(n)?;
    let read_ms = t.elapsed().as_secs_f64() * 1e3;
    let nodes = nodes(&state);
    let (first_frame_ms, zeta_step_us, h0_step_us) = time_frames(state, steps)?;
    Ok(SurfaceTimes {
        read_ms,
        first_frame_ms,
        zeta_step_us,
        h0_step_us,
        nodes,
    })
}

/// The process's peak resident memory in MB (Linux), if known.
pub fn peak_rss_mb() -> Option<f64> {
    let st = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb: f64 = st
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))?
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kb / 1024.0)
}

/// The report's lines for `what` (a file, or the synthetic grid).
pub fn report(what: &str, t: &SurfaceTimes, steps: usize) -> String {
    let mut out = String::new();
    let read = if what.starts_with("synthetic") {
        "tabulated (no file)"
    } else {
        "read and tabulated"
    };
    let _ = writeln!(
        out,
        "{what}: {} wavevector magnitudes; {read} in {:.1} ms; first {}×{} frame {:.1} ms \
         later ({:.1} ms in all).",
        t.nodes,
        t.read_ms,
        SIZE.0,
        SIZE.1,
        t.first_frame_ms,
        t.read_ms + t.first_frame_ms
    );
    let _ = writeln!(
        out,
        "  ζ step {:.0} µs, H0/E step (curves and claims recomputed) {:.0} µs: update and \
         frame, median of {steps} each, terminal output not included.",
        t.zeta_step_us, t.h0_step_us
    );
    if let Some(mb) = peak_rss_mb() {
        let _ = writeln!(out, "  peak memory of this process: {mb:.0} MB.");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_synthetic_grid_is_timed() {
        let t = time_synthetic(32, 3).unwrap();
        // 1023 wavevectors, fewer distinct magnitudes (symmetry).
        assert!(t.nodes > 100 && t.nodes < 1023, "{}", t.nodes);
        for v in [t.read_ms, t.first_frame_ms, t.zeta_step_us, t.h0_step_us] {
            assert!(v > 0.0 && v.is_finite(), "{t:?}");
        }
        let r = report("synthetic 32 × 32", &t, 3);
        assert!(
            r.contains("wavevector magnitudes; tabulated (no file)"),
            "{r}"
        );
        assert!(r.contains("ζ step "), "{r}");
    }
}
