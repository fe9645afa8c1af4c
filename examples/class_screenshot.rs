//! The lecturer's screen during a poll, drawn by the explorer's own view
//! code (the same `impl Widget for &App` a served lecturer gets) and
//! written as an SVG picture of the terminal: fig2 at 100×30, a class of
//! 31, 30 answers spread around the model's ½ crossing, before (`open`)
//! or after (`revealed`) the reveal. The picture in docs/teaching.md:
//!
//! ```sh
//! cargo run --example class_screenshot -- revealed > docs/class-reveal.svg
//! cargo run --example class_screenshot -- open > docs/class-poll.svg
//! ```
//!
//! (`scripts/gen_docs.sh` makes both; `tests/docs_blocks.rs` compares them.)

use std::fmt::Write;
use std::time::Duration;

use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::style::{Color, Modifier};
use ratatui::Terminal;
use rough_model::Axis;
use roughtui::class::{ClassView, Question, Seat, SeatState, Tally};
use roughtui::presets;
use roughtui::tui::app::{step_value, App};
use roughtui::tui::theme::Theme;

const SIZE: (u16, u16) = (100, 30);
/// A cell of the picture, in pixels.
const CELL: (f64, f64) = (8.4, 17.0);
const BACKGROUND: &str = "#1d1f21";
const FOREGROUND: &str = "#d7d7d7";

/// A dark terminal's palette for the named colours.
fn hex(c: Color) -> Option<String> {
    Some(
        match c {
            Color::Reset => return None,
            Color::Black => "#1d1f21",
            Color::Red => "#e0605a",
            Color::Green => "#8fc25a",
            Color::Yellow => "#e6c547",
            Color::Blue => "#5b8fd8",
            Color::Magenta => "#c585d2",
            Color::Cyan => "#5fc7c7",
            Color::Gray => "#c5c8c6",
            Color::DarkGray => "#7a7d7b",
            Color::LightRed => "#ff7b74",
            Color::LightGreen => "#b5e685",
            Color::LightYellow => "#ffe27a",
            Color::LightBlue => "#85b2ff",
            Color::LightMagenta => "#e0a8ec",
            Color::LightCyan => "#8ae8e8",
            Color::White => "#ffffff",
            Color::Rgb(r, g, b) => return Some(format!("#{r:02x}{g:02x}{b:02x}")),
            Color::Indexed(_) => "#d7d7d7",
        }
        .to_string(),
    )
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The buffer as SVG: a rectangle per coloured background, a text run per
/// stretch of cells in one style, stretched to the cells it covers.
fn svg(buf: &Buffer) -> String {
    let (w, h) = (buf.area.width, buf.area.height);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{:.0}" height="{:.0}" font-family="DejaVu Sans Mono, Menlo, Consolas, monospace" font-size="14">"#,
        f64::from(w) * CELL.0 + 16.0,
        f64::from(h) * CELL.1 + 16.0
    );
    let _ = writeln!(
        out,
        r#"<rect width="100%" height="100%" fill="{BACKGROUND}"/><g transform="translate(8 8)">"#
    );
    for y in 0..h {
        let top = f64::from(y) * CELL.1;
        let mut x = 0;
        while x < w {
            let cell = &buf[(x, y)];
            let reversed = cell.modifier.contains(Modifier::REVERSED);
            let (fg, bg) = (hex(cell.fg), hex(cell.bg));
            let (fg, bg) = if reversed {
                (
                    bg.or(Some(BACKGROUND.into())),
                    fg.or(Some(FOREGROUND.into())),
                )
            } else {
                (fg, bg)
            };
            // The run of cells in this cell's style.
            let mut end = x + 1;
            while end < w {
                let c = &buf[(end, y)];
                if c.fg != cell.fg || c.bg != cell.bg || c.modifier != cell.modifier {
                    break;
                }
                end += 1;
            }
            if let Some(bg) = &bg {
                let _ = writeln!(
                    out,
                    r#"<rect x="{:.1}" y="{top:.1}" width="{:.1}" height="{:.1}" fill="{bg}"/>"#,
                    f64::from(x) * CELL.0,
                    f64::from(end - x) * CELL.0 + 0.2,
                    CELL.1 + 0.2
                );
            }
            let text: String = (x..end).map(|i| buf[(i, y)].symbol()).collect();
            if !text.trim().is_empty() {
                let bold = if cell.modifier.contains(Modifier::BOLD) {
                    r#" font-weight="bold""#
                } else {
                    ""
                };
                // The run spans its cells exactly, whatever the font.
                let _ = writeln!(
                    out,
                    r#"<text x="{:.1}" y="{:.1}" textLength="{:.1}" lengthAdjust="spacing" fill="{}"{bold} xml:space="preserve">{}</text>"#,
                    f64::from(x) * CELL.0,
                    top + CELL.1 * 0.78,
                    f64::from(end - x) * CELL.0,
                    fg.as_deref().unwrap_or(FOREGROUND),
                    escape(&text)
                );
            }
            x = end;
        }
    }
    out.push_str("</g></svg>\n");
    out
}

fn main() -> anyhow::Result<()> {
    let revealed = std::env::args().nth(1).as_deref() == Some("revealed");
    print!("{}", picture(revealed)?);
    Ok(())
}

/// The lecturer's screen as an SVG picture: during the poll, or after the
/// reveal (`tests/docs_blocks.rs` compares it with docs/class-*.svg).
pub fn picture(revealed: bool) -> anyhow::Result<String> {
    let state = presets::load("fig2")?;
    let mut app = App::new(state, Theme::colored(), SIZE);
    let question = Question::of_claims(app.view, &app.claims, app.state.size_effect)
        .ok_or_else(|| anyhow::anyhow!("fig2 makes no claim"))?;
    // 30 answers, as students step the marker from 128 in quarter decades:
    // most a step or two up, a few on the far side of the crossing.
    let steps = [
        0, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 5, 5, 5, 6, 7, 9,
    ];
    let answers: Vec<f64> = steps
        .iter()
        .map(|&k| {
            (0..k).fold(128.0, |v, _| {
                step_value(Axis::Zeta, v, (1.0, 1e4), true, false)
            })
        })
        .collect();
    let names = [
        "ada", "bo", "chen", "dara", "eli", "femi", "gus", "hana", "ivo", "jun", "kai", "lea",
        "mo", "nia", "oto", "pia", "quinn", "rafa", "sol", "tao", "uma", "vik", "wen", "xia",
        "yan", "zoe", "ali", "bea", "cy", "dev", "eve",
    ];
    let seats = names
        .iter()
        .enumerate()
        .map(|(i, n)| Seat {
            id: i as u64 + 1,
            name: (*n).into(),
            state: match (revealed, i < answers.len()) {
                (true, _) => SeatState::Following,
                (false, true) => SeatState::Answered,
                (false, false) => SeatState::Answering,
            },
            size: if i % 11 == 4 { (80, 22) } else { SIZE },
            marker: if i % 7 == 3 { "half" } else { "braille" }.into(),
            idle: Duration::from_secs(5 + i as u64 * 3),
            via: "ssh",
        })
        .collect();
    app.class.view = Some(ClassView {
        seats,
        poll: Some(Tally {
            question,
            answers,
            asked: names.len(),
            revealed,
            sweep: app.state.sweep,
        }),
    });
    let status = if revealed {
        "revealed: ζ = 321.5 · S saves the answers · v asks again"
    } else {
        "asked 31 students: where does the plastic share pass ½? · v reveals · C cancels"
    };
    app.set_status(status, false);
    let mut t = Terminal::new(TestBackend::new(SIZE.0, SIZE.1))?;
    t.draw(|f| f.render_widget(&app, f.area()))?;
    Ok(svg(t.backend().buffer()))
}
