//! Damaged and hostile x3p and .gwy files: each refused with a line naming
//! the problem, never a panic, never an allocation beyond what the file's
//! size allows (a counting allocator watches every test here).

use std::io::Write;
use std::path::{Path, PathBuf};

use md5::{Digest, Md5};
mod fuzz;
#[path = "fuzz/harness.rs"]
mod harness;

use proptest::prelude::*;
use rough_surface::{parse, read_grid, Options, Problem};

#[global_allocator]
static ALLOC: fuzz::Counting = fuzz::Counting;

/// Every allocation of the tests stays below this (the files are a few
/// KiB; the largest legitimate buffer is a 2 MiB data.bin).
const CEILING: usize = 64 << 20;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/formats")
}

fn bytes(name: &str) -> Vec<u8> {
    std::fs::read(dir().join(name)).unwrap()
}

/// The refusal of `b` as a line, and that no allocation passed the
/// ceiling.
fn refuse(b: &[u8]) -> String {
    let e = parse(b, &Options::default()).expect_err("refused");
    assert!(harness::largest() < CEILING);
    e.1.to_string()
}

fn md5_hex(b: &[u8]) -> String {
    Md5::digest(b).iter().map(|b| format!("{b:02x}")).collect()
}

fn zip_of(files: &[(&str, &[u8])]) -> Vec<u8> {
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for (name, data) in files {
        w.start_file(*name, zip::write::SimpleFileOptions::default())
            .unwrap();
        w.write_all(data).unwrap();
    }
    w.finish().unwrap().into_inner()
}

/// main.xml of an nx × ny float64 map, its data's checksum `sum`.
fn main_xml(nx: usize, ny: usize, sum: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
 <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType>
  <Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment></CX>
   <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment></CY>
   <CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1>
 <Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
  <DataLink><PointDataLink>bindata/data.bin</PointDataLink>
   <MD5ChecksumPointData>{sum}</MD5ChecksumPointData></DataLink></Record3>
 <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>"#
    )
}

/// An x3p of an nx × ny map whose main.xml says `(sx, sy)`.
fn x3p(nx: usize, ny: usize, says: (usize, usize)) -> (Vec<u8>, Vec<u8>, String) {
    let data: Vec<u8> = (0..nx * ny)
        .flat_map(|i| (((i * 7919) % 113) as f64 * 1e-9).to_le_bytes())
        .collect();
    let xml = main_xml(says.0, says.1, &md5_hex(&data));
    (
        data,
        xml.clone().into_bytes(),
        format!("{} *main.xml\n", md5_hex(xml.as_bytes())),
    )
}

fn pack(data: &[u8], xml: &[u8], sums: &str) -> Vec<u8> {
    zip_of(&[
        ("main.xml", xml),
        ("bindata/data.bin", data),
        ("md5checksum.hex", sums.as_bytes()),
    ])
}

/// Sets the uncompressed size of member `name` in both its local header
/// and the central directory.
fn claim(zip: &mut [u8], name: &str, size: u32) {
    let n = name.as_bytes();
    for i in 0..zip.len() - 46 {
        if zip[i..i + 4] == *b"PK\x01\x02" && zip[i + 46..].starts_with(n) {
            zip[i + 24..i + 28].copy_from_slice(&size.to_le_bytes());
            let local = u32::from_le_bytes(zip[i + 42..i + 46].try_into().unwrap()) as usize;
            zip[local + 22..local + 26].copy_from_slice(&size.to_le_bytes());
        }
    }
}

#[test]
fn a_good_file_to_start_from() {
    let (d, x, s) = x3p(16, 12, (16, 12));
    let g = read_grid(&pack(&d, &x, &s), &Options::default()).unwrap();
    assert_eq!((g.nx, g.ny, g.lx), (16, 12, 16e-6));
}

#[test]
fn truncated_zips() {
    let full = bytes("sur_d.x3p");
    for cut in [
        0,
        3,
        4,
        30,
        100,
        full.len() / 2,
        full.len() - 23,
        full.len() - 1,
    ] {
        if cut == 0 {
            continue;
        }
        let e = refuse(&full[..cut]);
        assert!(
            e.starts_with("x3p: ") || e.starts_with("a binary file"),
            "cut at {cut}: {e}"
        );
    }
    assert!(refuse(&full[..full.len() / 2]).contains("not a readable zip archive"));
}

#[test]
fn zip_bombs_and_wrong_sizes() {
    let (d, x, s) = x3p(256, 256, (256, 256));
    // data.bin claims 1 GiB.
    let mut z = pack(&d, &x, &s);
    claim(&mut z, "bindata/data.bin", 1 << 30);
    assert_eq!(
        refuse(&z),
        "x3p: main.xml's 256 × 256 × 1 points of float64 take 524288 bytes but \
         bindata/data.bin holds 1073741824"
    );
    // main.xml claims a map beyond what is read.
    let big = main_xml(65536, 65536, "");
    let z = pack(&d, big.as_bytes(), "");
    assert_eq!(
        refuse(&z),
        "x3p: main.xml says 65536 × 65536 × 1 points: more than a file is read with"
    );
    // Four layers of 8192² float64 that data.bin claims to hold: beyond
    // the size limit, refused before it is unpacked.
    let layers = main_xml(8192, 8192, "").replace("<SizeZ>1<", "<SizeZ>4<");
    let mut z = pack(&d, layers.as_bytes(), "");
    claim(&mut z, "bindata/data.bin", 1 << 31);
    assert_eq!(
        refuse(&z),
        "x3p: bindata/data.bin unpacks to 2147483648 bytes: more than the 512 MB read"
    );
    // data.bin unpacks to more than its header says (a bomb that lies).
    let zeros = vec![0u8; 8 << 20];
    let mut z = pack(&zeros, &x, &s);
    claim(&mut z, "bindata/data.bin", 524288);
    assert_eq!(
        refuse(&z),
        "x3p: bindata/data.bin cannot be unpacked: File is larger than its declared \
         uncompressed size"
    );
    // Sizes that do not fit the data.
    let (d, x, s) = x3p(32, 24, (33, 24));
    assert_eq!(
        refuse(&pack(&d, &x, &s)),
        "x3p: main.xml's 33 × 24 × 1 points of float64 take 6336 bytes but \
         bindata/data.bin holds 6144"
    );
    let (d, x, s) = x3p(32, 24, (0, 24));
    assert_eq!(
        refuse(&pack(&d, &x, &s)),
        "x3p: main.xml: Record3/MatrixDimension/SizeX = 0 is not a count of points"
    );
}

#[test]
fn checksum_mismatches() {
    let (mut d, x, s) = x3p(16, 12, (16, 12));
    let sum = md5_hex(&d);
    d[17] ^= 1;
    let e = refuse(&pack(&d, &x, &s));
    assert_eq!(
        e,
        format!(
            "x3p: the MD5 checksum of bindata/data.bin is {} where the file records \
             {sum}: it was changed or damaged after it was written",
            md5_hex(&d)
        )
    );
    let (d, x, s) = x3p(16, 12, (16, 12));
    // An edited main.xml is read, with a warning.
    let changed = String::from_utf8(x).unwrap().replace("1e-6", "2e-6");
    let g = read_grid(&pack(&d, changed.as_bytes(), &s), &Options::default()).unwrap();
    assert!(
        g.notes[0].starts_with("warning: the MD5 checksum of main.xml is ")
            && g.notes[0].ends_with("main.xml was changed after it was written; read as it is"),
        "{:?}",
        g.notes
    );
}

#[test]
fn damaged_main_xml() {
    let (d, _, _) = x3p(16, 12, (16, 12));
    assert!(
        refuse(&pack(&d, b"<a><b></a>", "")).starts_with("x3p: main.xml is not well-formed XML")
    );
    let dtd = "<?xml version=\"1.0\"?><!DOCTYPE a [<!ENTITY x \"xx\">]><a>&x;</a>";
    assert!(refuse(&pack(&d, dtd.as_bytes(), "")).starts_with("x3p: main.xml is not well-formed"));
    assert_eq!(
        refuse(&pack(&d, b"<a/>", "")),
        "x3p: main.xml has no Record1"
    );
    let pcl = main_xml(16, 12, "").replace(">SUR<", ">PCL<");
    assert!(refuse(&pack(&d, pcl.as_bytes(), "")).contains("a point cloud (irregular x and y)"));
    let outside = main_xml(16, 12, "").replace("bindata/data.bin", "../data.bin");
    assert_eq!(
        refuse(&pack(&d, outside.as_bytes(), "")),
        "x3p: main.xml links to '../data.bin', outside the file"
    );
}

/// A GWYP file of one object nested `depth` deep: each level a
/// GwyContainer (13 bytes of name, 4 of size) whose one component `x\0o`
/// is the next, 20 bytes a level.
fn nest(depth: usize) -> Vec<u8> {
    let mut f = b"GWYP".to_vec();
    for level in 0..depth {
        f.extend_from_slice(b"GwyContainer\0");
        let inner = depth - 1 - level;
        let size = if inner == 0 { 0 } else { 20 * inner } as u32;
        f.extend_from_slice(&size.to_le_bytes());
        if inner > 0 {
            f.extend_from_slice(b"x\0o");
        }
    }
    f
}

#[test]
fn damaged_gwy_files() {
    let full = bytes("one.gwy");
    for cut in [
        4,
        5,
        17,
        100,
        full.len() / 2,
        full.len() - 9,
        full.len() - 1,
    ] {
        let e = refuse(&full[..cut]);
        assert!(e.starts_with("Gwyddion .gwy: "), "cut at {cut}: {e}");
        assert!(
            e.contains("truncated") || e.contains("no channel"),
            "cut at {cut}: {e}"
        );
    }
    // An array claiming more values than the file holds.
    let at = full.windows(6).position(|w| w == b"data\0D").unwrap() + 6;
    let mut b = full.clone();
    b[at..at + 4].copy_from_slice(&0x7fff_ffffu32.to_le_bytes());
    let e = refuse(&b);
    assert!(
        e.starts_with(&format!(
            "Gwyddion .gwy: component 'data' at byte {at} claims 2147483647 values \
             (17179869176 bytes) where"
        )),
        "{e}"
    );
    // An object claiming more bytes than there are.
    let mut b = full.clone();
    b[17..21].copy_from_slice(&u32::MAX.to_le_bytes());
    let e = refuse(&b);
    assert!(
        e.contains("object 'GwyContainer' at byte 4 claims 4294967295 bytes"),
        "{e}"
    );
    // A deep nest is refused, not recursed into.
    let e = refuse(&nest(100_000));
    assert_eq!(
        e,
        format!(
            "Gwyddion .gwy: objects nested deeper than 64 levels at byte {}",
            4 + 20 * 65
        )
    );
    // A shallow one holds no channel.
    assert_eq!(
        refuse(&nest(10)),
        "Gwyddion .gwy: no channel (no '/N/data' data field): nothing to read"
    );
    // Sizes that do not fit the data.
    let at = full.windows(6).position(|w| w == b"xres\0i").unwrap() + 6;
    let mut b = full.clone();
    b[at..at + 4].copy_from_slice(&29i32.to_le_bytes());
    assert_eq!(
        refuse(&b),
        "Gwyddion .gwy: '/0/data' is 29 × 20 points but its data holds 560 values"
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        rng_seed: fuzz::seed(),
        ..ProptestConfig::default()
    })]

    #[test]
    fn mutated_files_never_panic(
        which in 0usize..6,
        ops in prop::collection::vec((any::<u8>(), any::<usize>(), any::<u8>()), 1..6),
        cut in any::<usize>(),
    ) {
        let name = [
            "sur_d.x3p",
            "sur_valid_i.x3p",
            "hand_bin.x3p",
            "one.gwy",
            "three.gwy",
            "gwyddion_sur_valid_i.gwy",
        ][which];
        let mut b = fuzz::mutate(&bytes(name), &ops);
        if cut % 3 == 0 && !b.is_empty() {
            b.truncate(cut % b.len());
        }
        let r = parse(&b, &Options::default());
        if let Err((_, p)) = &r {
            prop_assert!(!p.to_string().is_empty());
        }
        let _ = read_grid(&b, &Options { channel: Some("2".into()), ..Options::default() });
        prop_assert!(harness::largest() < CEILING);
    }
}

/// The members of an x3p file.
fn members(name: &str) -> Vec<(String, Vec<u8>)> {
    use std::io::Read;
    let b = bytes(name);
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(&b[..])).unwrap();
    (0..z.len())
        .map(|i| {
            let mut f = z.by_index(i).unwrap();
            let mut v = Vec::new();
            f.read_to_end(&mut v).unwrap();
            (f.name().unwrap().to_string(), v)
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        rng_seed: fuzz::seed(),
        ..ProptestConfig::default()
    })]

    /// main.xml, data.bin or valid.bin changed and packed again (so the
    /// zip's own checks pass and the reader's are what is tested).
    #[test]
    fn mutated_members_never_panic(
        which in 0usize..3,
        ops in prop::collection::vec((any::<u8>(), any::<usize>(), any::<u8>()), 1..4),
    ) {
        let mut m = members("hand_bin.x3p");
        let k = which.min(m.len() - 1);
        m[k].1 = fuzz::mutate(&m[k].1, &ops);
        let files: Vec<(&str, &[u8])> = m.iter().map(|(n, b)| (n.as_str(), &b[..])).collect();
        let _ = parse(&zip_of(&files), &Options::default());
        prop_assert!(harness::largest() < CEILING);
    }
}

#[test]
fn problems_are_format_lines() {
    let e = parse(&nest(100), &Options::default()).unwrap_err();
    assert!(matches!(e, (None, Problem::Format(_))));
}
