//! A measured surface as a scene: the file it came from, how it was read,
//! what it holds, and the scene a surface opens on.
//!
//! Reading, detrending, windowing and the FFT are `rough_surface`'s; the
//! model sees only the moment table ([`rough_model::Roughness::Measured`]).
//! Here: the file's identity (absolute path, SHA-256, reading options), the
//! scene a new surface starts with, and the least-squares power law over the
//! band on screen, read in the paper's convention for display and for the
//! fitted ghost.

use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

use rough_model::{Dim, ParamValues};
use rough_surface::{Kind, Measured, Options, PowerLawFit, SurfaceError};

/// A measured surface, read from a file.
#[derive(Clone, Debug)]
pub struct SurfaceSource {
    /// The file, absolute and canonical (links resolved).
    pub path: PathBuf,
    /// How it was read (`--periodic`, `--pixel-size`).
    pub options: Options,
    pub measured: Arc<Measured>,
    /// When loaded from a snapshot that recorded another SHA-256: that one
    /// (the file changed since the snapshot was saved).
    pub recorded_sha256: Option<String>,
    /// The Hurst fit band set by hand (`--fit-band`, the spectrum view's
    /// keys), 1/m; `None`: the self-affine stretch found from the data.
    pub fit_band: Option<(f64, f64)>,
}

/// Two sources are the same surface when they are the same file, read the
/// same way, with the same content (the table compares in O(1)), fitted
/// over the same band.
impl PartialEq for SurfaceSource {
    fn eq(&self, other: &SurfaceSource) -> bool {
        self.path == other.path
            && self.options == other.options
            && self.fit_band == other.fit_band
            && self.measured.sha256 == other.measured.sha256
            && self.measured.table == other.measured.table
    }
}

/// The file made absolute against the current directory (not resolving
/// links, so that the path recorded is the one the user gave).
pub fn absolute(path: &Path) -> PathBuf {
    let joined = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir()
            .map(|d| d.join(path))
            .unwrap_or_else(|_| path.to_path_buf())
    };
    // Components drop the "." of "./steel.txt".
    joined.components().collect()
}

impl SurfaceSource {
    /// Reads the surface in `path` (one message naming file, line and
    /// problem when refused).
    pub fn read(path: &Path, options: Options) -> Result<SurfaceSource, SurfaceError> {
        let measured = rough_surface::read(path, &options)?;
        Ok(SurfaceSource {
            // The file was just read: its canonical path exists, and the
            // same file reached two ways compares equal.
            path: std::fs::canonicalize(path).unwrap_or_else(|_| absolute(path)),
            options,
            measured: Arc::new(measured),
            recorded_sha256: None,
            fit_band: None,
        })
    }

    /// The file's name without its extension, printable: the scene's name
    /// (which the scene cuts to its length).
    pub fn stem(&self) -> String {
        let stem = self
            .path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "surface".into());
        printable(&stem, usize::MAX)
    }

    /// The file's name, printable.
    pub fn file_name(&self) -> String {
        let name = self
            .path
            .file_name()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        printable(&name, 80)
    }

    /// The lower cutoff q0 of the data, 1/m.
    pub fn q0(&self) -> f64 {
        self.measured.table.q0()
    }

    /// The largest magnification the data allows.
    pub fn zeta_max(&self) -> f64 {
        self.measured.table.zeta_max()
    }

    pub fn dim(&self) -> Dim {
        self.measured.kind.dim()
    }

    /// The Hurst fit band, 1/m: the one set by hand, else the self-affine
    /// stretch found from the data (`None` when none was found).
    pub fn fit_band(&self) -> Option<(f64, f64)> {
        self.fit_band.or(self.measured.band)
    }

    /// The least-squares power law through the spectrum over the fit band
    /// (`None` with fewer than two points in it).
    pub fn fit(&self) -> Option<PowerLawFit> {
        let (lo, hi) = self.fit_band()?;
        // The band's ends are data points: an end a rounding below one
        // still takes it.
        self.measured.fit(lo * (1.0 - 1e-12), hi * (1.0 + 1e-12))
    }

    /// The notes of the surface as read (units, repairs, warnings).
    pub fn notes(&self) -> &[String] {
        &self.measured.notes
    }

    /// What the file held, in words: "a 512 × 512 map of 10 µm × 10 µm".
    pub fn describe(&self) -> String {
        use crate::physical::print::fmt_len;
        match self.measured.kind {
            Kind::Map { nx, ny, lx, ly } => {
                format!("a {nx} × {ny} map of {} × {}", fmt_len(lx), fmt_len(ly))
            }
            Kind::Line { n, l } => format!("a line scan of {n} points over {}", fmt_len(l)),
            Kind::Profiles {
                direction,
                nx,
                ny,
                lx,
                ly,
            } => format!(
                "the profiles along {} of a {nx} × {ny} map of {} × {}",
                direction.name(),
                fmt_len(lx),
                fmt_len(ly)
            ),
            Kind::Psd { dim, points } => format!(
                "{} PSD table of {points} points{}",
                match dim {
                    Dim::Areal => "an isotropic",
                    Dim::Profile => "a profile",
                },
                match &self.measured.measurement {
                    Some(m) => format!(" (measurement '{m}')"),
                    None => String::new(),
                }
            ),
        }
    }
}

/// The paper's amplitude of a fitted power law: Z (m^(2−2H)) of
/// C_Persson = Z q^(−2(1+H)) and the h_rms of that spectrum from q0 to
/// infinity, √(π Z q0^(−2H)/H) (`PowerLawFit::persson_z`: areal C^iso is
/// (2π)² C_Persson; a profile C1D is read as the profile of an isotropic
/// surface). `None` unless 0 < H ≤ 1 (the power law's domain).
pub fn fit_amplitude(fit: &PowerLawFit) -> Option<(f64, f64)> {
    if !(fit.hurst > 0.0 && fit.hurst <= 1.0) {
        return None;
    }
    let (z, h_rms) = (fit.persson_z()?, fit.h_rms()?);
    (h_rms > 0.0).then_some((z, h_rms))
}

/// The values a measured state holds for the parameters the data fixes:
/// h_rms = √m0 of the whole data, H of the fit over the fit band (kept
/// inside (0, 1]), q0 of the data. Written into snapshots for reference;
/// recomputed from the file when one is loaded.
pub fn fixed_values(src: &SurfaceSource, mut v: ParamValues) -> ParamValues {
    let t = &src.measured.table;
    v.q0 = t.q0();
    let m0 = t.at_zeta(t.zeta_max()).m0;
    v.h_rms = if m0 > 0.0 && m0.is_finite() {
        m0.sqrt()
    } else {
        v.h_rms
    };
    let hu = src.fit().map_or(0.8, |f| f.hurst);
    v.hurst = if hu.is_finite() {
        hu.clamp(0.01, 1.0)
    } else {
        0.8
    };
    v
}

/// `path` relative to the folder `base` where both are absolute and share
/// a root ("../data/steel.txt"); else `path` itself.
pub fn relative_to(path: &Path, base: &Path) -> PathBuf {
    let base = absolute(base);
    let base = base.canonicalize().unwrap_or(base);
    let dir = path.parent().unwrap_or(path);
    let dir_c = dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf());
    let path = match path.file_name() {
        Some(f) => dir_c.join(f),
        None => path.to_path_buf(),
    };
    let (p, b): (Vec<Component>, Vec<Component>) =
        (path.components().collect(), base.components().collect());
    if p.first() != b.first() {
        return path;
    }
    let common = p.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut out = PathBuf::new();
    for _ in common..b.len() {
        out.push("..");
    }
    for c in &p[common..] {
        out.push(c);
    }
    out
}

/// `text` without control characters, at most `max` characters.
pub fn printable(text: &str, max: usize) -> String {
    text.chars()
        .map(|c| if c.is_control() { '_' } else { c })
        .take(max)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_paths() {
        let d = tempfile::tempdir().unwrap();
        let sub = d.path().join("a").join("b");
        std::fs::create_dir_all(&sub).unwrap();
        let f = d.path().join("a").join("s.txt");
        std::fs::write(&f, "1 2\n").unwrap();
        assert_eq!(relative_to(&f, &sub), PathBuf::from("../s.txt"));
        assert_eq!(relative_to(&f, &d.path().join("a")), PathBuf::from("s.txt"));
        assert_eq!(relative_to(&f, d.path()), PathBuf::from("a/s.txt"));
    }

    #[test]
    fn the_fit_in_the_papers_convention() {
        // fig2: C^iso = (2π)² Z q^(−3.6), Z = 1e-8, q0 = 1e5 → h_rms 19.8166 nm.
        let q0 = 1e5f64;
        let psd = |q: f64| (2.0 * std::f64::consts::PI).powi(2) * 1e-8 * q.powf(-3.6);
        let fit = PowerLawFit {
            dim: Dim::Areal,
            hurst: 0.8,
            slope: -3.6,
            q0,
            psd_at_q0: psd(q0),
            q_lo: q0,
            q_hi: 1e9,
            points: 5,
            hurst_se: 0.0,
            rms_decades: 0.0,
            rms_decades_unweighted: 0.0,
        };
        let (z, h) = fit_amplitude(&fit).unwrap();
        assert!((z / 1e-8 - 1.0).abs() < 1e-14, "{z}");
        assert!((h / 1.9816636488030044e-8 - 1.0).abs() < 1e-14, "{h}");
        let bad = PowerLawFit { hurst: 1.2, ..fit };
        assert_eq!(fit_amplitude(&bad), None);
    }
}
