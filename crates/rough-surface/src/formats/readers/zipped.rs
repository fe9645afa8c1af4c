//! Instruments' files that are zip archives (Keyence .vk6/.vk7 and .zon,
//! Sensofar .plux), some behind a prefix of their own (a magic, a
//! thumbnail) that the zip's directory places: their members unpacked
//! with every size checked — no member unpacks to more than it declares
//! or than the reader allows, so a bomb is refused when it passes that,
//! not unpacked further.

use std::io::{Cursor, Read};

use zip::ZipArchive;

use super::bin::Bytes;
use crate::error::Failure;

/// A zip archive in a file's bytes, named for messages by its format.
pub(crate) struct Zipped<'a> {
    zip: ZipArchive<Cursor<&'a [u8]>>,
    b: Bytes<'a>,
}

impl<'a> Zipped<'a> {
    /// The archive in `bytes` (after any prefix), or the line saying why
    /// it cannot be read.
    pub fn open(bytes: &'a [u8], format: &'static str) -> Result<Zipped<'a>, Failure> {
        let b = Bytes::new(bytes, format);
        let zip = ZipArchive::new(Cursor::new(bytes)).map_err(|e| {
            b.bad(format!(
                "its zip archive cannot be read ({}): it is truncated or damaged",
                one_line(&e.to_string())
            ))
        })?;
        Ok(Zipped { zip, b })
    }

    /// The archive in `bytes`, if there is one (for telling formats apart).
    pub fn probe(bytes: &'a [u8]) -> Option<Zipped<'a>> {
        Zipped::open(bytes, "zip").ok()
    }

    /// A refusal naming the format.
    pub fn bad(&self, s: impl AsRef<str>) -> Failure {
        self.b.bad(s)
    }

    /// Whether the archive holds a member named `name`.
    pub fn has(&self, name: &str) -> bool {
        self.zip.index_for_name(name).is_some()
    }

    /// The members' names, in the archive's order.
    pub fn names(&self) -> Vec<String> {
        self.zip
            .file_names()
            .filter_map(|n| n.ok())
            .map(|n| n.into_owned())
            .collect()
    }

    /// The member `name` unpacked: refused when missing, when it declares
    /// more than `limit` bytes, or unpacks to other than it declares.
    pub fn member(&mut self, name: &str, limit: u64) -> Result<Vec<u8>, Failure> {
        let b = self.b;
        let shown = super::bin::printable(name, 80);
        let mut f = self.zip.by_name(name).map_err(|e| {
            b.bad(format!(
                "the member '{shown}' is missing or unreadable ({})",
                one_line(&e.to_string())
            ))
        })?;
        let declared = f.size();
        if declared > limit {
            return Err(b.bad(format!(
                "the member '{shown}' unpacks to {declared} bytes: more than the {} MB read",
                limit >> 20
            )));
        }
        // Grown as the bytes arrive: a member that declares more than it
        // holds allocates no more than it holds.
        let mut out = Vec::with_capacity(declared.min(1 << 20) as usize);
        let unpacking = |e: std::io::Error| {
            b.bad(format!(
                "the member '{shown}' cannot be unpacked ({}): the file is damaged",
                one_line(&e.to_string())
            ))
        };
        (&mut f)
            .take(declared)
            .read_to_end(&mut out)
            .map_err(unpacking)?;
        if out.len() as u64 != declared {
            return Err(b.bad(format!(
                "the member '{shown}' unpacks to {} bytes where the zip says {declared}: \
                 the file is damaged",
                out.len()
            )));
        }
        let mut more = [0u8; 1];
        if f.read(&mut more).map_err(unpacking)? > 0 {
            return Err(b.bad(format!(
                "the member '{shown}' unpacks to more bytes than the zip says \
                 ({declared}): the file is damaged"
            )));
        }
        Ok(out)
    }
}

/// A library's message on one line.
pub(crate) fn one_line(s: &str) -> String {
    super::bin::printable(&s.split_whitespace().collect::<Vec<_>>().join(" "), 200)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn zip_of(members: &[(&str, &[u8])]) -> Vec<u8> {
        let mut w = zip::ZipWriter::new(Cursor::new(Vec::new()));
        let o = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated);
        for (n, d) in members {
            w.start_file(*n, o).unwrap();
            w.write_all(d).unwrap();
        }
        w.finish().unwrap().into_inner()
    }

    #[test]
    fn members_are_bounded() {
        let mut bytes = b"PREFIX".to_vec();
        bytes.extend(zip_of(&[("a", b"hello"), ("big", &vec![0u8; 1 << 20])]));
        let mut z = Zipped::open(&bytes, "F").unwrap();
        assert!(z.has("a") && !z.has("b"));
        assert_eq!(z.names(), ["a", "big"]);
        assert_eq!(z.member("a", 10).unwrap(), b"hello");
        let e = z.member("big", 1000).unwrap_err().1.to_string();
        assert_eq!(
            e,
            "F: the member 'big' unpacks to 1048576 bytes: more than the 0 MB read"
        );
        assert!(z
            .member("c", 10)
            .unwrap_err()
            .1
            .to_string()
            .contains("missing"));
        let e = Zipped::open(&bytes[..bytes.len() - 3], "F").err().unwrap();
        assert!(e
            .1
            .to_string()
            .starts_with("F: its zip archive cannot be read"));
    }
}
