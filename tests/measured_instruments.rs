//! Instruments' own files through the command line as a researcher meets
//! them: read natively (the gzip-compressed copies of SurfaceTopography's
//! example files), `--channel` of a Nanoscope file, `--max-undefined` for
//! an FRT scan with a third of its points not measured (the note says so),
//! `--height-unit` refused where the file gives its unit and taken where it
//! gives none, and both recorded in a snapshot.

mod common;

use std::path::Path;
use std::process::{Command, Stdio};

use common::cli::{noted, BIN};
use roughtui::scene::State;
use roughtui::snapshot::{load_file, save_new};
use roughtui::surface::SurfaceSource;

fn container() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/instruments/container-2.zip")
        .to_str()
        .unwrap()
        .to_string()
}

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/rough-surface/tests/data/instruments")
        .join(format!("{name}.gz"))
        .to_str()
        .unwrap()
        .to_string()
}

/// Exit 2, nothing on stdout, one line with each of `words`.
fn refused(args: &[&str], words: &[&str]) {
    let out = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
}

fn moments(args: &[&str]) -> (String, Vec<String>) {
    let mut a = vec!["export", "--view", "moments", "--points", "5"];
    a.extend_from_slice(args);
    noted(&a)
}

#[test]
fn instruments_files_export_with_their_notes() {
    let sur = data("sur-2.sur");
    let (csv, notes) = moments(&["--surface", &sur]);
    assert_eq!(csv.lines().count(), 6, "{csv}");
    assert_eq!(
        notes[..2],
        [
            "117 non-measured points (marked zmin − 2) read as undefined",
            "117 undefined points (0.04 %) filled"
        ]
    );
    let di = data("di-3.di");
    let (_, notes) = moments(&["--surface", &di, "--channel", "Height"]);
    assert!(
        notes[0]
            .starts_with("channel 3 'Height' (nm) read; also in the file: 0 'ZSensor' (nm), 1 "),
        "{notes:?}"
    );
    refused(
        &["export", "--surface", &di, "--channel", "Phase"],
        &["Nanoscope: channel 2 'Phase'", "not a length"],
    );
    refused(
        &["export", "--surface", &sur, "--height-unit", "nm"],
        &["--height-unit nm applies to a file that does not give its height unit: this Digital Surf .sur file gives it"],
    );
    refused(
        &["export", "--surface", &sur, "--channel", "1"],
        &["--channel applies to files of several channels; a Digital Surf .sur file holds one"],
    );
}

#[test]
fn max_undefined_lets_a_scan_with_many_points_not_measured_in() {
    let frt = data("frt-2.frt");
    refused(
        &["export", "--surface", &frt],
        &[
            "12314 of 45000 points (27.4 %) are undefined",
            "up to 10 % are filled",
            "--max-undefined PERCENT",
        ],
    );
    let (_, notes) = moments(&["--surface", &frt, "--max-undefined", "30"]);
    assert!(
        notes
            .contains(&"12314 undefined points (27.4 %) filled (--max-undefined 30 %)".to_string()),
        "{notes:?}"
    );
    let out = Command::new(BIN)
        .args(["export", "--surface", &frt, "--max-undefined", "120"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("\"120\" is not a percentage above 0 and below 100"),
        "{err}"
    );
}

#[test]
fn a_wave_without_units_takes_the_units_given() {
    let ibw = data("10x10-one_channel_without_name.ibw");
    let (_, notes) = moments(&["--surface", &ibw]);
    assert_eq!(
        notes[..2],
        [
            "sizes read in m (the file names no unit; --lateral-unit to change)",
            "heights read in m (the file names no unit; --height-unit to change)"
        ]
    );
    let (_, notes) = moments(&[
        "--surface",
        &ibw,
        "--lateral-unit",
        "um",
        "--height-unit",
        "nm",
    ]);
    assert_eq!(
        notes[..2],
        [
            "sizes read in µm (--lateral-unit; the file gives no unit)",
            "heights read in nm (--height-unit; the file gives no unit)"
        ]
    );
}

#[test]
fn units_channel_and_share_are_recorded_in_a_snapshot() {
    let d = tempfile::tempdir().unwrap();
    let ibw = data("10x10-one_channel_without_name.ibw");
    let opts = rough_surface::Options {
        lateral_unit: rough_surface::HeightUnit::parse("um"),
        height_unit: rough_surface::HeightUnit::parse("nm"),
        max_undefined: Some(0.25),
        ..Default::default()
    };
    let s = State::measured(SurfaceSource::read(Path::new(&ibw), opts.clone()).unwrap()).unwrap();
    let p = save_new(d.path(), "wave", &s).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    assert!(
        text.contains("height_unit: \"nm\", lateral_unit: \"µm\", max_undefined: 25.0"),
        "{text}"
    );
    let back = load_file(&p).unwrap();
    assert_eq!(back.surface.unwrap().options, opts);
}

#[test]
fn a_contact_engineering_container_is_read() {
    let zip = container();
    // The first topography is a profile of uneven x: the first that reads
    // is the Nanoscope file, as it reads on its own.
    let (csv, notes) = moments(&["--surface", &zip]);
    assert!(
        notes[0].starts_with(
            "3 topographies in this contact.engineering container \
             ('80_Scale10.472_FIXEDv2p1.asc', 'gain_control_uncd_35.001', \
             'uncd_stylus_300um_5mar_3.txt'): 'gain_control_uncd_35.001' read"
        ),
        "{notes:?}"
    );
    assert!(
        notes[1].starts_with("'80_Scale10.472_FIXEDv2p1.asc' not read: x is not uniformly spaced")
    );
    let d = tempfile::tempdir().unwrap();
    let mut z = zip::ZipArchive::new(std::fs::File::open(&zip).unwrap()).unwrap();
    let mut member = Vec::new();
    std::io::Read::read_to_end(
        &mut z.by_name("gain_control_uncd_35_z03tr3R.001").unwrap(),
        &mut member,
    )
    .unwrap();
    let own = d.path().join("gain.001");
    std::fs::write(&own, member).unwrap();
    let (alone, _) = moments(&["--surface", own.to_str().unwrap()]);
    assert_eq!(csv, alone);
    // Another by --series, its unit from meta.yml; a name it does not hold.
    let (_, notes) = moments(&[
        "--surface",
        &zip,
        "--series",
        "uncd_stylus_300um_5mar_3.txt",
    ]);
    assert_eq!(notes[1], "x read in mm (meta.yml's unit)");
    refused(
        &["export", "--surface", &zip, "--series", "steel"],
        &["--series 'steel': the container holds no topography of that name"],
    );
    // --channel goes to the topography's file.
    let (_, notes) = moments(&["--surface", &zip, "--channel", "1"]);
    assert!(
        notes
            .iter()
            .any(|n| n.starts_with("channel 1 'Height' (nm) read")),
        "{notes:?}"
    );
}

#[test]
fn a_spreadsheet_is_named() {
    use std::io::Write;
    let d = tempfile::tempdir().unwrap();
    let p = d.path().join("scan.xlsx");
    let mut w = zip::ZipWriter::new(std::fs::File::create(&p).unwrap());
    w.start_file("xl/workbook.xml", zip::write::SimpleFileOptions::default())
        .unwrap();
    w.write_all(b"<workbook/>").unwrap();
    w.finish().unwrap();
    refused(
        &["export", "--surface", p.to_str().unwrap()],
        &["looks like an Excel spreadsheet (.xlsx): save the sheet of heights as CSV"],
    );
}
