//! The paper's four figures as snapshots, built into the binary, and a
//! scene where its "elastic again at small scales" lies within the contact
//! simulation's reach (`elastic-again`).

use crate::scene::State;

/// (name, RON text) of every preset: the paper's figures in key order
/// 1–4, then `elastic-again` (no key).
pub const PRESETS: [(&str, &str); 5] = [
    ("fig1", include_str!("../presets/fig1.ron")),
    ("fig2", include_str!("../presets/fig2.ron")),
    ("fig3", include_str!("../presets/fig3.ron")),
    ("fig4", include_str!("../presets/fig4.ron")),
    (
        "elastic-again",
        include_str!("../presets/elastic-again.ron"),
    ),
];

/// The names, for error messages and help.
pub fn names() -> Vec<&'static str> {
    PRESETS.iter().map(|(n, _)| *n).collect()
}

/// The preset called `name`, or an error listing the known ones.
pub fn load(name: &str) -> anyhow::Result<State> {
    let (_, text) = PRESETS.iter().find(|(n, _)| *n == name).ok_or_else(|| {
        anyhow::anyhow!(
            "unknown preset '{name}': known presets are {}",
            names().join(", ")
        )
    })?;
    State::from_ron(text).map_err(|e| anyhow::anyhow!("built-in preset {name}: {e}"))
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_preset_parses() {
        for n in super::names() {
            let s = super::load(n).unwrap();
            assert_eq!(s.name, n);
        }
    }

    #[test]
    fn unknown_preset_lists_known() {
        let e = super::load("fig9").unwrap_err().to_string();
        assert!(
            e.contains("fig9") && e.contains("fig1, fig2, fig3, fig4"),
            "{e}"
        );
    }
}
