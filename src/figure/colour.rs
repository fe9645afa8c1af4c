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

/// The 16-colour scale, as ANSI colour numbers, and the shares where each
/// band starts: blue below 10 % (elastic), bright blue, cyan, bright green,
/// bright yellow from 90 % (plastic), the elasto-plastic range in three
/// equal bands. The same path as viridis (blue, teal, green, yellow), and
/// lighter with every band in xterm's, Windows' and the VGA palette
/// (yellow, 3, is brown on VGA and the Linux console, so it is left out).
pub const ANSI16_SCALE: [(f64, u8); 5] = [
    (0.0, 4),
    (0.1, 12),
    (0.1 + 0.8 / 3.0, 6),
    (0.1 + 1.6 / 3.0, 10),
    (0.9, 11),
];

/// The ANSI colour number (0–15) of plastic share `share` on the
/// 16-colour scale (clamped to [0, 1]; NaN as 0).
pub fn share_ansi16(share: f64) -> u8 {
    let s = if share.is_nan() { 0.0 } else { share };
    ANSI16_SCALE
        .iter()
        .rev()
        .find(|(from, _)| s >= *from)
        .map_or(ANSI16_SCALE[0].1, |b| b.1)
}

/// The 256-colour scale: 16 equal bands of the share, each the colour of
/// xterm's 6×6×6 cube (16 + 36r + 6g + b) nearest to the 24-bit scale at
/// the band's middle among those no darker than the band before, so that
/// it still gets lighter with the share (the cube's nearest colours alone
/// do not).
pub const ANSI256_SCALE: [u8; 16] = [
    53, 53, 60, 60, 60, 60, 30, 30, 30, 72, 72, 77, 77, 113, 149, 184,
];

/// The xterm colour number (16–231) of plastic share `share` on the
/// 256-colour scale (clamped to [0, 1]; NaN as 0).
pub fn share_ansi256(share: f64) -> u8 {
    let s = if share.is_nan() {
        0.0
    } else {
        share.clamp(0.0, 1.0)
    };
    let n = ANSI256_SCALE.len();
    ANSI256_SCALE[((s * n as f64) as usize).min(n - 1)]
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

    /// The relative luminance of an sRGB colour (WCAG's formula).
    fn luminance((r, g, b): (u8, u8, u8)) -> f64 {
        let lin = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b)
    }

    /// The 16 colours as xterm, Windows' console (Campbell) and the VGA
    /// (Linux console) draw them.
    const PALETTES: [[(u8, u8, u8); 16]; 3] = [
        [
            (0, 0, 0),
            (205, 0, 0),
            (0, 205, 0),
            (205, 205, 0),
            (0, 0, 238),
            (205, 0, 205),
            (0, 205, 205),
            (229, 229, 229),
            (127, 127, 127),
            (255, 0, 0),
            (0, 255, 0),
            (255, 255, 0),
            (92, 92, 255),
            (255, 0, 255),
            (0, 255, 255),
            (255, 255, 255),
        ],
        [
            (12, 12, 12),
            (197, 15, 31),
            (19, 161, 14),
            (193, 156, 0),
            (0, 55, 218),
            (136, 23, 152),
            (58, 150, 221),
            (204, 204, 204),
            (118, 118, 118),
            (231, 72, 86),
            (22, 198, 12),
            (249, 241, 165),
            (59, 120, 255),
            (180, 0, 158),
            (97, 214, 214),
            (242, 242, 242),
        ],
        [
            (0, 0, 0),
            (170, 0, 0),
            (0, 170, 0),
            (170, 85, 0),
            (0, 0, 170),
            (170, 0, 170),
            (0, 170, 170),
            (170, 170, 170),
            (85, 85, 85),
            (255, 85, 85),
            (85, 255, 85),
            (255, 255, 85),
            (85, 85, 255),
            (255, 85, 255),
            (85, 255, 255),
            (255, 255, 255),
        ],
    ];

    #[test]
    fn the_16_colour_scale_gets_lighter_with_the_share_and_marks_the_regimes() {
        assert_eq!(share_ansi16(0.0), 4);
        assert_eq!(share_ansi16(0.0999), 4);
        assert_eq!(share_ansi16(0.1), 12);
        assert_eq!(share_ansi16(0.5), 6);
        assert_eq!(share_ansi16(0.8999), 10);
        assert_eq!(share_ansi16(0.9), 11);
        assert_eq!(share_ansi16(1.0), 11);
        assert_eq!(share_ansi16(-1.0), 4);
        assert_eq!(share_ansi16(f64::NAN), 4);
        for (p, palette) in PALETTES.iter().enumerate() {
            let mut last = -1.0;
            let mut bands = 0;
            for k in 0..=1000 {
                let l = luminance(palette[usize::from(share_ansi16(k as f64 / 1000.0))]);
                assert!(l >= last, "palette {p}: darker at share {k}‰");
                if l > last {
                    bands += 1;
                }
                last = l;
            }
            assert_eq!(bands, 5, "palette {p}");
        }
    }

    #[test]
    fn the_256_colour_scale_follows_the_24_bit_one() {
        // The cube's colours, as xterm draws them.
        let rgb = |n: u8| -> (u8, u8, u8) {
            const LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];
            let i = usize::from(n - 16);
            (LEVELS[i / 36], LEVELS[i / 6 % 6], LEVELS[i % 6])
        };
        assert_eq!(rgb(184), (215, 215, 0));
        assert_eq!(share_ansi256(0.0), 53);
        assert_eq!(share_ansi256(1.0), 184);
        assert_eq!(share_ansi256(f64::NAN), 53);
        let mut last = -1.0;
        for k in 0..=1000 {
            let s = k as f64 / 1000.0;
            let l = luminance(rgb(share_ansi256(s)));
            assert!(l >= last, "darker at share {k}‰");
            last = l;
        }
        // Each band within half the cube's widest step (0 to 95) of the
        // 24-bit scale at its middle, in every channel.
        let n = ANSI256_SCALE.len();
        for (k, &c) in ANSI256_SCALE.iter().enumerate() {
            let want = share_colour((k as f64 + 0.5) / n as f64);
            let got = rgb(c);
            for (a, b) in [(want.0, got.0), (want.1, got.1), (want.2, got.2)] {
                assert!(a.abs_diff(b) <= 48, "band {k}: {want:?} as {got:?}");
            }
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
