//! The join page's QR code: for the console's banner (text with colours, a
//! module row pair per line in half blocks) and for the lecturer's `Q`
//! (the same modules as the explorer's cells). Dark modules on light, as
//! scanners expect, whatever the terminal's own background.

use qrcode::{Color, EcLevel, QrCode};

/// Modules of light margin around the code (the standard asks 4; 2 reads
/// well on a screen and fits 80×24 with a long address).
pub const QUIET: usize = 2;

/// The code's modules with the quiet zone: `true` is dark. `None` for a
/// text too long for a QR code.
pub fn modules(text: &str) -> Option<Vec<Vec<bool>>> {
    let code = QrCode::with_error_correction_level(text.as_bytes(), EcLevel::M).ok()?;
    let w = code.width();
    let colors = code.to_colors();
    let n = w + 2 * QUIET;
    let mut rows = vec![vec![false; n]; n];
    for (i, c) in colors.iter().enumerate() {
        rows[QUIET + i / w][QUIET + i % w] = *c == Color::Dark;
    }
    Some(rows)
}

/// The code as lines of text for a terminal: `▀` with the upper module as
/// the foreground and the lower as the background (black, bright white),
/// two module rows a line.
pub fn terminal_lines(text: &str) -> Vec<String> {
    let Some(m) = modules(text) else {
        return Vec::new();
    };
    let colour = |dark: bool, fg: bool| match (dark, fg) {
        (true, true) => "30",
        (false, true) => "97",
        (true, false) => "40",
        (false, false) => "107",
    };
    m.chunks(2)
        .map(|pair| {
            let mut line = String::new();
            for x in 0..pair[0].len() {
                let top = pair[0][x];
                let bottom = pair.get(1).is_some_and(|r| r[x]);
                line.push_str(&format!(
                    "\x1b[{};{}m▀",
                    colour(top, true),
                    colour(bottom, false)
                ));
            }
            line.push_str("\x1b[0m");
            line
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_join_address_is_a_small_code_with_its_margin() {
        let url = "http://192.168.7.20:8080/?code=granite";
        let m = modules(url).unwrap();
        // Version 3 (29 modules) at level M for 39 bytes, plus the margin.
        assert_eq!(m.len(), 29 + 2 * QUIET);
        assert!(m.iter().all(|r| r.len() == m.len()));
        // The finder pattern's corner: dark, in from the margin.
        assert!(m[QUIET][QUIET] && !m[0][0]);
        let lines = terminal_lines(url);
        assert_eq!(lines.len(), m.len().div_ceil(2));
        assert_eq!(lines[0].matches('▀').count(), m.len());
        // Too long for any QR code: nothing, not a panic.
        assert!(modules(&"x".repeat(5000)).is_none());
    }
}
