//! A student's name as the class shows it.

/// The most characters of a student's name that are shown (after escaping).
pub const NAME_CHARS: usize = 32;

/// A student's SSH user name as the class shows it: control and
/// direction-changing characters escaped (`\x1b`, `\u{202e}`, a backslash
/// doubled), cut to [`NAME_CHARS`] characters with `…` as the last, and
/// `(no name)` for an empty one.
pub fn clean_name(raw: &str) -> String {
    let mut out = String::new();
    let mut n = 0;
    for c in raw.chars() {
        let esc: String = match c {
            '\\' => "\\\\".into(),
            c if (c as u32) < 0x100 && c.is_control() => format!("\\x{:02x}", c as u32),
            c if c.is_control() || invisible(c) => format!("\\u{{{:x}}}", c as u32),
            c => c.to_string(),
        };
        for e in esc.chars() {
            if n == NAME_CHARS {
                out.pop();
                out.push('…');
                return out;
            }
            out.push(e);
            n += 1;
        }
    }
    if out.is_empty() {
        out.push_str("(no name)");
    }
    out
}

/// Characters that draw nothing or reorder what follows: zero-width and
/// bidirectional controls, the byte-order mark.
fn invisible(c: char) -> bool {
    matches!(c as u32, 0x200b..=0x200f | 0x202a..=0x202e | 0x2060..=0x206f | 0xfeff)
}
