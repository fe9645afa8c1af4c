//! Anisotropy is never averaged silently: a map's rms slopes along x and
//! along y, from its spectrum to the largest ζ (Σ q_x² w and Σ q_y² w over
//! the wavevectors of the windowed FFT, the two halves of the isotropic
//! m2), and a note where their ratio passes [`RATIO`], with the plasticity
//! index Ψ_P of the profiles across and along the lay at the paper's
//! H0/E = 0.01 (the scene a surface opens on). `--direction x|y` then
//! reads the map as its profiles along one direction.

/// The ratio of the rms slopes along x and y above which a map is called
/// anisotropic.
pub const RATIO: f64 = 1.5;

/// H0/E of the note's Ψ_P (a measured surface's scene starts there).
const H0_OVER_E: f64 = 0.01;

/// A map's rms slopes along x and along y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slopes {
    pub x: f64,
    pub y: f64,
}

impl Slopes {
    /// h′x / h′y.
    pub fn ratio(&self) -> f64 {
        self.x / self.y
    }

    /// Whether the ratio, either way, passes [`RATIO`].
    pub fn anisotropic(&self) -> bool {
        let r = self.ratio();
        !(1.0 / RATIO..=RATIO).contains(&r)
    }

    /// Ψ_P of the profiles along x and along y: (E/H0) √(m2/2) with m2
    /// the mean-square slope of those profiles (docs/model.md, eq. 11).
    pub fn psi_p(&self) -> (f64, f64) {
        let psi = |s: f64| s / std::f64::consts::SQRT_2 / H0_OVER_E;
        (psi(self.x), psi(self.y))
    }

    /// "anisotropic: h′x/h′y = 3.4; Ψ_P across the lay (profiles along x)
    /// 11.3, along it (along y) 0.73 at H0/E = 0.01; --direction x|y reads
    /// one direction", or `None` for a map within [`RATIO`].
    pub fn note(&self) -> Option<String> {
        if !self.anisotropic() {
            return None;
        }
        let (px, py) = self.psi_p();
        let (across, along) = if self.x >= self.y {
            (("x", px), ("y", py))
        } else {
            (("y", py), ("x", px))
        };
        Some(format!(
            "anisotropic: h′x/h′y = {}; Ψ_P across the lay (profiles along {}) {}, \
             along it ({}) {} at H0/E = 0.01 and the largest ζ; --direction x|y reads \
             the profiles along one direction",
            sig(self.ratio()),
            across.0,
            sig(across.1),
            along.0,
            sig(along.1)
        ))
    }
}

/// Two significant digits, three from 1 to 100 ("3.4", "0.73", "11.3").
fn sig(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let digits = if (1.0..100.0).contains(&v.abs()) {
        3
    } else {
        2
    };
    if v == 0.0 {
        return "0".into();
    }
    let e = v.abs().log10().floor() as i32;
    if !(-6..=15).contains(&e) {
        // Far from 1 (a flat or degenerate map's ratio): scientific.
        return format!("{v:.1e}");
    }
    let decimals = (digits - 1 - e).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') && v.abs() >= 1.0 {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_for_people() {
        assert_eq!(sig(3.4), "3.4");
        // A mutated file's flat map: a zero or vanishing spread, no panic.
        assert_eq!(sig(0.0), "0");
        assert_eq!(sig(-0.0), "0");
        assert_eq!(sig(1e-300), "1.0e-300");
        assert_eq!(sig(f64::MIN_POSITIVE / 4.0), "5.6e-309");
        assert_eq!(sig(0.7312), "0.73");
        assert_eq!(sig(11.31), "11.3");
        assert_eq!(sig(250.4), "250");
        let s = Slopes { x: 0.16, y: 0.0103 };
        assert!(s.anisotropic());
        let n = s.note().unwrap();
        assert!(n.starts_with("anisotropic: h′x/h′y = 15.5; Ψ_P across the lay (profiles along x) 11.3, along it (y) 0.73"), "{n}");
        assert_eq!(Slopes { x: 1.0, y: 1.4 }.note(), None);
        let n = Slopes { x: 1.0, y: 2.0 }.note().unwrap();
        assert!(
            n.contains("h′x/h′y = 0.50; Ψ_P across the lay (profiles along y)"),
            "{n}"
        );
    }
}
