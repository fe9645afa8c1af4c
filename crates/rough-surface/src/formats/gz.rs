//! A gzip-compressed file (`.txt.gz`, or any file the readers read,
//! compressed), read as what it holds: unpacked up to
//! [`crate::MAX_BYTES`] (a bomb is refused when it passes that, not
//! unpacked further), then told apart like any file, by its content and
//! the name stored inside the gzip file, else its own name (`scan.plu.gz`
//! is a Sensofar file, and so is `plu_in.gz` holding `scan.plu`).

use std::io::Read;
use std::path::Path;

use crate::error::{Failure, Problem};

/// The first bytes of a gzip member.
pub(crate) const MAGIC: &[u8] = b"\x1f\x8b";

/// The extension the readers go by, lower case: `sur`; a `.gz`'s is its
/// inner name's with `.gz` (`txt.gz`), or `gz` alone.
pub(crate) fn extension(path: &Path) -> String {
    let ext = |p: &Path| {
        p.extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default()
    };
    let outer = ext(path);
    if outer != "gz" {
        return outer;
    }
    match path.file_stem().map(|s| ext(Path::new(s))) {
        Some(inner) if !inner.is_empty() => format!("{inner}.gz"),
        _ => outer,
    }
}

/// The extension of what a `.gz` of extension `ext` holds ("" unknown).
pub(crate) fn inner(ext: &str) -> &str {
    ext.strip_suffix(".gz")
        .unwrap_or(if ext == "gz" { "" } else { ext })
}

/// The name gzip stored of the file it compressed (its header's FNAME,
/// written unless `gzip -n`), if any.
pub(crate) fn stored_name(bytes: &[u8]) -> Option<String> {
    const FEXTRA: u8 = 4;
    const FNAME: u8 = 8;
    let flags = *bytes.get(3)?;
    if !bytes.starts_with(MAGIC) || flags & FNAME == 0 {
        return None;
    }
    let mut at = 10;
    if flags & FEXTRA != 0 {
        let n = u16::from_le_bytes([*bytes.get(10)?, *bytes.get(11)?]) as usize;
        at += 2 + n;
    }
    let rest = bytes.get(at..)?;
    let end = rest.iter().take(4096).position(|&c| c == 0)?;
    // Latin-1, as RFC 1952 says.
    Some(rest[..end].iter().map(|&c| c as char).collect())
}

/// The extension the readers go by for what the gzip file `bytes`, of
/// extension `ext`, holds: that of the name stored inside it, else the
/// one its own name gives (`scan.plu.gz`).
pub(crate) fn inner_of(bytes: &[u8], ext: &str) -> String {
    stored_name(bytes)
        .map(|n| extension(Path::new(&n)))
        .filter(|e| !e.is_empty())
        .unwrap_or_else(|| inner(ext).to_string())
}

fn bad(s: impl AsRef<str>) -> Failure {
    (
        None,
        Problem::Format(format!("gzip-compressed file: {}", s.as_ref())),
    )
}

/// The bytes a gzip file holds (several members one after the other, as
/// `gzip` writes them when files are concatenated, are one file).
pub(crate) fn unpack(bytes: &[u8]) -> Result<Vec<u8>, Failure> {
    unpack_up_to(bytes, crate::limits::MAX_BYTES)
}

/// [`unpack`], refusing more than `limit` bytes (unpacking stops there).
fn unpack_up_to(bytes: &[u8], limit: u64) -> Result<Vec<u8>, Failure> {
    let mut out = Vec::new();
    let mut d = flate2::read::MultiGzDecoder::new(bytes).take(limit + 1);
    d.read_to_end(&mut out).map_err(|e| {
        bad(format!(
            "cannot be unpacked ({e}): it is truncated or damaged"
        ))
    })?;
    if out.len() as u64 > limit {
        return Err(bad(format!(
            "unpacks to more than the {} MB read",
            limit >> 20
        )));
    }
    if out.is_empty() {
        return Err(bad("it holds nothing"));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_inside() {
        assert_eq!(extension(Path::new("a/m.TXT.gz")), "txt.gz");
        assert_eq!(extension(Path::new("m.gz")), "gz");
        assert_eq!(extension(Path::new("m.plu")), "plu");
        assert_eq!(inner("txt.gz"), "txt");
        assert_eq!(inner("gz"), "");
        use std::io::Write;
        let mut e = flate2::GzBuilder::new()
            .filename("surfalize_test_1.PLU")
            .write(Vec::new(), flate2::Compression::fast());
        e.write_all(b"x").unwrap();
        let named = e.finish().unwrap();
        assert_eq!(stored_name(&named).unwrap(), "surfalize_test_1.PLU");
        assert_eq!(inner_of(&named, "gz"), "plu");
        assert_eq!(inner_of(b"\x1f\x8b\x08\0\0\0\0\0\0\x03", "txt.gz"), "txt");
        assert_eq!(stored_name(b"\x1f\x8b\x08\x08\0"), None);
        assert!(unpack(b"\x1f\x8b\x08\0\0")
            .unwrap_err()
            .1
            .to_string()
            .contains("truncated"));
    }

    #[test]
    fn bombs_are_cut_off() {
        use std::io::Write;
        // 3 MB of zeros as three gzip members of 1 MB (3 KB in all): the
        // unpacking stops past the limit (512 MB for a file; 2 MB here, so
        // that the test is quick) and says so.
        let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
        e.write_all(&vec![0u8; 1 << 20]).unwrap();
        let member = e.finish().unwrap();
        let bomb = member.repeat(3);
        assert_eq!(unpack_up_to(&bomb, 3 << 20).unwrap().len(), 3 << 20);
        assert_eq!(
            unpack_up_to(&bomb, 2 << 20).unwrap_err().1.to_string(),
            "gzip-compressed file: unpacks to more than the 2 MB read"
        );
    }
}
