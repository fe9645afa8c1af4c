//! The poll's CSV: its header and fields a spreadsheet reads safely.

/// One field of a CSV row: quoted when it holds a comma, quote or line
/// break; a leading `=`, `+`, `-` or `@` (which a spreadsheet would run as
/// a formula) gets a `'` before it.
pub fn csv_field(s: &str) -> String {
    let s = if s.starts_with(['=', '+', '-', '@']) {
        format!("'{s}")
    } else {
        s.to_string()
    };
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s
    }
}

/// The first line of a poll's CSV.
pub const CSV_HEADER: &str = "question,quantity,unit,truth,name,answer,offset";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_fields_are_quoted_and_defused() {
        assert_eq!(csv_field("alice"), "alice");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(csv_field("=cmd()"), "'=cmd()");
        assert_eq!(csv_field("-1,2"), "\"'-1,2\"");
    }
}
