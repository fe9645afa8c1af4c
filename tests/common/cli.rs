//! Running the roughtui binary as a user would, without a terminal.

use std::process::{Command, Output, Stdio};

pub const BIN: &str = env!("CARGO_BIN_EXE_roughtui");

/// A run of the binary with `args`, stdin empty.
pub fn run(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

/// Stdout of a successful run (status 0, nothing on stderr).
pub fn stdout(args: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    assert!(err.is_empty(), "{err}");
    String::from_utf8(out.stdout).unwrap()
}

/// A successful run whose stderr holds only a surface's notes
/// ("roughtui: note: …", "roughtui: warning: …"): its stdout without the
/// `# ` comment lines a CSV starts with, and the notes (without the
/// "roughtui: " and "note: "). Each note is also one of the CSV's comment
/// lines, when stdout is a CSV.
#[allow(dead_code)]
pub fn noted(args: &[&str]) -> (String, Vec<String>) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    let notes: Vec<String> = err
        .lines()
        .map(|l| {
            let n = l
                .strip_prefix("roughtui: ")
                .unwrap_or_else(|| panic!("{l}"));
            assert!(n.starts_with("note: ") || n.starts_with("warning: "), "{l}");
            n.strip_prefix("note: ").unwrap_or(n).to_string()
        })
        .collect();
    let text = String::from_utf8(out.stdout).unwrap();
    let comments: Vec<&str> = text
        .lines()
        .take_while(|l| l.starts_with("# "))
        .map(|l| &l[2..])
        .collect();
    if !text.starts_with('<') {
        for n in &notes {
            assert!(comments.contains(&n.as_str()), "{n} not in {comments:?}");
        }
    }
    let body = text
        .split_inclusive('\n')
        .skip(comments.len())
        .collect::<String>();
    (body, notes)
}
