//! The lecturer's `Q`: the class's web page as a QR code, full screen, for
//! the projector, with its address under it (any key closes it). Dark
//! modules on light cells, two module rows a cell (`▀`); without colour,
//! or in ASCII, light modules as `█` / `#` (the screen's background dark).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::widgets::{Clear, Widget};

use crate::tui::app::App;

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    Clear.render(area, buf);
    let Some(url) = app.class.join_url.as_deref() else {
        return;
    };
    let g = app.theme.glyphs;
    let Some(m) = crate::tui::qr::modules(url) else {
        buf.set_stringn(
            area.x,
            area.y,
            "the address is too long for a QR code",
            usize::from(area.width),
            Style::new(),
        );
        return;
    };
    let n = m.len() as u16;
    let rows = n.div_ceil(2);
    let text = g.text(&format!("join the class: {url}")).into_owned();
    let keys = "any key closes this";
    if n > area.width || rows + 2 > area.height {
        let say = g.text("enlarge the terminal for the QR code").into_owned();
        buf.set_stringn(area.x, area.y, &say, usize::from(area.width), Style::new());
        buf.set_stringn(
            area.x,
            area.y + 1,
            &text,
            usize::from(area.width),
            Style::new(),
        );
        return;
    }
    let x0 = area.x + (area.width - n) / 2;
    let y0 = area.y + (area.height - rows - 2) / 2;
    let colour = app.theme.color && !g.ascii_only();
    for (r, pair) in m.chunks(2).enumerate() {
        for (c, &top) in pair[0].iter().enumerate() {
            let bottom = pair.get(1).is_some_and(|row| row[c]);
            let cell = &mut buf[(x0 + c as u16, y0 + r as u16)];
            if colour {
                let shade = |dark: bool| if dark { Color::Black } else { Color::White };
                cell.set_symbol("▀")
                    .set_style(Style::new().fg(shade(top)).bg(shade(bottom)));
            } else {
                // Light modules drawn, dark ones left dark: a full cell
                // only where both are light.
                let light = if g.ascii_only() { "#" } else { "█" };
                let upper = if g.ascii_only() { "\"" } else { "▀" };
                let lower = if g.ascii_only() { "," } else { "▄" };
                let sym = match (top, bottom) {
                    (false, false) => light,
                    (false, true) => upper,
                    (true, false) => lower,
                    (true, true) => " ",
                };
                cell.set_symbol(sym);
            }
        }
    }
    let y = y0 + rows;
    for (i, line) in [text.as_str(), keys].iter().enumerate() {
        let w = line.chars().count().min(usize::from(area.width)) as u16;
        let x = area.x + (area.width - w) / 2;
        buf.set_stringn(
            x,
            y + i as u16,
            line,
            usize::from(area.width),
            app.theme.title,
        );
    }
}
