//! Which format a file's bytes are in, told by their content (magic bytes)
//! rather than by the file's name, and a way forward for each file that is
//! not read: what it looks like and how to convert it.

use std::borrow::Cow;

use crate::error::{Failure, Problem};
use crate::formats::hints::hint;

/// The formats told apart.
#[derive(Debug, PartialEq)]
pub(crate) enum Format {
    /// ISO 25178-72 x3p (a zip; one without `main.xml` is named there).
    X3p,
    /// Gwyddion's native format.
    Gwy,
    /// An instrument's own format, read natively.
    Native(&'static crate::formats::readers::Native),
    /// Text (UTF-8, or Windows-1252 where it is not UTF-8).
    Text,
    /// A format not read: the line saying what it looks like.
    Other(String),
}

/// The format of `bytes`; `ext` (the file name's extension, lower case)
/// names formats that have no magic of their own.
pub(crate) fn format(bytes: &[u8], ext: &str) -> Format {
    let starts = |m: &[u8]| bytes.starts_with(m);
    let other = |what: &str| Format::Other(hint(what));
    if starts(crate::formats::readers::x3p::MAGIC) || starts(b"PK\x05\x06") {
        if let Some(n) = crate::formats::readers::sniff_zip(bytes, ext) {
            return Format::Native(n);
        }
        return Format::X3p;
    }
    if starts(crate::formats::readers::gwy::MAGIC) {
        return Format::Gwy;
    }
    if let Some(n) = crate::formats::readers::sniff(bytes, ext) {
        return Format::Native(n);
    }
    if utf16(bytes).is_some() {
        return Format::Text;
    }
    if starts(b"GWYQ") {
        return other("a Gwyddion file of another version");
    }
    if starts(b"\x89HDF\r\n\x1a\n") {
        return other("a NetCDF-4 or HDF5 file (not a Zygo .datx or a JPK .h5-jpk scan)");
    }
    if starts(b"CDF\x01") || starts(b"CDF\x02") || starts(b"CDF\x05") {
        return other("a NetCDF file");
    }
    if starts(b"\x93NUMPY") {
        return Format::Other(
            "looks like a NumPy .npy file: save the height array as text with \
             numpy.savetxt (one row of the map a line) and add '# Width:' and \
             '# Height:' lines"
                .to_string(),
        );
    }
    if starts(b"II*\x00") || starts(b"MM\x00*") {
        if let Some(why) = crate::formats::readers::damaged_tiff(bytes) {
            return Format::Other(why);
        }
    }
    for (magic, what) in [
        (&b"VK3_"[..], "a Keyence .vk3 file"),
        (b"Binary TrueMap", "a TrueMap .tmd file"),
        (b"OmniSurf3D", "an OmniSurf3D .os3d file"),
        (b"MATLAB", "a MATLAB .mat file"),
        (
            b"II*\x00",
            "a TIFF image that is not a JPK or Park Systems scan (Olympus LEXT … write TIFF)",
        ),
        (
            b"MM\x00*",
            "a TIFF image that is not a JPK or Park Systems scan (Olympus LEXT … write TIFF)",
        ),
        (b"\x89PNG", "a PNG image, not height data"),
        (b"\xff\xd8\xff", "a JPEG image, not height data"),
    ] {
        if starts(magic) {
            return other(what);
        }
    }
    if starts(b"BM") && binary(bytes) {
        return other("a BMP image, not height data");
    }
    match ext {
        "spm" | "001" | "002" | "003" if binary(bytes) => {
            return other("a Bruker/Digital Instruments Nanoscope file")
        }
        "mnt" => return other("a Digital Surf MountainsMap .mnt file"),
        "mdt" => return other("an NT-MDT .mdt file"),
        _ => {}
    }
    if matches!(ext, "plu" | "apx") && binary(bytes) {
        return Format::Other(format!(
            "named .{ext} but not a Sensofar file ({}): its name does not say what it holds; \
             open it in Gwyddion, which tells most formats apart, and save it as .gwy or .x3p",
            crate::formats::readers::plu::why_not(bytes)
        ));
    }
    if let Some((date, Some(ty))) = crate::formats::readers::plu::looks_like(bytes) {
        return Format::Other(format!(
            "looks like a Sensofar .plu file (its date '{}', measurement type {ty}), a format \
             without magic bytes that is told by its name: name it .plu (or .apx) to read it",
            crate::formats::readers::bin::printable(&date, 40)
        ));
    }
    if starts(b"fileType      ") {
        return other("an Agilent (Molecular Imaging) PicoView .mi file");
    }
    if !binary(bytes) && bytes[..bytes.len().min(1 << 20)].contains(&0) {
        // Text lines first, binary data after them (the NUL no text has).
        let first = String::from_utf8_lossy(&bytes[..bytes.len().min(60)]);
        let first = first.lines().next().unwrap_or("").trim().to_string();
        return Format::Other(format!(
            "a binary file whose first lines are text ('{first}'), in a format not read: \
             open it in Gwyddion (which reads most instruments' files) and save it as .gwy \
             or .x3p (or File → Save As → ASCII data matrix, .txt)"
        ));
    }
    if binary(bytes) {
        return Format::Other(
            "a binary file of a format not read: open it in Gwyddion (which reads most \
             instruments' files) and save it as .gwy or .x3p (or File → Save As → ASCII \
             data matrix, .txt)"
                .to_string(),
        );
    }
    Format::Text
}

/// Whether the first 4 KiB hold a NUL or control bytes that text does not.
fn binary(bytes: &[u8]) -> bool {
    bytes[..bytes.len().min(4096)]
        .iter()
        .any(|&b| b < 0x20 && !matches!(b, b'\t' | b'\n' | b'\r' | 0x0b | 0x0c | 0x1a))
}

/// Windows-1252 (a superset of Latin-1's printable characters) for the
/// bytes 0x80–0x9F; the five it leaves undefined decode as themselves.
const CP1252: [char; 32] = [
    '€', '\u{81}', '‚', 'ƒ', '„', '…', '†', '‡', 'ˆ', '‰', 'Š', '‹', 'Œ', '\u{8d}', 'Ž', '\u{8f}',
    '\u{90}', '‘', '’', '“', '”', '•', '–', '—', '˜', '™', 'š', '›', 'œ', '\u{9d}', 'ž', 'Ÿ',
];

/// Whether `bytes` start with a UTF-16 byte-order mark (Windows'
/// "Unicode" text), big-endian or not.
fn utf16(bytes: &[u8]) -> Option<bool> {
    match bytes {
        [0xff, 0xfe, ..] => Some(false),
        [0xfe, 0xff, ..] => Some(true),
        _ => None,
    }
}

/// Text bytes as a string: UTF-16 after its byte-order mark (Windows'
/// "Unicode"), UTF-8 when they are, else Windows-1252 (Latin-1's
/// superset, what Gwyddion and instruments on Windows write: `µm` as byte
/// 0xB5), with a note where not UTF-8.
pub(crate) fn decode(bytes: &[u8]) -> Result<(Cow<'_, str>, Option<String>), Failure> {
    if let Some(big) = utf16(bytes) {
        let unit = |c: &[u8]| {
            let b = [c[0], c[1]];
            if big {
                u16::from_be_bytes(b)
            } else {
                u16::from_le_bytes(b)
            }
        };
        // An odd last byte is a unit cut in half: a lone surrogate stands
        // for it, refused below.
        let units = bytes[2..]
            .chunks_exact(2)
            .map(unit)
            .chain((bytes.len() % 2 == 1).then_some(0xdc00));
        let mut t = String::with_capacity(bytes.len() / 2);
        let mut line = 1;
        for c in char::decode_utf16(units) {
            match c {
                Ok(c) if c != '\0' => {
                    line += usize::from(c == '\n');
                    t.push(c);
                }
                _ => return Err((Some(line), Problem::NotText)),
            }
        }
        return Ok((
            Cow::Owned(t),
            Some("read as UTF-16 text (Windows' \"Unicode\")".to_string()),
        ));
    }
    match std::str::from_utf8(bytes) {
        Ok(t) => Ok((Cow::Borrowed(t), None)),
        Err(e) => {
            let line = bytes[..e.valid_up_to()]
                .iter()
                .filter(|&&b| b == b'\n')
                .count()
                + 1;
            if binary(bytes) {
                return Err((Some(line), Problem::NotText));
            }
            let t: String = bytes
                .iter()
                .map(|&b| match b {
                    0x80..=0x9f => CP1252[(b - 0x80) as usize],
                    _ => b as char,
                })
                .collect();
            Ok((
                Cow::Owned(t),
                Some(format!(
                    "read as Windows-1252 (Latin-1) text: line {line} is not UTF-8"
                )),
            ))
        }
    }
}

/// A text file's bytes as the text to parse and what was assumed: UTF-8
/// or Windows-1252 ([`decode`]), a byte-order mark dropped, decimal commas
/// read as points when the first data row has them (Gwyddion's ASCII
/// export in a locale that writes them, its "use dot" off).
pub(crate) fn text(bytes: &[u8]) -> Result<(Cow<'_, str>, Vec<String>), Failure> {
    let (text, note) = decode(bytes)?;
    let mut notes: Vec<String> = note.into_iter().collect();
    let text = match text {
        Cow::Borrowed(t) => Cow::Borrowed(t.strip_prefix('\u{feff}').unwrap_or(t)),
        Cow::Owned(t) => Cow::Owned(t),
    };
    if matches!(
        crate::formats::text::scan::head(&text),
        Err((_, Problem::DecimalComma(_)))
    ) {
        notes.push("decimal commas read".to_string());
        return Ok((Cow::Owned(text.replace(',', ".")), notes));
    }
    Ok((text, notes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn magic_bytes_name_the_format() {
        assert_eq!(format(b"GWYP\0", "txt"), Format::Gwy);
        assert_eq!(format(b"PK\x03\x04rest", ""), Format::X3p);
        assert_eq!(format(b"1 2 3\n", "x3p"), Format::Text);
        let other = |b: &[u8], ext: &str| match format(b, ext) {
            Format::Other(s) => s,
            f => panic!("{f:?}"),
        };
        assert!(other(b"CDF\x01\0\0", "nc").contains("NetCDF"));
        assert!(other(b"\x89HDF\r\n\x1a\n\0", "nc").contains("HDF5"));
        assert!(other(b"\x93NUMPY\x01\x00", "npy").contains("numpy.savetxt"));
        assert!(other(b"II*\x00\x08\0", "tif").contains("TIFF"));
        assert!(other(b"VK3_\0\0", "vk3").contains("Keyence .vk3"));
        assert!(other(b"\0\x01\x02", "bin").contains("Gwyddion"));
        // Instruments' own files are read.
        let native = |b: &[u8], ext: &str| matches!(format(b, ext), Format::Native(_));
        assert!(native(b"\x89HDF\r\n\x1a\n\0", "datx"));
        assert!(native(b"VK6\0\0", "vk6"));
        assert!(native(b"\\*File list\r\n", ""));
        assert!(native(b"\x88\x1b\x03\x70\0", "dat"));
        let mut plu = b"Mon Apr 19 11:40:13 2021".to_vec();
        plu.resize(600, 0);
        plu[428] = 3;
        assert!(native(&plu, "plu"));
        assert!(other(&plu, "dat").contains("looks like a Sensofar .plu file"));
        // Cut short before its measurement type: read (and refused as cut).
        assert!(native(&plu[..300], "plu"));
        let mut bad = plu.clone();
        bad[428] = 99;
        assert_eq!(
            other(&bad, "plu"),
            "named .plu but not a Sensofar file (a measurement type of 99 at byte 428, where \
             Sensofar's are 0–6): its name does not say what it holds; open it in Gwyddion, \
             which tells most formats apart, and save it as .gwy or .x3p"
        );
        assert!(native(b"DIGITAL SURF\0", "sur"));
        let mut mi = b"fileType      Image\nversion PicoView\n".to_vec();
        mi.extend_from_slice(&[0; 16]);
        assert!(other(&mi, "mi").contains("PicoView .mi"));
        let mut head = b"# Width: 1 um\n1 2\n".repeat(300);
        head.extend_from_slice(&[7, 0, 0, 0]);
        assert!(other(&head, "")
            .starts_with("a binary file whose first lines are text ('# Width: 1 um')"));
        assert_eq!(format(b"\xff\xfe1\0 \0", "txt"), Format::Text);
        let (t, note) = decode(b"\xff\xfex\0 \0\xb5\0m\0\n\x001\0").unwrap();
        assert_eq!(
            (t.as_ref(), note.unwrap().as_str()),
            ("x µm\n1", "read as UTF-16 text (Windows' \"Unicode\")")
        );
        assert_eq!(
            decode(b"\xfe\xff\0x\0\n\0\0").unwrap_err(),
            (Some(2), Problem::NotText)
        );
        assert_eq!(
            decode(b"\xff\xfe1\0\n\0\x32").unwrap_err(),
            (Some(2), Problem::NotText)
        );
    }

    #[test]
    fn latin1_headers_decode() {
        let (t, note) = decode(b"# Width: 5 \xb5m\n1 2\n").unwrap();
        assert_eq!(t, "# Width: 5 µm\n1 2\n");
        assert!(note.unwrap().contains("line 1"));
        assert_eq!(decode(b"\x80 \x96").unwrap().0, "€ –");
        assert!(decode("µm".as_bytes()).unwrap().1.is_none());
        assert_eq!(decode(b"1 2\n\xff\0").unwrap_err().1, Problem::NotText);
    }
}
