//! What the manual quotes of the program is the program's own, read from
//! the program at test time: the CSV headers `roughtui export` writes for
//! every view its `--help` lists, the options and their values of every
//! command's `--help`, and the explorer's key table
//! ([`roughtui::tui::keys::BINDINGS`], which also drives the help overlay
//! and the footer). A view, option, value or key added to the program is
//! found here without a change to this test, and fails it until a page
//! says it.

mod common;

use std::collections::{BTreeMap, BTreeSet};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use common::docs::{self, pages, ROOT};

/// Pages not held to these checks yet, with the reason.
const NOT_YET: &[(&str, &str)] = &[];

/// The pages' text (README and docs/), each with its name, without the
/// pages [`NOT_YET`] names.
fn texts() -> Vec<(String, String)> {
    pages()
        .into_iter()
        .map(|p| (docs::name(&p), std::fs::read_to_string(&p).unwrap()))
        .filter(|(n, _)| !NOT_YET.iter().any(|(m, _)| m == n))
        .collect()
}

/// Every page's text, the pages [`NOT_YET`] names too (for what must be
/// said somewhere).
fn all_text() -> String {
    pages()
        .into_iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect::<Vec<_>>()
        .join("\n")
}

/// The `roughtui` binary's output (stdout) with `args`, stopped after
/// `limit`; `None` when it failed or took too long.
fn run(args: &[&str], limit: Duration) -> Option<String> {
    let mut child = Command::new(common::cli::BIN)
        .args(args)
        .current_dir(ROOT)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    // Read while it runs: a CSV fills the pipe long before it ends.
    let mut stdout = child.stdout.take()?;
    let reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        std::io::Read::read_to_end(&mut stdout, &mut s).map(|_| s)
    });
    let start = Instant::now();
    let status = loop {
        match child.try_wait().ok()? {
            Some(status) => break status,
            None if start.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return None;
            }
            None => std::thread::sleep(Duration::from_millis(20)),
        }
    };
    let out = reader.join().ok()?.ok()?;
    status
        .success()
        .then(|| String::from_utf8_lossy(&out).into_owned())
}

/// One option of a command's `--help`: its possible values, if it lists
/// them.
type Options = BTreeMap<String, Vec<String>>;

/// The options of `roughtui [COMMAND] --help`, with their possible values.
fn options(command: Option<&str>) -> Options {
    let mut args: Vec<&str> = command.into_iter().collect();
    args.push("--help");
    let help = run(&args, Duration::from_secs(20)).expect("--help");
    let mut out = Options::new();
    let mut current: Option<String> = None;
    let mut listing = false;
    for line in help.lines() {
        let t = line.trim();
        if let Some(rest) = t
            .strip_prefix("--")
            .or_else(|| t.strip_prefix("-h, --"))
            .or_else(|| t.strip_prefix("-V, --"))
        {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '-')
                .collect();
            out.entry(name.clone()).or_default();
            current = Some(name);
            listing = false;
            continue;
        }
        let Some(opt) = &current else { continue };
        if let Some(list) = t
            .strip_prefix("[possible values: ")
            .and_then(|l| l.strip_suffix(']'))
        {
            out.get_mut(opt)
                .unwrap()
                .extend(list.split(", ").map(String::from));
        } else if t == "Possible values:" {
            listing = true;
        } else if listing {
            if let Some(v) = t.strip_prefix("- ") {
                let v = v.split(':').next().unwrap().trim();
                out.get_mut(opt).unwrap().push(v.to_string());
            } else if !t.is_empty() {
                listing = false;
            }
        }
    }
    out
}

/// Every command's options: the explorer's (`""`), export's, bench's,
/// serve's and merge's.
fn all_options() -> BTreeMap<&'static str, Options> {
    ["", "export", "bench", "serve", "merge"]
        .into_iter()
        .map(|c| (c, options((!c.is_empty()).then_some(c))))
        .collect()
}

/// The CSV header `roughtui export --view VIEW` writes (its first line
/// that is not a `#` line), from the quickest scene that has the view:
/// fig2 at ζ = 4 (the simulation on a cell of one wavelength at four
/// nodes per shortest wavelength), or the example surface. `None` for a
/// view whose CSV has no header (the contact map's rows of numbers).
fn header(view: &str) -> Option<String> {
    // A simulation's options are refused by the other views at once.
    let tries: [&[&str]; 3] = [
        &["--set", "zeta=4", "--cell", "1", "--per-wavelength", "4"],
        &["--set", "zeta=4"],
        &["--surface", "surfaces/example.txt"],
    ];
    for extra in tries {
        let mut args = vec!["export", "--view", view];
        args.extend_from_slice(extra);
        if let Some(csv) = run(&args, Duration::from_secs(60)) {
            let first = csv.lines().find(|l| !l.starts_with('#'))?;
            return first
                .chars()
                .any(|c| c.is_ascii_alphabetic())
                .then(|| first.to_string());
        }
    }
    panic!("roughtui export --view {view} gave no CSV on fig2 at ζ = 4 or the example surface");
}

/// The axes' column names, which SWEPT, ACROSS and UP stand for.
const AXES: &[&str] = &["zeta", "h0_over_e", "h_rms", "hurst", "r_star"];

/// Whether the quoted `list` (`SWEPT,psi,…`) is `header`: SWEPT, ACROSS
/// and UP stand for an axis, a final `…` for the rest.
fn quotes(list: &str, header: &str) -> bool {
    let (list, prefix) = match list.strip_suffix(",…") {
        Some(l) => (l, true),
        None => (list, false),
    };
    let want: Vec<&str> = list.split(',').collect();
    let got: Vec<&str> = header.split(',').collect();
    if want.len() > got.len() || (!prefix && want.len() != got.len()) {
        return false;
    }
    want.iter()
        .zip(&got)
        .all(|(w, g)| w == g || (matches!(*w, "SWEPT" | "ACROSS" | "UP") && AXES.contains(g)))
}

/// The backticked spans of `text` (inline code, on one line).
fn code_spans(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        let parts: Vec<&str> = line.split('`').collect();
        out.extend(parts.iter().skip(1).step_by(2).map(|s| s.to_string()));
    }
    out
}

/// A quoted list of CSV columns: two or more names between commas.
fn is_column_list(s: &str) -> bool {
    let items: Vec<&str> = s.split(',').collect();
    items.len() >= 2
        && items.iter().all(|i| {
            *i == "…"
                || (!i.is_empty()
                    && i.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                    && i.chars().next().unwrap().is_ascii_alphabetic())
        })
}

/// Names in `snake_case` the pages quote that are not roughtui's columns:
/// other programs' functions and fields, crates and their features, a
/// snapshot's fields, and a column's former name (export.md says what it
/// became).
const NOT_COLUMNS: &[&str] = &[
    // SurfaceTopography, x3p and Gwyddion.
    "fourier_synthesis",
    "rms_slope_from_profile",
    "rms_height_from_profile",
    "rms_height_from_area",
    "rms_gradient",
    "integrate_psd",
    "integrate_psd_from_profile",
    "moment_power_spectrum",
    "power_spectrum_from_area",
    "power_spectrum_from_profile",
    "interpolate_undefined_data",
    "read_container",
    "to_matrix",
    "height_scale",
    "detrend_mode",
    "si_unit_xy",
    "si_unit_z",
    "read_topography",
    // Crates and their features; an example of this repository.
    "serde_path_to_error",
    "rand_chacha",
    "svg_backend",
    "line_series",
    "read_surface",
    // A snapshot's fields.
    "map_y",
    "size_effect",
    // Former names (export.md's "Changed columns").
    "hardness_ratio",
    // A part's own (`export --shard`), which merge turns into
    // sim_total_slope_fit_err.
    "sim_total_slope_heavy",
];

#[test]
fn the_csv_headers_and_columns_quoted_are_the_programs() {
    let opts = all_options();
    let views = opts["export"]
        .get("view")
        .cloned()
        .expect("export --help lists --view's values");
    assert!(views.len() >= 10, "{views:?}");
    let headers: BTreeMap<String, Option<String>> =
        views.iter().map(|v| (v.clone(), header(v))).collect();
    let columns: BTreeSet<&str> = headers
        .values()
        .flatten()
        .flat_map(|h| h.split(','))
        .chain(AXES.iter().copied())
        .collect();
    let mut failures = Vec::new();
    for (name, text) in texts() {
        for span in code_spans(&text) {
            if is_column_list(&span) {
                if !headers.values().flatten().any(|h| quotes(&span, h)) {
                    failures.push(format!(
                        "{name}: `{span}` is no view's CSV header (roughtui export writes: {})",
                        headers
                            .iter()
                            .filter_map(|(v, h)| h.as_ref().map(|h| format!("{v}: {h}")))
                            .collect::<Vec<_>>()
                            .join("; ")
                    ));
                }
            } else if span.contains('_')
                && span.starts_with(|c: char| c.is_ascii_lowercase())
                && span
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                && !columns.contains(span.as_str())
                && !NOT_COLUMNS.contains(&span.as_str())
            {
                failures.push(format!(
                    "{name}: `{span}` is no column roughtui export writes \
                     (if it is another program's name, add it to NOT_COLUMNS)"
                ));
            }
        }
        // A table row naming views beside a header: that header is each
        // view's.
        for line in text.lines().filter(|l| l.starts_with('|')) {
            let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
            let Some(list) = cells.get(1).and_then(|c| {
                let c = c.strip_prefix('`')?.strip_suffix('`')?;
                is_column_list(c).then_some(c)
            }) else {
                continue;
            };
            for span in code_spans(cells[0]) {
                if let Some(Some(h)) = headers.get(&span) {
                    if !quotes(list, h) {
                        failures.push(format!(
                            "{name}: the view `{span}` is given the header `{list}`; \
                             roughtui export writes `{h}`"
                        ));
                    }
                }
            }
        }
    }
    // Every view is in a table of the manual (the pages not yet checked
    // count here: a view must be said somewhere).
    let all = all_text();
    for v in &views {
        let in_table = all.lines().filter(|l| l.starts_with('|')).any(|l| {
            let first = l.trim_matches('|').split('|').next().unwrap_or("");
            code_spans(first).iter().any(|s| s == v)
        });
        if !in_table {
            failures.push(format!(
                "the view `{v}` (roughtui export --help) is in no table of the manual"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn quoted_lists_are_read_as_headers() {
    assert!(quotes("SWEPT,psi,h_use_over_h0", "zeta,psi,h_use_over_h0"));
    assert!(quotes("zeta,h0_over_e,psi,…", "zeta,h0_over_e,psi,elastic"));
    assert!(!quotes("zeta,psi", "zeta,psi,total"));
    assert!(!quotes("zeta,psi,hardness_ratio", "zeta,psi,h_use_over_h0"));
    assert!(is_column_list("q,psd,fit"));
    assert!(!is_column_list("1,,3"));
    assert!(!is_column_list("x,z,,"));
    assert_eq!(code_spans("a `b` c `d,e`\n```\n`x`\n```\n"), ["b", "d,e"]);
}

/// Options the pages name that are other programs': cargo's, the
/// scripts', Gwyddion's, SLURM's (`sbatch`, `squeue`).
const OTHER_PROGRAMS_OPTIONS: &[&str] = &[
    "account",
    "array",
    "big",
    "convert-to-gwy",
    "cpus-per-task",
    "example",
    "job-name",
    "locked",
    "me",
    "mem",
    "n",
    "nocapture",
    "ntasks",
    "partition",
    "path",
    "profile",
    "release",
    "test",
    "time",
    "timings",
    "workspace",
];

/// `--name` and, where a list follows (`--name a|b|c`), its values, as
/// the pages write them (blanks and line breaks between them allowed).
fn option_mentions(text: &str) -> Vec<(String, Vec<String>)> {
    let flat: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut out = Vec::new();
    let bytes = flat.as_bytes();
    let mut i = 0;
    while let Some(at) = flat[i..].find("--") {
        let start = i + at;
        i = start + 2;
        if start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'-') {
            continue;
        }
        let name: String = flat[i..]
            .chars()
            .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-')
            .collect();
        if name.is_empty() || !name.starts_with(|c: char| c.is_ascii_lowercase()) {
            continue;
        }
        let after = &flat[i + name.len()..];
        let value: String = after
            .strip_prefix(' ')
            .unwrap_or("")
            .chars()
            .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-' || *c == '|')
            .collect();
        let values = if value.contains('|') {
            value
                .split('|')
                .filter(|v| !v.is_empty())
                .map(String::from)
                .collect()
        } else {
            Vec::new()
        };
        out.push((name, values));
    }
    out
}

#[test]
fn the_options_and_values_quoted_are_the_programs() {
    let opts = all_options();
    let known: BTreeMap<&str, BTreeSet<&str>> = {
        let mut m: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
        for o in opts.values() {
            for (name, values) in o {
                m.entry(name.as_str())
                    .or_default()
                    .extend(values.iter().map(String::as_str));
            }
        }
        m
    };
    let mut failures = Vec::new();
    for (name, text) in texts() {
        for (opt, values) in option_mentions(&text) {
            if OTHER_PROGRAMS_OPTIONS.contains(&opt.as_str()) {
                continue;
            }
            let Some(possible) = known.get(opt.as_str()) else {
                failures.push(format!("{name}: --{opt} is no option of roughtui"));
                continue;
            };
            if possible.is_empty() {
                continue;
            }
            for v in &values {
                if !possible.contains(v.as_str()) {
                    failures.push(format!(
                        "{name}: --{opt} {v}: not one of its values ({})",
                        possible.iter().copied().collect::<Vec<_>>().join(", ")
                    ));
                }
            }
        }
        // A synopsis lists every value of the options it lists values of.
        for block in text.split("```text\n").skip(1) {
            let block = block.split("```").next().unwrap_or("");
            if !block.trim_start().starts_with("roughtui") {
                continue;
            }
            for (opt, values) in option_mentions(block) {
                let Some(possible) = known.get(opt.as_str()) else {
                    continue;
                };
                let given: BTreeSet<&str> = values.iter().map(String::as_str).collect();
                if !values.is_empty() && &given != possible {
                    failures.push(format!(
                        "{name}: the synopsis gives --{opt} {}; roughtui takes {}",
                        values.join("|"),
                        possible.iter().copied().collect::<Vec<_>>().join("|")
                    ));
                }
            }
        }
    }
    // Every option and every value of every command is said somewhere.
    let all = all_text();
    let mentioned: BTreeMap<String, BTreeSet<String>> = {
        let mut m: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (opt, values) in option_mentions(&all) {
            m.entry(opt).or_default().extend(values);
        }
        m
    };
    let flat: String = all.split_whitespace().collect::<Vec<_>>().join(" ");
    for (command, o) in &opts {
        for (opt, values) in o {
            if matches!(opt.as_str(), "help" | "version") {
                continue;
            }
            let Some(said) = mentioned.get(opt) else {
                failures.push(format!(
                    "--{opt} (roughtui {command} --help) is in no page of the manual"
                ));
                continue;
            };
            for v in values {
                let named = said.contains(v)
                    || flat.contains(&format!("--{opt} {v}"))
                    || (opt == "view" && flat.contains(&format!("`{v}`")));
                if !named {
                    failures.push(format!(
                        "--{opt} {v} (roughtui {command} --help) is in no page of the manual"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn options_are_read_as_the_pages_write_them() {
    let m = option_mentions("`--view slopes|indices` and --format\nsvg, a--b, --set h-rms=2nm");
    assert_eq!(
        m,
        [
            (
                "view".to_string(),
                vec!["slopes".to_string(), "indices".to_string()]
            ),
            ("format".to_string(), vec![]),
            ("set".to_string(), vec![]),
        ]
    );
}

/// The keys of a row's first cell (`↑ ↓, k j`, `[ ] and { }`, `q, Ctrl-C`):
/// the words that are keys.
fn key_words(cell: &str) -> Vec<String> {
    cell.replace(['`', ','], " ")
        .split_whitespace()
        .filter(|w| !matches!(*w, "and" | "or"))
        .map(String::from)
        .collect()
}

#[test]
fn the_key_table_is_the_explorers() {
    use roughtui::tui::keys::{Context, BINDINGS};
    let page = std::fs::read_to_string(format!("{ROOT}/docs/explorer.md")).unwrap();
    let table: Vec<&str> = page
        .lines()
        .skip_while(|l| !l.starts_with("Keys (one table drives"))
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .collect();
    assert!(table.len() >= 15, "docs/explorer.md's key table: {table:?}");
    // Rows about served sessions and prompts name their keys in the second
    // cell (teaching.md has the class's).
    let documented: BTreeSet<String> = table
        .iter()
        .map(|r| r.trim_matches('|').split('|').next().unwrap().trim())
        .filter(|c| !c.starts_with("served") && !c.starts_with("in a prompt"))
        .flat_map(key_words)
        .collect();
    let explorer = |c: Context| {
        matches!(
            c,
            Context::Main
                | Context::MainAndHelp
                | Context::NotStudent
                | Context::Surface
                | Context::ContactView
                | Context::Any
        )
    };
    let bound: BTreeSet<String> = BINDINGS
        .iter()
        .filter(|b| explorer(b.context))
        .flat_map(|b| key_words(b.label))
        .collect();
    let mut failures = Vec::new();
    for k in &bound {
        if !documented.contains(k) {
            failures.push(format!(
                "the explorer's key {k} (tui::keys::BINDINGS) is not in docs/explorer.md's key table"
            ));
        }
    }
    for k in &documented {
        if !bound.contains(k) {
            failures.push(format!(
                "docs/explorer.md's key table names {k}, which the explorer does not bind"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
