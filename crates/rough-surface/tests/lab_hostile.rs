//! Damaged and hostile files in the lab's formats (Digital Surf compressed
//! and profiles, WSxM, BCR, Nanonis .sxm, Gwyddion 1, Seiko .xqd), one
//! reader at a time: cut short, sizes that lie, streams that unpack to more
//! than they say — each refused with one line naming the format and the
//! problem, never a panic, never an allocation beyond what the file's size
//! allows (a counting allocator watches every test here). Then every file
//! of tests/data/lab mutated at random (`FUZZ_CASES` cases a file, 48 by
//! default; `FUZZ_SEED` as tests/fuzz/mod.rs says).

use std::io::Write;
use std::path::{Path, PathBuf};

mod fuzz;
#[path = "fuzz/harness.rs"]
mod harness;

#[global_allocator]
static ALLOC: fuzz::Counting = fuzz::Counting;

use harness::{put, refuse};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lab")
}

/// A file's bytes (a `.gz` unpacked).
fn bytes(name: &str) -> Vec<u8> {
    harness::file_bytes(&dir().join(name))
}

/// The file cut short at several places, by its last byte too: each
/// refused, naming `format`.
fn truncated(name: &str, format: &str) {
    harness::truncated(&bytes(name), name, format, true, &[1, 8]);
}

/// `from` replaced by `to` (the first time) in the text of `b`.
fn swap(b: &[u8], from: &str, to: &str) -> Vec<u8> {
    let at = b
        .windows(from.len())
        .position(|w| w == from.as_bytes())
        .unwrap_or_else(|| panic!("no '{from}'"));
    let mut out = b[..at].to_vec();
    out.extend_from_slice(to.as_bytes());
    out.extend_from_slice(&b[at + from.len()..]);
    out
}

#[test]
fn digital_surf_compressed() {
    const F: &str = "Digital Surf compressed .sur: ";
    truncated("surz-1.sur", F);
    let full = bytes("surz-1.sur");
    // The directory: after the header and a 33-byte comment.
    let dir = 512 + 33;
    let mut b = full.clone();
    put(&mut b, dir, &u32::MAX.to_le_bytes());
    assert!(refuse("x.sur", &b).contains("compressed streams where the file has room"));
    let mut b = full.clone();
    put(&mut b, dir + 4, &(1u32 << 31).to_le_bytes());
    assert!(refuse("x.sur", &b).contains("more than zlib makes of them"));
    let mut b = full.clone();
    put(&mut b, dir + 8, &u32::MAX.to_le_bytes());
    assert!(refuse("x.sur", &b).contains("runs past the end of the file"));
    let mut b = full.clone();
    put(&mut b, 108, &1i32.to_le_bytes());
    put(&mut b, 116, &56u32.to_le_bytes());
    assert!(refuse("x.sur", &b).contains("the compressed streams unpack to 16128 bytes"));
    let mut b = full.clone();
    put(&mut b, 108, &(1i32 << 20).to_le_bytes());
    put(&mut b, 112, &(1i32 << 10).to_le_bytes());
    put(&mut b, 116, &(1u32 << 30).to_le_bytes());
    assert_eq!(
        refuse("x.sur", &b),
        "Digital Surf compressed .sur: the heights: 1048576 × 1024 points, more than \
         the 67108864 a file is read with"
    );
    // A stream that unpacks to more than it says: 10 MB of zeros said to
    // be a 64 × 64 map's 16 KB is cut off past 16 KB.
    let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
    e.write_all(&vec![0u8; 10 << 20]).unwrap();
    let bomb = e.finish().unwrap();
    let mut b = full[..512].to_vec();
    put(&mut b, 108, &64i32.to_le_bytes());
    put(&mut b, 112, &64i32.to_le_bytes());
    put(&mut b, 116, &4096u32.to_le_bytes());
    put(&mut b, 334, &0u16.to_le_bytes());
    b.extend_from_slice(&1u32.to_le_bytes());
    b.extend_from_slice(&16384u32.to_le_bytes());
    b.extend_from_slice(&(bomb.len() as u32).to_le_bytes());
    b.extend_from_slice(&bomb);
    assert_eq!(
        refuse("x.sur", &b),
        "Digital Surf compressed .sur: compressed stream 0 unpacks to more than 16384 bytes \
         where its directory says 16384: it is damaged"
    );
    // A stream that is not zlib.
    let mut b = full;
    let at = dir + 4 + 16;
    b[at..at + 8].copy_from_slice(b"notzlib!");
    assert!(refuse("x.sur", &b).contains("compressed stream 0 cannot be unpacked"));
}

#[test]
fn digital_surf_objects() {
    let full = bytes("surz-2.pro");
    let mut b = full.clone();
    put(&mut b, 18, &20i16.to_le_bytes());
    assert_eq!(
        refuse("x.pro", &b),
        "Digital Surf compressed .sur: a spectrum (object type 20): the file holds no \
         heights (a surface or a profile is read)"
    );
    let mut b = full.clone();
    put(&mut b, 112, &2i32.to_le_bytes());
    put(&mut b, 116, &600u32.to_le_bytes());
    assert!(refuse("x.pro", &b).contains("a profile (object type 1) of 2 rows"));
    let mut b = full;
    put(&mut b, 212, b"a.u.\0");
    assert!(refuse("x.pro", &b).contains("the unit of the heights is 'a.u.', not a length"));
}

#[test]
fn wsxm() {
    truncated("sample_0.top.gz", "WSxM: ");
    let full = bytes("sample_0.top.gz");
    let e = refuse(
        "x.top",
        &swap(
            &full,
            "Image header size: 2996",
            "Image header size: 9999999",
        ),
    );
    assert!(e.contains("runs past the end of the file"), "{e}");
    let e = refuse(
        "x.top",
        &swap(&full, "Number of rows: 512", "Number of rows: 999"),
    );
    assert!(e.contains("but the file holds"), "{e}");
    let e = refuse(
        "x.top",
        &swap(&full, "Number of rows: 512", "Number of rows: 9e9"),
    );
    assert!(e.contains("'Number of rows' is not a count"), "{e}");
    let e = refuse(
        "x.top",
        &swap(
            &swap(&full, "Image header size: 2996", "Image header size: 3003"),
            "Number of columns: 512",
            "Number of columns: 4294967295",
        ),
    );
    assert!(e.contains("more than the 67108864"), "{e}");
    let e = refuse(
        "x.top",
        &swap(&full, "Image Data Type: short", "Image Data Type: cmplx"),
    );
    assert!(e.contains("data of type 'cmplx'"), "{e}");
    let e = refuse(
        "x.top",
        &swap(&full, "Z Amplitude: 59.7449 nm", "Z Amplitude: 59.7449 nA"),
    );
    assert!(
        e.contains("is in 'nA', not a length: the file holds no heights"),
        "{e}"
    );
    let e = refuse("x.top", &swap(&full, "SxM Image file", "SxM Curve file"));
    assert_eq!(
        e,
        "WSxM: a WSxM 'SxM Curve file', not an image: the file holds no heights"
    );
    let e = refuse("x.top", &swap(&full, "[Header end]", "[Header and]"));
    assert!(e.contains("no '[Header end]'"), "{e}");
}

#[test]
fn image_metrology_bcr() {
    truncated("bcr-1.bcr", "Image Metrology .bcr: ");
    truncated("bcrf-2.bcrf", "Image Metrology .bcr: ");
    let full = bytes("bcr-1.bcr");
    let e = refuse("x.bcr", &swap(&full, "xpixels = 48", "xpixels = 99999"));
    assert!(e.contains("but the file holds"), "{e}");
    let e = refuse(
        "x.bcr",
        &swap(&full, "ypixels = 32", "ypixels = 4294967295999"),
    );
    assert!(
        e.contains("'ypixels' is '4294967295999'") || e.contains("more than"),
        "{e}"
    );
    let e = refuse(
        "x.bcr",
        &swap(&full, "headersize = 2048", "headersize = 99999999"),
    );
    assert!(
        e.contains("the header size '99999999' is not a size"),
        "{e}"
    );
    let e = refuse(
        "x.bcr",
        &swap(&full, "headersize = 2048", "headersize = 4096"),
    );
    assert!(e.contains("but the file holds 5120 bytes"), "{e}");
    let e = refuse("x.bcr", &swap(&full, "zunit = nm", "zunit = V "));
    assert!(
        e.contains("zunit is 'V', not a unit of length: the file holds no heights"),
        "{e}"
    );
    let e = refuse("x.bcr", &swap(&full, "# a comment", "forcecurve=1"));
    assert_eq!(
        e,
        "Image Metrology .bcr: force curves: the file holds no heights"
    );
}

#[test]
fn nanonis_sxm() {
    truncated("sxm-1.sxm", "Nanonis .sxm: ");
    let full = bytes("sxm-1.sxm");
    let e = refuse(
        "x.sxm",
        &swap(&full, "       64        48", "  99999999  99999999"),
    );
    assert!(e.contains("more than the 67108864"), "{e}");
    let e = refuse(
        "x.sxm",
        &swap(&full, "       64        48", "       64       480"),
    );
    assert!(e.contains("but the file holds"), "{e}");
    let e = refuse("x.sxm", &swap(&full, "\tZ\tm\tboth", "\tZ\tm\tsideways"));
    assert!(e.contains("the direction 'sideways' of channel 'Z'"), "{e}");
    let e = refuse("x.sxm", &swap(&full, ":SCANIT_END:", ":SCANIT_END?"));
    assert!(e.contains("no ':SCANIT_END:' line"), "{e}");
    let e = refuse("x.sxm", &swap(&full, "\tZ\tm\tboth", "\tY\tm\tboth"));
    assert!(
        e.contains("no channel 'Z' (the topography): the file holds Y (m), Current (A)"),
        "{e}"
    );
    let e = refuse(
        "x.sxm",
        &swap(
            &full,
            "FLOAT            MSBFIRST",
            "INT              MSBFIRST",
        ),
    );
    assert!(e.contains("data of type 'INT MSBFIRST'"), "{e}");
}

#[test]
fn gwyddion_1() {
    truncated("gwyo-1.gwy", "Gwyddion .gwy: ");
    let full = bytes("gwyo-1.gwy");
    let mut b = full.clone();
    put(&mut b, 17, &u32::MAX.to_le_bytes());
    assert!(refuse("x.gwy", &b).contains("the container claims 4294967295 bytes"));
    let mut b = full.clone();
    put(&mut b, 21, &7u32.to_le_bytes());
    assert!(refuse("x.gwy", &b).contains("has the unknown type 7"));
    let mut b = full;
    put(&mut b, 4, b"GwyDataField\0");
    assert!(refuse("x.gwy", &b).starts_with("Gwyddion .gwy: "));
    // Objects nested beyond any file.
    let mut nest = b"GWYOGwyContainer\0".to_vec();
    let mut inner = Vec::new();
    for _ in 0..10_000 {
        inner.extend_from_slice(b"o\0o");
        inner.extend_from_slice(b"GwyContainer\0");
        inner.extend_from_slice(&(1u32 << 30).to_le_bytes());
    }
    let mut body = 80u32.to_le_bytes().to_vec();
    body.extend_from_slice(b"/0/data\0GwyDataField\0");
    body.extend_from_slice(&(inner.len() as u32).to_le_bytes());
    body.extend_from_slice(&inner);
    nest.extend_from_slice(&(body.len() as u32).to_le_bytes());
    nest.extend_from_slice(&body);
    let e = refuse("x.gwy", &nest);
    assert!(
        e.contains("nested deeper than 64") || e.contains("claims"),
        "{e}"
    );
}

#[test]
fn seiko_xqd() {
    truncated("xqd-1.xqd", "Seiko/SII .xqd: ");
    let full = bytes("xqd-1.xqd");
    let mut b = full.clone();
    put(&mut b, 0x57a, &u16::MAX.to_le_bytes());
    assert!(refuse("x.xqd", &b).contains("65535 × 64 points of 2 bytes do not fill"));
    let mut b = full.clone();
    put(&mut b, 0x18, &u32::MAX.to_le_bytes());
    assert!(refuse("x.xqd", &b).contains("do not fill the data from byte 4294967295"));
    let mut b = full.clone();
    put(&mut b, 0x14, &7u32.to_le_bytes());
    assert!(refuse("x.xqd", &b).contains("the header says the file ends at byte 7"));
    let mut b = full.clone();
    put(&mut b, 0x98, &f64::NAN.to_le_bytes());
    assert!(refuse("x.xqd", &b).contains("the spacing along x is NaN nm"));
    assert_eq!(
        refuse("x.xqp", &full),
        "Seiko/SII .xqd: a phase or current image (.xqp, .xqi): the file holds no heights"
    );
}

/// The files mutated, as they are named (the `.gz` ones unpacked).
const FILES: [&str; 13] = [
    "surz-1.sur",
    "surz-2.pro",
    "surz-3.sur",
    "surz-rs.sur",
    "sample_0.top.gz",
    "sample_1_um_scale.stp.gz",
    "bcr-1.bcr",
    "bcrf-2.bcrf",
    "sxm-1.sxm",
    "A151216.123306-02602.sxm.gz",
    "gwyo-1.gwy",
    "xqd-1.xqd",
    "xqd-2.xqd",
];

crate::mutation_fuzz!(FILES, bytes);
