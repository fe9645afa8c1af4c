//! What `roughtui bench` runs and about how long it takes, said before it
//! starts; and the time it took, said at the end.
//!
//! The durations are those of a run on a two-core machine with nothing
//! else running (release build; the contact curve as docs/accuracy-speed.md
//! gives it), so they are a floor: a busy machine takes longer, which is
//! why a run names the load average it starts and ends at.

use std::fmt::Write as _;

use crate::cli::BenchArgs;

/// One part of a run: what it does and about how many seconds it takes.
struct Part {
    what: String,
    seconds: f64,
    /// Left out by `--quick`.
    long: bool,
}

/// Seconds per timed pass of all the slope methods over the reference ψ
/// (0.07 s for the default 15 passes on 2026-11-28, two idle cores).
const SLOPES_PASS: f64 = 0.005;
/// The speed targets with `roughtui export` against its NumPy peer (three
/// runs of each, python3's start-up most of it).
const TARGETS: f64 = 5.0;
/// One load at ζ = 32 and 64, three cold solves each.
const SOLVER: f64 = 1.5;
/// fig2's 13-load curve at ζ = 128 on 1024² (23.1 s measured on
/// 2026-11-28, two idle cores).
const CURVE: f64 = 23.0;
/// The synthetic 1024² map: tabulated, first frame, 41 + 41 steps.
const SYNTHETIC: f64 = 0.2;

fn parts(args: &BenchArgs, methods: usize, reference: usize) -> Vec<Part> {
    let passes = args.passes.max(1);
    vec![
        Part {
            what: format!(
                "the initial slopes by {methods} methods over {reference} reference ψ, \
                 {passes} timed passes each"
            ),
            seconds: SLOPES_PASS * f64::from(passes + 1),
            long: false,
        },
        Part {
            what: "the speed targets: the regime maps, the slopes view's frame, and \
                   `roughtui export` against its NumPy peer (3 runs each)"
                .into(),
            seconds: TARGETS,
            long: false,
        },
        Part {
            what: "the contact solver: one load on fig2's surface at ζ = 32 (256²) and 64 \
                   (512²), 3 cold solves each"
                .into(),
            seconds: SOLVER,
            long: false,
        },
        Part {
            what: "fig2's 13-load contact curve at ζ = 128 on 1024²".into(),
            seconds: CURVE,
            long: true,
        },
        Part {
            what: "a synthetic 1024 × 1024 measured map: the first screen, 41 ζ and 41 \
                   H0/E steps"
                .into(),
            seconds: SYNTHETIC,
            long: false,
        },
    ]
}

/// "about 23 s", "about 0.2 s", "under 0.1 s".
fn about(seconds: f64) -> String {
    if seconds < 0.1 {
        "under 0.1 s".into()
    } else if seconds < 1.0 {
        format!("about {seconds:.1} s")
    } else {
        format!("about {seconds:.0} s")
    }
}

/// What a run with `args` does, in order, and about how long it takes.
pub fn text(args: &BenchArgs, methods: usize, reference: usize) -> String {
    let mut out = String::new();
    if let Some(path) = &args.surface {
        let _ = writeln!(
            out,
            "roughtui bench --surface {}: the file read to the explorer's first \
             160×48 screen, then 41 ζ and 41 H0/E steps, each drawn: about twice the \
             file's reading (0.1 s for a 1024² text map, 1 s for 4096²).",
            path.display()
        );
        return out;
    }
    let parts = parts(args, methods, reference);
    let _ = writeln!(out, "roughtui bench runs, in turn:");
    for (i, p) in parts.iter().enumerate() {
        let when = if p.long && args.quick {
            "left out: --quick".to_string()
        } else {
            about(p.seconds)
        };
        let _ = writeln!(out, "  {}. {} ({when})", i + 1, p.what);
    }
    let total = |quick: bool| -> f64 {
        parts
            .iter()
            .filter(|p| !(quick && p.long))
            .map(|p| p.seconds)
            .sum()
    };
    if args.quick {
        let _ = writeln!(
            out,
            "{} in all on a two-core machine with nothing else running, longer on a busy one.",
            about(total(true))
        );
    } else {
        let _ = writeln!(
            out,
            "{} in all on a two-core machine with nothing else running, longer on a busy \
             one; --quick leaves out the contact curve ({}).",
            about(total(false)),
            about(total(true))
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    fn args(line: &[&str]) -> BenchArgs {
        let cli =
            crate::cli::Cli::try_parse_from(["roughtui", "bench"].iter().chain(line).copied())
                .unwrap();
        match cli.command {
            Some(crate::cli::Command::Bench(a)) => a,
            _ => unreachable!(),
        }
    }

    #[test]
    fn the_plan_names_each_part_and_its_time() {
        let t = text(&args(&[]), 13, 1251);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 7, "{t}");
        assert_eq!(lines[0], "roughtui bench runs, in turn:");
        assert_eq!(
            lines[1],
            "  1. the initial slopes by 13 methods over 1251 reference ψ, 15 timed passes \
             each (under 0.1 s)"
        );
        assert!(
            lines[4]
                .starts_with("  4. fig2's 13-load contact curve at ζ = 128 on 1024² (about 23 s)"),
            "{t}"
        );
        assert!(lines[6].starts_with("about 30 s in all"), "{t}");
        assert!(
            lines[6].ends_with("--quick leaves out the contact curve (about 7 s)."),
            "{t}"
        );
        let q = text(&args(&["--quick", "--passes", "3"]), 13, 1251);
        assert!(q.contains("3 timed passes each (under 0.1 s)"), "{q}");
        assert!(q.contains("on 1024² (left out: --quick)"), "{q}");
        assert!(q.contains("about 7 s in all"), "{q}");
        let s = text(&args(&["--surface", "x.txt"]), 13, 1251);
        assert!(
            s.starts_with("roughtui bench --surface x.txt: the file read"),
            "{s}"
        );
    }
}
