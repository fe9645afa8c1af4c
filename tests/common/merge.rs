//! Two CSVs of an ensemble compared: one machine's and the merge of its
//! parts.

/// The largest relative difference between two CSVs' numbers (in the `#`
/// lines and the rows), their words the same.
pub fn difference(one: &str, merged: &str) -> f64 {
    let (a, b): (Vec<&str>, Vec<&str>) = (one.lines().collect(), merged.lines().collect());
    assert_eq!(a.len(), b.len(), "lines:\n{one}\n---\n{merged}");
    let mut worst = 0f64;
    for (x, y) in a.iter().zip(&b) {
        let split = |l: &str| -> Vec<String> {
            l.split([',', ' ', '(', ')', ';'])
                .map(str::to_string)
                .collect()
        };
        let (p, q) = (split(x), split(y));
        assert_eq!(p.len(), q.len(), "\n{x}\n{y}");
        for (u, v) in p.iter().zip(&q) {
            match (u.parse::<f64>(), v.parse::<f64>()) {
                (Ok(u), Ok(v)) if u.is_nan() || v.is_nan() => {
                    assert!(u.is_nan() && v.is_nan(), "\n{x}\n{y}")
                }
                (Ok(u), Ok(v)) => {
                    worst = worst.max((u - v).abs() / u.abs().max(v.abs()).max(1e-300))
                }
                _ => assert_eq!(u, v, "\n{x}\n{y}"),
            }
        }
    }
    worst
}
