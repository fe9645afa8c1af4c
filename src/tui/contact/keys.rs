//! The contact view's keys (`[ ]`, `b`, `i`, `r`, `R`, `t`, `A`) and what
//! `p` saves: the picture and the surface's heights.

use super::convergence::MEASURED;
use super::{load_value, Plot, LOADS, SEED_CHOICES};
use crate::contact::Hardness;
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
        // From the table, b and i show their plots.
        Message::ContactSweep | Message::ContactSlopes if pane.table => {
            pane.table = false;
            pane.plot = if msg == Message::ContactSweep {
                Plot::Share
            } else {
                Plot::Slopes
            };
            let text = plot_words(pane.plot);
            app.set_status(text, false);
        }
        Message::ContactSweep | Message::ContactSlopes => {
            let plot = if msg == Message::ContactSweep {
                Plot::Share
            } else {
                Plot::Slopes
            };
            pane.plot = if pane.plot == plot { Plot::Load } else { plot };
            let text = plot_words(pane.plot);
            app.set_status(text, false);
        }
        Message::ContactTable if app.state.is_measured() && !pane.table => {
            app.set_status(MEASURED, true);
        }
        Message::ContactTable => {
            pane.table = !pane.table;
            let text = if pane.table {
                "convergence at the chosen load: 4, 8, 16 nodes per shortest wavelength × cells \
                 of 1, 2, 4 longest wavelengths, the smallest grids first (t: back)"
            } else {
                match pane.plot {
                    Plot::Share => "back to the plastic share against ζ (t: the convergence table)",
                    Plot::Slopes => {
                        "back to the initial slopes against ζ (t: the convergence table)"
                    }
                    Plot::Load => "back to the areas against the load (t: the convergence table)",
                }
            };
            app.set_status(text, false);
        }
        Message::ContactHardness => {
            pane.sampling.hardness = pane.sampling.hardness.next();
            let text = match (pane.sampling.hardness, app.state.size_effect) {
                (Hardness::Asperity, true) => {
                    "hardness per asperity: each contact patch H0 √(1 + R*/(1.2 R)), R the \
                     fitted radius of its asperity (A: per summit)"
                }
                (Hardness::Summit, true) => {
                    "hardness per summit: each node H0 √(1 + R*/(1.2 R)), R the curvature \
                     radius of the summit it climbs to (A: one cap)"
                }
                (Hardness::Asperity, false) => {
                    "hardness per asperity: the size effect's, so e switches it on (A: per summit)"
                }
                (Hardness::Summit, false) => {
                    "hardness per summit: the size effect's, so e switches it on (A: one cap)"
                }
                (Hardness::Global, _) => {
                    "one hardness cap for every node, the theory's (A: per asperity)"
                }
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

/// What the status line says of a plot.
fn plot_words(plot: Plot) -> &'static str {
    match plot {
        Plot::Share => {
            "the plastic share against ζ at the chosen load (b: the areas against the load, i: \
             the initial slopes, t: the table)"
        }
        Plot::Slopes => {
            "the initial slopes against ζ, fitted over light loads (i: the areas against the \
             load, b: the plastic share, t: the table)"
        }
        Plot::Load => "the areas against the load (b: the plastic share, i: the initial slopes)",
    }
}

/// `p` in the contact view: the picture of the plot (the contact map at
/// the chosen load, or the initial slopes against ζ) and, for a power-law
/// scene, the surface's heights as the view solves them (the drawn seed on
/// its cell and grid), each a new file named from `stem`.
pub fn save(app: &mut App, stem: &str) {
    let pane = &app.contact;
    let picture = match pane.plot {
        Plot::Share => None,
        _ => Some(picture(app)),
    };
    let surface = (!app.state.is_measured()).then(|| {
        let mut bytes = vec![];
        crate::export::write_surface(&mut bytes, &app.state, &pane.sampling, pane.seed)
            .map(|()| bytes)
    });
    let dir = app.save_dir.clone();
    let mut saved = vec![];
    let mut errors = vec![];
    if let Some(svg) = picture {
        match svg.and_then(|svg| {
            crate::snapshot::save_file_new(&dir, stem, "svg", "picture", svg.as_bytes())
        }) {
            Ok(p) => saved.push(p.display().to_string()),
            Err(e) => errors.push(format!("{e:#}")),
        }
    }
    if let Some(bytes) = surface {
        let name = format!("{stem}-surface");
        match bytes.and_then(|b| crate::snapshot::save_file_new(&dir, &name, "txt", "surface", &b))
        {
            Ok(p) => saved.push(p.display().to_string()),
            Err(e) => errors.push(format!("{e:#}")),
        }
    }
    let share = app.contact.plot == Plot::Share;
    match (saved.is_empty(), errors.first()) {
        (_, Some(e)) => app.set_status(e.clone(), true),
        (true, None) => app.set_status(
            "no picture of b's plot here: roughtui export --view contact-sweep --format svg draws it",
            true,
        ),
        (false, None) => {
            let mut text = format!("saved {}", saved.join(" and "));
            if saved.len() > 1 || share {
                text.push_str(" (heights: roughtui --surface FILE --periodic reads them)");
            }
            if share {
                text.push_str("; b's picture: roughtui export --view contact-sweep --format svg");
            }
            app.set_status(text, false);
        }
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
    if pane.plot == Plot::Share {
        anyhow::bail!(
            "no picture of b's plot here: roughtui export --view contact-sweep --format svg \
             draws it"
        );
    }
    if pane.plot == Plot::Slopes {
        return slopes_picture(app);
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

/// The `i` plot as the paper's figure with the simulation's points, from
/// the slopes on screen.
fn slopes_picture(app: &App) -> anyhow::Result<String> {
    let pane = &app.contact;
    if let Some(why) = &pane.why_not {
        anyhow::bail!("no picture of the initial slopes: {why}");
    }
    let mut d = crate::figure::ContactSlopes {
        surface: format!(
            "a cell of {}, {}",
            pane.sampling.cell_words(),
            crate::contact::Seeds {
                first: pane.seed,
                count: pane.seeds_asked() as u32,
            }
            .words()
        ),
        hardness: crate::export::hardness_short(&app.state, pane.sampling.hardness),
        ..Default::default()
    };
    let mut sd: [Vec<f64>; 3] = Default::default();
    for (k, z) in pane.zetas.iter().enumerate() {
        let Some(st) = pane.slopes_at(k) else {
            continue;
        };
        d.zeta.push(*z);
        for i in 0..3 {
            d.slope[i].push(st[i].mean);
            sd[i].push(st[i].sd);
        }
    }
    if d.zeta.is_empty() {
        anyhow::bail!("the initial slopes are not solved yet: p again when they are");
    }
    if pane.seeds_asked() > 1 {
        d.sd = Some(sd);
    }
    // The theory's curves on screen are (log10 ζ, log10 S): total,
    // elastic, plastic.
    let curves = &pane.theory.curves;
    if let Some(total) = curves.first() {
        d.theory_zeta = total.iter().map(|p| 10f64.powf(p.0)).collect();
        let back = |c: &Vec<(f64, f64)>| -> Vec<f64> {
            d.theory_zeta
                .iter()
                .map(|z| {
                    c.iter()
                        .find(|p| (10f64.powf(p.0) / z - 1.0).abs() < 1e-12)
                        .map_or(0.0, |p| 10f64.powf(p.1))
                })
                .collect()
        };
        d.theory = [back(&curves[1]), back(&curves[2]), back(&curves[0])];
        let s = &app.state;
        d.persson = d
            .theory_zeta
            .iter()
            .map(|&z| {
                let p = s
                    .params
                    .with(rough_model::Axis::Zeta, z)
                    .unwrap_or(s.params);
                let (psi, _) = rough_model::psi_in_use(&p, s.size_effect, s.moments);
                (2.0 / std::f64::consts::PI).sqrt() / psi.to_f64()
            })
            .collect();
    }
    crate::figure::render_contact_slopes(&app.state, &d)
}
