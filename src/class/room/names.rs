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

/// A seat's token: 128 random bits from the system's generator, as 32
/// hexadecimal digits (only the page that took the seat knows it).
pub fn token() -> String {
    use std::io::Read;
    let mut b = [0u8; 16];
    let read = std::fs::File::open("/dev/urandom").and_then(|mut f| f.read_exact(&mut b));
    if read.is_err() {
        // No system generator: the time and the process, hashed twice
        // (a seat's token then guards against slips, not guessers).
        use std::hash::{BuildHasher, Hasher};
        let t = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        for (i, half) in b.chunks_mut(8).enumerate() {
            let mut h = std::collections::hash_map::RandomState::new().build_hasher();
            h.write_u128(t ^ i as u128);
            half.copy_from_slice(&h.finish().to_le_bytes());
        }
    }
    b.iter().map(|x| format!("{x:02x}")).collect()
}
