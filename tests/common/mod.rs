//! Helpers shared by the integration tests (each test file includes the
//! parts it needs with `mod common;`).
#![allow(dead_code)]

pub mod app;
pub mod browser;
pub mod cli;
pub mod client;
pub mod codes;
pub mod contact;
pub mod docs;
pub mod lecture;
pub mod measured;
pub mod merge;
pub mod room;
pub mod serve;
pub mod svg;
pub mod tmux;

use std::path::Path;

use ratatui::backend::TestBackend;
use ratatui::Terminal;

/// A valid schema-v1 snapshot (fig2), laid out as in the issue: the error
/// tests edit it and expect line and column numbers of this layout.
pub const GOOD: &str = "(
    version: 1,
    name: \"fig2\",
    params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, hurst: 0.8, r_star: 0.001, q0: 100000.0),
    size_effect: false,
    sweep: (axis: Zeta, from: 1.0, to: 10000.0),
    model: Exact,
)
";

/// The file names in `dir`, sorted.
pub fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// The text of a drawn test terminal, one line per row.
pub fn buffer_text(t: &Terminal<TestBackend>) -> String {
    let buf = t.backend().buffer();
    let mut s = String::new();
    for y in 0..buf.area.height {
        for x in 0..buf.area.width {
            s.push_str(buf[(x, y)].symbol());
        }
        s.push('\n');
    }
    s
}

/// A key press as crossterm reports it.
pub fn key(
    code: crossterm::event::KeyCode,
    mods: crossterm::event::KeyModifiers,
) -> crossterm::event::KeyEvent {
    crossterm::event::KeyEvent {
        code,
        modifiers: mods,
        kind: crossterm::event::KeyEventKind::Press,
        state: crossterm::event::KeyEventState::NONE,
    }
}
