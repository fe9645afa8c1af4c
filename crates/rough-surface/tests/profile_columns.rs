//! Profiles written as three columns, against SurfaceTopography 1.27.1 on
//! the same values (`scripts/profile_columns_reference.py`, committed in
//! tests/data/profile_columns_reference.txt): a Dektak CSV export (its
//! header blocks, `x,z,,` rows, x printed to 0.1 µm at a 0.156 µm
//! spacing) and an .hfm profile (`X;Y;valid`, 33 of 810 points not
//! measured) are read as x z profiles over n times the least-squares
//! spacing of their x (numpy's polyfit), the .hfm's rows of validity 0
//! filled as undefined points: Rq, RΔq, the moments (h_rms, slopes) and
//! the spectrum match.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{read, Kind, Options, Problem};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

#[derive(Default)]
struct Case {
    file: String,
    spacing: [f64; 3],
    undefined: (usize, usize),
    real: (f64, f64),
    n: usize,
    l: f64,
    moments: Vec<[f64; 4]>,
    spectrum: Vec<(f64, f64)>,
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(data().join("profile_columns_reference.txt")).unwrap();
    let num = |s: &str| s.parse::<f64>().unwrap();
    let mut out: Vec<Case> = Vec::new();
    let mut section = "";
    for l in text.lines() {
        let w: Vec<&str> = l.split_whitespace().collect();
        let last = out.last_mut();
        match w[0] {
            "#" => {}
            "spacing" => out.push(Case {
                file: w[1].to_string(),
                spacing: [num(w[2]), num(w[3]), num(w[4])],
                ..Case::default()
            }),
            "undefined" => last.unwrap().undefined = (w[2].parse().unwrap(), w[3].parse().unwrap()),
            "real" => last.unwrap().real = (num(w[2]), num(w[3])),
            "surface" => {
                // "surface NAME periodic 0 pixel_size 0.0 line n 640 l 9.98e-05"
                let c = last.unwrap();
                assert_eq!(w[1], c.file);
                c.n = w[8].parse().unwrap();
                c.l = num(w[10]);
            }
            "moments" | "spectrum" => section = w[0],
            "q0" | "zeta_max" | "end" => section = "",
            _ if section == "moments" => {
                last.unwrap()
                    .moments
                    .push([num(w[0]), num(w[1]), num(w[2]), num(w[3])])
            }
            _ if section == "spectrum" => last.unwrap().spectrum.push((num(w[0]), num(w[1]))),
            _ => panic!("{l}"),
        }
    }
    out
}

#[test]
fn three_column_profiles_match_surfacetopography() {
    let cases = cases();
    assert_eq!(cases.len(), 2);
    for c in &cases {
        // The .hfm's heights lie on a 106.6 mm form, 8e5 times their rms
        // (0.13 µm): SurfaceTopography's own lowest mode moves by 1.6e-10
        // when it reads them in m rather than mm, by 7e-10 when 106.6 is
        // subtracted first; ours is within 1.4e-9 of its.
        let tol = if c.file.ends_with(".hfm") {
            3e-9
        } else {
            1e-12
        };
        let (mut worst_l, mut worst_r, mut worst_m, mut worst_s) = (0f64, 0f64, 0f64, 0f64);
        let m = read(&data().join(&c.file), &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        let Kind::Line { n, l } = m.kind else {
            panic!("{}: {:?}", c.file, m.kind)
        };
        assert_eq!(n, c.n, "{}", c.file);
        let e = rel(l, c.l);
        assert!(e < 1e-13, "{}: L {l} vs {}", c.file, c.l);
        worst_l = worst_l.max(e);
        let (undefined, total) = c.undefined;
        assert_eq!(total, n);
        let filled = m
            .notes
            .iter()
            .find(|t| t.contains("undefined points"))
            .cloned();
        if undefined > 0 {
            let note = filled.unwrap_or_else(|| panic!("{}: {:?}", c.file, m.notes));
            assert_eq!(note, format!("{undefined} undefined points (4.1 %) filled"));
            assert_eq!(
                m.notes[0],
                format!("{undefined} points not measured (validity 0) read as undefined")
            );
        } else {
            assert!(filled.is_none(), "{:?}", m.notes);
        }
        let r = m.real.as_ref().unwrap();
        assert!(!r.areal);
        for (got, want) in [(r.rms_height, c.real.0), (r.rms_slope, c.real.1)] {
            let e = rel(got, want);
            assert!(e < tol, "{}: {got} vs {want}", c.file);
            worst_r = worst_r.max(e);
        }
        for &[zeta, m0, m2, m4] in &c.moments {
            let got = m.table.at_zeta(zeta);
            for (a, b) in [(got.m0, m0), (got.m2, m2), (got.m4, m4)] {
                let e = rel(a, b);
                assert!(e < tol, "{} ζ {zeta}: {a} vs {b}", c.file);
                worst_m = worst_m.max(e);
            }
        }
        assert_eq!(m.spectrum.len(), c.spectrum.len(), "{}", c.file);
        let peak = c.spectrum.iter().fold(0f64, |a, p| a.max(p.1));
        for (&(q, s), &(rq, rs)) in m.spectrum.iter().zip(&c.spectrum) {
            assert!(rel(q, rq) < 1e-13, "{} spectrum q {q} vs {rq}", c.file);
            let e = (s - rs).abs() / rs.max(1e-12 * peak);
            assert!(e < tol, "{} spectrum at q {q}: {s} vs {rs}", c.file);
            worst_s = worst_s.max(e);
        }
        println!(
            "{} against SurfaceTopography: L {worst_l:.1e}, Rq/RΔq {worst_r:.1e}, \
             moments {worst_m:.1e}, spectrum {worst_s:.1e}",
            c.file
        );
    }
}

/// The Dektak export's x, printed to 0.1 µm: the spacing read is the
/// least-squares one (within 3e-6 of the true 0.156 µm), where the end
/// points' (99.7 − 0)/639 is 1.6e-4 off.
#[test]
fn dektak_spacing_is_the_least_squares_one() {
    let c = cases().into_iter().next().unwrap();
    assert_eq!(c.file, "dektak_profile.csv");
    let [ls, truth, ends] = c.spacing;
    assert!(rel(ls, truth) < 3e-6 && rel(ends, truth) > 1.5e-4);
    let m = read(&data().join(&c.file), &Options::default()).unwrap();
    let Kind::Line { n, l } = m.kind else {
        panic!()
    };
    // The x column's unit is µm ("Lateral um").
    assert!(rel(l, n as f64 * ls * 1e-6) < 1e-13, "{l}");
    assert_eq!(
        m.notes,
        ["read as Windows-1252 (Latin-1) text: line 4 is not UTF-8"]
    );
    assert!(
        m.summary.starts_with("line scan of 640 points"),
        "{}",
        m.summary
    );
}

fn temp_with(name: &str, bytes: &[u8]) -> (tempfile::TempDir, PathBuf) {
    let d = tempfile::tempdir().unwrap();
    let p = d.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    (d, p)
}

/// More rows of validity 0 than 10 %: refused with the count, and filled
/// with --max-undefined, saying so.
#[test]
fn validity_zeros_count_as_undefined() {
    let text = std::fs::read_to_string(data().join("hfm_profile.hfm")).unwrap();
    let mut rows = 0;
    let more: String = text
        .split_inclusive('\n')
        .map(|l| {
            if l.ends_with(";1\r\n") {
                rows += 1;
                if rows % 12 == 0 {
                    return l.replace(";1\r\n", ";0\r\n");
                }
            }
            l.to_string()
        })
        .collect();
    let (_d, p) = temp_with("more.hfm", more.as_bytes());
    let e = read(&p, &Options::default()).unwrap_err();
    assert_eq!(
        e.problem,
        Problem::Undefined {
            count: 97,
            total: 810,
            allowed: 0.1
        }
    );
    let m = read(
        &p,
        &Options {
            max_undefined: Some(0.15),
            ..Options::default()
        },
    )
    .unwrap();
    assert_eq!(
        m.notes[..2],
        [
            "97 points not measured (validity 0) read as undefined",
            "97 undefined points (12 %) filled (--max-undefined 15 %)"
        ]
    );
}

/// The Dektak profile as Windows' "Unicode" CSV (UTF-16 with its byte-order
/// mark) of three columns, the rows' numbers first (`index, x in µm, y in
/// µm`, as SurfaceTopography's csv-2.csv): the same line scan, so
/// SurfaceTopography's numbers for the Dektak's values.
#[test]
fn utf16_with_rows_numbers_reads_as_the_profile() {
    let bytes = std::fs::read(data().join("dektak_profile.csv")).unwrap();
    let text: String = bytes.iter().map(|&b| b as char).collect();
    let rows = text.split("Raw Micrometer,\r\n").nth(1).unwrap();
    let mut csv = String::from("index, x in µm, y in µm\r\n");
    for (k, r) in rows.lines().filter(|l| !l.trim().is_empty()).enumerate() {
        let f: Vec<&str> = r.split(',').collect();
        csv.push_str(&format!("{k},{},{}\r\n", f[0], f[1]));
    }
    let mut utf16 = vec![0xff, 0xfe];
    utf16.extend(csv.encode_utf16().flat_map(u16::to_le_bytes));
    let (_d, p) = temp_with("unicode.csv", &utf16);
    let m = read(&p, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        m.notes,
        [
            "read as UTF-16 text (Windows' \"Unicode\")",
            "the first column (0, 1, 2 …) read as the rows' numbers, x and z after it"
        ]
    );
    let c = cases().into_iter().next().unwrap();
    let Kind::Line { n, l } = m.kind else {
        panic!()
    };
    assert_eq!(n, c.n);
    assert!(rel(l, c.l) < 1e-13);
    let r = m.real.unwrap();
    assert!(rel(r.rms_height, c.real.0) < 1e-12 && rel(r.rms_slope, c.real.1) < 1e-12);
}
