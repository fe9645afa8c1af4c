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
