//! The command line's values: what an option's text must be, parsed once
//! with the refusal clap prints (lengths and units, bands, `--set` pairs,
//! points, grids, sweeps, durations).

use clap::ValueEnum;
use rough_model::Axis;

use super::AxisArg;

/// `--pixel-size`: a length > 0.
pub(crate) fn parse_pixel_size(s: &str) -> Result<f64, String> {
    let v = crate::physical::value::parse_value(Axis::HRms, s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("\"{}\" is not a length > 0", s.trim()))
    }
}

/// `--height-unit`: a length unit.
pub(crate) fn parse_height_unit(s: &str) -> Result<rough_surface::HeightUnit, String> {
    rough_surface::HeightUnit::parse(s).ok_or_else(|| {
        format!(
            "\"{}\" is not a length unit: m, mm, µm (um), nm, Å (A) or pm",
            s.trim()
        )
    })
}

/// `--max-undefined PERCENT`: a percentage above 0 and below 100 (`35`,
/// `35%`, `35 %`).
pub(crate) fn parse_percent(s: &str) -> Result<f64, String> {
    let t = s.trim().trim_end_matches('%').trim_end();
    match t.parse::<f64>() {
        Ok(v) if v > 0.0 && v < 100.0 => Ok(v),
        _ => Err(format!(
            "\"{}\" is not a percentage above 0 and below 100 (e.g. 35)",
            s.trim()
        )),
    }
}

/// `--fit-band FROM:TO`: two wavevectors in 1/m, or two wavelengths with
/// a unit (q = 2π/λ), as (q_lo, q_hi).
pub fn parse_fit_band(s: &str) -> Result<(f64, f64), String> {
    let bad = || {
        format!(
            "\"{}\" is not a band: FROM:TO in 1/m (1e6:1e8) or as wavelengths (60nm:6um)",
            s.trim()
        )
    };
    let (a, b) = s.split_once(':').ok_or_else(bad)?;
    let q = |v: &str| -> Result<(f64, bool), String> {
        let v = v.trim();
        if v.ends_with(|c: char| c.is_alphabetic()) {
            let l = crate::physical::value::parse_value(Axis::HRms, v)?;
            Ok((std::f64::consts::TAU / l, true))
        } else {
            v.parse::<f64>().map(|q| (q, false)).map_err(|_| bad())
        }
    };
    let ((a, la), (b, lb)) = (q(a)?, q(b)?);
    if la != lb {
        return Err(format!(
            "\"{}\": both ends in 1/m or both as wavelengths with a unit",
            s.trim()
        ));
    }
    let (lo, hi) = (a.min(b), a.max(b));
    if !(lo > 0.0 && hi.is_finite() && hi > lo) {
        return Err(format!(
            "\"{}\": a band needs two different lengths > 0",
            s.trim()
        ));
    }
    Ok((lo, hi))
}

/// What `--set` (and a `KEY=VALUE` typed at the value prompt) sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetKey {
    /// A swept parameter.
    Param(Axis),
    /// The lower cutoff q0, 1/m.
    Q0,
    /// The longest wavelength L = 2π/q0.
    L,
    /// The elastic modulus: the composite E* alone, Young's E with `Nu`.
    E,
    /// The macroscopic hardness H0.
    H0,
    /// Poisson's ratio, which forms E* = E/(1 − ν²) from E.
    Nu,
}

impl SetKey {
    /// The name as `--set` takes it.
    pub fn name(self) -> &'static str {
        match self {
            SetKey::Param(a) => crate::figure::axis_arg(a),
            SetKey::Q0 => "q0",
            SetKey::L => "l",
            SetKey::E => "e",
            SetKey::H0 => "h0",
            SetKey::Nu => "nu",
        }
    }

    /// The key called `name` (any case).
    pub fn parse(name: &str) -> Result<SetKey, String> {
        let n = name.trim().to_lowercase();
        if let Some(a) = Axis::ALL
            .into_iter()
            .find(|a| crate::figure::axis_arg(*a) == n)
        {
            return Ok(SetKey::Param(a));
        }
        Ok(match n.as_str() {
            "q0" => SetKey::Q0,
            "l" => SetKey::L,
            "e" => SetKey::E,
            "h0" => SetKey::H0,
            "nu" => SetKey::Nu,
            _ => {
                return Err(format!(
                    "unknown parameter '{}': one of h0-over-e, h-rms, zeta, hurst, r-star, \
                     q0, l, e, h0, nu",
                    name.trim()
                ))
            }
        })
    }
}

/// `--set KEY=VALUE`: the key known and the value a number (with a unit
/// for lengths and pressures); whether it is in range is checked on the
/// scene.
pub fn parse_set(s: &str) -> Result<(SetKey, String), String> {
    let (key, value) = s
        .split_once('=')
        .ok_or("must be AXIS=VALUE, e.g. h0-over-e=0.001 or r-star=0.5mm")?;
    let key = SetKey::parse(key)?;
    match key {
        SetKey::Param(axis) => {
            crate::physical::value::parse_value(axis, value)?;
        }
        SetKey::Q0 => {
            crate::physical::parse_q0_number(value)?;
        }
        SetKey::L => {
            crate::physical::value::parse_value(Axis::HRms, value)?;
        }
        SetKey::E | SetKey::H0 => {
            crate::physical::parse_pressure(value)?;
        }
        SetKey::Nu => {
            value
                .trim()
                .parse::<f64>()
                .map_err(|_| format!("\"{}\" is not a number", value.trim()))?;
        }
    }
    Ok((key, value.trim().to_string()))
}

/// Most points an export computes along a curve.
pub const MAX_POINTS: usize = 10_000_000;

/// `--points`: one message for every bad value (0, -5, 1e9, abc).
pub(crate) fn parse_points(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if (2..=MAX_POINTS).contains(&n) => Ok(n),
        _ => Err(format!("must be a whole number from 2 to {MAX_POINTS}")),
    }
}

/// A whole number from `lo` to `hi`, or the refusal.
fn whole_in(s: &str, lo: u64, hi: u64) -> Result<u64, String> {
    match s.trim().parse::<u64>() {
        Ok(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => Err(format!("must be a whole number from {lo} to {hi}")),
    }
}

/// `--seeds N`: realisations to average, 1 … [`crate::contact::MAX_SEEDS`].
pub(crate) fn parse_seeds(s: &str) -> Result<u32, String> {
    whole_in(s, 1, u64::from(crate::contact::MAX_SEEDS)).map(|n| n as u32)
}

/// `--cell K`: longest wavelengths a side, 1 … [`crate::contact::sampling::MAX_CELL`].
pub(crate) fn parse_cell(s: &str) -> Result<u32, String> {
    whole_in(s, 1, u64::from(crate::contact::sampling::MAX_CELL)).map(|n| n as u32)
}

/// `--contact-grid N`: a power of two from 8 (the memory is checked when
/// the grid is built).
pub(crate) fn parse_contact_grid(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if n >= 8 && n.is_power_of_two() => Ok(n),
        _ => Err("must be a power of two, 8 or more (nodes a side: 256, 512, 1024, …)".into()),
    }
}

/// `--per-wavelength K`: nodes per shortest wavelength, 3 … 64 (more than
/// two hold the shortest wavelength).
pub(crate) fn parse_per_wavelength(s: &str) -> Result<u32, String> {
    whole_in(s, 3, 64).map(|n| n as u32)
}

/// `--grid COLSxROWS`, each side a whole number (checked against the map's
/// limits when the map is built).
pub(crate) fn parse_grid(s: &str) -> Result<(usize, usize), String> {
    let bad = || "must be COLSxROWS, two whole numbers such as 50x30".to_string();
    let (c, r) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    Ok((
        c.trim().parse().map_err(|_| bad())?,
        r.trim().parse().map_err(|_| bad())?,
    ))
}

/// `--sweep AXIS:FROM:TO`: the axis and both ends as typed, lengths with
/// a unit as the value prompt takes them (`h-rms:1nm:1um`; a bare number
/// in metres).
#[derive(Clone, Debug, PartialEq)]
pub struct SweepArg {
    pub axis: Axis,
    pub from: f64,
    pub to: f64,
    /// The ends as typed, for the refusal that names them.
    pub typed: [String; 2],
}

/// `--sweep AXIS:FROM:TO`; the range itself is checked against the axis's
/// domain when the sweep is built.
pub(crate) fn parse_sweep(s: &str) -> Result<SweepArg, String> {
    let names = || {
        AxisArg::value_variants()
            .iter()
            .filter_map(|v| v.to_possible_value().map(|p| p.get_name().to_string()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let parts: Vec<&str> = s.split(':').collect();
    let [axis, from, to] = parts[..] else {
        return Err("must be AXIS:FROM:TO, e.g. zeta:1:1e4".into());
    };
    let axis: Axis = AxisArg::from_str(axis.trim(), true)
        .map_err(|_| format!("unknown axis '{axis}': one of {}", names()))?
        .into();
    let end = |v: &str| {
        crate::physical::value::parse_value(axis, v)
            .map_err(|e| format!("{e} (AXIS:FROM:TO, e.g. zeta:1:1e4 or h-rms:1nm:1um)"))
    };
    Ok(SweepArg {
        axis,
        from: end(from)?,
        to: end(to)?,
        typed: [from.trim().to_string(), to.trim().to_string()],
    })
}

/// `90s`, `30m`, `2h` (1 s to 24 h).
pub fn parse_duration(s: &str) -> Result<std::time::Duration, String> {
    let bad = || format!("{s:?} is not a time like 90s, 30m or 2h");
    let t = s.trim();
    let (num, unit) = t.split_at(t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len()));
    let n: u64 = num.parse().map_err(|_| bad())?;
    let secs = match unit.trim() {
        "s" => n,
        "m" => n.saturating_mul(60),
        "h" => n.saturating_mul(3600),
        _ => return Err(bad()),
    };
    if !(1..=86_400).contains(&secs) {
        return Err(format!("{s:?} is outside 1s to 24h"));
    }
    Ok(std::time::Duration::from_secs(secs))
}
