//! roughtui as a library: the command line, snapshots, presets, the headless
//! commands and the TUI, so that tests and benchmarks reach them. The binary
//! (`src/main.rs`) only parses and dispatches. Each module uses only those
//! on the floors below it (docs/development.md draws them; `tests/layers.rs`
//! checks them).

pub mod bench;
pub mod class;
pub mod cli;
pub mod contact;
pub mod export;
pub mod figure;
pub mod physical;
pub mod presets;
pub mod scene;
pub mod serve;
pub mod snapshot;
pub mod surface;
pub mod tui;
