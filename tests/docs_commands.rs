//! Every command the README and the manual in `docs/` show is run here, as
//! a reader would type it, in a folder holding the files the commands name.
//!
//! The commands are the lines of the ```sh blocks (```text blocks are
//! synopses and screens, not run). `roughtui export` runs for real, its
//! output redirected as written; the explorer, `serve` and `bench` run
//! with `ROUGHTUI_CHECK_ONLY=1`, which reads and checks everything the
//! command line names and stops before the terminal is taken or a port is
//! opened. `cargo run --release -- ARGS` is run as `roughtui ARGS`; other
//! programs (`cargo test`, `ssh`) are left to the tests that cover them.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// One command from the documentation: where it was and what it says.
struct DocCommand {
    file: String,
    line: usize,
    text: String,
}

/// The ```sh blocks' commands of `README.md` and `docs/*.md`, continuation
/// lines joined and comments dropped.
fn doc_commands() -> Vec<DocCommand> {
    let mut files = vec![PathBuf::from(ROOT).join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(Path::new(ROOT).join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    let mut out = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.strip_prefix(ROOT).unwrap().display().to_string();
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

/// Shell words: blanks split, quotes group, `~/` is the test's home.
fn words(command: &str, home: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quote = None;
    let mut started = false;
    for c in command.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                started = true;
            }
            (None, c) if c.is_whitespace() => {
                if started {
                    out.push(std::mem::take(&mut word));
                    started = false;
                }
            }
            (None, c) => {
                word.push(c);
                started = true;
            }
        }
    }
    if started {
        out.push(word);
    }
    for w in &mut out {
        if let Some(rest) = w.strip_prefix("~/") {
            *w = home.join(rest).display().to_string();
        }
    }
    out
}

/// A folder with what the documentation's commands name: the repository's
/// `surfaces/`, `presets/` and `lessons/`, a snapshot `my-set.ron`, the
/// surfaces `steel.txt` and `afm.txt` (the shipped example's map), a
/// header-less line scan `scan.txt`, an x3p `scan.x3p` and a Gwyddion
/// file of four channels `afm.gwy` (rough-surface's test data) and a
/// lecturer's public key.
fn workspace() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for sub in ["surfaces", "presets", "lessons"] {
        let from = Path::new(ROOT).join(sub);
        if from.is_dir() {
            std::os::unix::fs::symlink(&from, dir.path().join(sub)).unwrap();
        }
    }
    let example = Path::new(ROOT).join("surfaces/example.txt");
    for name in ["steel.txt", "afm.txt"] {
        std::fs::copy(&example, dir.path().join(name)).unwrap();
    }
    std::fs::copy(
        Path::new(ROOT).join("presets/fig2.ron"),
        dir.path().join("my-set.ron"),
    )
    .unwrap();
    let scan: String = (0..512)
        .map(|i| {
            let x = i as f64 / 512.0 * std::f64::consts::TAU;
            format!("{:e}\n", 1e-8 * (3.0 * x).sin() + 2e-9 * (37.0 * x).cos())
        })
        .collect();
    std::fs::write(dir.path().join("scan.txt"), scan).unwrap();
    let formats = Path::new(ROOT).join("crates/rough-surface/tests/data/formats");
    for (from, to) in [("sur_d.x3p", "scan.x3p"), ("three.gwy", "afm.gwy")] {
        std::fs::copy(formats.join(from), dir.path().join(to)).unwrap();
    }
    let key = "ssh-ed25519 AAAAC3NzaC1lZDI1NTE5AAAAIOMqqnkVzrm0SdG6UOoqKLsabgH5C9okWi0dh2l9GKJl lecturer@example\n";
    std::fs::write(dir.path().join("lecturer.pub"), key).unwrap();
    std::fs::create_dir_all(dir.path().join("home/.ssh")).unwrap();
    std::fs::write(dir.path().join("home/.ssh/id_ed25519.pub"), key).unwrap();
    dir
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
        let export = argv.get(1).map(String::as_str) == Some("export");
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
            let stdout = String::from_utf8_lossy(&out.stdout);
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
