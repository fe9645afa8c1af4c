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
    // fig2 sweeps ζ from 1 to 1e4 with the paper's asymptotic moments, so
    // ψ stays finite at ζ = 1: (E/H0)·√(m2/2) = 0.19816636488030044 (mpmath).
    let first: Vec<f64> = lines[1].split(',').map(|f| f.parse().unwrap()).collect();
    assert_eq!(first[0], 1.0);
    assert!(
        (first[1] / 0.19816636488030044 - 1.0).abs() < 1e-13,
        "{}",
        lines[1]
    );
    assert_eq!(first[2], 1.0);
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
    let base = ["export", "--preset", "fig2", "--points", "3"];
    let closed = run(&base);
    let exact = run(&[&base[..], &["--model", "exact"]].concat());
    assert_eq!(exact.status.code(), Some(0));
    let (e, c) = (
        String::from_utf8(exact.stdout).unwrap(),
        String::from_utf8(closed.stdout).unwrap(),
    );
    assert_eq!(e.lines().count(), 4);
    // Same moments, so the same ψ; another model, other slopes.
    let psi = |t: &str| {
        t.lines()
            .nth(2)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .to_owned()
    };
    assert_eq!(psi(&e), psi(&c));
    assert_ne!(e.lines().nth(2), c.lines().nth(2));
}

#[test]
fn moments_override_changes_psi() {
    // At ζ = 100 the paper's asymptotic moments give Ψ_P = 0.49777140312440325
    // (mpmath); the truncated spectrum's exact moments give less, and ψ = 0
    // at ζ = 1 where there is no roughness left.
    let base = ["export", "--preset", "fig2", "--points", "3"];
    let field = |out: Output, row: usize| -> f64 {
        assert_eq!(out.status.code(), Some(0));
        let text = String::from_utf8(out.stdout).unwrap();
        text.lines()
            .nth(row)
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse()
            .unwrap()
    };
    let asymptotic = field(run(&base), 2);
    assert!(
        (asymptotic / 0.49777140312440325 - 1.0).abs() < 1e-13,
        "{asymptotic}"
    );
    let truncated = run(&[&base[..], &["--moments", "truncated"]].concat());
    assert_eq!(field(truncated, 1), 0.0);
    let truncated = field(run(&[&base[..], &["--moments", "truncated"]].concat()), 2);
    assert!(truncated < asymptotic && truncated > 0.4, "{truncated}");
}

#[test]
fn usage_errors_exit_2_with_a_message() {
    usage_error(
        &["export", "--preset", "fig2", "--moments", "asimptotic"],
        &["--moments", "asimptotic", "asymptotic"],
    );
    // Every bad count gets the same message, negative and huge ones too.
    for bad in ["0", "1", "-5", "1e9", "abc", "10000001"] {
        usage_error(
            &["export", "--preset", "fig2", "--points", bad],
            &[
                &format!("invalid value '{bad}' for '--points <N>'"),
                "must be a whole number from 2 to 10000000",
            ],
        );
    }
    usage_error(
        &["export", "--preset", "fig2", "--model", "foo"],
        &["'foo'", "exact, closed-form"],
    );
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

#[test]
fn asymptotic_moments_at_hurst_one_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("h1.ron");
    std::fs::write(
        &path,
        "(version: 1, name: \"h1\", params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, \
         hurst: 1.0, r_star: 0.001, q0: 100000.0), size_effect: false, \
         sweep: (axis: Zeta, from: 1.0, to: 10000.0), model: Exact)",
    )
    .unwrap();
    let file = path.to_str().unwrap();
    assert_eq!(
        run(&["export", "--load", file, "--points", "2"])
            .status
            .code(),
        Some(0)
    );
    usage_error(
        &[
            "export",
            "--load",
            file,
            "--points",
            "2",
            "--moments",
            "asymptotic",
        ],
        &["hurst = 1", "moments", "Truncated"],
    );
}
