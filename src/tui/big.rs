//! Numbers in large type for the projector: five rows of full blocks
//! (`#` in ASCII), three columns a digit and one between, so the back of
//! a lecture hall reads them.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

/// Rows a large character takes.
pub const ROWS: u16 = 5;

/// A character's rows (`#` where it is drawn); `None` for one the large
/// type has not.
fn glyph(c: char) -> Option<[&'static str; 5]> {
    Some(match c {
        '0' => ["###", "# #", "# #", "# #", "###"],
        '1' => [" # ", "## ", " # ", " # ", "###"],
        '2' => ["###", "  #", "###", "#  ", "###"],
        '3' => ["###", "  #", " ##", "  #", "###"],
        '4' => ["# #", "# #", "###", "  #", "  #"],
        '5' => ["###", "#  ", "###", "  #", "###"],
        '6' => ["###", "#  ", "###", "# #", "###"],
        '7' => ["###", "  #", "  #", "  #", "  #"],
        '8' => ["###", "# #", "###", "# #", "###"],
        '9' => ["###", "# #", "###", "  #", "###"],
        '.' => [" ", " ", " ", " ", "#"],
        ':' => [" ", "#", " ", "#", " "],
        '/' => ["  #", "  #", " # ", "#  ", "#  "],
        '%' => ["# #", "  #", " # ", "#  ", "# #"],
        '-' | '−' => ["   ", "   ", "###", "   ", "   "],
        '+' => ["   ", " # ", "###", " # ", "   "],
        'e' => ["   ", "###", "# #", "## ", "###"],
        '×' => ["   ", "# #", " # ", "# #", "   "],
        ' ' => ["  ", "  ", "  ", "  ", "  "],
        _ => return None,
    })
}

/// Whether `text` can be written in large type.
pub fn fits(text: &str) -> bool {
    text.chars().all(|c| glyph(c).is_some())
}

/// The columns `text` takes in large type.
pub fn width(text: &str) -> u16 {
    let w: usize = text
        .chars()
        .filter_map(glyph)
        .map(|g| g[0].chars().count() + 1)
        .sum();
    (w as u16).saturating_sub(1)
}

/// Writes `text` in large type at `(x, y)`, cut at `area`'s edge; its
/// blocks are `█` (`#` when `ascii`). Characters it has no glyph for are
/// left out (see [`fits`]).
pub fn draw(
    text: &str,
    (x, y): (u16, u16),
    area: Rect,
    ascii: bool,
    style: Style,
    buf: &mut Buffer,
) {
    let block = if ascii { "#" } else { "█" };
    let mut col = x;
    for g in text.chars().filter_map(glyph) {
        for (r, row) in g.iter().enumerate() {
            let yy = y + r as u16;
            for (i, c) in row.chars().enumerate() {
                let xx = col + i as u16;
                if c == '#' && xx < area.right() && yy < area.bottom() {
                    buf[(xx, yy)].set_symbol(block).set_style(style);
                }
            }
        }
        col += g[0].chars().count() as u16 + 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_in_five_rows_of_blocks() {
        assert!(fits("321.5") && fits("18/30") && fits("60%") && fits("0:42") && fits("1e-3"));
        assert!(!fits("ζ = 3") && !fits("nm"));
        assert_eq!(width("1"), 3);
        assert_eq!(width("321.5"), 4 * 3 + 1 + 4);
        let area = Rect::new(0, 0, 20, 5);
        let mut buf = Buffer::empty(area);
        draw("10", (0, 0), area, true, Style::new(), &mut buf);
        let rows: Vec<String> = (0..5)
            .map(|y| (0..7).map(|x| buf[(x, y)].symbol()).collect())
            .collect();
        assert_eq!(
            rows,
            [" #  ###", "##  # #", " #  # #", " #  # #", "### ###"]
        );
    }
}
