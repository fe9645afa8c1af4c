//! The help overlay: the keys (from the one key table), then the symbols the
//! screen uses, a line each, in pages when the terminal is short.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

use super::app::App;
use super::keys::{self, Context};
use super::views::claims_line;
use super::wrap::wrap;

/// What each symbol on the screen means.
pub const SYMBOLS: &[(&str, &str)] = &[
    (
        "Ψ_GW",
        "Greenwood–Williamson plasticity index (E/H0)√(h_rms/R_s)",
    ),
    ("Ψ_P", "Persson's plasticity index √V/H0 (eq. 11)"),
    (
        "Ψ*",
        "the index with size-dependent hardness, √V/H_y (eq. 12)",
    ),
    ("Ψ*asy", "the paper's asymptotic form of Ψ* (eq. 13)"),
    ("ψ", "the index in use: Ψ* with the size effect, else Ψ_P"),
    ("R_s", "mean radius of the asperity summits"),
    ("λ1", "shortest wavelength of the roughness, 2π/q1"),
    ("h′", "rms slope of the surface, √(2 m2)"),
    (
        "ε",
        "d_rep/R = 2h′: the strain scale of the asperities (eq. 17)",
    ),
    (
        "d_rep",
        "repulsive diameter 4h′/h″, h″ the rms curvature (eq. 16)",
    ),
    (
        "V",
        "variance of the full-contact pressure, E² m2/2 (Persson)",
    ),
    ("H0/E", "bulk hardness over E, the composite modulus E*"),
    (
        "q0  L",
        "longest wavelength L = 2π/q0 (Enter: q0=1e5 or l=62.8um)",
    ),
    ("h_rms", "rms height of the roughness"),
    ("ζ", "magnification q1/q0: how fine the roughness goes"),
    (
        "H",
        "the Hurst exponent of the roughness (never a hardness)",
    ),
    ("H0  H_y", "the hardness: bulk; size-dependent at R_s"),
    ("R*", "length of the hardness size effect (0 = none)"),
    ("p̄", "mean (nominal) contact pressure"),
    (
        "S_el S_pl",
        "initial slopes H0·dA/dp̄/A0 (H_y with the size effect)",
    ),
    ("S_tot", "their sum, the total contact area's slope"),
    ("S_P", "Persson's purely elastic slope, for comparison"),
    ("marker", "the swept value: the readout is computed there"),
    (
        "exact at",
        "the marker: how far the other model's slopes lie from these",
    ),
    (
        "claims",
        "crossings and minima along the sweep; with truncated moments",
    ),
    (
        "",
        "none below ζ = 10, where the cut at q0, not the model, makes them",
    ),
    (
        "regime",
        "plastic share < 10 % elastic, ≤ 90 % elasto-plastic, else",
    ),
    (
        "",
        "plastic: this program's thresholds (the paper sets none)",
    ),
    (
        MARKS,
        "on the x axis: ψ = 1; plastic share 10 %; plastic share 90 %",
    ),
    (
        "A_el A_pl",
        "elastic area: the mass on [0, H] of Appendix A's solution;",
    ),
    (
        "",
        "plastic: the rest, the paper's \"subtracting the elastic one\".",
    ),
    (
        "",
        "Every share and regime rests on this reading: with Persson's",
    ),
    ("", "elastic erf(p̄/√(2V)) instead, fig2's share at ζ = 1000"),
    ("", "would be 0.078, not 0.738"),
];

/// The symbols only a measured surface shows, listed after ζ on one.
pub const MEASURED_SYMBOLS: &[(&str, &str)] = &[
    ("q0 q1", "the band of wavevectors the moments sum over"),
    (
        "H fit",
        "a power-law fit over the fit band, found from the data",
    ),
    ("", "or set ([ ] { } move its ends, b: found again);"),
    ("", "with its standard error; flagged when not self-affine"),
    (
        "h_rms(ζ)",
        "rms height from the PSD up to ζ: √m0, detrended, windowed",
    ),
    ("h′(ζ)", "rms slope from the PSD up to ζ: √(2 m2)"),
    (
        "Sq Sdq",
        "real space, detrended, no window: rms height and gradient",
    ),
    ("Rq RΔq", "a line scan's real-space rms height and slope"),
];

/// Where [`SYMBOLS`] names the regime marks: the glyph set's own.
const MARKS: &str = "ψ ◦ ●";

/// The help's lines, all pages together, each marked whether it is a
/// heading.
pub fn lines(app: &App) -> Vec<(bool, Line<'static>)> {
    let t = &app.theme;
    let g = t.glyphs;
    let mut lines = Vec::new();
    let mut prompt_heading = false;
    let bindings: Vec<_> = keys::BINDINGS
        .iter()
        .filter(|b| b.context.listed(app))
        .collect();
    // The keys' column: as wide as the longest label, at least 15.
    let width = bindings
        .iter()
        .map(|b| Span::raw(keys::key_text(g, b.label)).width() + 1)
        .max()
        .unwrap_or(0)
        .max(15);
    for b in bindings {
        if b.context == Context::Prompt && !prompt_heading {
            lines.push((
                true,
                Line::styled("in a prompt (save name, value):", t.title),
            ));
            prompt_heading = true;
        }
        lines.push((
            false,
            Line::from(vec![
                Span::styled(padded(&keys::key_text(g, b.label), width), t.title),
                Span::raw(g.text(b.help).into_owned()),
            ]),
        ));
    }
    lines.push((true, Line::styled("symbols:", t.title)));
    let measured: &[(&str, &str)] = if app.state.is_measured() {
        MEASURED_SYMBOLS
    } else {
        &[]
    };
    let after_zeta = SYMBOLS.iter().position(|s| s.0 == "ζ").map_or(0, |i| i + 1);
    let (before, after) = SYMBOLS.split_at(after_zeta);
    for &(sym, what) in before.iter().chain(measured).chain(after) {
        let sym = if sym == MARKS {
            use super::glyphs::Mark;
            [Mark::PsiOne, Mark::ShareLow, Mark::ShareHigh]
                .map(|m| g.mark(m))
                .join(" ")
        } else {
            g.text(sym).into_owned()
        };
        lines.push((
            false,
            Line::from(vec![
                Span::styled(padded(&sym, 10), t.title),
                Span::raw(g.text(what).into_owned()),
            ]),
        ));
    }
    scene(app, &mut lines);
    lines
}

/// Columns of text inside the help's frame, after a leading blank.
const TEXT_W: usize = 75;

/// The scene's caption (whole: the screen shows one row of it at 80
/// columns) and its claims, a line each, under "this scene:".
fn scene(app: &App, lines: &mut Vec<(bool, Line<'static>)>) {
    let caption = app.state.caption.as_deref().unwrap_or("");
    if caption.is_empty() && app.claims.is_empty() {
        return;
    }
    let g = app.theme.glyphs;
    lines.push((true, Line::styled("this scene:", app.theme.title)));
    if app.class.hidden_question().is_some() {
        // A poll is open: what would answer it waits for the reveal.
        let l = " the caption and the claims show after the poll's reveal";
        lines.push((false, Line::raw(l)));
        return;
    }
    for l in wrap(&g.text(caption), TEXT_W, usize::MAX, g.cut()) {
        lines.push((false, Line::raw(format!(" {l}"))));
    }
    let dot = g.text("·");
    if app.class.claims_hidden() {
        let l = " this step's claims show after the lesson's next poll";
        lines.push((false, Line::raw(l)));
        return;
    }
    for c in &app.claims {
        // Each claim whole: in full where it fits, else short.
        let l = claims_line(std::slice::from_ref(c), TEXT_W - 2, g);
        lines.push((false, Line::styled(format!(" {dot} {l}"), app.theme.ok)));
    }
}

/// ` text` padded to `width` columns: by display width, so that a
/// combining mark (the bar of p̄) takes no column of its own.
fn padded(text: &str, width: usize) -> String {
    let pad = width.saturating_sub(Span::raw(text).width());
    format!(" {text}{}", " ".repeat(pad))
}

/// `lines` in pages of `per_page`; a heading never ends a page.
fn pages(lines: Vec<(bool, Line<'static>)>, per_page: usize) -> Vec<Vec<Line<'static>>> {
    let mut pages: Vec<Vec<Line>> = vec![Vec::new()];
    for (heading, line) in lines {
        let used = pages.last().map_or(0, Vec::len);
        if used == per_page || (heading && used + 1 >= per_page && used > 0) {
            pages.push(Vec::new());
        }
        if let Some(p) = pages.last_mut() {
            p.push(line);
        }
    }
    pages
}

pub fn render_help(app: &App, area: Rect, buf: &mut Buffer) {
    let lines = lines(app);
    let w = 78.min(area.width);
    let h = (lines.len() as u16 + 2).min(area.height);
    let per_page = usize::from(h.saturating_sub(2)).max(1);
    let mut pages = pages(lines, per_page);
    let count = pages.len();
    let page = app.help_page % count;
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    let title = if count > 1 {
        format!(
            " help {}/{count} · → next page · Esc or ? closes ",
            page + 1
        )
    } else {
        " help · Esc or ? closes ".to_string()
    };
    let g = app.theme.glyphs;
    let title = g.text(&title).into_owned();
    Clear.render(r, buf);
    Paragraph::new(std::mem::take(&mut pages[page]))
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_set(g.border())
                .title(title),
        )
        .render(r, buf);
}
