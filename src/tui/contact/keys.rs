//! The contact view's keys (`[ ]`, `b`, `r`, `R`, `t`) and its picture (`p`).

use super::convergence::MEASURED;
use super::{load_value, LOADS, SEED_CHOICES};
use crate::tui::app::{App, Message};

/// The contact view's keys.
pub fn on_key(app: &mut App, msg: Message) {
    let pane = &mut app.contact;
    match msg {
        Message::ContactLoad { up } => {
            let k = if up {
                (pane.load + 1).min(LOADS - 1)
            } else {
                pane.load.saturating_sub(1)
            };
            if k == pane.load {
                app.set_status(
                    "the load runs from 1e-3 to 1 times the hardness in use",
                    false,
                );
            }
            app.contact.load = k;
        }
        // From the table, b shows its plot of the plastic share.
        Message::ContactSweep if pane.table => {
            pane.table = false;
            pane.sweep = true;
            app.set_status(
                "the plastic share against ζ (b: the areas against the load, t: the table)",
                false,
            );
        }
        Message::ContactSweep => pane.sweep = !pane.sweep,
        Message::ContactTable if app.state.is_measured() && !pane.table => {
            app.set_status(MEASURED, true);
        }
        Message::ContactTable => {
            pane.table = !pane.table;
            let text = if pane.table {
                "convergence at the chosen load: 4, 8, 16 nodes per shortest wavelength × cells \
                 of 1, 2, 4 longest wavelengths, the smallest grids first (t: back)"
            } else if pane.sweep {
                "back to the plastic share against ζ (t: the convergence table)"
            } else {
                "back to the areas against the load (t: the convergence table)"
            };
            app.set_status(text, false);
        }
        Message::ContactHardness => {
            use crate::contact::Hardness;
            let asperity = pane.sampling.hardness == Hardness::Global;
            pane.sampling.hardness = if asperity {
                Hardness::Asperity
            } else {
                Hardness::Global
            };
            let text = match (asperity, app.state.size_effect) {
                (true, true) => {
                    "hardness per asperity: each contact patch H0 √(1 + R*/(1.2 R)), R the \
                     radius of its asperity (A: one cap)"
                }
                (true, false) => {
                    "hardness per asperity: the size effect's, so e switches it on (A: one cap)"
                }
                (false, _) => "one hardness cap for every node, the theory's (A: per asperity)",
            };
            app.set_status(text, false);
        }
        Message::ContactSeeds if app.state.is_measured() => app.set_status(
            "a measured map is one surface: the simulation solves its own heights",
            true,
        ),
        Message::ContactSeeds => {
            let at = SEED_CHOICES.iter().position(|&s| s == pane.seeds);
            pane.seeds = SEED_CHOICES[at.map_or(0, |i| (i + 1) % SEED_CHOICES.len())];
            let n = pane.seeds;
            let last = pane.seed.wrapping_add(u64::from(n) - 1);
            let text = if n == 1 {
                format!("one surface: seed {}", pane.seed)
            } else {
                format!(
                    "{n} surfaces: seeds {}–{last}, mean ± sd (R: more)",
                    pane.seed
                )
            };
            app.set_status(text, false);
        }
        Message::ContactSeed if app.state.is_measured() => app.set_status(
            "a measured map has no seed: the simulation solves its own heights",
            true,
        ),
        Message::ContactSeed => {
            let seed = pane.seed.wrapping_add(1);
            app.state.seed = Some(seed);
            app.modified = true;
            app.set_status(format!("another surface: seed {seed}"), false);
        }
        _ => {}
    }
}

/// The contact view's picture (`p`): the contact map at the chosen load.
pub fn picture(app: &App) -> anyhow::Result<String> {
    let pane = &app.contact;
    if pane.table {
        anyhow::bail!(
            "no picture of the convergence table: roughtui export --view contact-convergence \
             writes it as CSV"
        );
    }
    if pane.sweep {
        anyhow::bail!(
            "no picture of b's plot here: roughtui export --view contact-sweep --format svg \
             draws it"
        );
    }
    if let Some(why) = &pane.why_not {
        anyhow::bail!("no contact map: {why}");
    }
    let solved = match pane.chosen() {
        Some(Ok(s)) => s,
        Some(Err(e)) => anyhow::bail!("no contact map: {e}"),
        None => anyhow::bail!("the contact map is not solved yet: p again when it is"),
    };
    let n = pane.tasks.first().map_or(0, |t| t.scene.n);
    let side = match pane.tasks.first() {
        Some(t) => crate::contact::solved_side(&app.state, &t.scene)?,
        None => anyhow::bail!("the contact map is not solved yet: p again when it is"),
    };
    let measured = pane
        .tasks
        .first()
        .is_some_and(|t| t.scene.surface.is_some());
    let r = &solved.result;
    let nodes: Vec<u8> = solved.map.iter().map(|v| *v as u8).collect();
    crate::export::contact_map_picture(
        &app.state,
        (&nodes, n, side),
        load_value(pane.load),
        (r.area, r.plastic_area),
        (!measured).then_some(pane.seed),
    )
}
