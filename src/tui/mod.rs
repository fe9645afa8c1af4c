//! The full-screen explorer.

use crate::snapshot::State;

pub fn run(state: State) -> anyhow::Result<()> {
    anyhow::bail!("the explorer for {} is not built yet", state.name)
}
