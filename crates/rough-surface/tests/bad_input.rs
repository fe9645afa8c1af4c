//! Every refusal: one message naming the file, the line where there is one,
//! and the problem; never a panic.

use std::io::Write;
use std::path::PathBuf;

use proptest::prelude::*;
use rough_surface::{parse, read, Options, MAX_BYTES};

struct File {
    _dir: tempfile::TempDir,
    path: PathBuf,
}

fn file(bytes: &[u8]) -> File {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.txt");
    std::fs::write(&path, bytes).unwrap();
    File { _dir: dir, path }
}

/// The message for `text` read with `opts`, "FILE" standing for the path.
fn message(text: &str, opts: Options) -> String {
    let f = file(text.as_bytes());
    let e = read(&f.path, &opts).expect_err("refused");
    e.to_string().replace(&f.path.display().to_string(), "FILE")
}

fn refuse(text: &str) -> String {
    message(text, Options::default())
}

/// A 4 × 4 matrix with a header, rows `rows` instead of the default ones.
fn map(header: &str, rows: &[&str]) -> String {
    let mut t = String::from(header);
    for r in rows {
        t.push_str(r);
        t.push('\n');
    }
    t
}

const SIZE: &str = "# Width: 4 µm\n# Height: 4 µm\n# Value units: nm\n";
const GOOD: [&str; 4] = ["1 2 3 4", "2 1 4 3", "0 5 1 2", "3 3 0 1"];

#[test]
fn a_good_map_reads() {
    let f = file(map(SIZE, &GOOD).as_bytes());
    let m = read(&f.path, &Options::default()).unwrap();
    assert_eq!(
        m.summary,
        "map 4 × 4, 4 µm × 4 µm, plane removed, Hann window"
    );
}

#[test]
fn ragged_rows() {
    assert_eq!(
        refuse(&map(SIZE, &["1 2 3 4", "1 2 3", "1 2 3 4", "1 2 3 4"])),
        "bad surface FILE, line 5: 3 columns where the first row has 4"
    );
}

#[test]
fn non_numbers_nan_and_infinity() {
    assert_eq!(
        refuse(&map(SIZE, &["1 2 3 4", "1 2 3 4", "1 2 x 4", "1 2 3 4"])),
        "bad surface FILE, line 6: 'x' is not a number"
    );
    assert_eq!(
        refuse(&map(
            SIZE,
            &["1 2 3 4", "1 NaN 3 4", "1 2 nan 4", "1 2 3 4"]
        )),
        "bad surface FILE: 2 of 16 points (12.5 %) are undefined (NaN, empty or \
         masked): up to 10 % are filled, more is refused; crop the data to the \
         part that was measured, or allow more with --max-undefined PERCENT"
    );
    assert_eq!(
        refuse(&map(SIZE, &["1 2 3 4", "1 2 3 4", "1 2 3 4", "1 2 3 -inf"])),
        "bad surface FILE, line 7: -inf is not a finite number"
    );
}

#[test]
fn a_size_is_needed() {
    assert_eq!(
        refuse(&map("", &GOOD)),
        "bad surface FILE: no size: add header lines '# Width: 10 µm' and \
         '# Height: 10 µm' or give the sample spacing with --pixel-size"
    );
    assert_eq!(
        refuse("1 2 3 4 5\n"),
        "bad surface FILE: no size: add a header line '# Width: 10 µm' (the \
         scan's length) or give the sample spacing with --pixel-size"
    );
    // The pixel size supplies it.
    let f = file(map("", &GOOD).as_bytes());
    let opts = Options {
        periodic: false,
        pixel_size: Some(1e-6),
        ..Options::default()
    };
    assert!(read(&f.path, &opts).is_ok());
    // … and is refused where the file gives its size.
    assert_eq!(
        message(&map(SIZE, &GOOD), opts),
        "bad surface FILE, line 1: --pixel-size 1 µm does not apply: the file gives its size"
    );
    assert_eq!(
        refuse(&map("# Width: 4 µm\n", &GOOD)),
        "bad surface FILE, line 1: a map needs both '# Width:' and '# Height:'; \
         '# Height:' is missing"
    );
}

#[test]
fn unknown_units() {
    assert_eq!(
        refuse(&map("# Width: 4 furlong\n# Height: 4 µm\n", &GOOD)),
        "bad surface FILE, line 1: unknown unit 'furlong': lengths are read in \
         m, mm, µm (um), nm, pm or Å"
    );
    assert_eq!(
        refuse(&map("# Width: 4\n# Height: 4\n# Value units: V\n", &GOOD)),
        "bad surface FILE, line 3: unknown unit 'V': lengths are read in m, mm, \
         µm (um), nm, pm or Å"
    );
}

#[test]
fn fewer_than_four_points() {
    assert_eq!(
        refuse(&map(SIZE, &["1 2 3", "1 2 3", "3 2 1", "0 0 1"])),
        "bad surface FILE, line 4: 3 points along x: at least 4 are needed"
    );
    assert_eq!(
        refuse(&map(SIZE, &["1 2 3 4", "1 2 3 4", "4 3 2 1"])),
        "bad surface FILE: 3 points along y: at least 4 are needed"
    );
    assert_eq!(
        refuse("# Width: 1 mm\n1 2 3\n"),
        "bad surface FILE: 3 points along the line: at least 4 are needed"
    );
}

#[test]
fn flat_surfaces() {
    assert_eq!(
        refuse(&map(SIZE, &["2 2 2 2"; 4])),
        "bad surface FILE: the surface is flat: every height is the same"
    );
    assert_eq!(
        refuse(&map(SIZE, &["0 1 2 3", "1 2 3 4", "2 3 4 5", "3 4 5 6"])),
        "bad surface FILE: the surface is flat: nothing is left after removing \
         its tilt (the heights lie on a plane)"
    );
}

#[test]
fn non_uniform_line_scans() {
    let t = "# x z\n0 1e-9\n1e-6 -2e-9\n2e-6 3e-9\n3.5e-6 0\n4e-6 1e-9\n";
    assert_eq!(
        refuse(t),
        "bad surface FILE, line 5: x is not uniformly spaced: x = 0.0000035 where \
         the least-squares spacing 0.00000105 puts 0.00000305 (a line scan \
         needs uniform x, to 1% of the spacing beyond the rounding of the printed digits)"
    );
    // Without the header line the content says it is a scan.
    assert!(refuse(&t[6..]).starts_with("bad surface FILE, line 4: x is not uniformly"));
    // Printed with few digits, a uniform x passes.
    let mut t = String::new();
    for i in 0..300 {
        t.push_str(&format!(
            "{:.3e} {:e}\n",
            i as f64 * 1.1e-7,
            (i as f64).sin() * 1e-9
        ));
    }
    let f = file(t.as_bytes());
    assert!(read(&f.path, &Options::default()).is_ok());
}

#[test]
fn bad_psd_tables() {
    let q = [1e5, 2e5, 4e5, 8e5, 1.6e6];
    let row = |q: f64, c: f64| format!("{q:e} {c:e}\n");
    let mut t = String::new();
    for (i, &qi) in q.iter().enumerate() {
        t.push_str(&row(if i == 3 { 4e5 } else { qi }, qi.powf(-3.6)));
    }
    assert_eq!(
        refuse(&t),
        "bad surface FILE, line 4: q must increase: q = 400000 at point 4 follows q = 400000"
    );
    let mut t = String::from("# q C\n");
    for (i, &qi) in q.iter().enumerate() {
        t.push_str(&row(qi, if i == 2 { 0.0 } else { qi.powf(-3.6) }));
    }
    assert_eq!(
        refuse(&t),
        "bad surface FILE, line 4: PSD value 0 at point 3 must be finite and > 0"
    );
}

#[test]
fn ambiguous_two_columns() {
    // Uniform q with a falling C: a raw FFT's PSD, or (unlikely) heights.
    let mut t = String::new();
    for k in 1..40 {
        t.push_str(&format!("{} {:e}\n", k as f64 * 1e5, (k as f64).powf(-3.0)));
    }
    assert_eq!(
        refuse(&t),
        "bad surface FILE: two columns that could be a line scan (x z) or a PSD \
         table (q C): add a header line '# x z' for a line scan or '# q C' for a PSD table"
    );
    let f = file(format!("# q C\n{t}").as_bytes());
    assert!(read(&f.path, &Options::default()).is_ok());
}

#[test]
fn too_large_files_are_not_read() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.txt");
    let f = std::fs::File::create(&path).unwrap();
    f.set_len(MAX_BYTES + 1).unwrap(); // sparse: no disk used
    let e = read(&path, &Options::default()).unwrap_err().to_string();
    assert_eq!(
        e,
        format!(
            "bad surface {}: 536870913 bytes is too large: surface files are read up to 512 MB",
            path.display()
        )
    );
}

#[test]
fn not_text_and_empty() {
    let mut bytes = map(SIZE, &GOOD).into_bytes();
    bytes.extend_from_slice(b"1 2 \xff 4\n");
    let f = file(&bytes);
    let e = read(&f.path, &Options::default()).unwrap_err().to_string();
    // Not UTF-8: read as Windows-1252, where 0xFF is 'ÿ'.
    assert!(e.ends_with(", line 8: 'ÿ' is not a number"), "{e}");
    let f = file(b"1 2\n\x00\x01\x02\xff\n");
    let e = read(&f.path, &Options::default()).unwrap_err().to_string();
    assert!(e.contains("a binary file of a format not read"), "{e}");
    assert_eq!(
        refuse(""),
        "bad surface FILE: no data rows (the file is empty or all comments)"
    );
    assert_eq!(
        refuse("# only\n# comments\n\n"),
        "bad surface FILE: no data rows (the file is empty or all comments)"
    );
}

#[test]
fn other_refusals() {
    // Decimal commas are read (formats.rs tests the values).
    assert_eq!(
        refuse("1,5 2,5 3,5 4,5\n"),
        "bad surface FILE: no size: add a header line '# Width: 10 µm' (the scan's length) \
         or give the sample spacing with --pixel-size"
    );
    let two = format!(
        "# Channel: Height\n{}# Channel: Phase\n{}",
        map(SIZE, &GOOD),
        map("", &GOOD)
    );
    // Two channels (Gwyddion's exports concatenated): the first of
    // heights is read, an error in it names the file's line.
    let f = file(two.as_bytes());
    let m = read(&f.path, &Options::default()).unwrap();
    assert_eq!(
        m.notes,
        vec![
            "channel 0 'Height' (nm) read; also in the file: 1 'Phase' (m) (--channel N or TITLE)"
        ]
    );
    assert_eq!(
        refuse(&two.replacen("2 1 4 3", "2 1 x 3", 1)),
        "bad surface FILE, line 6: 'x' is not a number"
    );
    let wrong = two.replace("Value units: nm", "Value units: V").replace(
        "# Channel: Phase\n",
        "# Channel: Phase\n# Value units: deg\n",
    );
    assert_eq!(
        refuse(&wrong),
        "bad surface FILE: no channel holds heights (values in a unit of length): \
         0 'Height' (V), 1 'Phase' (deg)"
    );
    let dir = tempfile::tempdir().unwrap();
    let e = read(dir.path(), &Options::default()).unwrap_err();
    assert!(e.to_string().ends_with(": is a folder, not a file"));
    let e = read(&dir.path().join("missing.txt"), &Options::default()).unwrap_err();
    assert!(e.to_string().contains(": cannot read: "), "{e}");
}

/// Three columns: a profile's validity column or empty trailing cells
/// (read as x z, `profile_columns.rs`), else an XYZ point cloud.
#[test]
fn three_column_profiles() {
    let hfm = |rows: &[&str]| {
        let mut t = String::from("X;Y;valid\r\n[mm];[mm];[1/0]\r\n");
        for r in rows {
            t.push_str(r);
            t.push_str("\r\n");
        }
        t
    };
    let good = [
        "0.0;1.5;1",
        "0.5;1.2;1",
        "1.0;1.7;1",
        "1.5;1.1;1",
        "2.0;1.4;1",
    ];
    let f = file(hfm(&good).as_bytes());
    assert!(read(&f.path, &Options::default()).is_ok());
    let mut bad = good;
    bad[2] = "1.0;1.7;2";
    assert_eq!(
        refuse(&hfm(&bad)),
        "bad surface FILE, line 5: the validity column holds 2: 1 marks a measured \
         point, 0 one not measured"
    );
    bad[2] = "1.0;1.7;";
    assert_eq!(
        refuse(&hfm(&bad)),
        "bad surface FILE, line 5: the validity column holds nothing: 1 marks a \
         measured point, 0 one not measured"
    );
    let none: Vec<String> = good.iter().map(|r| r.replace(";1", ";0")).collect();
    let none: Vec<&str> = none.iter().map(String::as_str).collect();
    assert!(
        refuse(&hfm(&none)).contains("5 of 5 points (100 %) are undefined"),
        "{}",
        refuse(&hfm(&none))
    );
    assert_eq!(
        refuse(&hfm(&good[..3])),
        "bad surface FILE: 3 points along the line: at least 4 are needed"
    );
    // A Dektak export: the header block, then `x,z,,`.
    let dektak = "Scan Parameters\r\r\nStylus,Radius: 2.5 um\r\nScan Data\r\r\n\
                  Lateral um,Raw Micrometer,\r\n";
    let rows = [
        "0.0,-0.00933,,",
        "0.2,-0.00760,,",
        "0.3,-0.00644,,",
        "0.5,-0.00498,,",
    ];
    let t = format!("{dektak}{}\r\n", rows.join("\r\n"));
    let f = file(t.as_bytes());
    assert!(read(&f.path, &Options::default()).is_ok());
    // Cut off inside its last row.
    assert_eq!(
        refuse(&t[..t.len() - 5]),
        "bad surface FILE, line 8: 2 columns where the first row has 3"
    );
    // x running backwards.
    let back = format!(
        "{dektak}{}\r\n",
        rows.iter().rev().cloned().collect::<Vec<_>>().join("\r\n")
    );
    assert!(refuse(&back).starts_with("bad surface FILE, line 8: x must increase"));
    // A third number in one row: no longer empty trailing cells, so a
    // point cloud's message, as any three numbers a row.
    let cloud = t.replacen("0.2,-0.00760,,", "0.2,-0.00760,7,", 1);
    assert!(refuse(&cloud).contains("three numbers a row: looks like an XYZ point cloud"));
    assert_eq!(
        refuse("x y z\n0 0 1\n1 0 2\n0 1 3\n1 1 4\n"),
        "bad surface FILE, line 2: three numbers a row: looks like an XYZ point cloud (x y z), \
         a regular grid of heights is needed: open it in Gwyddion as XYZ data, rasterize it \
         (XYZ Data → Rasterize) and save it as .gwy or .x3p (or File → Save As → ASCII data \
         matrix)"
    );
    // A validity column named, but the values of an XYZ cloud: refused.
    assert!(refuse("x;y;valid\n0;0;5\n1;0;2\n0;1;3\n1;1;4\n").contains("validity column holds 5"));
}

#[test]
fn a_file_is_never_changed() {
    let text = map(SIZE, &GOOD);
    let f = file(text.as_bytes());
    read(&f.path, &Options::default()).unwrap();
    let mut w = std::fs::OpenOptions::new()
        .append(true)
        .open(&f.path)
        .unwrap();
    w.write_all(b"").unwrap();
    assert_eq!(std::fs::read_to_string(&f.path).unwrap(), text);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Arbitrary text of numbers, words and headers: a result or a
    /// refusal, never a panic.
    #[test]
    fn never_panics(lines in prop::collection::vec(
        prop::collection::vec(prop_oneof![
            any::<f64>().prop_map(|v| v.to_string()),
            (-3i32..3).prop_map(|v| v.to_string()),
            Just("#".to_string()), Just("Width: 2 µm".to_string()),
            Just("Height: 1 nm".to_string()), Just("x".to_string()),
            Just("Columns: Wavevector (1/m), PSD (m³)".to_string()),
            Just("q/π × 2D PSD".to_string()), Just(",".to_string()),
            Just("X;Y;valid".to_string()), Just("[mm];[mm];[1/0]".to_string()),
            Just("Lateral um,Raw Micrometer,".to_string()), Just(",,".to_string()),
            Just(";".to_string()),
        ], 0..6), 0..12),
        periodic in any::<bool>(),
        pixel in prop::option::of(prop_oneof![Just(1e-6), Just(0.0), Just(f64::NAN)]),
    ) {
        let text: String = lines.iter().map(|l| l.join(" ") + "\n").collect();
        let _ = parse(text.as_bytes(), &Options { periodic, pixel_size: pixel, ..Options::default() });
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The Dektak and .hfm profiles cut anywhere and with a byte changed:
    /// a result or a refusal, never a panic.
    #[test]
    fn cut_and_changed_profiles_never_panic(
        which in any::<bool>(),
        cut in 0.0f64..1.0,
        at in 0.0f64..1.0,
        byte in prop_oneof![Just(b';'), Just(b','), Just(b'0'), Just(b'\n'), Just(b'-'), Just(b'e'), any::<u8>()],
    ) {
        let name = if which { "dektak_profile.csv" } else { "hfm_profile.hfm" };
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name);
        let mut bytes = std::fs::read(path).unwrap();
        bytes.truncate((cut * bytes.len() as f64) as usize);
        if !bytes.is_empty() {
            let i = ((at * bytes.len() as f64) as usize).min(bytes.len() - 1);
            bytes[i] = byte;
        }
        let _ = parse(&bytes, &Options::default());
    }

    /// Anything after a UTF-16 byte-order mark, odd lengths and lone
    /// surrogates included: a result or a refusal, never a panic.
    #[test]
    fn utf16_never_panics(
        big in any::<bool>(),
        text in "[0-9 ,;.\n\re-]{0,80}",
        tail in prop::collection::vec(any::<u8>(), 0..5),
    ) {
        let mut bytes = if big { vec![0xfe, 0xff] } else { vec![0xff, 0xfe] };
        for u in text.encode_utf16() {
            bytes.extend(if big { u.to_be_bytes() } else { u.to_le_bytes() });
        }
        bytes.extend(tail);
        let _ = parse(&bytes, &Options::default());
    }
}
