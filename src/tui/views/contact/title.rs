//! The contact view's title: the grid, the seeds, and where there is
//! room how the power law is sampled.

use ratatui::text::Span;

use crate::tui::contact::ContactPane;
use crate::tui::glyphs::Glyphs;

/// "seed 1", "seeds 1–4", or while they come in "seeds 1–4, 2 in" (at the
/// chosen load; in `b`'s plot, those whose whole sweep is in).
pub(super) fn seeds_words(pane: &ContactPane) -> String {
    let asked = pane.seeds_asked();
    if asked == 1 {
        return format!("seed {}", pane.seed);
    }
    let last = pane.seed.wrapping_add(asked as u64 - 1);
    let got = if pane.plot != crate::tui::contact::Plot::Load {
        pane.seeds_in()
    } else {
        pane.at_load(pane.load).map_or(0, |s| s[0].n)
    };
    if got < asked && !pane.chosen_is_coarse() {
        format!("seeds {}–{last}, {got} in", pane.seed)
    } else {
        format!("seeds {}–{last}", pane.seed)
    }
}

/// `head` with the cell, the nodes per shortest wavelength and a hardness
/// per asperity (which must show whenever it is on) where a title of `w`
/// columns has room for them beside the progress; `n` the scene's grid.
pub(super) fn with_sampling(
    pane: &ContactPane,
    gl: Glyphs,
    head: String,
    (n, w): (Option<usize>, usize),
) -> String {
    match (n, pane.tasks.first()) {
        (Some(n), Some(task)) if task.scene.surface.is_none() => {
            let s = &pane.sampling;
            let per = s.per_wavelength(n, task.scene.zeta());
            let per = if (per - per.round()).abs() < 0.05 {
                format!("{per:.0}")
            } else {
                format!("{per:.1}")
            };
            let per_node = match s.hardness {
                crate::contact::Hardness::Global => "",
                crate::contact::Hardness::Asperity => " · H per asperity",
                crate::contact::Hardness::Summit => " · H per summit",
            };
            let asperity = !per_node.is_empty();
            // The sweep's grids differ by ζ; their nodes per wavelength not.
            let per = if pane.plot != crate::tui::contact::Plot::Load {
                String::new()
            } else {
                format!(" · {per} nodes/λ")
            };
            let long = format!("{head} · cell {}{per}{per_node}", s.cell);
            let short = format!("{head}{per_node}");
            let room = |t: &str| Span::raw(gl.text(t).as_ref()).width() + 18 <= w;
            if room(&long) {
                long
            } else if asperity {
                short
            } else {
                head
            }
        }
        _ => head,
    }
}
