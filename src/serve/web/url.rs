//! A query string's values (`name=ada&code=x%20y`), as a browser's
//! `URLSearchParams` writes them: `+` a space, `%XX` a byte, then UTF-8
//! (invalid bytes become U+FFFD).

/// The value of `key` in `query`, decoded; the first if there are several.
pub fn param(query: &str, key: &str) -> Option<String> {
    query
        .split('&')
        .filter_map(|kv| kv.split_once('=').or(Some((kv, ""))))
        .find(|(k, _)| decode(k) == key)
        .map(|(_, v)| decode(v))
}

fn decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'+' => out.push(b' '),
            b'%' if i + 2 < b.len() => match (hex(b[i + 1]), hex(b[i + 2])) {
                (Some(h), Some(l)) => {
                    out.push(h << 4 | l);
                    i += 2;
                }
                _ => out.push(b'%'),
            },
            c => out.push(c),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn hex(c: u8) -> Option<u8> {
    (c as char).to_digit(16).map(|d| d as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_decoded_as_browsers_encode_them() {
        let q = "name=Ada+Lovelace&code=gr%C3%A4nit&cols=120&bad=%zz%4&empty";
        assert_eq!(param(q, "name").as_deref(), Some("Ada Lovelace"));
        assert_eq!(param(q, "code").as_deref(), Some("gränit"));
        assert_eq!(param(q, "cols").as_deref(), Some("120"));
        assert_eq!(param(q, "bad").as_deref(), Some("%zz%4"));
        assert_eq!(param(q, "empty").as_deref(), Some(""));
        assert_eq!(param(q, "rows"), None);
        assert_eq!(param("name=%FF", "name").as_deref(), Some("\u{fffd}"));
        assert_eq!(param("name=a%1", "name").as_deref(), Some("a%1"));
        assert_eq!(param("name=%é1", "name").as_deref(), Some("%é1"));
    }
}
