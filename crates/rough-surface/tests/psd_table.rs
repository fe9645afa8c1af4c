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
    let (line, p) = err("# h\n1 2\n1 3\n");
    assert_eq!(line, Some(3));
    assert_eq!(
        p.to_string(),
        "q must increase: q = 1 at point 2 follows q = 1"
    );
    assert_eq!(err("# nothing\n"), (None, Problem::Empty));
}
