//! `--detrend none|mean|plane|curvature` against SurfaceTopography 1.27.1's
//! detrend modes (none, `center`, `height`, `curvature`;
//! `scripts/detrend_reference.py`, committed in
//! tests/data/detrend_reference.txt): the rms height and slope, the height
//! range and the moments at two cutoffs of maps and lines, periodic and
//! not. A periodic surface refuses a tilt or curvature, a PSD table any
//! mode.

mod agree;
use agree::rel;

use std::path::{Path, PathBuf};

use rough_surface::{parse, read, Detrend, Options};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

#[test]
fn each_mode_matches_surfacetopography() {
    let text = std::fs::read_to_string(data().join("detrend_reference.txt")).unwrap();
    let (mut worst_r, mut worst_m) = (0f64, 0f64);
    let mut n = 0;
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |k: usize| w[k].parse::<f64>().unwrap();
        let mode = Detrend::parse(w[2]).unwrap();
        let opts = Options {
            periodic: w[1] == "1",
            detrend: Some(mode),
            ..Options::default()
        };
        let what = format!("{} {}", w[0], w[2]);
        let m = read(&data().join(w[0]), &opts).unwrap_or_else(|e| panic!("{what}: {e}"));
        let r = m.real.unwrap();
        for (got, want) in [
            (r.rms_height, num(3)),
            (r.rms_slope, num(4)),
            (r.amplitude.range, num(5)),
        ] {
            let e = rel(got, want);
            assert!(e < 1e-11, "{what}: {got} vs {want} ({e:.1e})");
            worst_r = worst_r.max(e);
        }
        for at in [6, 10] {
            let got = m.table.at_zeta(num(at));
            for (k, g) in [got.m0, got.m2, got.m4].into_iter().enumerate() {
                let want = num(at + 1 + k);
                let e = rel(g, want);
                assert!(e < 1e-10, "{what} ζ {}: m{} {g} vs {want}", num(at), 2 * k);
                worst_m = worst_m.max(e);
            }
        }
        // The summary says what was removed, and the flag that chose it.
        assert!(
            m.summary.contains(&format!("(--detrend {})", w[2])),
            "{}",
            m.summary
        );
        n += 1;
    }
    assert_eq!(n, 18);
    eprintln!(
        "--detrend against SurfaceTopography: rms height, slope, range {worst_r:.1e}, \
         moments {worst_m:.1e}"
    );
}

#[test]
fn what_a_mode_does_not_apply_to() {
    let opts = |periodic, mode| Options {
        periodic,
        detrend: Some(mode),
        ..Options::default()
    };
    let e = read(
        &data().join("map_periodic.txt"),
        &opts(true, Detrend::Plane),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "bad surface {}: --detrend plane removes a tilt, which would leave a periodic \
             surface no longer periodic: give --detrend mean or none with --periodic, or leave \
             out --periodic",
            data().join("map_periodic.txt").display()
        )
    );
    let e = read(&data().join("psd_knee.txt"), &opts(false, Detrend::Mean)).unwrap_err();
    assert!(
        e.to_string()
            .ends_with("--detrend mean does not apply to a PSD table: it holds no heights"),
        "{e}"
    );
    // A quadratic surface has nothing left after its curvature.
    let mut text = String::from("# Width: 4 um\n# Height: 3 um\n");
    for j in 0..6 {
        let row: Vec<String> = (0..8)
            .map(|i| format!("{}", 1.0 + 0.3 * (i * i) as f64 - 0.2 * (i * j) as f64))
            .collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    let e = parse(text.as_bytes(), &opts(false, Detrend::Curvature)).unwrap_err();
    assert_eq!(
        e.1.to_string(),
        "the surface is flat: nothing is left after removing its curvature \
         (--detrend curvature; the heights lie on a quadratic)"
    );
    // The plane leaves it; the note says what another mode removed.
    let m = parse(text.as_bytes(), &opts(false, Detrend::Plane)).unwrap();
    assert!(
        m.notes.iter().all(|n| !n.contains("--detrend")),
        "{:?}",
        m.notes
    );
    let m = parse(text.as_bytes(), &opts(false, Detrend::None)).unwrap();
    assert!(
        m.notes.contains(
            &"nothing removed before the spectrum and Sq (--detrend none; the default \
              removes the plane)"
                .to_string()
        ),
        "{:?}",
        m.notes
    );
}
