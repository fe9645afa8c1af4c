//! The regime map view: the plastic share S_pl/S_tot over the swept
//! parameter (across) and a second one (up), two points per terminal cell
//! (upper half block ▀ in the upper point's colour over the lower point's;
//! in ASCII a space in the colour of the two points' mean), the Ψ = 1
//! contour and the current point, in as many colours as the terminal
//! promises (24-bit, 256, or a 16-colour scale). Under NO_COLOR one
//! character of a ramp per cell. Drawing only reads the map `update`
//! computed.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::chart::{self, Scale};
use crate::figure::{
    share_ansi16, share_ansi256, share_char, share_colour, RegimeMap, ELASTIC_BELOW, PLASTIC_ABOVE,
    RAMP,
};
use crate::tui::app::App;
use crate::tui::plots::to_plot;
use crate::tui::theme::Palette;

/// The contour's and the current point's characters under NO_COLOR.
const CONTOUR_CHAR: &str = "o";
const POINT_CHAR: &str = "X";

/// One of the 16 ANSI colours by its number (0–7 normal, 8–15 bright), as
/// the named colour (SGR 30–37, 90–97) that 16-colour terminals know.
pub fn ansi16(n: u8) -> Color {
    const NAMED: [Color; 16] = [
        Color::Black,
        Color::Red,
        Color::Green,
        Color::Yellow,
        Color::Blue,
        Color::Magenta,
        Color::Cyan,
        Color::Gray,
        Color::DarkGray,
        Color::LightRed,
        Color::LightGreen,
        Color::LightYellow,
        Color::LightBlue,
        Color::LightMagenta,
        Color::LightCyan,
        Color::White,
    ];
    NAMED[usize::from(n & 15)]
}

/// The colour of plastic share `share` in `palette`.
pub fn share_color(palette: Palette, share: f64) -> Color {
    match palette {
        Palette::TrueColor => {
            let (r, g, b) = share_colour(share);
            Color::Rgb(r, g, b)
        }
        Palette::Ansi256 => Color::Indexed(share_ansi256(share)),
        Palette::Ansi16 => ansi16(share_ansi16(share)),
    }
}

/// The Ψ = 1 contour's colour: white, outside the sequential scale; in 16
/// colours bright magenta (the scale's blues, cyan, green and yellow, and
/// the point's red, all differ from it in hue).
pub fn contour_color(palette: Palette) -> Color {
    match palette {
        Palette::TrueColor => Color::Rgb(255, 255, 255),
        Palette::Ansi256 => Color::Indexed(231),
        Palette::Ansi16 => Color::LightMagenta,
    }
}

/// The chart panel `area` with its graph `g`.
pub fn render(app: &App, (area, g): (Rect, Rect), buf: &mut Buffer) {
    let t = &app.theme;
    let Some(map) = app
        .map
        .peek()
        .filter(|m| Some(&m.spec) == app.map_spec(g).as_ref())
    else {
        return;
    };
    let spec = &map.spec;
    let (xa, ya) = (spec.x.axis(), spec.y.axis());
    let gl = t.glyphs;
    let psi = gl.text(if spec.size_effect { "Ψ*" } else { "Ψ_P" });
    let mut title = vec![Span::styled(
        gl.text(&format!(
            "plastic share over {} × {}",
            xa.symbol(),
            ya.symbol()
        ))
        .into_owned(),
        t.title,
    )];
    let hint = "  (key y: next y axis)";
    let used = title[0].content.chars().count();
    if used + hint.chars().count() <= usize::from(area.width) {
        title.push(Span::styled(hint, t.dim));
    }
    Line::from(title).render(Rect { height: 1, ..area }, buf);
    // While a claim's poll is open the colours wait: along the marker's
    // row they show where the share passes ½ (and the contour where Ψ
    // reaches 1); the axes and the current point stay.
    let hidden = app.class.marks_hidden();
    if !hidden {
        legend(app, &psi, Rect::new(area.x, area.y + 1, area.width, 1), buf);
    }

    let bounds = |s: &rough_model::Sweep| {
        let log = s.axis().is_log();
        [to_plot(log, s.from()), to_plot(log, s.to())]
    };
    let (x, y) = (
        Scale::of_axis(xa, bounds(&spec.x)),
        Scale::of_axis(ya, bounds(&spec.y)),
    );
    chart::axes(t, (&x, &y), xa.symbol(), (area, g), buf);
    if hidden {
        let what = format!("the map's colours and its {psi} = 1 contour");
        chart::withheld(app, &what, g, buf);
    } else {
        cells(app, map, g, buf);
    }
    point(app, map, g, !hidden, buf);
}

/// The scale's legend: its ends with the thresholds, the contour and the
/// point; in full words where the panel is wide enough.
fn legend(app: &App, psi: &str, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let gl = t.glyphs;
    let (el, pl) = (ELASTIC_BELOW * 100.0, PLASTIC_ABOVE * 100.0);
    // In ASCII the swatches are coloured spaces: background, not foreground.
    let paint = |c: Color| {
        if gl.ascii_only() {
            Style::new().bg(c)
        } else {
            Style::new().fg(c)
        }
    };
    let bar: Vec<Span> = if t.color {
        (0..10)
            .map(|i| {
                let c = share_color(t.palette, f64::from(i) / 9.0);
                Span::styled(gl.map_swatch(), paint(c))
            })
            .collect()
    } else {
        vec![Span::raw(format!("'{}'", RAMP.iter().collect::<String>()))]
    };
    let (contour, point) = if t.color {
        let c = contour_color(t.palette);
        let style = if gl.ascii_only() {
            Style::new().bg(c)
        } else {
            Style::new().fg(c).bg(Color::Black)
        };
        (
            Span::styled(gl.map_cell(), style),
            Span::styled(gl.map_point(), point_style()),
        )
    } else {
        (Span::raw(CONTOUR_CHAR), Span::raw(POINT_CHAR))
    };
    let marks = [
        contour,
        Span::raw(format!(" {psi}=1  ")),
        point,
        Span::raw(" now"),
    ];
    let line = |head: String, tail: String, note: Option<String>| {
        let mut spans = vec![Span::raw(head)];
        spans.extend(bar.iter().cloned());
        spans.push(Span::raw(tail));
        spans.extend(marks.iter().cloned());
        spans.extend(note.map(|n| Span::styled(n, t.dim)));
        Line::from(spans)
    };
    let wide = line(
        "elastic ".into(),
        " plastic  ".into(),
        Some(format!(
            "  (elastic <{el:.0}%, plastic >{pl:.0}%: this program's thresholds)"
        )),
    );
    let narrow = line(format!("el <{el:.0}% "), format!(" >{pl:.0}% pl  "), None);
    let fits = |l: &Line| l.width() <= usize::from(area.width);
    if fits(&wide) { wide } else { narrow }.render(area, buf);
}

/// Whether the Ψ = 1 contour passes this point's right or upper side: one
/// point thick, where marking both sides would draw a band.
fn contour(map: &RegimeMap, col: usize, row: usize) -> bool {
    let (right, up) = map.contour_edges(col, row);
    right || up
}

fn point_style() -> Style {
    Style::new().fg(Color::Red).add_modifier(Modifier::BOLD)
}

/// The map's cells: terminal row `r` from the top holds map rows
/// `rows − 1 − 2r` (upper half) and `rows − 2 − 2r` (lower half).
fn cells(app: &App, map: &RegimeMap, g: Rect, buf: &mut Buffer) {
    let spec = &map.spec;
    let (cols, rows) = (spec.cols, spec.rows);
    if cols != usize::from(g.width) || rows != 2 * usize::from(g.height) {
        return;
    }
    let t = &app.theme;
    let (color, palette, gl) = (t.color, t.palette, t.glyphs);
    let rgb = |share: f64| share_color(palette, share);
    let line = contour_color(palette);
    for r in 0..rows / 2 {
        let (up, low) = (rows - 1 - 2 * r, rows - 2 - 2 * r);
        for c in 0..cols {
            let cell = &mut buf[(g.x + c as u16, g.y + r as u16)];
            let (su, sl) = (map.share_at(c, up), map.share_at(c, low));
            let (cu, cl) = (contour(map, c, up), contour(map, c, low));
            if color && gl.ascii_only() {
                // One point per cell: the mean of the two, or the contour.
                let bg = if cu || cl { line } else { rgb(0.5 * (su + sl)) };
                cell.set_symbol(gl.map_cell())
                    .set_style(Style::new().bg(bg));
            } else if color {
                let fg = if cu { line } else { rgb(su) };
                let bg = if cl { line } else { rgb(sl) };
                cell.set_symbol(gl.map_cell())
                    .set_style(Style::new().fg(fg).bg(bg));
            } else if cu || cl {
                cell.set_symbol(CONTOUR_CHAR);
            } else {
                cell.set_char(share_char(0.5 * (su + sl)));
            }
        }
    }
}

/// The current point, when it lies on the map: on its share's colour
/// when `shares` (the cells are drawn).
fn point(app: &App, map: &RegimeMap, g: Rect, shares: bool, buf: &mut Buffer) {
    let spec = &map.spec;
    let (cols, rows) = (spec.cols, spec.rows);
    if cols != usize::from(g.width) || rows != 2 * usize::from(g.height) {
        return;
    }
    let (fx, fy) = spec.position();
    if !((0.0..=1.0).contains(&fx) && (0.0..=1.0).contains(&fy)) {
        return;
    }
    let c = (fx * (cols - 1) as f64).round() as usize;
    let row = (fy * (rows - 1) as f64).round() as usize;
    let r = (rows - 1 - row) / 2;
    let cell = &mut buf[(g.x + c as u16, g.y + r as u16)];
    let t = &app.theme;
    if t.color {
        let style = if shares {
            point_style().bg(share_color(t.palette, map.share_at(c, row)))
        } else {
            point_style()
        };
        cell.set_symbol(t.glyphs.map_point()).set_style(style);
    } else {
        cell.set_symbol(POINT_CHAR);
    }
}
