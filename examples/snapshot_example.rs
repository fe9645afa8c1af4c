//! Prints the fig2 preset as the explorer's `s` saves it: the example
//! snapshot of docs/explorer.md (`tests/docs_snapshot.rs` checks the two
//! agree). `cargo run --example snapshot_example`.

fn main() -> anyhow::Result<()> {
    print!("{}", roughtui::presets::load("fig2")?.to_ron());
    Ok(())
}
