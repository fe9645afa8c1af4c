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
pub const CSV_HEADER: &str =
    "question,quantity,unit,truth,name,answer,offset,step,time,poll,revealed";

/// A truth or an answer: the shortest digits that read back the same, or
/// `nowhere` (a poll answered "nowhere in the sweep").
pub fn csv_value(v: f64) -> String {
    if v == super::question::NOWHERE {
        "nowhere".into()
    } else {
        crate::physical::csv_number::format(v)
    }
}

/// `2026-11-25T10:15:02Z`: a time in UTC, to the second.
pub fn utc(t: std::time::SystemTime) -> String {
    // default_stem writes `x-YYYYMMDD-HHMMSS`.
    let s = crate::snapshot::default_stem("x", t);
    let d = s.get(2..10).unwrap_or("00000000");
    let h = s.get(11..17).unwrap_or("000000");
    format!(
        "{}-{}-{}T{}:{}:{}Z",
        &d[..4],
        &d[4..6],
        &d[6..8],
        &h[..2],
        &h[2..4],
        &h[4..6]
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_are_utc_to_the_second() {
        let t = std::time::UNIX_EPOCH + std::time::Duration::from_secs(1_764_065_702);
        assert_eq!(utc(t), "2025-11-25T10:15:02Z");
        assert_eq!(csv_value(crate::class::NOWHERE), "nowhere");
        assert_eq!(csv_value(321.5), "321.5");
    }

    #[test]
    fn csv_fields_are_quoted_and_defused() {
        assert_eq!(csv_field("alice"), "alice");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(csv_field("=cmd()"), "'=cmd()");
        assert_eq!(csv_field("-1,2"), "\"'-1,2\"");
    }
}
