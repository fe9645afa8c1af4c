//! Moving fields between a grid and one twice as fine (same periodic cell):
//! a coarse grid's solution is the fine grid's starting point.

/// The n/2 × n/2 field of every other node of an n × n field (injection;
/// exact for a surface whose modes lie below the coarse grid's Nyquist
/// wavenumber).
pub fn restrict(f: &[f64], n: usize) -> Vec<f64> {
    let m = n / 2;
    let mut out = Vec::with_capacity(m * m);
    for y in 0..m {
        let row = &f[2 * y * n..2 * y * n + n];
        out.extend(row.iter().step_by(2));
    }
    out
}

/// The 2n × 2n field bilinearly interpolated from the n × n periodic field
/// `f` (the coarse nodes are the fine grid's even nodes).
pub fn prolong(f: &[f64], n: usize) -> Vec<f64> {
    let m = 2 * n;
    let mut out = vec![0.0; m * m];
    for y in 0..n {
        let y1 = (y + 1) % n;
        let (a, b) = (&f[y * n..(y + 1) * n], &f[y1 * n..(y1 + 1) * n]);
        let (even, rest) = out[2 * y * m..].split_at_mut(m);
        let odd = &mut rest[..m];
        for x in 0..n {
            let x1 = (x + 1) % n;
            even[2 * x] = a[x];
            even[2 * x + 1] = 0.5 * (a[x] + a[x1]);
            odd[2 * x] = 0.5 * (a[x] + b[x]);
            odd[2 * x + 1] = 0.25 * (a[x] + a[x1] + b[x] + b[x1]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prolong_then_restrict_is_the_identity() {
        let n = 8;
        let f: Vec<f64> = (0..n * n).map(|i| ((i * 7 % 13) as f64).sin()).collect();
        assert_eq!(restrict(&prolong(&f, n), 2 * n), f);
    }

    #[test]
    fn prolong_is_exact_for_a_periodic_plane_in_each_row_pair() {
        // A field linear between neighbours is reproduced midway.
        let n = 4;
        let f: Vec<f64> = (0..n * n).map(|i| (i % n) as f64).collect();
        let g = prolong(&f, n);
        assert_eq!(g[1], 0.5);
        assert_eq!(g[2 * n + 3], 1.5);
    }
}
