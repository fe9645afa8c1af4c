//! A contact ensemble split over machines and put back together: `export
//! … --seeds N --shard K/M` on each part, `roughtui merge` on the parts,
//! against the one machine's `export … --seeds N` — every mean and sample
//! standard deviation within 1e-12 (the merge computes them from the seeds'
//! own values in seed order, as one machine does: they come out equal), the
//! `#` lines the same but for their numbers' last digits, the picture the
//! same; the refusals one line each,
//! exit status 2; `--output` writes a part whole or not at all and never
//! over a file.

mod common;
use std::path::Path;

use common::cli::{run, stdout, BIN};
use common::merge::difference;

/// The one machine's CSV of `args` with `--seeds n`, and the merge of its
/// `m` parts (given to merge in reverse order).
fn one_and_merged(dir: &Path, args: &[&str], n: u32, m: u32) -> (String, String) {
    let n = n.to_string();
    let all = [args, &["--seeds", &n]].concat();
    let one = stdout(&[&["export"], &all[..]].concat());
    let parts = solve_parts(dir, &all, m);
    let parts: Vec<&str> = parts.iter().map(String::as_str).collect();
    let merged = stdout(&[&["merge"], &parts[..]].concat());
    (one, merged)
}

/// The `m` parts of the export `all` (its arguments, `--seeds` among
/// them) written in `dir`, the last first: their paths.
fn solve_parts(dir: &Path, all: &[&str], m: u32) -> Vec<String> {
    let mut parts = vec![];
    for k in (1..=m).rev() {
        let file = dir.join(format!("part-{k}-of-{m}.csv"));
        let shard = format!("{k}/{m}");
        let out = file.to_str().unwrap();
        stdout(&[&["export"], all, &["--shard", &shard, "--output", out]].concat());
        parts.push(file.display().to_string());
    }
    parts
}

#[test]
fn merged_parts_are_the_one_machine_ensemble() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[&str], u32, u32); 4] = [
        (
            "contact",
            &[
                "--view", "contact", "--preset", "fig2", "--set", "zeta=8", "--cell", "1",
                "--points", "5",
            ],
            5,
            3,
        ),
        (
            "contact-sweep",
            &[
                "--view",
                "contact-sweep",
                "--preset",
                "fig2",
                "--cell",
                "1",
                "--per-wavelength",
                "3",
            ],
            3,
            2,
        ),
        (
            "contact-convergence",
            &[
                "--view",
                "contact-convergence",
                "--preset",
                "fig2",
                "--set",
                "zeta=2",
            ],
            4,
            4,
        ),
        // A hardness per asperity: the heaviest load is beyond what the
        // asperities carry, for every seed; one machine names the first.
        (
            "contact, asperity",
            &[
                "--view",
                "contact",
                "--preset",
                "fig2",
                "--size-effect",
                "on",
                "--hardness",
                "asperity",
                "--set",
                "zeta=16",
                "--cell",
                "1",
                "--points",
                "4",
            ],
            4,
            2,
        ),
    ];
    for (i, (name, args, n, m)) in cases.iter().enumerate() {
        let sub = dir.path().join(i.to_string());
        std::fs::create_dir(&sub).unwrap();
        let (one, merged) = one_and_merged(&sub, args, *n, *m);
        let d = difference(&one, &merged);
        println!("{name}: {n} seeds in {m} parts, merged against one machine: largest relative difference {d:e}");
        assert!(d <= 1e-12, "{name}: {d}");
        // The rows to the last digit (a `#` line's statistic of the seeds'
        // means, as a mean of the seeds' own, may differ in its last).
        fn rows(t: &str) -> Vec<&str> {
            t.lines().filter(|l| !l.starts_with('#')).collect()
        }
        assert_eq!(rows(&one), rows(&merged), "{name}: not the same rows");
    }
}

#[test]
fn merged_pictures_are_the_one_machines() {
    let dir = tempfile::tempdir().unwrap();
    for (i, args) in [
        &[
            "--view", "contact", "--preset", "fig2", "--set", "zeta=8", "--cell", "1", "--points",
            "4",
        ][..],
        &[
            "--view",
            "contact-sweep",
            "--preset",
            "fig4",
            "--cell",
            "1",
            "--per-wavelength",
            "3",
        ][..],
    ]
    .iter()
    .enumerate()
    {
        let all = [*args, &["--seeds", "3"]].concat();
        let one = stdout(&[&["export"], &all[..], &["--format", "svg"]].concat());
        let mut parts = vec![];
        for k in 1..=3 {
            let file = dir.path().join(format!("{i}-{k}.csv"));
            let shard = format!("{k}/3");
            let out = file.to_str().unwrap();
            stdout(&[&["export"], &all[..], &["--shard", &shard, "--output", out]].concat());
            parts.push(file.display().to_string());
        }
        let parts: Vec<&str> = parts.iter().map(String::as_str).collect();
        let merged = stdout(&[&["merge", "--format", "svg"], &parts[..]].concat());
        assert!(
            merged.starts_with("<svg") || merged.starts_with("<?xml"),
            "{merged}"
        );
        assert_eq!(one, merged, "{args:?}");
    }
}

#[test]
fn contact_slopes_parts_merge_to_the_one_machines_csv_and_picture() {
    // The fit's error, |mean light slope − mean heavy slope| over the
    // seeds, is no seed's own: each part carries the seeds' heavy-window
    // slopes (`*_heavy`) and merge forms it as one machine does.
    let dir = tempfile::tempdir().unwrap();
    let all = [
        "--view",
        "contact-slopes",
        "--preset",
        "fig2",
        "--cell",
        "1",
        "--per-wavelength",
        "3",
        "--seeds",
        "3",
    ];
    let parts = solve_parts(dir.path(), &all, 2);
    let part = std::fs::read_to_string(&parts[0]).unwrap();
    let header = part.lines().find(|l| !l.starts_with('#')).unwrap();
    assert!(
        header.contains(",sim_elastic_slope_heavy,sim_plastic_slope_heavy,sim_total_slope_heavy,")
            && !header.contains("_fit_err"),
        "{header}"
    );
    assert!(
        part.lines().any(|l| l.starts_with("# part columns = ")
            && l.contains("fit error: sim_elastic_slope_heavy, sim_plastic_slope_heavy, sim_total_slope_heavy;")),
        "{part}"
    );
    let parts: Vec<&str> = parts.iter().map(String::as_str).collect();
    let one = stdout(&[&["export"], &all[..]].concat());
    let merged = stdout(&[&["merge"], &parts[..]].concat());
    let d = difference(&one, &merged);
    println!("contact-slopes: 3 seeds in 2 parts, merged against one machine: largest relative difference {d:e}");
    assert!(d <= 1e-12, "{d}");
    assert_eq!(one, merged);
    let fit_err = merged
        .lines()
        .find(|l| !l.starts_with('#'))
        .unwrap()
        .split(',')
        .position(|c| c == "sim_total_slope_fit_err")
        .unwrap();
    let first = merged
        .lines()
        .filter(|l| !l.starts_with('#'))
        .nth(1)
        .unwrap();
    let e: f64 = first.split(',').nth(fit_err).unwrap().parse().unwrap();
    assert!(e.is_finite() && e > 0.0, "{first}");
    let one = stdout(&[&["export"], &all[..], &["--format", "svg"]].concat());
    let merged = stdout(&[&["merge", "--format", "svg"], &parts[..]].concat());
    assert!(merged.contains("<svg"), "{merged}");
    assert_eq!(one, merged);
}

/// A failed run: status 2, one line on stderr holding `says`.
fn refused(args: &[&str], says: &str) {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(says), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
}

const SMALL: [&str; 11] = [
    "export", "--view", "contact", "--preset", "fig2", "--set", "zeta=4", "--cell", "1",
    "--points", "3",
];

#[test]
fn bad_shards_are_refused_in_one_line() {
    for (extra, says) in [
        (
            &["--seeds", "4", "--shard", "2"][..],
            "must be K/M, part K of M",
        ),
        (&["--seeds", "4", "--shard", "a/b"], "must be K/M"),
        (
            &["--seeds", "4", "--shard", "5/4"],
            "part 5 of 4 does not exist",
        ),
        (
            &["--seeds", "4", "--shard", "0/4"],
            "part 0 of 4 does not exist",
        ),
        (
            &["--seeds", "4", "--shard", "1/0"],
            "M, the number of parts, must be at least 1",
        ),
        (
            &["--seeds", "4", "--shard", "1/5"],
            "5 parts of seeds 1–4 would leave a part without a seed",
        ),
        (
            &["--shard", "1/2"],
            "2 parts of seed 1 would leave a part without a seed",
        ),
        (
            &["--seeds", "4", "--shard", "1/2", "--format", "svg"],
            "roughtui merge --format svg",
        ),
        (
            &["--seeds", "4", "--slurm-array", "5"],
            "5 parts of seeds 1–4",
        ),
    ] {
        refused(&[&SMALL[..], extra].concat(), says);
    }
    refused(
        &["export", "--view", "slopes", "--shard", "1/2"],
        "--shard applies to the views that solve --seeds",
    );
    refused(
        &["export", "--view", "contact-map", "--shard", "1/1"],
        "not to --view contact-map",
    );
    refused(
        &[
            "export",
            "--view",
            "contact",
            "--surface",
            "surfaces/example.txt",
            "--seeds",
            "2",
            "--shard",
            "1/2",
        ],
        "--seeds 2 does not apply to a measured map",
    );
    refused(&["merge"], "PART");
    refused(
        &["merge", "/nonexistent/part.csv"],
        "cannot read the part /nonexistent/part.csv",
    );
}

/// Parts of `SMALL` with `--seeds 4` in `dir`: part K of 2, or with other
/// options added.
fn part(dir: &Path, name: &str, k: u32, extra: &[&str]) -> String {
    let file = dir.join(name).display().to_string();
    let shard = format!("{k}/2");
    stdout(
        &[
            &SMALL[..],
            extra,
            &["--seeds", "4", "--shard", &shard, "--output", &file],
        ]
        .concat(),
    );
    file
}

#[test]
fn parts_of_other_ensembles_missing_or_twice_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (a, b) = (part(d, "a.csv", 1, &[]), part(d, "b.csv", 2, &[]));
    // The two parts merge.
    assert!(stdout(&["merge", &a, &b]).contains("seeds 1–4 (columns: means over 4"));
    let other_scene = part(d, "zeta.csv", 2, &["--set", "h0-over-e=0.02"]);
    refused(&["merge", &a, &other_scene], "made with other options than");
    let grid = part(d, "grid.csv", 2, &["--per-wavelength", "16"]);
    refused(&["merge", &a, &grid], "`--per-wavelength 16`, which");
    // A version's part: its line says so.
    let text = std::fs::read_to_string(&b).unwrap();
    let old = d.join("old.csv");
    std::fs::write(
        &old,
        text.replace("solved by roughtui ", "solved by roughtui 0.0."),
    )
    .unwrap();
    refused(
        &["merge", &a, old.to_str().unwrap()],
        "the parts of one ensemble come from one version",
    );
    // The scene edited in a part's lines.
    let edited = d.join("edited.csv");
    std::fs::write(&edited, text.replace("# hurst = 0.8", "# hurst = 0.7")).unwrap();
    refused(
        &["merge", &a, edited.to_str().unwrap()],
        "`# hurst = 0.7  (Hurst exponent)` where",
    );
    refused(&["merge", &a], "seeds 3, 4 (part 2/2 not given)");
    refused(&["merge", &a, &a, &b], "seed 1 is in two parts");
    // A part whose rows were cut short names the seed and the load.
    let cut = d.join("cut.csv");
    let kept: Vec<&str> = text.lines().filter(|l| !l.starts_with("4,1,")).collect();
    std::fs::write(&cut, kept.join("\n")).unwrap();
    refused(
        &["merge", &a, cut.to_str().unwrap()],
        "seed 4 has no row at p_over_h = 1",
    );
    // Not a part at all.
    let plain = d.join("plain.csv");
    std::fs::write(&plain, stdout(&[&SMALL[..], &["--seeds", "4"]].concat())).unwrap();
    refused(
        &["merge", &a, plain.to_str().unwrap()],
        "is not a part of a sharded export",
    );
    refused(&["merge", "--format", "svg", &a], "seeds 3, 4");
}

#[test]
fn output_is_written_whole_and_a_part_done_is_skipped() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let a = part(d, "a.csv", 1, &[]);
    let before = std::fs::metadata(&a).unwrap().modified().unwrap();
    // The same part again: skipped, the file untouched.
    let out = std::process::Command::new(BIN)
        .args(
            [
                &SMALL[..],
                &["--seeds", "4", "--shard", "1/2", "--output", &a],
            ]
            .concat(),
        )
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("part 1/2 (seeds 1–2) is done already"),
        "{err}"
    );
    assert_eq!(std::fs::metadata(&a).unwrap().modified().unwrap(), before);
    // Another part, or another export, into it: refused, never overwritten.
    let text = std::fs::read_to_string(&a).unwrap();
    refused(
        &[
            &SMALL[..],
            &["--seeds", "4", "--shard", "2/2", "--output", &a],
        ]
        .concat(),
        "the file exists and is not part 2/2 of this export",
    );
    refused(
        &[&SMALL[..], &["--seeds", "4", "--output", &a]].concat(),
        "the file exists; roughtui does not overwrite a file",
    );
    assert_eq!(std::fs::read_to_string(&a).unwrap(), text);
    // Nothing but the parts in the folder: no temporary file left.
    let names: Vec<String> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["a.csv"]);
}
