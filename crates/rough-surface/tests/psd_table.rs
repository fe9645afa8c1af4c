//! PSD tables: read, checked, refused by line.

use rough_surface::{parse, Options, Problem};

#[test]
fn a_two_column_table_reads_with_comments() {
    let text = "# q (1/m)  C (m^4)\n1e5 1e-20\n\n1e6, 1e-23 # comment\n1e7\t1e-26\n";
    let m = parse(text.as_bytes(), &Options::default()).unwrap();
    assert_eq!(m.table.q0(), 1e5);
    assert_eq!(m.table.zeta_max(), 100.0);
    assert_eq!(m.spectrum.len(), 3);
    let fit = m.fit(1e5, 1e7).unwrap();
    assert!((fit.slope + 3.0).abs() < 1e-12, "{fit:?}");
    assert!((fit.hurst - 0.5).abs() < 1e-12, "{fit:?}");
    assert_eq!(m.sha256.len(), 64);
}

#[test]
fn refusals_name_the_line() {
    let err = |t: &str| parse(t.as_bytes(), &Options::default()).unwrap_err();
    assert_eq!(err("1 2\n3 x\n"), (Some(2), Problem::NotNumber("x".into())));
    assert_eq!(
        err("1 2\n3 NaN\n"),
        (Some(2), Problem::NotFinite("NaN".into()))
    );
    assert_eq!(
        err("1 2\n3 4 5\n"),
        (Some(2), Problem::Ragged { got: 3, want: 2 })
    );
    let (line, p) = err("# q C\n1 2\n1 3\n");
    assert_eq!(line, Some(3));
    assert_eq!(
        p.to_string(),
        "q must increase: q = 1 at point 2 follows q = 1"
    );
    assert_eq!(err("# nothing\n"), (None, Problem::Empty));
}

#[test]
fn the_fit_of_fig2s_spectrum_is_fig2s_surface() {
    // psd_fig2.txt: (2π)² Z q^(−3.6), Z = 1e-8, q from 1e5 to 1e9.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/psd_fig2.txt");
    let m = rough_surface::read(&path, &Options::default()).unwrap();
    let fit = m.fit(1e5, 1e9).unwrap();
    assert!((fit.hurst - 0.8).abs() < 1e-13, "{fit:?}");
    assert!((fit.persson_z().unwrap() / 1e-8 - 1.0).abs() < 1e-12);
    // docs/model.md's h_rms of fig2: 19.816636488030044 nm (mpmath: …0300551).
    let h = fit.h_rms().unwrap();
    assert!((h / 19.816636488030055e-9 - 1.0).abs() < 1e-12, "{h}");
    assert!((fit.psd(1e7) / m.spectrum[2].1 - 1.0).abs() < 1e-12);
}

#[test]
fn a_profile_fit_converts_by_isotropy() {
    // C1D = B q^(−(1+2H)) of an isotropic C^iso = A q^(−2(1+H)) has
    // A = B · 2√π Γ(1+H)/Γ(H+½) = 3.67886050951675162 B at H = 0.8 (mpmath).
    let text = "# q C\n1e5 1e-20\n1e7 1e-25.2\n";
    let text = text.replace("1e-25.2", &format!("{:e}", 1e-20 * 100f64.powf(-2.6)));
    let mut m = parse(text.as_bytes(), &Options::default()).unwrap();
    // Read as a profile PSD through contact.engineering's series name.
    let ce = format!(
        "# 1D PSD along x\n# --------------\n# Columns: Wavevector (1/m), PSD (m³)\n{}",
        text.lines().skip(1).collect::<Vec<_>>().join("\n")
    );
    let p = parse(ce.as_bytes(), &Options::default()).unwrap();
    assert_eq!(
        p.kind,
        rough_surface::Kind::Psd {
            dim: rough_model::Dim::Profile,
            points: 2
        }
    );
    let (fa, fp) = (m.fit(1e5, 1e7).unwrap(), p.fit(1e5, 1e7).unwrap());
    assert!((fp.hurst - 0.8).abs() < 1e-12, "{fp:?}");
    let b = 1e-20 * 1e5f64.powf(2.6);
    let z = fp.persson_z().unwrap();
    let want = b * 3.678_860_509_516_751_6 / (2.0 * std::f64::consts::PI).powi(2);
    assert!((z / want - 1.0).abs() < 1e-14, "{z} {want}");
    // The same numbers read as areal C^iso give another H (slope −2.6).
    assert!((fa.hurst - 0.3).abs() < 1e-12);
    m.spectrum.clear();
    assert!(m.fit(1e5, 1e7).is_none());
}

#[test]
fn the_example_surface_reads() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../surfaces/example.txt");
    let m = rough_surface::read(&path, &Options::default()).unwrap();
    assert_eq!(
        m.kind,
        rough_surface::Kind::Map {
            nx: 192,
            ny: 192,
            lx: 50e-6,
            ly: 50e-6
        }
    );
    assert_eq!(
        m.summary,
        "map 192 × 192, 50 µm × 50 µm, plane removed, Hann window"
    );
    // Above the roll-off the fit finds the synthesis' Hurst exponent.
    let q0 = m.table.q0();
    let fit = m.fit(4.0 * q0, 60.0 * q0).unwrap();
    assert!((fit.hurst - 0.8).abs() < 0.1, "{fit:?}");
}
