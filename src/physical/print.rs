//! Number and name formatting for the explorer's panels and charts: one
//! formatter per kind of value, shared by every view.

use rough_model::{Axis, Regime};

/// Three significant digits; scientific outside 1e-3 … 1e5.
pub fn fmt_num(v: f64) -> String {
    if v.is_nan() {
        return "—".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "∞".into() } else { "-∞".into() };
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e5).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.2e}")
    }
}

fn length_unit(m: f64) -> (f64, &'static str) {
    let a = m.abs();
    if a < 1e-6 {
        (1e9, "nm")
    } else if a < 1e-3 {
        (1e6, "µm")
    } else if a < 1.0 {
        (1e3, "mm")
    } else {
        (1.0, "m")
    }
}

/// A length in m with a readable unit: "20.0 nm", "19.7 µm", "1.00 mm".
pub fn fmt_len(m: f64) -> String {
    if !m.is_finite() || m == 0.0 {
        return format!("{} m", fmt_num(m));
    }
    let (k, u) = length_unit(m);
    format!("{} {u}", fmt_num(m * k))
}

fn is_whole(v: f64) -> bool {
    (v - v.round()).abs() < 1e-9 * v.abs().max(1.0)
}

/// A short form for range ends and axis labels: "1 nm", "10 mm", "1e-4", "0.05".
pub fn fmt_short(axis: Axis, v: f64) -> String {
    if matches!(axis, Axis::HRms | Axis::RStar) && v.is_finite() && v > 0.0 {
        let (k, u) = length_unit(v);
        let s = v * k;
        return if is_whole(s) {
            format!("{} {u}", s.round())
        } else {
            format!("{} {u}", fmt_num(s))
        };
    }
    let d = v.log10();
    if v > 0.0 && is_whole(d) && axis.is_log() {
        return fmt_decade(d.round() as i32);
    }
    if is_whole(v) {
        return format!("{}", v.round());
    }
    let s = format!("{v}");
    if s.len() <= 5 {
        s
    } else {
        fmt_num(v)
    }
}

/// A decade label: 0.01, 0.1, 1, 10, 100, else 1e-3, 1e3 ….
pub fn fmt_decade(d: i32) -> String {
    match d {
        -2 => "0.01".into(),
        -1 => "0.1".into(),
        0 => "1".into(),
        1 => "10".into(),
        2 => "100".into(),
        _ => format!("1e{d}"),
    }
}

/// The parameter's value with its unit.
pub fn fmt_param(axis: Axis, v: f64) -> String {
    match axis {
        Axis::HRms | Axis::RStar => fmt_len(v),
        _ => fmt_num(v),
    }
}

/// A plastic share in per cent with as many decimals as it takes for the
/// shown number to fall in the same regime as the true one: 9.996 % shows
/// as "9.996%", not as "10.0%" next to the word "elastic".
pub fn fmt_share(share: f64) -> String {
    let regime = Regime::of_share(share);
    let pct = share * 100.0;
    for decimals in 1..=6 {
        let shown = format!("{pct:.decimals$}");
        if shown
            .parse::<f64>()
            .is_ok_and(|v| Regime::of_share(v / 100.0) == regime)
        {
            return format!("{shown}%");
        }
    }
    match regime {
        Regime::Elastic => "< 10%".into(),
        Regime::Plastic => "> 90%".into(),
        Regime::ElastoPlastic => format!("{pct}%"),
    }
}

/// How far `other` lies from `this`, in per cent or as a ratio.
pub fn fmt_rel(other: f64, this: f64) -> String {
    if other == this {
        return "±0%".into();
    }
    if !(this.is_finite() && other.is_finite()) || this == 0.0 {
        return "n/a".into();
    }
    let d = other / this - 1.0;
    if d.abs() < 10.0 {
        format!("{:+.1}%", d * 100.0)
    } else {
        format!("×{}", fmt_num(other / this))
    }
}

/// The load p̄/H as the readout writes it: four significant digits,
/// trailing zeros dropped (0.01778, 0.01, 1).
pub fn load_text(v: f64) -> String {
    let decimals = (3 - v.log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}
