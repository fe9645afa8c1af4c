//! Tests of the regime map (`figure::map`).

use super::*;

fn fig(name: &str) -> State {
    crate::presets::load(name).unwrap()
}

#[test]
fn grid_ends_and_axes() {
    let s = fig("fig2");
    let spec = MapSpec::of(&s, (5, 4), None).unwrap();
    assert_eq!(spec.y.axis(), Axis::H0OverE);
    assert_eq!(spec.x_at(0), 1.0);
    assert_eq!(spec.x_at(4), 1e4);
    assert_eq!(spec.x_at(2), 100.0);
    assert_eq!(spec.y_at(0), 1e-4);
    assert_eq!(spec.y_at(3), 1e-1);
    assert_eq!(spec.y_at(1), 1e-3);
    let (fx, fy) = spec.position();
    assert!((fx - 128f64.ln() / 1e4f64.ln()).abs() < 1e-15);
    assert!((fy - 2.0 / 3.0).abs() < 1e-15);
    assert_eq!(spec.next_y(), Axis::HRms);
}

#[test]
fn refuses_bad_grids_and_the_swept_axis() {
    let s = fig("fig2");
    for g in [(1, 5), (5, 1), (0, 0), (10_001, 2), (2000, 1001)] {
        let e = MapSpec::of(&s, g, None).unwrap_err();
        assert!(e.to_string().contains("out of range"), "{e}");
    }
    let e = MapSpec::of(&s, (5, 5), Some(Axis::Zeta)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "map y axis zeta is the swept parameter: choose another of \
         h0-over-e, h-rms, hurst, r-star"
    );
}

#[test]
fn cache_recomputes_only_when_the_map_changes() {
    let mut s = fig("fig2");
    let mut cache = MapCache::new();
    let spec = |s: &State| MapSpec::of(s, (20, 10), None).unwrap();
    let first = cache.get(&spec(&s)).clone();
    assert_eq!(cache.computes(), 1);
    // Moving the marker along either axis keeps the map.
    s.params = s.params.with(Axis::Zeta, 500.0).unwrap();
    s.params = s.params.with(Axis::H0OverE, 0.02).unwrap();
    let again = cache.get(&spec(&s));
    assert_eq!(again.share, first.share);
    assert_eq!(again.spec.base.zeta(), 500.0);
    assert_eq!(cache.computes(), 1);
    // What the map depends on recomputes it.
    s.size_effect = true;
    cache.get(&spec(&s));
    assert_eq!(cache.computes(), 2);
    s.params = s.params.with(Axis::HRms, 1e-7).unwrap();
    cache.get(&spec(&s));
    assert_eq!(cache.computes(), 3);
    s.model = s.model.other();
    cache.get(&spec(&s));
    assert_eq!(cache.computes(), 4);
}

#[test]
fn contour_lies_where_psi_crosses_one() {
    let s = fig("fig2");
    let m = RegimeMap::compute(&MapSpec::of(&s, (30, 20), None).unwrap());
    let mut on = 0;
    for row in 0..20 {
        for col in 0..30 {
            let (right, up) = m.contour_edges(col, row);
            let here = m.psi_at(col, row) >= 1.0;
            if right {
                assert_ne!(here, m.psi_at(col + 1, row) >= 1.0);
            }
            if up {
                assert_ne!(here, m.psi_at(col, row + 1) >= 1.0);
            }
            on += usize::from(m.on_contour(col, row));
        }
    }
    // ψ grows down the map (softer) and across (finer): one crossing per column.
    assert!(on >= 30, "{on}");
    for col in 0..30 {
        assert!(m.psi_at(col, 0) > 1.0 && m.psi_at(col, 19) < 1.0);
    }
}

#[test]
fn rows_shared_among_threads_give_the_same_map() {
    let s = fig("fig4");
    let spec = MapSpec::of(&s, (100, 61), None).unwrap();
    let whole = RegimeMap::compute(&spec);
    let n = 100 * 61;
    let mut one = vec![vec![0.0; n]; 5];
    if let [a, b, c, d, e] = one.as_mut_slice() {
        fill_rows(&spec, 0..61, scaled_psi(&spec).as_deref(), [a, b, c, d, e]);
    }
    assert_eq!(
        [
            &whole.psi,
            &whole.elastic,
            &whole.plastic,
            &whole.total,
            &whole.share
        ],
        [&one[0], &one[1], &one[2], &one[3], &one[4]]
    );
    assert_eq!(whole.share.len(), 6100);
}

#[test]
fn scaled_rows_agree_with_pointwise_values() {
    // Both models, both moment conventions, with and without the size
    // effect: H0/E up (rows scaled from row 0) and h_rms up (each row a
    // sweep of its own) against ψ and the slopes computed cell by cell,
    // under the scenes' own bound against pointwise values (1e-13).
    for (name, model, moments) in [
        ("fig2", Model::ClosedForm, Moments::Asymptotic),
        ("fig4", Model::ClosedForm, Moments::Asymptotic),
        ("fig2", Model::Exact, Moments::Truncated),
        ("fig4", Model::Exact, Moments::Truncated),
        ("measured", Model::Exact, Moments::Truncated),
        ("measured", Model::ClosedForm, Moments::Truncated),
    ] {
        let mut s = if name == "measured" {
            crate::scene::synthetic(32).unwrap()
        } else {
            fig(name)
        };
        s.model = model;
        s.moments = moments;
        // A measured surface fixes h_rms: R* up there.
        let other = if name == "measured" {
            Axis::RStar
        } else {
            Axis::HRms
        };
        for (y, scaled, bound) in [(None, true, 4.5e-16), (Some(other), false, 1e-13)] {
            let spec = MapSpec::of(&s, (120, 30), y).unwrap();
            assert_eq!(scaled_psi(&spec).is_some(), scaled);
            let m = RegimeMap::compute(&spec);
            let mut worst = [0.0f64; 4];
            for row in 0..spec.rows {
                let p = at(&spec.base, spec.y.axis(), spec.y_at(row));
                for col in 0..spec.cols {
                    let p = at(&p, spec.x.axis(), spec.x_at(col));
                    let psi = spec.roughness.psi_in_use(&p, s.size_effect, moments).0;
                    let sl = slopes(model, psi);
                    let k = m.index(col, row);
                    let got = [m.psi[k], m.elastic[k], m.plastic[k], m.total[k]];
                    let want = [psi.to_f64(), sl.elastic, sl.plastic, sl.total];
                    for i in 0..4 {
                        if got[i] != want[i] {
                            worst[i] = worst[i].max((got[i] / want[i] - 1.0).abs());
                        }
                    }
                }
            }
            let w = worst.iter().copied().fold(0.0, f64::max);
            assert!(w <= bound, "{name} {model:?} y {y:?}: {worst:?}");
        }
    }
}

#[test]
fn size_effect_shrinks_the_plastic_region() {
    let mut s = fig("fig2");
    let plastic = |s: &State| {
        let m = RegimeMap::compute(&MapSpec::of(s, (40, 20), None).unwrap());
        m.share.iter().filter(|&&v| v > 0.5).count()
    };
    let without = plastic(&s);
    s.size_effect = true;
    let with = plastic(&s);
    assert!(with < without, "{with} !< {without}");
    assert!(without > 0);
}
