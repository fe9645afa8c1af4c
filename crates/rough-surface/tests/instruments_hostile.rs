//! Damaged and hostile instruments' files, one reader at a time: files cut
//! short, sizes that lie, dimensions beyond any file, offsets past the end
//! — each refused with one line naming the format and the problem, never a
//! panic, and never an allocation beyond what the file's size allows (a
//! counting allocator watches every test here). Then every reader's real
//! file mutated at random (`FUZZ_CASES` cases a reader, 48 by default).

use std::path::{Path, PathBuf};

mod fuzz;
#[path = "fuzz/harness.rs"]
mod harness;

use rough_surface::{parse_named, Options};

#[global_allocator]
static ALLOC: fuzz::Counting = fuzz::Counting;

use harness::{put, refuse};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/instruments")
}

/// An example file's bytes (stored gzip-compressed).
fn bytes(name: &str) -> Vec<u8> {
    harness::file_bytes(&dir().join(format!("{name}.gz")))
}

/// The file cut short at several places: each refused, naming `format`.
fn truncated(name: &str, format: &str) {
    harness::truncated(&bytes(name), name, format, false, &[1, 100]);
}

/// The first place `what` occurs in `b`.
fn find(b: &[u8], what: &[u8]) -> usize {
    b.windows(what.len()).position(|w| w == what).unwrap()
}

#[test]
fn digital_surf_sur() {
    truncated("sur-2.sur", "Digital Surf .sur: ");
    let full = bytes("sur-2.sur");
    // Sizes beyond any file, and a count that does not match them.
    let mut b = full.clone();
    put(&mut b, 108, &(1i32 << 20).to_le_bytes());
    put(&mut b, 112, &(1i32 << 10).to_le_bytes());
    put(&mut b, 116, &(1u32 << 30).to_le_bytes());
    assert_eq!(
        refuse("x.sur", &b),
        "Digital Surf .sur: the heights: 1048576 × 1024 points, more than the \
         67108864 a file is read with"
    );
    put(&mut b, 116, &7u32.to_le_bytes());
    assert!(refuse("x.sur", &b).contains("do not make its count of 7"));
    // A comment that pushes the heights past the end.
    let mut b = full.clone();
    put(&mut b, 334, &u16::MAX.to_le_bytes());
    assert!(refuse("x.sur", &b).contains("the file holds 1090480 bytes"));
    let mut b = full.clone();
    put(&mut b, 98, &12u16.to_le_bytes());
    assert_eq!(
        refuse("x.sur", &b),
        "Digital Surf .sur: heights of 12 bits: 16 or 32 bits are read"
    );
    let mut b = full;
    put(&mut b, 212, b"furlong\0");
    assert!(refuse("x.sur", &b).contains("the unit of the heights is 'furlong'"));
}

#[test]
fn sensofar_plu() {
    truncated("plu-1.plu", "Sensofar .plu: ");
    let full = bytes("plu-1.plu");
    let mut b = full.clone();
    put(&mut b, 500, &u32::MAX.to_le_bytes());
    put(&mut b, 504, &u32::MAX.to_le_bytes());
    assert!(refuse("x.plu", &b).contains("more than the 67108864"));
    let mut b = full.clone();
    put(&mut b, 500, &2000u32.to_le_bytes());
    assert!(refuse("x.plu", &b).contains("but the file holds 3230225 bytes"));
    let mut b = full.clone();
    b[489] = 200;
    assert!(refuse("x.plu", &b).starts_with("Sensofar .plu: "));
    let mut b = full;
    put(&mut b, 428, &1u32.to_le_bytes());
    assert_eq!(
        refuse("x.plu", &b),
        "Sensofar .plu: measurement type 1: a topography (type 3) is read, this is a profile"
    );
}

#[test]
fn nanoscope_di() {
    truncated("di-3.di", "Nanoscope: ");
    let full = bytes("di-3.di");
    // The header cut before its end line.
    assert!(refuse("x.di", &full[..20000]).contains("no '\\*File list end' line"));
    let mut b = full.clone();
    let at = find(&b, b"\\Data offset: 40960");
    b.splice(at + 19..at + 19, *b"99");
    assert!(refuse("x.di", &b).contains("image 0 ends at byte 4227171 but the file holds"));
    // A data length that cannot hold the image (a wrong number of lines
    // is mended from the scan list, as SurfaceTopography mends it).
    let mut b = full.clone();
    let at = find(&b, b"\\Data length: 131072");
    put(&mut b, at, b"\\Data length: 131070");
    assert!(refuse("x.di", &b).contains("does not fit its data length of 131070 bytes"));
    // The first image's own Samps/line (after its data offset).
    let mut b = full.clone();
    let image = find(&b, b"\\Data offset: 40960");
    let at = image + find(&b[image..], b"\\Samps/line: 256");
    put(&mut b, at, b"\\Samps/line: 2x6");
    assert_eq!(
        refuse("x.di", &b),
        "Nanoscope: image 0's 'samps/line' is not a count"
    );
    // Force curves and text data are named.
    let mut b = full;
    put(&mut b, 0, b"\\*Force file list\r\n");
    assert!(refuse("x.di", &b).contains("force curves"));
}

#[test]
fn wyko_opd() {
    truncated("opd-1.opd", "Wyko .opd: ");
    let full = bytes("opd-1.opd");
    // The 'Raw' array claims more columns than its block holds.
    let mut b = full.clone();
    put(&mut b, 24020, &u16::MAX.to_le_bytes());
    assert!(refuse("x.opd", &b).contains("Raw: 65535 × 480 points take 125827200 bytes"));
    let mut b = full.clone();
    put(&mut b, 20, &7i32.to_le_bytes());
    assert!(refuse("x.opd", &b).contains("not a multiple of 24 bytes"));
    let mut b = full;
    put(&mut b, 20, &(24 * 10_000_000i32).to_le_bytes());
    assert!(refuse("x.opd", &b).contains("runs past the end of the file"));
}

#[test]
fn zygo_metropro_dat() {
    truncated("metropro-1.dat", "Zygo MetroPro .dat: ");
    let full = bytes("metropro-1.dat");
    let mut b = full.clone();
    put(&mut b, 68, &u16::MAX.to_be_bytes());
    put(&mut b, 70, &u16::MAX.to_be_bytes());
    assert!(refuse("x.dat", &b).contains(": 65535 × 65535 points, more than"));
    let mut b = full.clone();
    put(&mut b, 6, &1000u32.to_be_bytes());
    assert!(refuse("x.dat", &b).contains("a header of 1000 bytes"));
    let mut b = full;
    put(&mut b, 218, &7i16.to_be_bytes());
    assert!(refuse("x.dat", &b).contains("the phase resolution is 7"));
}

#[test]
fn alicona_al3d() {
    truncated("al3d-1.al3d", "Alicona .al3d: ");
    let full = bytes("al3d-1.al3d");
    let field = |s: &str| {
        let mut v = s.as_bytes().to_vec();
        v.resize(30, 0);
        v
    };
    let mut b = full.clone();
    put(&mut b, 121 + 20, &field("9999"));
    assert!(refuse("x.al3d", &b).contains("but the file holds"));
    let mut b = full.clone();
    put(&mut b, 121 + 20, &field("99999999"));
    assert!(refuse("x.al3d", &b).contains("more than the 67108864"));
    let mut b = full.clone();
    put(&mut b, 329 + 20, &field("18446744073709551615"));
    assert!(refuse("x.al3d", &b).starts_with("Alicona .al3d: "));
    let mut b = full;
    put(&mut b, 17 + 52 + 20, &field("4000000000"));
    assert!(refuse("x.al3d", &b).contains("more than the file holds"));
}

#[test]
fn nanosurf_nid() {
    truncated("nid-1.nid", "Nanosurf .nid: ");
    let full = bytes("nid-1.nid");
    let mut b = full.clone();
    let at = find(&b, b"Lines=256\r\nFrame");
    b.splice(at + 6..at + 6, *b"99");
    assert!(
        refuse("x.nid", &b).contains("a data set of 256 × 99256 points is larger than the file")
    );
    let mut b = full.clone();
    let at = find(&b, b"#!");
    b[at] = b'%';
    assert!(refuse("x.nid", &b).starts_with("Nanosurf .nid: "));
    let mut b = full;
    let at = find(&b, b"GroupCount=2");
    put(&mut b, at, b"GroupCount=9");
    assert!(refuse("x.nid", &b).contains("no 'Gr2-Count'"));
}

/// The checksum of an Igor wave's headers made right again.
fn igor_checksum(b: &mut [u8]) {
    put(b, 2, &[0, 0]);
    let sum = b[..384].chunks_exact(2).fold(0i16, |a, c| {
        a.wrapping_add(i16::from_le_bytes([c[0], c[1]]))
    });
    put(b, 2, &sum.wrapping_neg().to_le_bytes());
}

#[test]
fn igor_ibw() {
    truncated("spot_1-1000nm.ibw", "Igor .ibw: ");
    let full = bytes("spot_1-1000nm.ibw");
    let mut b = full.clone();
    put(&mut b, 64 + 68, &i32::MAX.to_le_bytes());
    igor_checksum(&mut b);
    assert!(refuse("x.ibw", &b).contains("more than the 67108864"));
    let mut b = full.clone();
    put(&mut b, 64 + 68 + 8, &100i32.to_le_bytes());
    igor_checksum(&mut b);
    assert!(refuse("x.ibw", &b).contains("but the file holds"));
    let mut b = full.clone();
    put(&mut b, 12, &i32::MAX.to_le_bytes());
    igor_checksum(&mut b);
    assert!(refuse("x.ibw", &b).contains("the note at byte"));
    let mut b = full;
    put(&mut b, 64 + 16, &3i16.to_le_bytes());
    igor_checksum(&mut b);
    assert_eq!(refuse("x.ibw", &b), "Igor .ibw: a wave of complex numbers");
}

#[test]
fn iso_sdf() {
    let full = bytes("sdf-1.sdf");
    let text = String::from_utf8(full.clone()).unwrap();
    let e = refuse(
        "x.sdf",
        text.replace("NumPoints = 7", "NumPoints = 9999999")
            .as_bytes(),
    );
    assert!(e.contains("more than the file holds"), "{e}");
    let e = refuse("x.sdf", &full[..full.len() * 2 / 3]);
    assert!(e.contains("the file is truncated"), "{e}");
    let e = refuse("x.sdf", text.replace("Zscale", "Zskale").as_bytes());
    assert_eq!(e, "ISO 25178-71 .sdf: the header has no 'Zscale'");
    // A binary one: its header, then fewer values than it claims.
    let mut b = b"bISO-1.0".to_vec();
    b.extend_from_slice(&[b' '; 34]);
    b.extend_from_slice(&300u16.to_le_bytes());
    b.extend_from_slice(&200u16.to_le_bytes());
    for v in [1e-6f64, 1e-6, 1e-9, 1e-9] {
        b.extend_from_slice(&v.to_le_bytes());
    }
    b.extend_from_slice(&[0, 5, 0]);
    b.extend_from_slice(&[0u8; 1000]);
    assert!(refuse("x.sdf", &b).contains("300 × 200 points take 120000 bytes from byte 81"));
}

#[test]
fn bruker_opdx() {
    truncated("opdx-3.opdx", "Bruker .opdx: ");
    let full = bytes("opdx-3.opdx");
    let mut b = full.clone();
    let at = find(&b, b"NumPoints") + 10;
    put(&mut b, at, &u64::MAX.to_le_bytes());
    assert!(refuse("x.opdx", &b).starts_with("Bruker .opdx: "));
    let mut b = full.clone();
    put(&mut b, 12, &u32::MAX.to_le_bytes());
    assert!(refuse("x.opdx", &b).contains("runs past the end of the file"));
    // Containers nested beyond any file are refused, not recursed into.
    let mut nest = full[..12].to_vec();
    for _ in 0..100_000 {
        nest.extend_from_slice(&1u32.to_le_bytes());
        nest.extend_from_slice(b"c\x7d\x04");
        nest.extend_from_slice(&(1u32 << 30).to_le_bytes());
    }
    let e = refuse("x.opdx", &nest);
    assert!(
        e.contains("nested deeper than 64") || e.contains("runs past"),
        "{e}"
    );
}

#[test]
fn frt_frt() {
    truncated("frt-2.frt", "FRT .frt: ");
    let full = bytes("frt-2.frt");
    let mut b = full.clone();
    // Block 0x66's points.
    put(&mut b, 54, &u32::MAX.to_le_bytes());
    assert!(refuse("x.frt", &b).contains("do not fit the heights' block"));
    let mut b = full.clone();
    put(&mut b, 20, &u32::MAX.to_le_bytes());
    assert!(refuse("x.frt", &b).contains("claims 4294967295 bytes"));
    let mut b = full;
    put(&mut b, 12, b"2.00");
    assert_eq!(
        refuse("x.frt", &b),
        "FRT .frt: version '2.00': 1.00 and 1.01 are read"
    );
}

#[test]
fn gzip_nests() {
    use std::io::Write;
    // A gzip file inside one.
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(&bytes("sdf-1.sdf")).unwrap();
    let inner = e.finish().unwrap();
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(&inner).unwrap();
    let twice = e.finish().unwrap();
    let r = parse_named(&twice, "x.sdf.gz", &Options::default()).unwrap_err();
    assert_eq!(
        r.1.to_string(),
        "a gzip-compressed file inside a gzip-compressed file"
    );
}

/// Each reader's example files, as they are named.
const FILES: [&str; 14] = [
    "sur-2.sur",
    "plu-1.plu",
    "di-2.di",
    "di-5.di",
    "opd-1.opd",
    "metropro-1.dat",
    "al3d-1.al3d",
    "nid-1.nid",
    "spot_1-1000nm.ibw",
    "10x10-one_channel_without_name.ibw",
    "sdf-1.sdf",
    "opdx-3.opdx",
    "frt-1.frt",
    "frt-2.frt",
];

crate::mutation_fuzz!(FILES, bytes);
