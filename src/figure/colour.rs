//! The regime map's scale: plastic share S_pl/S_tot in [0, 1] as a colour
//! (sequential, viridis-like: dark violet elastic → yellow plastic, readable
//! in grey and by most colour-blind readers) or, under NO_COLOR, a character.

/// Viridis at shares 0, ¼, ½, ¾, 1 (sRGB), interpolated linearly between.
const STOPS: [(u8, u8, u8); 5] = [
    (68, 1, 84),
    (59, 82, 139),
    (33, 145, 140),
    (94, 201, 98),
    (253, 231, 37),
];

/// The colour of plastic share `share` (clamped to [0, 1]; NaN as 0).
pub fn share_colour(share: f64) -> (u8, u8, u8) {
    let s = if share.is_nan() {
        0.0
    } else {
        share.clamp(0.0, 1.0)
    };
    let t = s * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: u8, y: u8| (f64::from(x) + (f64::from(y) - f64::from(x)) * f).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The NO_COLOR ramp, from elastic (blank) to plastic (`@`), densest last.
pub const RAMP: [char; 10] = [' ', '.', ':', '-', '=', '+', '*', '#', '%', '@'];

/// The ramp character of plastic share `share`: ten equal bands of [0, 1].
pub fn share_char(share: f64) -> char {
    let s = if share.is_nan() {
        0.0
    } else {
        share.clamp(0.0, 1.0)
    };
    RAMP[((s * RAMP.len() as f64) as usize).min(RAMP.len() - 1)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_runs_from_violet_to_yellow_and_gets_lighter() {
        assert_eq!(share_colour(0.0), (68, 1, 84));
        assert_eq!(share_colour(1.0), (253, 231, 37));
        assert_eq!(share_colour(0.5), (33, 145, 140));
        assert_eq!(share_colour(-3.0), share_colour(0.0));
        assert_eq!(share_colour(f64::NAN), share_colour(0.0));
        let luma = |(r, g, b): (u8, u8, u8)| {
            0.2126 * f64::from(r) + 0.7152 * f64::from(g) + 0.0722 * f64::from(b)
        };
        let mut last = -1.0;
        for k in 0..=100 {
            let l = luma(share_colour(k as f64 / 100.0));
            assert!(l > last, "lightness falls at share {k}%");
            last = l;
        }
    }

    #[test]
    fn ramp_bands() {
        assert_eq!(share_char(0.0), ' ');
        assert_eq!(share_char(0.0999), ' ');
        assert_eq!(share_char(0.1), '.');
        assert_eq!(share_char(0.95), '@');
        assert_eq!(share_char(1.0), '@');
        assert_eq!(share_char(f64::NAN), ' ');
    }
}
