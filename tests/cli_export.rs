//! `roughtui export`: the CSV contract and its usage errors.

use std::io::Read;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_roughtui");
const HEADER: &str = "x,psi,hardness_ratio,elastic,plastic,total,persson_elastic";

fn run(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

fn usage_error(args: &[&str], words: &[&str]) {
    let out = run(args);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty());
    for w in words {
        assert!(err.contains(w), "{args:?}: wants {w:?} in {err}");
    }
}

#[test]
fn default_is_200_points_with_both_ends() {
    let out = run(&["export", "--preset", "fig2"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], HEADER);
    assert_eq!(lines.len(), 201);
    // fig2 sweeps ζ from 1 to 1e4; at ζ = 1 there is no roughness: ψ = 0.
    assert_eq!(lines[1], "1,0,1,inf,0,inf,inf");
    assert!(lines[200].starts_with("10000,"), "{}", lines[200]);
    for l in &lines[1..] {
        assert_eq!(l.split(',').count(), 7, "{l}");
        for f in l.split(',') {
            let v: f64 = f.parse().unwrap();
            assert!(!v.is_nan(), "{l}");
        }
    }
}

#[test]
fn model_override_changes_the_slopes() {
    let exact = run(&["export", "--preset", "fig2", "--points", "3"]);
    let closed = run(&[
        "export",
        "--preset",
        "fig2",
        "--points",
        "3",
        "--model",
        "closed-form",
    ]);
    assert_eq!(closed.status.code(), Some(0));
    let (e, c) = (
        String::from_utf8(exact.stdout).unwrap(),
        String::from_utf8(closed.stdout).unwrap(),
    );
    assert_eq!(c.lines().count(), 4);
    assert_eq!(e.lines().nth(1), c.lines().nth(1)); // ζ = 1: both infinite/zero
    assert_ne!(e.lines().nth(2), c.lines().nth(2));
}

#[test]
fn usage_errors_exit_2_with_a_message() {
    usage_error(
        &["export", "--preset", "fig2", "--points", "1"],
        &["--points", "1 is not in 2..="],
    );
    usage_error(
        &["export", "--preset", "fig2", "--points", "abc"],
        &["--points", "invalid digit"],
    );
    usage_error(
        &["export", "--preset", "fig2", "--points", "-5"],
        &["unexpected argument '-5'"],
    );
    usage_error(
        &["export", "--preset", "fig2", "--model", "foo"],
        &["'foo'", "exact, closed-form"],
    );
    usage_error(&["export"], &["--preset", "--load"]);
    usage_error(
        &["export", "--preset", "fig2", "--load", "x.ron"],
        &["cannot be used with"],
    );
    usage_error(
        &["export", "--preset", "fig9"],
        &["unknown preset 'fig9'", "fig1, fig2, fig3, fig4"],
    );
}

#[test]
fn a_closed_stdout_is_not_a_crash() {
    // Like `roughtui export … | head -1`: the reader goes away early.
    let mut child = Command::new(BIN)
        .args(["export", "--preset", "fig4", "--points", "200000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 10];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    assert_eq!(&first, b"x,psi,hard");
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert_eq!(err, "");
}
