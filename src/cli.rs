//! Command-line definitions.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

#[derive(Debug, Parser)]
#[command(
    name = "roughtui",
    version,
    about = "Explore elasto-plastic rough contact with size-dependent hardness (Ciavarella 2024)",
    long_about = "Explore elasto-plastic rough contact with size-dependent hardness \
                  (Ciavarella, Lubricants 2024, 12(3), 83). Without a command, opens the \
                  full-screen explorer on fig2, a preset, or a saved snapshot."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub source: Source,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Print the scene's curves as CSV on stdout.
    Export(ExportArgs),
    /// Time each way of computing the initial slopes against the reference data.
    Bench(BenchArgs),
}

/// Where the parameter set comes from.
#[derive(Debug, Args, Clone, Default)]
#[group(multiple = false)]
pub struct Source {
    /// A built-in preset: fig1, fig2, fig3 or fig4.
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// A snapshot file (RON, schema version 1).
    #[arg(long, value_name = "FILE")]
    pub load: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct ExportArgs {
    #[command(flatten)]
    pub source: RequiredSource,
    /// Number of points, both ends included.
    #[arg(long, default_value_t = 200, value_parser = clap::value_parser!(u32).range(2..=10_000_000))]
    pub points: u32,
    /// Override the snapshot's model.
    #[arg(long, value_enum)]
    pub model: Option<ModelArg>,
    /// Override the snapshot's spectrum moments: the truncated spectrum's
    /// exact moments, or the paper's asymptotic ones (eq. 10).
    #[arg(long, value_enum)]
    pub moments: Option<MomentsArg>,
}

#[derive(Debug, Args, Clone)]
#[group(required = true, multiple = false)]
pub struct RequiredSource {
    /// A built-in preset: fig1, fig2, fig3 or fig4.
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// A snapshot file (RON, schema version 1).
    #[arg(long, value_name = "FILE")]
    pub load: Option<PathBuf>,
}

impl From<RequiredSource> for Source {
    fn from(r: RequiredSource) -> Source {
        Source {
            preset: r.preset,
            load: r.load,
        }
    }
}

#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Timed passes per method (the median is reported).
    #[arg(long, default_value_t = 15)]
    pub passes: u32,
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
