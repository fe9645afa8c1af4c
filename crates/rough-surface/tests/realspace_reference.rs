//! Sq and Sdq of maps, Rq and RΔq of line scans and of a map's profiles
//! (`--direction x|y`), against SurfaceTopography 1.27.1's
//! `rms_height_from_area`, `rms_gradient`, `rms_height_from_profile` and
//! `rms_slope_from_profile` on the same detrended data, and Sa, Ssk, Sku,
//! Sz (Ra, Rsk, Rku, Rz) against numpy on its detrended heights
//! (`scripts/realspace_reference.py`, committed in
//! tests/data/realspace.txt): within 1e-12.

use std::path::Path;

use rough_surface::{read, Direction, Options};

#[test]
fn real_space_numbers_match_surfacetopography() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let text = std::fs::read_to_string(data.join("realspace.txt")).unwrap();
    let (mut worst, mut worst_a) = (0f64, 0f64);
    let mut n = 0;
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |s: &str| s.parse::<f64>().unwrap();
        let pixel = num(w[2]);
        let opts = Options {
            periodic: w[1] == "1",
            pixel_size: (pixel > 0.0).then_some(pixel),
            direction: match w[3] {
                "x" => Some(Direction::X),
                "y" => Some(Direction::Y),
                _ => None,
            },
            ..Options::default()
        };
        let m = read(&data.join(w[0]), &opts).unwrap();
        let r = m.real.expect(w[0]);
        assert_eq!(r.areal, w[3] == "map", "{}", w[0]);
        let a = r.amplitude;
        for (k, (got, want)) in [
            (r.rms_height, num(w[4])),
            (r.rms_slope, num(w[5])),
            (a.mean_abs, num(w[6])),
            (a.skewness, num(w[7])),
            (a.kurtosis, num(w[8])),
            (a.range, num(w[9])),
        ]
        .into_iter()
        .enumerate()
        {
            let e = ((got - want) / want).abs();
            assert!(
                e < 1e-12,
                "{} {} column {k}: {got} vs {want} ({e:.1e})",
                w[0],
                w[3]
            );
            if k < 2 {
                worst = worst.max(e);
            } else {
                worst_a = worst_a.max(e);
            }
        }
        n += 1;
    }
    assert_eq!(n, 10);
    eprintln!(
        "Sq, Sdq, Rq, RΔq against SurfaceTopography: worst {worst:.1e}; Sa, Ssk, Sku, Sz \
         (Ra …) against numpy: worst {worst_a:.1e}"
    );
}

#[test]
fn psd_tables_have_no_real_space_numbers() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let m = read(&data.join("psd_knee.txt"), &Options::default()).unwrap();
    assert!(m.real.is_none());
}
