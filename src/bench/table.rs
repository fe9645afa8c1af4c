//! The table of `roughtui bench` and how its numbers are printed.

use std::fmt::Write as _;

use rough_study::compare::ErrorStat;

/// The table's header, fixed by the command's contract.
pub const HEADER: &str = "| method | terms | ns/point | max rel error | worst psi |";

/// One measured row of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub name: String,
    pub terms: String,
    pub ns_per_point: f64,
    pub err: ErrorStat,
}

/// Errors print like `3.2e-15`; ∞ as `inf`, exact as `0`.
pub fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e.is_infinite() {
        "inf".into()
    } else {
        format!("{e:.1e}")
    }
}

/// ψ with four significant digits: plain between 1e-3 and 1e4, else `1.5e-8`.
pub fn fmt_psi(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.digits$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        let t = format!("{v:.3e}");
        let (m, e) = t.split_once('e').unwrap_or((&t, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        format!("{m}e{e}")
    }
}

/// A range of ψ from [`rough_study::compare::accurate_range`] as text.
pub fn fmt_range(range: Option<(f64, f64, bool)>) -> String {
    match range {
        None => "nowhere".into(),
        Some((a, b, all)) => format!(
            "ψ from {} to {}{}",
            fmt_psi(a),
            fmt_psi(b),
            if all { " (all ψ > 0)" } else { "" }
        ),
    }
}

/// The markdown table of `rows`.
pub fn render_table(rows: &[Row]) -> String {
    let mut s = String::new();
    s.push_str(HEADER);
    s.push('\n');
    s.push_str("|---|---|---:|---:|---:|\n");
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.1} | {} | {} |",
            r.name,
            r.terms,
            r.ns_per_point,
            fmt_err(r.err.max),
            fmt_psi(r.err.worst_psi)
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use rough_study::compare::methods;

    #[test]
    fn psi_format() {
        assert_eq!(fmt_psi(0.55), "0.55");
        assert_eq!(fmt_psi(12.090201005025126), "12.09");
        assert_eq!(fmt_psi(1.998), "1.998");
        assert_eq!(fmt_psi(1e-308), "1e-308");
        assert_eq!(fmt_psi(1.7976931348623157e308), "1.798e308");
        assert_eq!(fmt_psi(2.6023616895101482e-2), "0.02602");
        assert_eq!(fmt_psi(0.0), "0");
        assert_eq!(fmt_err(3.2e-15), "3.2e-15");
        assert_eq!(fmt_range(None), "nowhere");
        assert_eq!(
            fmt_range(Some((1e-308, 0.2576, false))),
            "ψ from 1e-308 to 0.2576"
        );
    }

    #[test]
    fn table_has_exact_header_and_every_row() {
        let rows: Vec<Row> = methods()
            .iter()
            .map(|m| Row {
                name: m.name.into(),
                terms: m.terms.clone(),
                ns_per_point: 12.3,
                err: ErrorStat {
                    max: 3.2e-15,
                    worst_psi: 1.0,
                },
            })
            .collect();
        let t = render_table(&rows);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines[0], HEADER);
        assert_eq!(lines.len(), 2 + rows.len());
        for need in ["shipped", "image 1 ", "image 2 ", "image 4 ", "image 8 "] {
            assert!(t.contains(need), "{need}");
        }
        assert!(t.contains("image 64"));
        assert!(t.contains("fourier 8") && t.contains("fourier 64"));
        assert!(t.contains("naive") && t.contains("model error"));
        assert!(t.contains("finite"));
        assert!(lines[2].contains("| 3.2e-15 |"), "{}", lines[2]);
        for l in &lines[2..] {
            assert_eq!(l.matches('|').count(), 6, "{l}");
        }
    }
}
