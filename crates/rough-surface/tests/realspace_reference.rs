//! Sq and Sdq of maps, Rq and RΔq of line scans, against SurfaceTopography
//! 1.27.1's `rms_height_from_area`, `rms_gradient`,
//! `rms_height_from_profile` and `rms_slope_from_profile` on the same
//! detrended data (`scripts/realspace_reference.py`, committed in
//! tests/data/realspace.txt): within 1e-12. The height parameters beside
//! them (Sa, Ssk, Sku, Sz; Ra, Rsk, Rku, Rz) against its `max()` − `min()`
//! and NumPy's moments of its detrended heights: within 1e-9 (relative; the
//! skewness's error relative to 1 where it is smaller).

use std::path::Path;

use rough_surface::{read, Options};

#[test]
fn real_space_numbers_match_surfacetopography() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let text = std::fs::read_to_string(data.join("realspace.txt")).unwrap();
    let mut worst = 0f64;
    let mut worst_iso = [0f64; 4];
    let mut n = 0;
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |s: &str| s.parse::<f64>().unwrap();
        let pixel = num(w[2]);
        let opts = Options {
            periodic: w[1] == "1",
            pixel_size: (pixel > 0.0).then_some(pixel),
            ..Options::default()
        };
        let m = read(&data.join(w[0]), &opts).unwrap();
        let r = m.real.expect(w[0]);
        assert_eq!(r.areal, w[3] == "map", "{}", w[0]);
        for (got, want) in [(r.rms_height, num(w[4])), (r.rms_slope, num(w[5]))] {
            let e = ((got - want) / want).abs();
            assert!(e < 1e-12, "{}: {got} vs {want} ({e:.1e})", w[0]);
            worst = worst.max(e);
        }
        let names = if r.areal {
            ["Sa", "Ssk", "Sku", "Sz"]
        } else {
            ["Ra", "Rsk", "Rku", "Rz"]
        };
        for (k, (name, got)) in r.heights().into_iter().enumerate() {
            assert_eq!(name, names[k]);
            let want = num(w[6 + k]);
            let scale = if k == 1 {
                want.abs().max(1.0)
            } else {
                want.abs()
            };
            let e = (got - want).abs() / scale;
            assert!(e < 1e-9, "{} {name}: {got} vs {want} ({e:.1e})", w[0]);
            worst_iso[k] = worst_iso[k].max(e);
        }
        n += 1;
    }
    assert_eq!(n, 8);
    eprintln!("Sq, Sdq, Rq, RΔq against SurfaceTopography: worst {worst:.1e}");
    eprintln!("Sa, Ssk, Sku, Sz (and R…): worst {worst_iso:?}");
}

#[test]
fn psd_tables_have_no_real_space_numbers() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let m = read(&data.join("psd_knee.txt"), &Options::default()).unwrap();
    assert!(m.real.is_none());
}
