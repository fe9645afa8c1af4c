//! The Hurst fit's verdict measures the points it shows: on a Zygo
//! MetroPro map (SurfaceTopography's example file), over the band found
//! from the data before the band's ends were trimmed (8.94e3…6.08e5 /m),
//! the first bins lie 1.0–1.6 decades off the fitted line, which the
//! mode-weighted rms (0.077 decades) hides and the unweighted one (0.689)
//! does not: not a power law. The default band now leaves them out, and
//! is a power law; so is the shipped example's.

use std::path::Path;

use rough_surface::{read, Options, Verdict};

#[test]
fn the_unweighted_rms_decides_a_poor_fit() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let m = read(
        &root.join("tests/data/instruments/metropro-1.dat.gz"),
        &Options::default(),
    )
    .unwrap();
    let f = m.fit(8.9e3, 6.1e5).unwrap();
    assert_eq!(f.points, 25);
    assert!((f.rms_decades - 0.077).abs() < 5e-4, "{f:?}");
    assert!((f.rms_decades_unweighted - 0.689).abs() < 5e-4, "{f:?}");
    // The points the spectrum view shows, against the line it draws.
    let worst = m
        .spectrum
        .iter()
        .filter(|(q, _)| *q >= f.q_lo && *q <= f.q_hi)
        .map(|&(q, c)| (c / f.psd(q)).log10().abs())
        .fold(0f64, f64::max);
    assert!(worst > 1.6 && worst < 1.7, "{worst}");
    assert_eq!(f.verdict(), Verdict::Poor);
    assert_eq!(f.verdict().words(), Some("not a power law over this band"));
    // The default band starts past them.
    let d = m.default_fit().unwrap();
    assert!(d.q_lo > 8e4 && d.rms_decades_unweighted <= 0.1, "{d:?}");
    assert_eq!(d.verdict(), Verdict::SelfAffine);
    let example = root.join("../../surfaces/example.txt");
    let f = read(&example, &Options::default())
        .unwrap()
        .default_fit()
        .unwrap();
    assert!(f.rms_decades_unweighted <= 0.1, "{f:?}");
    assert_eq!(f.verdict(), Verdict::SelfAffine);
}
