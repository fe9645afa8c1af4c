//! The contact view's convergence table (`t`): one row for each pair of
//! nodes per shortest wavelength and cell, the areas over the seeds as they
//! come in (smallest grids first), the pairs the machine cannot solve with
//! the reason, and the theory at the same load for scale.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{pct, pct_pm, progress_fit, share_pct, title_line};
use crate::contact::{Grid, Stat};
use crate::physical::print::load_text;
use crate::tui::app::App;
use crate::tui::contact::convergence::{Row, RowStats};
use crate::tui::contact::load_value;
use crate::tui::glyphs::Glyphs;
use crate::tui::views::chart;

/// The table in the contact view's chart panel `area`.
pub(super) fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let gl = t.glyphs;
    let pane = &app.contact;
    let c = &pane.convergence;
    let w = usize::from(area.width);
    let h = app.state.hardness_name();
    let load = load_value(pane.load);
    let seeds = if pane.seeds <= 1 {
        format!("seed {}", pane.seed)
    } else {
        let last = pane.seed.wrapping_add(u64::from(pane.seeds) - 1);
        format!("seeds {}–{last}", pane.seed)
    };
    let head = gl
        .text(&format!(
            "convergence at p̄ = {} {h} · {seeds}",
            load_text(load)
        ))
        .into_owned();
    let used = Span::raw(head.as_str()).width();
    let right = if c.why_not.is_some() {
        String::new()
    } else if c.busy() {
        progress_fit(&c.progress, gl, w.saturating_sub(used + 2))
    } else {
        let (n, secs) = c
            .rows
            .iter()
            .flat_map(|r| r.results.iter().flatten())
            .filter_map(|r| r.as_ref().ok())
            .fold((0, 0.0), |(n, s), r| (n + 1, s + r.took.as_secs_f64()));
        format!("{n} solved, {secs:.1} s")
    };
    title_line(t, (&head, &right), area, buf);
    if area.height < 4 {
        return;
    }
    let rest = Rect::new(area.x, area.y + 1, area.width, area.height - 1);
    if let Some(why) = &c.why_not {
        Paragraph::new(gl.text(why).into_owned())
            .style(t.dim)
            .wrap(Wrap { trim: true })
            .render(rest, buf);
        return;
    }
    if chart::withheld(app, "the simulation and the theory's areas", rest, buf) {
        return;
    }
    // The theory at the load, for scale.
    let ix = app
        .state
        .roughness()
        .surface(&app.state.params, app.state.moments)
        .indices;
    let psi = ix.psi_in_use(app.state.size_effect);
    let theory = match rough_model::areas(app.state.model, psi, load) {
        Ok(a) => format!(
            "theory: {} %, {} % plastic",
            pct(a.total),
            share_pct(a.plastic, a.total)
        ),
        Err(_) => "theory: —".into(),
    };
    let line = format!("contact A/A0 and plastic share S_pl/S_tot, mean ± sd · {theory}");
    let line = if Span::raw(line.as_str()).width() <= w {
        line
    } else {
        theory
    };
    Line::styled(gl.text(&line).into_owned(), t.dim).render(Rect { height: 1, ..rest }, buf);
    let own = (pane.sampling.grid, pane.sampling.cell);
    let lines = table(&c.rows, w, gl, pane.seeds.max(1) as usize, own);
    let mut y = rest.y + 2;
    for (i, l) in lines.iter().enumerate() {
        if y >= area.bottom() {
            return;
        }
        let style = if i == 0 { t.dim } else { Style::new() };
        Line::styled(l.clone(), style).render(Rect::new(area.x, y, area.width, 1), buf);
        y += 1;
    }
    // Under the table: why a pair is not solved, and what the columns are.
    let mut notes: Vec<String> = c
        .rows
        .iter()
        .filter_map(|r| {
            let why = r.grid.as_ref().err().map(String::as_str).or(r.failure())?;
            Some(format!(
                "{}/λ, K {}: not solved: {why}.",
                r.per_wavelength, r.cell
            ))
        })
        .collect();
    notes.push(format!(
        "n/λ: nodes per shortest wavelength 2π/(ζq0); K: the cell in longest wavelengths \
         2π/q0; grid: the power of two giving as many nodes; {} the plot's sampling.",
        mark(gl)
    ));
    if y + 1 < area.bottom() {
        Paragraph::new(gl.text(&notes.join(" ")).into_owned())
            .style(t.dim)
            .wrap(Wrap { trim: true })
            .render(
                Rect::new(area.x, y + 1, area.width, area.bottom() - y - 1),
                buf,
            );
    }
}

/// The mark of the plot's own row.
fn mark(gl: Glyphs) -> &'static str {
    if gl.ascii_only() {
        "<"
    } else {
        "◀"
    }
}

/// The table's lines, header first: the widest form of the columns that
/// fits `w`.
fn table(rows: &[Row], w: usize, gl: Glyphs, seeds: usize, own: (Grid, u32)) -> Vec<String> {
    let sup = if gl.ascii_only() { "^2" } else { "²" };
    // (narrow ±, iterations and time columns, the corrected area, the
    // column gap)
    for (narrow, extra, corr, gap) in [
        (false, true, true, 2),
        (false, false, true, 2),
        (true, false, true, 2),
        (true, false, false, 2),
        (true, false, false, 1),
    ] {
        let pm = |s: &Stat| {
            let v = if s.n > 1 {
                pct_pm(s.mean, s.sd)
            } else {
                pct(s.mean)
            };
            if narrow {
                v.replace(" ± ", "±")
            } else {
                v
            }
        };
        let mut head = vec!["n/λ", "K", "grid", "contact %"];
        if corr {
            head.push("corrected %");
        }
        head.push("plastic %");
        if extra {
            head.extend(["iter.", "s/solve"]);
        }
        head.push("seeds");
        let mut cells: Vec<Vec<String>> = vec![head.iter().map(|s| s.to_string()).collect()];
        for r in rows {
            let mut line = vec![r.per_wavelength.to_string(), r.cell.to_string()];
            let stats: Option<RowStats> = r.stats();
            match (&r.grid, stats) {
                (Err(_), _) => {
                    line.extend(["—".into(), "not solved (below)".into()]);
                }
                (Ok(n), None) if r.failure().is_some() => {
                    line.extend([format!("{n}{sup}"), "failed (below)".into()]);
                }
                (Ok(n), None) => {
                    line.push(format!("{n}{sup}"));
                    line.extend(["…".into(), "…".into()]);
                    if corr {
                        line.push("…".into());
                    }
                    if extra {
                        line.extend(["".into(), "".into()]);
                    }
                    line.push(format!("0/{seeds}"));
                }
                (Ok(n), Some(s)) => {
                    line.push(format!("{n}{sup}"));
                    line.push(pm(&s.area));
                    if corr {
                        line.push(pm(&s.corrected));
                    }
                    line.push(pm(&s.share));
                    if extra {
                        line.push(format!("{:.0}", s.iterations.mean));
                        line.push(match s.seconds {
                            x if x >= 10.0 => format!("{x:.0}"),
                            x if x >= 1.0 => format!("{x:.1}"),
                            x if x >= 0.01 => format!("{x:.2}"),
                            _ => "<0.01".into(),
                        });
                    }
                    let got = r.results.iter().filter(|x| x.is_some()).count();
                    line.push(if got < r.results.len() {
                        format!("{got}/{}", r.results.len())
                    } else {
                        got.to_string()
                    });
                }
            }
            if (Grid::PerWavelength(r.per_wavelength), r.cell) == own {
                line.push(mark(gl).into());
            }
            cells.push(line);
        }
        let lines = layout(&cells, head.len(), gap);
        let widest = lines.iter().map(|l| Span::raw(l.as_str()).width()).max();
        if widest.unwrap_or(0) <= w || gap == 1 {
            return lines.iter().map(|l| gl.text(l).into_owned()).collect();
        }
    }
    vec![]
}

/// Columns padded to their widest cell (numbers right, the first `cols`
/// cells of each line; a longer last cell, "not solved", runs on).
fn layout(cells: &[Vec<String>], cols: usize, gap: usize) -> Vec<String> {
    let width = |s: &str| Span::raw(s).width();
    let mut widths = vec![0; cols];
    for line in cells {
        // A short line's last cell spans the rest: it sets no width.
        let n = if line.len() < cols {
            line.len() - 1
        } else {
            cols
        };
        for (k, c) in line.iter().take(n).enumerate() {
            widths[k] = widths[k].max(width(c));
        }
    }
    cells
        .iter()
        .map(|line| {
            let mut out = String::new();
            for (k, c) in line.iter().enumerate() {
                if k > 0 {
                    out.push_str(&" ".repeat(gap));
                }
                let pad = widths.get(k).map_or(0, |w| w.saturating_sub(width(c)));
                let spans = k + 1 == line.len() && line.len() < cols;
                if k < 3 && !spans {
                    out.push_str(&" ".repeat(pad));
                    out.push_str(c);
                } else {
                    out.push_str(c);
                    if k + 1 < line.len() {
                        out.push_str(&" ".repeat(pad));
                    }
                }
            }
            out.trim_end().to_string()
        })
        .collect()
}
