//! Damaged and hostile makers' files (Keyence, JPK, Park Systems,
//! Sensofar .plux, Zygo .datx): cut short, sizes that lie, members that
//! unpack to more than they declare, a zip bomb — each refused with one
//! line naming the format, never a panic, never an allocation beyond
//! what the file allows (a counting allocator watches every test); then
//! each file mutated at random (`FUZZ_CASES` cases a file, 48 by
//! default; `FUZZ_SEED` as tests/fuzz/mod.rs says).

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

mod fuzz;
#[path = "fuzz/harness.rs"]
mod harness;

use rough_surface::{read_grid_named, Options};

#[global_allocator]
static ALLOC: fuzz::Counting = fuzz::Counting;

use harness::{put, refuse, CEILING};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/makers")
}

/// A file's bytes (a .gz unpacked).
fn bytes(name: &str) -> Vec<u8> {
    harness::file_bytes(&dir().join(name))
}

/// The file cut short at several places, by its last byte too: each
/// refused, naming `format`.
fn truncated(name: &str, format: &str) {
    harness::truncated(
        &bytes(name),
        name.trim_end_matches(".gz"),
        format,
        true,
        &[],
    );
}

fn zip_of(members: &[(&str, &[u8])]) -> Vec<u8> {
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let o = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (n, d) in members {
        w.start_file(*n, o).unwrap();
        w.write_all(d).unwrap();
    }
    w.finish().unwrap().into_inner()
}

/// The members of the zip `b` (after any prefix).
fn members(b: &[u8]) -> Vec<(String, Vec<u8>)> {
    let mut z = zip::ZipArchive::new(std::io::Cursor::new(b)).unwrap();
    (0..z.len())
        .map(|i| {
            let mut f = z.by_index(i).unwrap();
            let mut d = Vec::new();
            f.read_to_end(&mut d).unwrap();
            (f.name().unwrap().to_string(), d)
        })
        .collect()
}

#[test]
fn keyence_vk() {
    truncated("synthetic.vk4", "Keyence .vk4: ");
    truncated("synthetic.vk7", "Keyence .vk7: ");
    let full = bytes("synthetic.vk4");
    let image = u32::from_le_bytes(full[12 + 24..12 + 28].try_into().unwrap()) as usize;
    // An image that claims more than any file holds, then more than this one.
    let mut b = full.clone();
    put(&mut b, image, &u32::MAX.to_le_bytes());
    put(&mut b, image + 4, &u32::MAX.to_le_bytes());
    assert!(refuse("x.vk4", &b).contains("does not make its"));
    put(&mut b, image + 16, &u32::MAX.to_le_bytes());
    let e = refuse("x.vk4", &b);
    assert!(
        e.contains("does not make its") || e.contains("more than the"),
        "{e}"
    );
    let mut b = full.clone();
    put(&mut b, image, &6000u32.to_le_bytes());
    put(&mut b, image + 16, &(6000u32 * 40 * 4).to_le_bytes());
    assert!(refuse("x.vk4", &b).contains("but the file holds"));
    let mut b = full.clone();
    put(&mut b, image + 8, &12u32.to_le_bytes());
    assert_eq!(
        refuse("x.vk4", &b),
        "Keyence .vk4: height image 1 has values of 12 bits: 8, 16 or 32 are read"
    );
    let mut b = full.clone();
    put(&mut b, 12, &u32::MAX.to_le_bytes());
    assert!(refuse("x.vk4", &b).contains("runs past the end of the file"));
    let e = read_grid_named(
        &full,
        "x.vk4",
        &Options {
            channel: Some("2".into()),
            ..Options::default()
        },
    )
    .unwrap_err();
    assert!(e.1.to_string().contains("no channel 2"), "{e:?}");
    // A .vk7 whose member is not a .vk4, and one without it.
    let mut prefix = b"VK7".to_vec();
    prefix.extend(zip_of(&[("Vk4File", b"VK3_ not this")]));
    assert_eq!(
        refuse("x.vk7", &prefix),
        "Keyence .vk7: the member 'Vk4File' is not a .vk4 (no 'VK4_')"
    );
    let mut prefix = b"VK6".to_vec();
    prefix.extend(zip_of(&[("Vk6ImageData", b"")]));
    assert!(refuse("x.vk6", &prefix).starts_with("Keyence .vk6: no 'Vk4File' member"));
}

#[test]
fn zip_bombs_are_refused_unpacked_no_further() {
    // 512 MB of zeros as the .vk6's member: refused by its declared size,
    // and, declaring less, when it passes that.
    let zeros = vec![0u8; 1 << 20];
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let o = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .large_file(true);
    w.start_file("Vk4File", o).unwrap();
    for _ in 0..(rough_surface::MAX_BYTES >> 20) + 1 {
        w.write_all(&zeros).unwrap();
    }
    let zipped = w.finish().unwrap().into_inner();
    let mut b = b"VK6".to_vec();
    b.extend(&zipped);
    assert!(b.len() < 1 << 20, "{}", b.len());
    let e = refuse("bomb.vk6", &b);
    assert!(e.contains("more than the 512 MB read"), "{e}");
    assert!(harness::largest() < CEILING);
}

#[test]
fn keyence_zon() {
    truncated("synthetic.zon", "Keyence .zon: ");
    let full = bytes("synthetic.zon");
    let at = full.windows(4).position(|w| w == b"PK\x03\x04").unwrap();
    let mut m = members(&full[at..]);
    let rezip = |m: &[(String, Vec<u8>)]| {
        let mut b = full[..at].to_vec();
        let refs: Vec<(&str, &[u8])> = m.iter().map(|(n, d)| (n.as_str(), &d[..])).collect();
        b.extend(zip_of(&refs));
        b
    };
    let heights = m
        .iter()
        .position(|(n, _)| n.starts_with("4cdb0c75"))
        .unwrap();
    let mut plane = m[heights].1.clone();
    put(&mut plane, 0, &i32::MAX.to_le_bytes());
    put(&mut plane, 12, &i32::MAX.to_le_bytes());
    m[heights].1 = plane;
    let e = refuse("x.zon", &rezip(&m));
    assert!(e.starts_with("Keyence .zon: the heights' plane"), "{e}");
    let mut m = members(&full[at..]);
    let unit = m
        .iter()
        .position(|(n, _)| n.starts_with("686613b8"))
        .unwrap();
    m[unit].1 = b"<a><XYCalibration><MeterPerPixel>-1</MeterPerPixel></XYCalibration></a>".to_vec();
    assert_eq!(
        refuse("x.zon", &rezip(&m)),
        "Keyence .zon: the calibration's XYCalibration/MeterPerPixel is -1"
    );
    let mut b = full.clone();
    put(&mut b, 0, b"KPK1");
    assert!(refuse("x.zon", &b).contains("KPK1"));
}

#[test]
fn sensofar_plux() {
    truncated("synthetic.plux", "Sensofar .plux: ");
    let m = members(&bytes("synthetic.plux"));
    let index = String::from_utf8(m[0].1.clone()).unwrap();
    let with = |index: &str| {
        let refs = [
            ("index.xml", index.as_bytes()),
            ("LAYER_0.raw", &m[1].1[..]),
        ];
        zip_of(&refs)
    };
    let e = refuse(
        "x.plux",
        &with(&index.replace("<IMAGE_SIZE_X>48", "<IMAGE_SIZE_X>4800000")),
    );
    assert!(
        e.contains("more than the") || e.contains("float32 heights take"),
        "{e}"
    );
    let e = refuse(
        "x.plux",
        &with(&index.replace("<IMAGE_SIZE_X>48", "<IMAGE_SIZE_X>49")),
    );
    assert!(
        e.contains("holds 6912 bytes where 49 × 36 float32 heights take 7056"),
        "{e}"
    );
    let e = refuse(
        "x.plux",
        &with(&index.replace("0.6458</FOV_X>", "0</FOV_X>")),
    );
    assert_eq!(e, "Sensofar .plux: the pixel size GENERAL/FOV_X is 0 µm");
    let e = refuse(
        "x.plux",
        &with(&index.replace("LAYER_0.raw", "LAYER_9.raw")),
    );
    assert!(e.contains("'LAYER_9.raw' is missing"), "{e}");
}

#[test]
fn jpk_tiff_and_park() {
    truncated("sample_0.jpk-qi-image.gz", "JPK image scan: ");
    let full = bytes("sample_0.jpk-qi-image.gz");
    // The first directory's count of tags made huge.
    let mut b = full.clone();
    put(&mut b, 8, &u16::MAX.to_be_bytes());
    let e = refuse("x.jpk", &b);
    assert!(e.starts_with("TIFF: a directory of 65535 tags"), "{e}");
    let park = bytes("synthetic_park.tiff");
    let e = refuse("x.tiff", &park[..park.len() / 2]);
    assert!(
        e.starts_with("Park Systems TIFF: ") || e.starts_with("TIFF: "),
        "{e}"
    );
    // The header's points made larger than the data tag.
    let at = park.windows(6).position(|w| w == b"T\0o\0p\0").unwrap() - 4;
    let mut b = park.clone();
    put(&mut b, at + 100, &65u32.to_le_bytes());
    assert!(refuse("x.tiff", &b).contains("the data: 65 × 48 points take 12480 bytes"));
    let mut b = park.clone();
    put(&mut b, at + 100, &u32::MAX.to_le_bytes());
    put(&mut b, at + 104, &u32::MAX.to_le_bytes());
    assert!(refuse("x.tiff", &b).contains("more than the"));
    let mut b = park.clone();
    put(&mut b, at, &1u32.to_le_bytes());
    assert_eq!(
        refuse("x.tiff", &b),
        "Park Systems TIFF: a line profile image (type 1): maps are read"
    );
    let mut b = park;
    put(&mut b, at + 244, &"V\0\0\0".as_bytes()[..4]);
    assert_eq!(
        refuse("x.tiff", &b),
        "Park Systems TIFF: the 'Topography' image holds values in 'V', not heights (a length)"
    );
}

#[test]
fn hdf5_files() {
    truncated("sample_0.h5-jpk.gz", "JPK .h5-jpk: ");
    truncated("synthetic.datx", "Zygo .datx: ");
    let datx = bytes("synthetic.datx");
    // A unit that is not a length.
    let at = datx.windows(10).position(|w| w == b"NanoMeters").unwrap();
    let mut b = datx.clone();
    for k in datx
        .windows(10)
        .enumerate()
        .filter(|(_, w)| *w == b"NanoMeters")
        .map(|(k, _)| k)
    {
        put(&mut b, k, b"Fringes\0\0\0");
    }
    assert!(at > 0);
    let e = refuse("x.datx", &b);
    assert!(
        e.starts_with("Zygo .datx: the surface is in 'Fringes'"),
        "{e}"
    );
    // An HDF5 file that is neither.
    let e = refuse("x.h5", &datx[..8]);
    assert!(e.contains("HDF5"), "{e}");
}

/// The makers' files mutated, as they are named (the `.gz` ones unpacked).
const FILES: [&str; 8] = [
    "synthetic.vk4",
    "synthetic.vk7",
    "synthetic.zon",
    "synthetic.plux",
    "synthetic.datx",
    "synthetic_park.tiff",
    "sample_0.jpk-qi-image.gz",
    "sample_0.h5-jpk.gz",
];

crate::mutation_fuzz!(FILES, bytes);
