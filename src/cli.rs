//! Command-line definitions.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};
use rough_model::Axis;

mod cluster;
pub mod setup;
mod simulate;
mod values;
pub use cluster::{parse_shard, Cluster, MergeArgs, Shard};
pub use simulate::{HardnessArg, LoadScaleArg, Simulate};
pub use values::{parse_duration, parse_fit_band, parse_set, SetKey, SweepArg, MAX_POINTS};
use values::{
    parse_grid, parse_height_unit, parse_percent, parse_pixel_size, parse_points, parse_seeds,
    parse_sweep,
};

#[derive(Debug, Parser)]
#[command(
    name = "roughtui",
    version,
    about = "Explore elasto-plastic rough contact with size-dependent hardness (Ciavarella 2024)",
    long_about = "Explore elasto-plastic rough contact with size-dependent hardness \
                  (Ciavarella, Lubricants 2024, 12(3), 83). Without a command, opens the \
                  full-screen explorer on fig2, a preset, a saved snapshot, or a measured \
                  surface (--surface FILE: a topography map, a line scan or a PSD table).",
    after_help = "The explorer needs a terminal of at least 80×24; in it, ? lists the keys \
                  (Enter types a value, s saves, q quits). NO_COLOR=1 (or c) draws without colour; \
                  ASCII only where the locale is not UTF-8 (M switches). \
                  For data without a terminal use `roughtui export`."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub source: Source,
    #[command(flatten)]
    pub setup: Setup,
    #[command(flatten)]
    pub simulate: Simulate,
    /// What the explorer draws with: braille dots, half blocks, blocks or
    /// ASCII only [default: from the locale and TERM]. `M` switches.
    #[arg(long, value_enum, value_name = "SET")]
    pub marker: Option<MarkerArg>,
    /// Rehearse a lesson (RON: its steps' scenes, views, captions and
    /// polls) alone: `n` / `N` step through it.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["preset", "load", "surface"])]
    pub lesson: Option<PathBuf>,
}

/// A glyph set on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MarkerArg {
    Braille,
    Half,
    Block,
    Ascii,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Print a view (slopes, indices, regime map, load, a surface's spectrum
    /// or moments, the contact simulation) as CSV or SVG on stdout; fig2
    /// unless --preset, --load or --surface says otherwise.
    Export(ExportArgs),
    /// Time each way of computing the initial slopes against the reference
    /// data, the explorer's frames, the contact solver and a measured map
    /// (it says what it runs and about how long first).
    Bench(BenchArgs),
    /// Serve the explorer over SSH to a class: students `ssh -p PORT HOST`.
    Serve(ServeArgs),
    /// Put the parts of a sharded contact export (`export … --seeds N
    /// --shard K/M`) together: the CSV one machine's `--seeds N` writes.
    Merge(MergeArgs),
}

/// Where the parameter set comes from.
#[derive(Debug, Args, Clone, Default)]
#[group(multiple = false)]
pub struct Source {
    /// A built-in preset: fig1, fig2, fig3, fig4 (the paper's figures) or
    /// elastic-again (a scene whose Ψ* comes down through 1 within the
    /// contact simulation's reach).
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// A snapshot file (RON, schema version 1).
    #[arg(long, value_name = "FILE")]
    pub load: Option<PathBuf>,
    /// A measured surface: a topography map (plain-text matrix with
    /// Gwyddion's header), a line scan or a PSD table, detected from its
    /// content.
    #[arg(long, value_name = "FILE")]
    pub surface: Option<PathBuf>,
}

/// How to read a surface, and parameters set on the command line.
#[derive(Debug, Args, Clone, Default)]
pub struct Setup {
    /// The surface's data is periodic: only its mean is removed, no window.
    #[arg(long, requires = "surface")]
    pub periodic: bool,
    /// The sample spacing of data without a size header, e.g. 50nm (units
    /// as the value prompt takes them: m cm mm µm um nm pm).
    #[arg(long, value_name = "LENGTH", requires = "surface", allow_hyphen_values = true, value_parser = parse_pixel_size)]
    pub pixel_size: Option<f64>,
    /// The measurement to read from a contact.engineering download of
    /// several (its "Topography:" name) [default: the first, named in the
    /// caption].
    #[arg(long, value_name = "NAME", requires = "surface")]
    pub series: Option<String>,
    /// Read a map as its profiles along x or y (line-scan conventions):
    /// every view then shows that direction alone.
    #[arg(long, value_enum, value_name = "x|y", requires = "surface")]
    pub direction: Option<DirectionArg>,
    /// The channel of a file of several (Gwyddion's .gwy, a Nanoscope,
    /// Nanosurf or Igor file's images, ASCII exports concatenated): its
    /// number or its title (the first channel of heights when not given).
    #[arg(long, value_name = "N|TITLE", requires = "surface")]
    pub channel: Option<String>,
    /// The unit of the surface's heights: m, mm, µm (um, microns), nm, Å
    /// (A) or pm; for a text file whatever it says, for an instrument's
    /// file where it gives none. Without it heights take the file's value
    /// unit, else its lateral unit (said in a note).
    #[arg(long, value_name = "UNIT", requires = "surface", value_parser = parse_height_unit)]
    pub height_unit: Option<rough_surface::HeightUnit>,
    /// The lateral unit of a file that gives none: the x column of an
    /// `x z` line scan, the sizes of an Igor wave without units (heights
    /// without a unit of their own follow it).
    #[arg(long, value_name = "UNIT", requires = "surface", value_parser = parse_height_unit)]
    pub lateral_unit: Option<rough_surface::HeightUnit>,
    /// The share of undefined (not measured, masked, NaN) points that is
    /// filled, in percent, e.g. 35 [default: 10]; more is refused.
    #[arg(long, value_name = "PERCENT", requires = "surface", value_parser = parse_percent)]
    pub max_undefined: Option<f64>,
    /// The form removed from the surface's heights before its spectrum and
    /// Sq: none, the mean, the least-squares plane (a line scan's line) or
    /// the least-squares quadratic (curvature), as SurfaceTopography's
    /// detrend modes [default: plane; mean with --periodic].
    #[arg(long, value_enum, value_name = "MODE", requires = "surface")]
    pub detrend: Option<DetrendArg>,
    /// The Hurst fit band of a measured surface: wavevectors in 1/m
    /// (1e6:1e8) or wavelengths with a unit (60nm:6um) [default: the
    /// spectrum's self-affine stretch, found from the data].
    #[arg(long, value_name = "FROM:TO", value_parser = parse_fit_band)]
    pub fit_band: Option<(f64, f64)>,
    /// Set a parameter, e.g. --set h0-over-e=0.001 --set r-star=0.5mm
    /// (repeatable; units as the value prompt takes them). AXIS is one of
    /// h0-over-e, h-rms, zeta, hurst, r-star; or q0 (1/m) or l (the
    /// longest wavelength 2π/q0, a length); or material values e (the
    /// composite modulus E*, or Young's modulus with nu) and h0 (the
    /// hardness) in Pa, kPa, MPa or GPa, which set H0/E: --set e=210GPa
    /// --set h0=2GPa [--set nu=0.3].
    #[arg(long = "set", value_name = "AXIS=VALUE", value_parser = parse_set)]
    pub set: Vec<(SetKey, String)>,
}

/// `--direction`: along x (the map's rows) or y.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DirectionArg {
    X,
    Y,
}

impl From<DirectionArg> for rough_surface::Direction {
    fn from(d: DirectionArg) -> Self {
        match d {
            DirectionArg::X => rough_surface::Direction::X,
            DirectionArg::Y => rough_surface::Direction::Y,
        }
    }
}

/// `--detrend`: the form removed from a measured surface's heights.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DetrendArg {
    None,
    Mean,
    Plane,
    Curvature,
}

impl From<DetrendArg> for rough_surface::Detrend {
    fn from(d: DetrendArg) -> Self {
        match d {
            DetrendArg::None => rough_surface::Detrend::None,
            DetrendArg::Mean => rough_surface::Detrend::Mean,
            DetrendArg::Plane => rough_surface::Detrend::Plane,
            DetrendArg::Curvature => rough_surface::Detrend::Curvature,
        }
    }
}

impl Setup {
    /// How `--surface` is to be read.
    pub fn surface_options(&self) -> rough_surface::Options {
        rough_surface::Options {
            periodic: self.periodic,
            pixel_size: self.pixel_size,
            series: self.series.clone(),
            direction: self.direction.map(Into::into),
            channel: self.channel.clone(),
            height_unit: self.height_unit,
            lateral_unit: self.lateral_unit,
            max_undefined: self.max_undefined.map(|p| p / 100.0),
            detrend: self.detrend.map(Into::into),
        }
    }
}

impl BenchArgs {
    /// How `--surface` is to be read.
    pub fn surface_options(&self) -> rough_surface::Options {
        rough_surface::Options {
            periodic: self.periodic,
            pixel_size: self.pixel_size,
            series: self.series.clone(),
            direction: self.direction.map(Into::into),
            channel: self.channel.clone(),
            height_unit: None,
            lateral_unit: None,
            max_undefined: self.max_undefined.map(|p| p / 100.0),
            detrend: None,
        }
    }
}

#[derive(Debug, Args, Clone)]
pub struct ExportArgs {
    #[command(flatten)]
    pub source: Source,
    #[command(flatten)]
    pub setup: Setup,
    /// What to export: the slopes against the swept parameter, the
    /// plasticity indices, the regime map, the areas against the load, a
    /// measured surface's spectrum (q, psd, fit), or the moments per ζ
    /// (m0, m2, m4, h_rms, h′, h″, R_s; Sq, Sdq and the fit as comments).
    #[arg(long, value_enum, default_value_t = ViewArg::Slopes)]
    pub view: ViewArg,
    /// CSV numbers, or an SVG picture of the view.
    #[arg(long, value_enum, default_value_t = FormatArg::Csv)]
    pub format: FormatArg,
    /// Points along the curve, both ends included (slopes, indices, load;
    /// default 200).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = parse_points)]
    pub points: Option<usize>,
    /// Map cells across × up, both ends of each axis included (map only;
    /// default 50x30).
    #[arg(long, value_name = "COLSxROWS", value_parser = parse_grid)]
    pub grid: Option<(usize, usize)>,
    /// The map's y axis (map only; default h0-over-e, or zeta when H0/E is
    /// swept).
    #[arg(long, value_enum, value_name = "AXIS")]
    pub map_y: Option<AxisArg>,
    /// Override the snapshot's model.
    #[arg(long, value_enum)]
    pub model: Option<ModelArg>,
    /// Override the snapshot's spectrum moments: the truncated spectrum's
    /// exact moments, or the paper's asymptotic ones (eq. 10).
    #[arg(long, value_enum)]
    pub moments: Option<MomentsArg>,
    /// Override the snapshot's size effect (Ψ* and H_y when on, Ψ_P and H0
    /// when off).
    #[arg(long, value_enum, value_name = "on|off")]
    pub size_effect: Option<OnOff>,
    /// Override the snapshot's sweep, e.g. zeta:1:1e4 or h-rms:1nm:1um
    /// (lengths with a unit as the value prompt takes them; a bare number
    /// in metres).
    #[arg(long, value_name = "AXIS:FROM:TO", value_parser = parse_sweep)]
    pub sweep: Option<SweepArg>,
    /// Seed of the simulated surface's random phases (contact views only;
    /// default 1), the first of --seeds.
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,
    /// Realisations to average (contact views): seeds --seed, --seed + 1, …;
    /// the CSV gives means and sample standard deviations (default 1).
    #[arg(long, value_name = "N", value_parser = parse_seeds)]
    pub seeds: Option<u32>,
    #[command(flatten)]
    pub simulate: Simulate,
    #[command(flatten)]
    pub cluster: Cluster,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ViewArg {
    Slopes,
    Indices,
    Map,
    Load,
    Spectrum,
    /// The moments and what they give per ζ (export only).
    Moments,
    /// The boundary-element simulation beside the theory, against the load.
    Contact,
    /// The simulation's plastic share against ζ beside the theory's.
    ContactSweep,
    /// The simulated contact map at p̄ = 0.01 H (SVG; CSV: a row of 0 out
    /// of contact, 1 elastic, 2 at the hardness per grid row).
    ContactMap,
    /// The simulation at p̄ = 0.01 H on 4, 8 and 16 nodes per shortest
    /// wavelength and cells of 1, 2 and 4 longest wavelengths, over the
    /// seeds (CSV).
    ContactConvergence,
    /// The simulation's initial slopes H·dA/dp̄/A0 against ζ beside the
    /// theory's (the paper's figure with the simulation's points).
    ContactSlopes,
    /// The synthetic surface the contact views solve, as a height matrix
    /// (readable by `--surface FILE --periodic` and SurfaceTopography).
    Surface,
}

impl ViewArg {
    /// The figure view, or `None` for export's own moments view
    /// (src/export/moments.rs) and the contact views (src/contact.rs).
    pub fn figure(self) -> Option<crate::figure::View> {
        use crate::figure::View;
        Some(match self {
            ViewArg::Slopes => View::Slopes,
            ViewArg::Indices => View::Indices,
            ViewArg::Map => View::Map,
            ViewArg::Load => View::Load,
            ViewArg::Spectrum => View::Spectrum,
            ViewArg::Moments
            | ViewArg::Contact
            | ViewArg::ContactSweep
            | ViewArg::ContactMap
            | ViewArg::ContactConvergence
            | ViewArg::ContactSlopes
            | ViewArg::Surface => return None,
        })
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    Csv,
    Svg,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OnOff {
    On,
    Off,
}

/// A parameter on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AxisArg {
    H0OverE,
    HRms,
    Zeta,
    Hurst,
    RStar,
}

impl From<AxisArg> for Axis {
    fn from(a: AxisArg) -> Axis {
        match a {
            AxisArg::H0OverE => Axis::H0OverE,
            AxisArg::HRms => Axis::HRms,
            AxisArg::Zeta => Axis::Zeta,
            AxisArg::Hurst => Axis::Hurst,
            AxisArg::RStar => Axis::RStar,
        }
    }
}

/// `serve`'s SSH address when neither `--listen` nor `--web` is given.
pub const DEFAULT_LISTEN: &str = "127.0.0.1:2222";

#[derive(Debug, Args)]
pub struct ServeArgs {
    /// Address and port of the SSH server [default: 127.0.0.1:2222, loopback;
    /// none with --web alone].
    #[arg(long, value_name = "ADDR:PORT")]
    pub listen: Option<std::net::SocketAddr>,
    /// Also serve the class to browsers: a page and a WebSocket on this
    /// address and port (plain HTTP; put it behind a TLS proxy off campus).
    #[arg(long, value_name = "ADDR:PORT")]
    pub web: Option<std::net::SocketAddr>,
    /// The host key (OpenSSH Ed25519, mode 0600), made if absent [default:
    /// $XDG_CONFIG_HOME/roughtui/host_ed25519 or ~/.config/roughtui/host_ed25519].
    #[arg(long, value_name = "PATH")]
    pub host_key: Option<PathBuf>,
    /// The lecturer's public keys (authorized_keys format); the lecturer logs
    /// in as user `lecturer`. Without it everyone explores alone.
    #[arg(long, value_name = "FILE")]
    pub lecturer_keys: Option<PathBuf>,
    #[command(flatten)]
    pub source: Source,
    #[command(flatten)]
    pub setup: Setup,
    #[command(flatten)]
    pub simulate: Simulate,
    /// Most students at once, over SSH and the web together (the
    /// lecturer's key takes no place).
    #[arg(long, default_value_t = 150, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub max_sessions: u32,
    /// Most students at once from one address (a campus NAT puts a whole
    /// room behind one).
    #[arg(long, default_value_t = 150, value_parser = clap::value_parser!(u32).range(1..=10_000))]
    pub max_per_address: u32,
    /// A session without a key (or a lecturer's move, when following) for
    /// this long ends: a number with s, m or h.
    #[arg(long, default_value = "30m", value_parser = parse_duration, value_name = "TIME")]
    pub idle_timeout: std::time::Duration,
    /// Students log in with this word, typed at "class code:" (any user
    /// name, which becomes their name in the class). Without it, and
    /// without --class-code-file, students need no password.
    #[arg(long, value_name = "WORD", conflicts_with = "class_code_file")]
    pub class_code: Option<String>,
    /// The class code from a file (its text, blanks around it dropped).
    #[arg(long, value_name = "FILE")]
    pub class_code_file: Option<PathBuf>,
    /// No line per join and leave and no summary each minute on the console.
    #[arg(long)]
    pub quiet: bool,
    /// What every session draws with [default: from each client's TERM and
    /// the LANG / LC_* it sends]; each student can switch with `M`.
    #[arg(long, value_enum, value_name = "SET")]
    pub marker: Option<MarkerArg>,
    /// Lead the class through a lesson (RON): `n` / `N` step, `v` opens a
    /// step's poll, all its polls go to one CSV.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["preset", "load", "surface"])]
    pub lesson: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Timed passes per method (the median is reported).
    #[arg(long, default_value_t = 15)]
    pub passes: u32,
    /// Leave out the longest part, fig2's 13-load contact curve on 1024²
    /// (about 23 of the run's 30 s on two idle cores).
    #[arg(long, conflicts_with = "surface")]
    pub quick: bool,
    /// Time a measured surface instead: the file to the first screen, ζ
    /// and H0/E steps, peak memory.
    #[arg(long, value_name = "FILE")]
    pub surface: Option<PathBuf>,
    /// The surface's data is periodic (as for the explorer).
    #[arg(long, requires = "surface")]
    pub periodic: bool,
    /// The surface's sample spacing (as for the explorer).
    #[arg(long, value_name = "LENGTH", requires = "surface", allow_hyphen_values = true, value_parser = parse_pixel_size)]
    pub pixel_size: Option<f64>,
    /// The measurement of a download of several (as for the explorer).
    #[arg(long, value_name = "NAME", requires = "surface")]
    pub series: Option<String>,
    /// A map's profiles along x or y (as for the explorer).
    #[arg(long, value_enum, value_name = "x|y", requires = "surface")]
    pub direction: Option<DirectionArg>,
    /// The channel of a file of several (as for the explorer).
    #[arg(long, value_name = "N|TITLE", requires = "surface")]
    pub channel: Option<String>,
    /// The share of undefined points filled, in percent (as for the
    /// explorer).
    #[arg(long, value_name = "PERCENT", requires = "surface", value_parser = parse_percent)]
    pub max_undefined: Option<f64>,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ModelArg {
    Exact,
    ClosedForm,
}

impl From<ModelArg> for rough_model::Model {
    fn from(m: ModelArg) -> Self {
        match m {
            ModelArg::Exact => rough_model::Model::Exact,
            ModelArg::ClosedForm => rough_model::Model::ClosedForm,
        }
    }
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum MomentsArg {
    Truncated,
    Asymptotic,
}

impl From<MomentsArg> for rough_model::Moments {
    fn from(m: MomentsArg) -> Self {
        match m {
            MomentsArg::Truncated => rough_model::Moments::Truncated,
            MomentsArg::Asymptotic => rough_model::Moments::Asymptotic,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::parse_duration;
    use std::time::Duration;

    #[test]
    fn durations() {
        assert_eq!(parse_duration("30m"), Ok(Duration::from_secs(1800)));
        assert_eq!(parse_duration("90s"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("2h"), Ok(Duration::from_secs(7200)));
        assert!(parse_duration("0s")
            .unwrap_err()
            .contains("outside 1s to 24h"));
        assert!(parse_duration("25h").unwrap_err().contains("outside"));
        assert!(parse_duration("5").unwrap_err().contains("not a time"));
        assert!(parse_duration("-5m").unwrap_err().contains("not a time"));
    }
}
