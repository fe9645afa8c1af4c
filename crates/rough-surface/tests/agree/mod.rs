//! What the reference tests share: the relative difference they measure
//! against an independent reader, and the check of a read surface's note
//! on undefined points. (Each test binary takes what it needs.)
#![allow(dead_code)]

/// |a − b| / |b|, 0 where the two are equal (zeros included).
pub fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

/// That `notes` say how many points were undefined (`undefined` > 0), or
/// say nothing of undefined points (`undefined` = 0); `who` names the
/// case in a failure.
pub fn undefined_noted(who: &str, notes: &[String], undefined: usize) {
    if undefined > 0 {
        let want = format!("{undefined} undefined point");
        assert!(
            notes.iter().any(|n| n.starts_with(&want)),
            "{who}: {notes:?}"
        );
    } else {
        assert!(
            !notes.iter().any(|n| n.contains("undefined")),
            "{who}: {notes:?}"
        );
    }
}
