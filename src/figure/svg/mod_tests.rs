//! The SVG pictures' unit tests: legends, ticks, wrapping.

use super::wrap::wrap;

#[test]
fn legend_says_where_a_curve_hides() {
    use super::*;
    let svg = |name: &str| {
        let s = crate::presets::load(name).unwrap();
        render_svg(View::Slopes, &s, &FigureOptions::default()).unwrap()
    };
    let fig3 = svg("fig3");
    assert!(fig3.contains("elastic (= total here)"));
    // Below the chart, so not drawn: not listed either.
    assert!(!fig3.contains(">\nplastic"));
    let fig2 = svg("fig2");
    assert!(!fig2.contains("= total here") && !fig2.contains("below the chart"));
}

#[test]
fn one_tick_style_per_axis() {
    use super::{power_of_ten, Scale};
    assert_eq!(power_of_ten(-4), "10⁻⁴");
    assert_eq!(power_of_ten(0), "10⁰");
    assert_eq!(power_of_ten(12), "10¹²");
    let s = |lo: f64, hi: f64| Scale {
        log: true,
        lo,
        hi,
        desc: String::new(),
    };
    let plain = s(0.01, 1000.0);
    let labels: Vec<String> = (-2..=3).map(|k| plain.label(f64::from(k))).collect();
    assert_eq!(labels, ["0.01", "0.1", "1", "10", "100", "1000"]);
    let wide = s(1e-4, 10.0);
    let labels: Vec<String> = (-4..=1).map(|k| wide.label(f64::from(k))).collect();
    assert_eq!(labels, ["10⁻⁴", "10⁻³", "10⁻²", "10⁻¹", "10⁰", "10¹"]);
    assert_eq!(wide.label(0.5), "");
}

#[test]
fn wrap_breaks_at_spaces() {
    assert_eq!(wrap("aa bb cc", 5), ["aa bb", "cc"]);
    assert_eq!(wrap("", 5), Vec::<String>::new());
    assert_eq!(wrap("longword x", 3), ["longword", "x"]);
}
