//! x3p and Gwyddion .gwy files written by independent writers (x3pio,
//! SurfaceTopography, gwyfile, and by hand from ISO 25178-72) read to the
//! heights x3pio and gwyfile read from them (scripts/formats_reference.py
//! writes the files and the references), the same moments as the same
//! heights in a text matrix, Gwyddion's ASCII export with decimal commas
//! and Latin-1, and the choice of a .gwy channel.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{parse, read, read_grid, Kind, Measured, Options};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/formats")
}

fn bytes(name: &str) -> Vec<u8> {
    std::fs::read(dir().join(name)).unwrap()
}

struct Ref {
    name: String,
    nx: usize,
    ny: usize,
    lx: f64,
    ly: f64,
}

fn refs() -> Vec<Ref> {
    std::fs::read_to_string(dir().join("reference.txt"))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            Ref {
                name: w[0].to_string(),
                nx: w[1].parse().unwrap(),
                ny: w[2].parse().unwrap(),
                lx: w[3].parse().unwrap(),
                ly: w[4].parse().unwrap(),
            }
        })
        .collect()
}

/// The heights of NAME.txt, parsed here (not by the crate's reader).
fn heights(name: &str) -> Vec<f64> {
    std::fs::read_to_string(dir().join(format!("{name}.txt")))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .flat_map(|l| l.split_whitespace().map(|v| v.parse::<f64>().unwrap()))
        .collect()
}

/// The file and channel a reference is about.
fn source(name: &str) -> Option<(String, Option<&'static str>)> {
    let file = match name {
        "three_3" => return Some(("three.gwy".into(), Some("3"))),
        n if n.starts_with("gwy_ascii") => return None,
        n if ["one", "three", "mask"].contains(&n) => format!("{n}.gwy"),
        n => format!("{n}.x3p"),
    };
    Some((file, None))
}

#[test]
fn heights_as_x3pio_and_gwyfile_read_them() {
    let refs = refs();
    assert_eq!(refs.len(), 18);
    let mut worst = 0f64;
    for r in &refs {
        let Some((file, channel)) = source(&r.name) else {
            continue;
        };
        let opts = Options {
            channel: channel.map(String::from),
            ..Options::default()
        };
        let g = read_grid(&bytes(&file), &opts).unwrap_or_else(|e| panic!("{file}: {e:?}"));
        assert_eq!((g.nx, g.ny), (r.nx, r.ny), "{file}");
        assert!(rel(g.lx, r.lx) < 1e-15, "{file}: lx {} vs {}", g.lx, r.lx);
        assert!(rel(g.ly, r.ly) < 1e-15, "{file}: ly {} vs {}", g.ly, r.ly);
        let want = heights(&r.name);
        assert_eq!(g.z.len(), want.len(), "{file}");
        let scale = want
            .iter()
            .filter(|v| !v.is_nan())
            .fold(0f64, |a, v| a.max(v.abs()));
        for (k, (a, b)) in g.z.iter().zip(&want).enumerate() {
            assert_eq!(a.is_nan(), b.is_nan(), "{file} point {k}: {a} vs {b}");
            if !b.is_nan() {
                let e = (a - b).abs() / scale;
                assert!(e <= 1e-15, "{file} point {k}: {a} vs {b}");
                worst = worst.max(e);
            }
        }
    }
    eprintln!("largest height difference: {worst:.1e} of the largest height");
}

#[test]
fn gwy_files_written_by_gwyddion_itself() {
    // Gwyddion 2.62 converted five of the x3p files (its own x3p reader and
    // serialisation, with a /0/meta container and its mask of the invalid
    // points): the same heights as x3pio reads from the x3p, up to the z
    // offset Gwyddion adds, and the same undefined points.
    let refs = refs();
    for name in ["sur_d", "sur_valid_i", "st_sur_i", "hand_bin", "hand_list"] {
        let file = format!("gwyddion_{name}.gwy");
        let g = read_grid(&bytes(&file), &Options::default()).unwrap();
        let r = refs.iter().find(|r| r.name == name).unwrap();
        assert_eq!((g.nx, g.ny), (r.nx, r.ny), "{file}");
        assert!(rel(g.lx, r.lx) < 1e-15 && rel(g.ly, r.ly) < 1e-15, "{file}");
        let want = heights(name);
        let pairs: Vec<(f64, f64)> = g.z.iter().copied().zip(want.iter().copied()).collect();
        assert!(
            pairs.iter().all(|(a, b)| a.is_nan() == b.is_nan()),
            "{file}"
        );
        let defined = pairs.iter().filter(|(a, _)| !a.is_nan());
        let n = defined.clone().count() as f64;
        let offset = defined.clone().map(|(a, b)| a - b).sum::<f64>() / n;
        let scale = defined.clone().fold(0f64, |m, (_, b)| m.max(b.abs()));
        for (a, b) in defined {
            assert!(
                (a - offset - b).abs() <= 1e-12 * scale,
                "{file}: {a} vs {b}"
            );
        }
    }
}

/// The moments of `a` and `b` at every ζ of a's table.
fn same_moments(a: &Measured, b: &Measured, what: &str) -> f64 {
    match (a.kind, b.kind) {
        (
            Kind::Map { nx, ny, lx, ly },
            Kind::Map {
                nx: n2,
                ny: m2,
                lx: l2,
                ly: k2,
            },
        ) => {
            assert_eq!((nx, ny), (n2, m2), "{what}");
            assert!(rel(lx, l2) < 1e-15 && rel(ly, k2) < 1e-15, "{what}");
        }
        (k, l) => assert_eq!(k, l, "{what}"),
    }
    assert!(rel(a.table.q0(), b.table.q0()) < 1e-15, "{what}");
    let mut worst = 0f64;
    let zmax = a.table.zeta_max();
    for k in 0..=20 {
        let zeta = zmax.powf(k as f64 / 20.0);
        let (p, q) = (a.table.at_zeta(zeta), b.table.at_zeta(zeta));
        for (x, y) in [(p.m0, q.m0), (p.m2, q.m2), (p.m4, q.m4)] {
            let e = rel(x, y);
            assert!(e < 1e-12, "{what} ζ {zeta}: {x} vs {y}");
            worst = worst.max(e);
        }
    }
    worst
}

#[test]
fn moments_as_the_same_heights_in_text() {
    let mut worst = 0f64;
    for r in refs() {
        let Some((file, channel)) = source(&r.name) else {
            continue;
        };
        let want = heights(&r.name);
        if want.iter().any(|v| v.is_nan()) {
            continue; // moments_of_masked_files
        }
        let opts = Options {
            channel: channel.map(String::from),
            ..Options::default()
        };
        let m = read(&dir().join(&file), &opts).unwrap_or_else(|e| panic!("{e}"));
        let t = read(&dir().join(format!("{}.txt", r.name)), &Options::default())
            .unwrap_or_else(|e| panic!("{e}"));
        worst = worst.max(same_moments(&m, &t, &file));
        let what = if file.ends_with(".x3p") {
            "x3p "
        } else {
            "Gwyddion .gwy "
        };
        assert!(m.summary.starts_with(what), "{}", m.summary);
    }
    eprintln!("largest moment difference: {worst:.1e}");
    // A layer and a channel named.
    let m = read(&dir().join("sur_layers.x3p"), &Options::default()).unwrap();
    assert_eq!(m.notes, vec!["layer 1 of 3 read".to_string()]);
}

#[test]
fn moments_of_masked_files() {
    // Undefined points are filled: a masked file reads, saying so.
    for (file, count) in [
        ("sur_nan_d.x3p", 3),
        ("sur_valid_i.x3p", 3),
        ("st_sur_i.x3p", 3),
        ("hand_list.x3p", 1),
        ("hand_bin.x3p", 3),
        ("mask.gwy", 3),
        ("gwyddion_sur_valid_i.gwy", 3),
    ] {
        let m = read(&dir().join(file), &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(m.kind, Kind::Map { .. }), "{file}");
        let filled = format!("{count} undefined point");
        assert!(
            m.notes.iter().any(|n| n.contains(&filled)),
            "{file}: {:?}",
            m.notes
        );
    }
}

#[test]
fn masked_points_are_undefined_and_filled() {
    // The reader names them, the pipeline fills them.
    let m = read(&dir().join("mask.gwy"), &Options::default()).unwrap();
    assert_eq!(
        m.notes,
        vec![
            "3 points under the mask '/0/mask' read as undefined".to_string(),
            "3 undefined points (0.54 %) filled".to_string()
        ]
    );
    let g = read_grid(&bytes("mask.gwy"), &Options::default()).unwrap();
    assert_eq!(
        g.notes,
        vec!["3 points under the mask '/0/mask' read as undefined".to_string()]
    );
    let g = read_grid(&bytes("sur_valid_i.x3p"), &Options::default()).unwrap();
    assert_eq!(
        g.notes,
        vec!["3 points marked invalid in bindata/valid.bin read as undefined".to_string()]
    );
    assert_eq!(g.undefined(), 3);
    let g = read_grid(&bytes("hand_list.x3p"), &Options::default()).unwrap();
    assert!(g.z[4 * 12 + 7].is_nan() && g.undefined() == 1);
}

#[test]
fn gwyddion_ascii_with_decimal_commas_and_latin1() {
    let dots = std::fs::read_to_string(dir().join("gwy_ascii_comma.txt"))
        .unwrap()
        .replace(',', ".");
    let want = parse(dots.as_bytes(), &Options::default()).unwrap();
    assert_eq!(
        want.kind,
        Kind::Map {
            nx: 12,
            ny: 10,
            lx: 6e-6,
            ly: 5e-6
        }
    );
    let m = read(&dir().join("gwy_ascii_comma.txt"), &Options::default()).unwrap();
    assert_eq!(m.notes, vec!["decimal commas read".to_string()]);
    assert_eq!(m.table, want.table);
    let m = read(&dir().join("gwy_ascii_latin1.txt"), &Options::default()).unwrap();
    assert_eq!(
        m.notes,
        vec![
            "read as Windows-1252 (Latin-1) text: line 2 is not UTF-8".to_string(),
            "decimal commas read".to_string()
        ]
    );
    assert_eq!(m.table, want.table);
    // Two channels concatenated: the height channel, as SurfaceTopography
    // reads it (scripts/formats_reference.py checks that it does).
    let two = read(&dir().join("gwy_ascii_two.txt"), &Options::default()).unwrap();
    assert_eq!(
        two.notes,
        vec![
            "channel 1 'Height' (m) read; also in the file: 0 'Phase' (deg) \
             (--channel N or TITLE)"
                .to_string()
        ]
    );
    assert_eq!(two.kind, want.kind);
    assert_eq!(two.table, want.table);
    // A comma that separates numbers is not a decimal mark.
    let m = parse(b"# Width: 4 m\n1.5,2,3,4.25\n", &Options::default()).unwrap();
    assert!(
        !m.notes.iter().any(|n| n.contains("decimal")),
        "{:?}",
        m.notes
    );
}

#[test]
fn gwy_channels_by_number_title_and_unit() {
    let three = bytes("three.gwy");
    let with = |c: &str| Options {
        channel: Some(c.to_string()),
        ..Options::default()
    };
    let g = read_grid(&three, &Options::default()).unwrap();
    assert_eq!(
        g.notes,
        vec![
            "channel 0 'Height' (m) read; also in the file: 1 'Amplitude' (V), 2 'Phase' \
             (deg), 3 'Height (retrace)' (µm) (--channel N or TITLE)"
                .to_string()
        ]
    );
    let by_number = read_grid(&three, &with("3")).unwrap();
    let by_title = read_grid(&three, &with("height (RETRACE)")).unwrap();
    assert_eq!(by_number, by_title);
    assert_eq!(by_number.z, read_grid(&three, &with("3")).unwrap().z);
    let list = "the channels are 0 'Height' (m), 1 'Amplitude' (V), 2 'Phase' (deg), \
                3 'Height (retrace)' (µm)";
    let err = |c: &str| read_grid(&three, &with(c)).unwrap_err().1.to_string();
    assert_eq!(
        err("1"),
        format!("Gwyddion .gwy: channel 1 'Amplitude' (V) holds values in V, not a length: {list}")
    );
    assert_eq!(
        err("Phase"),
        format!("Gwyddion .gwy: channel 2 'Phase' (deg) holds values in deg, not a length: {list}")
    );
    assert_eq!(err("7"), format!("Gwyddion .gwy: no channel 7; {list}"));
    assert_eq!(
        err("Deflection"),
        format!("Gwyddion .gwy: no channel titled 'Deflection'; {list}")
    );
    // --channel on a file without channels.
    let e = read(&dir().join("sur_d.x3p"), &with("1"))
        .unwrap_err()
        .to_string();
    assert!(e.ends_with(
        "--channel applies to files of several channels (Gwyddion's .gwy, its ASCII \
         exports concatenated)"
    ));
    // A file without a channel of heights.
    let one = bytes("one.gwy");
    let at = one.windows(11).position(|w| w == b"unitstr\0snm").unwrap() + 9;
    let mut volts = one.clone();
    volts[at..at + 2].copy_from_slice(b"mV");
    assert_eq!(
        read_grid(&volts, &Options::default())
            .unwrap_err()
            .1
            .to_string(),
        "Gwyddion .gwy: no channel holds heights (sizes and values in a unit of length): \
         0 'Topography' (mV)"
    );
    // One channel: no note.
    assert!(read_grid(&bytes("one.gwy"), &Options::default())
        .unwrap()
        .notes
        .is_empty());
}

#[test]
fn other_formats_get_a_way_forward() {
    let t = tempfile::tempdir().unwrap();
    let refuse = |name: &str, content: &[u8]| {
        let p = t.path().join(name);
        std::fs::write(&p, content).unwrap();
        read(&p, &Options::default()).unwrap_err().to_string()
    };
    // Read natively: a file cut short says so, naming the format.
    let e = refuse("scan.datx", b"\x89HDF\r\n\x1a\n\0\0\0\0");
    assert!(
        e.contains("Zygo .datx: its HDF5 structure cannot be read"),
        "{e}"
    );
    let e = refuse("h.h5", b"\x89HDF\r\n\x1a\n\0\0\0\0");
    assert!(e.contains("looks like a NetCDF-4 or HDF5 file"), "{e}");
    assert!(refuse("h.nc", b"CDF\x01\0\0\0").contains("looks like a NetCDF file"));
    assert!(refuse("h.npy", b"\x93NUMPY\x01\0v\0").contains("numpy.savetxt"));
    assert!(refuse("h.tif", b"II*\0\x08\0\0\0").contains("TIFF: a directory's size"));
    let mut tiff = b"II*\0\x08\0\0\0\x01\0".to_vec();
    tiff.extend_from_slice(&[0, 1, 3, 0, 1, 0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 0]);
    assert!(refuse("h.tif", &tiff).contains("looks like a TIFF image that is not a JPK or Park"));
    assert!(refuse("h.spm", b"\\*File list\r\n\\Version: 0x09200201\r\n").contains("Nanoscope"));
    assert!(refuse("h.vk4", b"VK4_\0\0\0\0").contains("Keyence .vk4: "));
    assert!(refuse("h.plu", b"09/11/2020 12:00\0\0\0\0").contains("Sensofar .plu"));
    assert!(refuse("h.dat", b"\x88\x1b\x03\x71\0\0").contains("Zygo MetroPro"));
    // By content, not by name: an x3p named .txt is read.
    let p = t.path().join("named_wrong.txt");
    std::fs::copy(dir().join("sur_d.x3p"), &p).unwrap();
    assert!(read(&p, &Options::default()).is_ok());
    // A zip that is not an x3p.
    let e = refuse("a.zip", &zip_of(&[("readme.txt", b"hello")]));
    assert!(e.ends_with("a zip archive without main.xml: not an x3p file (an x3p holds main.xml and bindata/data.bin)"), "{e}");
    // An XYZ point cloud.
    let mut xyz = String::from("# Lateral units: m\n");
    for i in 0..10 {
        for j in 0..10 {
            xyz.push_str(&format!("{}e-6 {}e-6 {}e-9\n", i, j, (i * j) % 7));
        }
    }
    let e = refuse("cloud.xyz", xyz.as_bytes());
    assert!(
        e.contains("line 2: three numbers a row: looks like an XYZ point cloud (x y z), a regular grid of heights is needed"),
        "{e}"
    );
}

/// A zip of `files`, deflated.
pub fn zip_of(files: &[(&str, &[u8])]) -> Vec<u8> {
    use std::io::Write;
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for (name, data) in files {
        w.start_file(*name, zip::write::SimpleFileOptions::default())
            .unwrap();
        w.write_all(data).unwrap();
    }
    w.finish().unwrap().into_inner()
}
