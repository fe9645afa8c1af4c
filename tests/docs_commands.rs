//! Every command the README and the manual in `docs/` show is run here, as
//! a reader would type it, in a folder holding the files the commands name.
//!
//! The commands are the lines of the ```sh blocks (```text blocks are
//! synopses and screens, not run). `roughtui export` and `roughtui merge`
//! run for real, their output redirected as written (or to `--output`);
//! the explorer, `serve` and `bench` run with `ROUGHTUI_CHECK_ONLY=1`,
//! which reads and checks everything the command line names and stops
//! before the terminal is taken or a port is opened. `cargo run --release
//! -- ARGS` is run as `roughtui ARGS`; other programs (`cargo test`,
//! `ssh`) are left to the tests that cover them.

mod common;

use std::path::Path;
use std::process::Command;

use common::docs::{self, pages, words, workspace, ROOT};

/// One command from the documentation: where it was and what it says.
struct DocCommand {
    file: String,
    line: usize,
    text: String,
}

/// The ```sh blocks' commands of `README.md` and `docs/*.md`, continuation
/// lines joined and comments dropped.
fn doc_commands() -> Vec<DocCommand> {
    let mut out = Vec::new();
    for path in pages() {
        let text = std::fs::read_to_string(&path).unwrap();
        let name = docs::name(&path);
        let mut in_sh = false;
        let mut pending: Option<(usize, String)> = None;
        for (i, line) in text.lines().enumerate() {
            let trimmed = line.trim_start();
            if let Some(info) = trimmed.strip_prefix("```") {
                in_sh = !in_sh && matches!(info.trim(), "sh" | "bash" | "shell");
                continue;
            }
            if !in_sh {
                continue;
            }
            let code = strip_comment(line).trim_end().to_string();
            let (start, mut joined) = pending.take().unwrap_or((i + 1, String::new()));
            if let Some(head) = code.strip_suffix('\\') {
                joined.push_str(head);
                joined.push(' ');
                pending = Some((start, joined));
                continue;
            }
            joined.push_str(code.trim());
            if !joined.trim().is_empty() {
                out.push(DocCommand {
                    file: name.clone(),
                    line: start,
                    text: joined.trim().to_string(),
                });
            }
        }
    }
    out
}

/// The line without a `#` comment (a `#` outside quotes after a blank).
fn strip_comment(line: &str) -> &str {
    let mut quote = None;
    let mut prev_blank = true;
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (None, '\'' | '"') => quote = Some(c),
            (None, '#') if prev_blank => return &line[..i],
            _ => {}
        }
        prev_blank = c.is_whitespace();
    }
    line
}

#[test]
fn every_documented_command_runs() {
    let commands = doc_commands();
    assert!(
        commands.len() >= 20,
        "only {} commands found in the documentation",
        commands.len()
    );
    let dir = workspace();
    let home = dir.path().join("home");
    let mut ran = 0;
    let mut failures = Vec::new();
    for c in &commands {
        let mut argv = words(&c.text, &home);
        // `cargo run --release -- ARGS` is `roughtui ARGS`.
        if argv.starts_with(&["cargo".into(), "run".into()]) {
            match argv.iter().position(|w| w == "--") {
                Some(i) => argv.splice(..=i, ["roughtui".to_string()]),
                None => argv.splice(.., ["roughtui".to_string()]),
            };
        }
        if argv.first().map(String::as_str) != Some("roughtui") {
            continue;
        }
        assert!(
            !argv.iter().any(|w| w.contains('|') && !w.contains('=')),
            "{}:{}: a pipe or a synopsis in a ```sh block (use ```text for synopses): {}",
            c.file,
            c.line,
            c.text
        );
        let mut stdout_to = None;
        if let Some(i) = argv.iter().position(|w| w == ">") {
            stdout_to = argv.get(i + 1).cloned();
            argv.truncate(i);
        }
        // `export` and `merge` run for real: they print (or write) files.
        let export = matches!(argv.get(1).map(String::as_str), Some("export" | "merge"));
        let mut cmd = Command::new(common::cli::BIN);
        cmd.args(&argv[1..])
            .stdin(std::process::Stdio::null())
            .current_dir(dir.path())
            .env("HOME", &home)
            .env_remove("NO_COLOR");
        if !export {
            cmd.env("ROUGHTUI_CHECK_ONLY", "1");
        }
        let out = cmd.output().unwrap();
        ran += 1;
        if !out.status.success() {
            failures.push(format!(
                "{}:{}: `{}` exited with {}: {}",
                c.file,
                c.line,
                c.text,
                out.status,
                String::from_utf8_lossy(&out.stderr).trim()
            ));
            continue;
        }
        if export {
            // `--output FILE`: what it wrote, not stdout.
            let written = argv
                .windows(2)
                .find(|w| w[0] == "--output")
                .map(|w| std::fs::read(dir.path().join(&w[1])).unwrap_or_default());
            let stdout = String::from_utf8_lossy(written.as_deref().unwrap_or(&out.stdout));
            let svg = argv.windows(2).any(|w| w[0] == "--format" && w[1] == "svg");
            let looks_right = if svg {
                stdout.contains("<svg") && stdout.trim_end().ends_with("</svg>")
            } else {
                stdout.lines().count() >= 3
            };
            if !looks_right {
                failures.push(format!(
                    "{}:{}: `{}` printed no {}",
                    c.file,
                    c.line,
                    c.text,
                    if svg { "SVG" } else { "CSV" }
                ));
            }
            if let Some(name) = stdout_to {
                std::fs::write(dir.path().join(name), &out.stdout).unwrap();
            }
        }
    }
    assert!(ran >= 20, "only {ran} documented commands were run");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn comments_and_words_are_read_as_a_shell_would() {
    assert_eq!(strip_comment("roughtui   # fig2"), "roughtui   ");
    assert_eq!(
        strip_comment("roughtui --set 'a#b'"),
        "roughtui --set 'a#b'"
    );
    let home = Path::new("/home/x");
    assert_eq!(
        words("roughtui --lecturer-keys ~/.ssh/k.pub 'a b'", home),
        ["roughtui", "--lecturer-keys", "/home/x/.ssh/k.pub", "a b"]
    );
}

/// docs/explorer.md's example snapshot is the fig2 preset as the explorer's
/// `s` saves it today (the program's own text, not one written by hand).
#[test]
fn the_documented_snapshot_is_what_the_program_saves() {
    let doc = std::fs::read_to_string(Path::new(ROOT).join("docs/explorer.md")).unwrap();
    let start = doc
        .find("```ron\n")
        .expect("a ```ron block in docs/explorer.md")
        + 7;
    let len = doc[start..].find("```").unwrap();
    let saved = roughtui::presets::load("fig2").unwrap().to_ron();
    assert_eq!(&doc[start..start + len], saved);
}
