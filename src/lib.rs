//! roughtui as a library: the command line, snapshots, presets, the headless
//! commands and the TUI, so that tests and benchmarks reach them. The binary
//! (`src/main.rs`) only parses and dispatches.

pub mod bench;
pub mod cli;
pub mod csv_number;
pub mod export;
pub mod figure;
pub mod presets;
pub mod serve;
pub mod snapshot;
pub mod tui;

use cli::Source;
use snapshot::State;

/// The state named by `--preset` or `--load`, fig2 when neither is given.
pub fn load_source(src: &Source) -> anyhow::Result<State> {
    if let Some(path) = &src.load {
        return snapshot::load_file(path);
    }
    presets::load(src.preset.as_deref().unwrap_or("fig2"))
}
