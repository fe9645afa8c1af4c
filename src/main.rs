//! roughtui: a terminal explorer of elasto-plastic rough contact with
//! size-dependent hardness. Thin: parse, dispatch, map errors to exit codes.

use std::io::BufWriter;
use std::process::ExitCode;

use clap::Parser;
use roughtui::cli::{Cli, Command};
use roughtui::{export, load_source, tui};

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("roughtui: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Export(a)) => {
            let state = load_source(&a.source.into())?;
            let stdout = std::io::stdout();
            let mut out = BufWriter::with_capacity(1 << 16, stdout.lock());
            export::write_csv(&mut out, &state, a.points as usize, a.model.map(Into::into))
        }
        Some(Command::Bench(a)) => roughtui::bench::run(&a),
        None => {
            let state = load_source(&cli.source)?;
            tui::run(state)
        }
    }
}
