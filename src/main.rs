//! roughtui: a terminal explorer of elasto-plastic rough contact with
//! size-dependent hardness. Thin: parse, dispatch, map errors to exit codes.

use std::io::{ErrorKind, Write};
use std::process::ExitCode;

use anyhow::Context;
use clap::Parser;
use roughtui::cli::setup::load_source;
use roughtui::cli::{Cli, Command};
use roughtui::{export, tui};

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            // A refused command line is one line, as every refusal is:
            // clap's message with its hints, without the usage lines.
            let _ = writeln!(std::io::stderr(), "roughtui: {}", one_line(&e.to_string()));
            return ExitCode::from(2);
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        // A reader that stops early (`roughtui export … | head -1`) is not
        // an error: stop quietly.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            // Not eprintln!, which panics when stderr itself is a closed pipe.
            let _ = writeln!(std::io::stderr(), "roughtui: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// clap's error `text` on one line: "error: " dropped, the usage and
/// "For more information" lines left out, the rest joined with "; ".
fn one_line(text: &str) -> String {
    let parts: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| {
            !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more information")
        })
        .collect();
    // "…were not provided:" runs on into what was not.
    let mut line = String::new();
    for p in parts {
        if !line.is_empty() {
            line.push_str(if line.ends_with(':') { " " } else { "; " });
        }
        line.push_str(p);
    }
    line.strip_prefix("error: ").unwrap_or(&line).to_string()
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == ErrorKind::BrokenPipe)
    })
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Some(Command::Export(a)) => export::main(&a),
        Some(Command::Merge(a)) => export::merge::main(&a),
        Some(Command::Bench(a)) => roughtui::bench::run(&a, check_only()),
        Some(Command::Serve(a)) => {
            let lesson = a
                .lesson
                .as_deref()
                .map(roughtui::class::lesson::read)
                .transpose()?;
            let state = match &lesson {
                Some(l) => l.steps[0].state.clone(),
                None => load_source(&a.source, &a.setup)?,
            };
            a.simulate.check(&state)?;
            if let Some(w) = state.surface_warning() {
                println!("warning: {w}");
            }
            for n in state.surface.iter().flat_map(|s| s.notes()) {
                println!("{n}");
            }
            use roughtui::serve::code::ClassCode;
            let class_code = match (&a.class_code, &a.class_code_file) {
                (Some(w), _) => Some(ClassCode::word(w).context("--class-code")?),
                (None, Some(f)) => Some(ClassCode::read(f)?),
                (None, None) => None,
            };
            if check_only() {
                return Ok(());
            }
            roughtui::serve::run(roughtui::serve::Options {
                // SSH on its default address unless only the web is asked.
                listen: match (a.listen, a.web) {
                    (None, None) => Some(roughtui::cli::DEFAULT_LISTEN.parse()?),
                    (l, _) => l,
                },
                web: a.web,
                host_key: a.host_key,
                lecturer_keys: a.lecturer_keys,
                state,
                max_sessions: a.max_sessions as usize,
                max_per_address: a.max_per_address as usize,
                idle_timeout: a.idle_timeout,
                class_code,
                quiet: a.quiet,
                marker: a.marker.map(Into::into),
                lesson,
                simulate: a.simulate.clone(),
            })
        }
        None => {
            let (state, lesson) = tui::start_state(&cli)?;
            if check_only() {
                return Ok(());
            }
            tui::run(
                state,
                cli.source.load.as_deref(),
                cli.marker.map(Into::into),
                lesson,
                &cli.simulate,
            )
        }
    }
}

/// `ROUGHTUI_CHECK_ONLY=1`: read and check everything the command line
/// names (scene, files, values), then stop before the terminal is taken or
/// a server listens. The documentation's commands are run this way by
/// `tests/docs_commands.rs`.
fn check_only() -> bool {
    std::env::var_os("ROUGHTUI_CHECK_ONLY").is_some_and(|v| v == "1")
}
