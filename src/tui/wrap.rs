//! Text wrapped to the screen's width.

/// `text` word-wrapped into at most `rows` lines of `width` characters; when
/// it does not fit, the last line ends in `cut` ("…"). Words longer than a
/// line are cut.
pub fn wrap(text: &str, width: usize, rows: usize, cut_mark: char) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    if width == 0 || rows == 0 {
        return lines;
    }
    let mut cur = String::new();
    let mut cut = false;
    for word in text.split_whitespace() {
        let n = cur.chars().count();
        let w = word.chars().count();
        if n > 0 && n + 1 + w > width {
            if lines.len() + 1 == rows {
                cut = true;
                break;
            }
            lines.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.extend(word.chars().take(width));
        cut |= w > width;
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    if cut {
        if let Some(last) = lines.last_mut() {
            let keep = last.chars().count().min(width - 1);
            *last = last
                .chars()
                .take(keep)
                .chain([cut_mark])
                .collect::<String>();
        }
    }
    lines
}
