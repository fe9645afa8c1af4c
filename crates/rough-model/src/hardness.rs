//! The size-dependent hardness law of Swadener, George and Pharr.

/// H_y/H0 = √(1 + R*/R_p) with R_p = 1.2 R_s (dimensionless).
///
/// `r_star` and `r_s` in metres, `r_star` ≥ 0, `r_s` > 0 or ∞. Equal to 1 when
/// R* = 0 or R_s = ∞ (ζ = 1). Accurate to 2 ulp.
pub fn hardness_ratio(r_star: f64, r_s: f64) -> f64 {
    if r_star == 0.0 || r_s == f64::INFINITY {
        return 1.0;
    }
    (1.0 + r_star / (1.2 * r_s)).sqrt()
}
