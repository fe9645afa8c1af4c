//! The screens and outputs the documentation shows are the program's own.
//!
//! A fenced block under a marker is made by the program:
//!
//! ```text
//! <!-- screen: [VAR=VALUE …] roughtui ARGS · 80x24 [· keys K K …] [· REGION] -->
//! <!-- output: [VAR=VALUE …] roughtui ARGS [· csv-head | · head N] -->
//! ```
//!
//! A `screen` is the explorer drawn without a terminal
//! ([`roughtui::tui::screen`]: started as `roughtui ARGS` starts, in a
//! terminal of that size with LANG=C.UTF-8, TERM=xterm-256color and the
//! variables given, after the keys), the whole screen or one of its
//! regions (`chart`, `sliders`, `readout`, `status`, …). An `output` is
//! what the command prints (stdout, then stderr), run in a folder holding
//! the files the documented commands name, the explorer, `serve` and
//! `bench` with `ROUGHTUI_CHECK_ONLY=1`; several `output` markers over one
//! block give their outputs in turn.
//!
//! The test fails while a block differs from what the program makes;
//! `ROUGHTUI_UPDATE_DOCS=1 cargo test --test docs_blocks` (or
//! `scripts/gen_docs.sh screens`) writes the blocks again. A block that
//! looks like a screen (braille, chart axes, a slider's `▶`) must have a
//! marker.

mod common;

/// The class pictures' maker (docs/teaching.md), its `main` unused here.
#[path = "../examples/class_screenshot.rs"]
#[allow(dead_code)]
mod class_screenshot;

use std::path::Path;
use std::process::{Command, Stdio};

use common::docs::{self, pages, words, workspace};
use roughtui::tui::screen;

/// What makes a block.
#[derive(Debug)]
enum Maker {
    Screen {
        env: Env,
        args: Vec<String>,
        size: (u16, u16),
        keys: String,
        region: Option<String>,
    },
    Output {
        env: Env,
        args: Vec<String>,
        cut: Cut,
    },
}

/// Which lines of an output a block shows.
#[derive(Debug)]
enum Cut {
    All,
    /// The first N lines.
    Head(usize),
    /// A CSV's `#` lines and its header.
    CsvHead,
}

/// A marked block: where it is and what makes it.
struct Block {
    /// The markers' text, for messages.
    marker: String,
    line: usize,
    makers: Vec<Maker>,
    /// The fence's indentation (a block in a list item).
    indent: String,
    /// Lines of the page: the block's content is `start..end`.
    start: usize,
    end: usize,
}

/// Environment variables a marker sets, as (name, value).
type Env = Vec<(String, String)>;

/// `VAR=VALUE … roughtui ARGS`: the variables and the arguments.
fn command(text: &str) -> Result<(Env, Vec<String>), String> {
    let mut w = words(text, Path::new("/nonexistent"))
        .into_iter()
        .peekable();
    let mut env = Vec::new();
    while let Some((k, v)) = w.peek().and_then(|x| x.split_once('=')) {
        if !k.chars().all(|c| c.is_ascii_uppercase() || c == '_') {
            break;
        }
        env.push((k.to_string(), v.to_string()));
        w.next();
    }
    if w.next().as_deref() != Some("roughtui") {
        return Err(format!("`{text}`: a roughtui command"));
    }
    Ok((env, w.collect()))
}

fn maker(kind: &str, spec: &str) -> Result<Maker, String> {
    let mut parts = spec.split(" · ").map(str::trim);
    let (env, args) = command(parts.next().unwrap_or(""))?;
    match kind {
        "screen" => {
            let (mut size, mut keys, mut region) = (None, String::new(), None);
            for p in parts {
                if let Some(k) = p.strip_prefix("keys ") {
                    keys = k.to_string();
                } else if let Some((w, h)) = p.split_once('x') {
                    let n = |s: &str| s.parse::<u16>().map_err(|_| format!("{p}: a size WxH"));
                    size = Some((n(w)?, n(h)?));
                } else {
                    region = Some(p.to_string());
                }
            }
            let size = size.ok_or("a screen needs its size (80x24)")?;
            Ok(Maker::Screen {
                env,
                args,
                size,
                keys,
                region,
            })
        }
        _ => {
            let cut = match parts.next() {
                None => Cut::All,
                Some("csv-head") => Cut::CsvHead,
                Some(p) => match p.strip_prefix("head ").and_then(|n| n.parse().ok()) {
                    Some(n) => Cut::Head(n),
                    None => return Err(format!("{p}: csv-head or head N")),
                },
            };
            Ok(Maker::Output { env, args, cut })
        }
    }
}

/// The marked blocks of `text`; unmarked blocks that look like screens are
/// errors.
fn blocks(text: &str) -> Result<Vec<Block>, Vec<String>> {
    let lines: Vec<&str> = text.lines().collect();
    let (mut out, mut errors) = (Vec::new(), Vec::new());
    let mut pending: Vec<(usize, &str, &str)> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let t = lines[i].trim();
        if let Some(m) = t.strip_prefix("<!-- ").and_then(|m| m.strip_suffix(" -->")) {
            if let Some((kind @ ("screen" | "output"), spec)) = m.split_once(": ") {
                pending.push((i + 1, kind, spec));
                i += 1;
                continue;
            }
        }
        if !t.starts_with("```") {
            if !pending.is_empty() && !t.is_empty() {
                errors.push(format!("line {}: a marker not over a block", pending[0].0));
                pending.clear();
            }
            i += 1;
            continue;
        }
        let indent = lines[i][..lines[i].len() - lines[i].trim_start().len()].to_string();
        let info = t.trim_start_matches('`').trim();
        let close = (i + 1..lines.len())
            .find(|&j| lines[j].trim() == "```")
            .unwrap_or(lines.len());
        let body = &lines[i + 1..close];
        if pending.is_empty() {
            let screen_like = body.iter().any(|l| {
                l.chars()
                    .any(|c| ('\u{2801}'..='\u{28FF}').contains(&c) || "┤└▶↔".contains(c))
            });
            if screen_like && !matches!(info, "sh" | "bash" | "shell") {
                errors.push(format!(
                    "line {}: a screen without a marker (<!-- screen: roughtui … · 80x24 -->)",
                    i + 1
                ));
            }
        } else {
            let makers: Result<Vec<Maker>, String> =
                pending.iter().map(|(_, k, s)| maker(k, s)).collect();
            match makers {
                Ok(makers) => out.push(Block {
                    marker: pending
                        .iter()
                        .map(|(_, k, s)| format!("{k}: {s}"))
                        .collect::<Vec<_>>()
                        .join(" + "),
                    line: pending[0].0,
                    makers,
                    indent,
                    start: i + 1,
                    end: close,
                }),
                Err(e) => errors.push(format!("line {}: {e}", pending[0].0)),
            }
            pending.clear();
        }
        i = close + 1;
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// The environment a documented screen is drawn in: a UTF-8 terminal, the
/// variables the marker gives.
fn screen_env(given: &[(String, String)]) -> impl Fn(&str) -> Option<String> + '_ {
    move |k: &str| {
        if let Some((_, v)) = given.iter().find(|(g, _)| g == k) {
            return Some(v.clone());
        }
        match k {
            "LANG" => Some("C.UTF-8".into()),
            "TERM" => Some("xterm-256color".into()),
            _ => None,
        }
    }
}

/// The lines `m` makes.
fn make(m: &Maker, dir: &Path) -> Result<Vec<String>, String> {
    match m {
        Maker::Screen {
            env,
            args,
            size,
            keys,
            region,
        } => {
            let keys = screen::parse_keys(keys)?;
            let s =
                screen::draw(args, screen_env(env), *size, &keys).map_err(|e| format!("{e:#}"))?;
            let area = match region {
                None => None,
                Some(r) => Some(s.region(r).ok_or(format!("no region {r} on this screen"))?),
            };
            let mut lines = s.text(area);
            while lines.last().is_some_and(|l| l.is_empty()) {
                lines.pop();
            }
            Ok(lines)
        }
        Maker::Output { env, args, cut } => {
            let mut cmd = Command::new(common::cli::BIN);
            cmd.args(args)
                .stdin(Stdio::null())
                .current_dir(dir)
                .env("HOME", dir.join("home"))
                .env_remove("NO_COLOR");
            if args.first().map(String::as_str) != Some("export") {
                cmd.env("ROUGHTUI_CHECK_ONLY", "1");
            }
            for (k, v) in env {
                cmd.env(k, v);
            }
            let out = cmd.output().map_err(|e| e.to_string())?;
            let text = String::from_utf8_lossy(&out.stdout).into_owned()
                + &String::from_utf8_lossy(&out.stderr);
            let lines = text.lines().map(|l| l.trim_end().to_string());
            Ok(match cut {
                Cut::All => lines.collect(),
                Cut::Head(n) => lines.take(*n).collect(),
                Cut::CsvHead => {
                    let mut v: Vec<String> = Vec::new();
                    for l in lines {
                        let header = !l.starts_with('#');
                        v.push(l);
                        if header {
                            break;
                        }
                    }
                    v
                }
            })
        }
    }
}

fn updating() -> bool {
    std::env::var_os("ROUGHTUI_UPDATE_DOCS").is_some_and(|v| v == "1")
}

#[test]
fn every_screen_and_output_shown_is_the_programs() {
    let dir = workspace();
    let (mut failures, mut count, mut written) = (Vec::new(), 0, Vec::new());
    for path in pages() {
        let name = docs::name(&path);
        let text = std::fs::read_to_string(&path).unwrap();
        let found = match blocks(&text) {
            Ok(b) => b,
            Err(e) => {
                failures.extend(e.into_iter().map(|e| format!("{name}: {e}")));
                continue;
            }
        };
        let mut lines: Vec<String> = text.lines().map(String::from).collect();
        // From the last block up, so that the earlier ones keep their lines.
        for b in found.iter().rev() {
            count += 1;
            let made: Result<Vec<String>, String> = b
                .makers
                .iter()
                .map(|m| make(m, dir.path()))
                .collect::<Result<Vec<_>, _>>()
                .map(|v| v.concat());
            let made = match made {
                Ok(m) => m,
                Err(e) => {
                    failures.push(format!("{name}:{}: `{}`: {e}", b.line, b.marker));
                    continue;
                }
            };
            let want: Vec<String> = made
                .iter()
                .map(|l| {
                    if l.is_empty() {
                        String::new()
                    } else {
                        format!("{}{l}", b.indent)
                    }
                })
                .collect();
            let shown = &lines[b.start..b.end];
            if shown != want.as_slice() {
                if updating() {
                    lines.splice(b.start..b.end, want);
                    written.push(format!("{name}:{}", b.line));
                    continue;
                }
                let at = shown
                    .iter()
                    .zip(&want)
                    .position(|(a, b)| a != b)
                    .unwrap_or(shown.len().min(want.len()));
                failures.push(format!(
                    "{name}:{}: the block under `{}` is not what the program shows \
                     ({} lines shown, {} made); first difference, line {}:\n  shown: {:?}\n  made:  {:?}",
                    b.line,
                    b.marker,
                    shown.len(),
                    want.len(),
                    b.start + at + 1,
                    shown.get(at).map_or("", String::as_str),
                    want.get(at).map_or("", String::as_str),
                ));
            }
        }
        if updating() && written.iter().any(|w| w.starts_with(&format!("{name}:"))) {
            let mut out = lines.join("\n");
            out.push('\n');
            std::fs::write(&path, out).unwrap();
        }
    }
    for w in &written {
        eprintln!("wrote the block at {w}");
    }
    assert!(count >= 6, "only {count} marked blocks found");
    assert!(
        failures.is_empty(),
        "{}\n\nMake them again with `scripts/gen_docs.sh screens` \
         (ROUGHTUI_UPDATE_DOCS=1 cargo test --test docs_blocks).",
        failures.join("\n")
    );
}

#[test]
fn markers_are_read_as_written() {
    let page = "text\n<!-- screen: NO_COLOR=1 roughtui --preset fig3 · 100x30 · keys Tab Tab · chart -->\n   ```text\n   old\n   ```\n<!-- output: roughtui --set zeta=0 -->\n<!-- output: roughtui export · csv-head -->\n```text\n```\n";
    let b = blocks(page).unwrap();
    assert_eq!(b.len(), 2);
    assert_eq!((b[0].start, b[0].end, b[0].indent.as_str()), (3, 4, "   "));
    match &b[0].makers[0] {
        Maker::Screen {
            env,
            args,
            size,
            keys,
            region,
        } => {
            assert_eq!(env, &[("NO_COLOR".to_string(), "1".to_string())]);
            assert_eq!(args, &["--preset", "fig3"]);
            assert_eq!(*size, (100, 30));
            assert_eq!(keys, "Tab Tab");
            assert_eq!(region.as_deref(), Some("chart"));
        }
        m => panic!("{m:?}"),
    }
    assert_eq!(b[1].makers.len(), 2);
    assert!(matches!(
        b[1].makers[1],
        Maker::Output {
            cut: Cut::CsvHead,
            ..
        }
    ));
    assert_eq!((b[1].start, b[1].end), (8, 8));
    let unmarked = "```text\n ▶ ζ    ↔       128\n```\n";
    assert!(blocks(unmarked).is_err());
}

/// docs/teaching.md's pictures of the lecturer's screen during a poll and
/// after its reveal are what `examples/class_screenshot.rs` draws now.
#[test]
fn the_class_pictures_are_the_programs() {
    let mut failures = Vec::new();
    for (revealed, file) in [
        (false, "docs/class-poll.svg"),
        (true, "docs/class-reveal.svg"),
    ] {
        let made = class_screenshot::picture(revealed).unwrap();
        let path = Path::new(docs::ROOT).join(file);
        if std::fs::read_to_string(&path).ok().as_deref() == Some(made.as_str()) {
            continue;
        }
        if updating() {
            std::fs::write(&path, made).unwrap();
            eprintln!("wrote {file}");
        } else {
            failures.push(format!(
                "{file} is not what examples/class_screenshot.rs draws now"
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{}\n\nMake them again with `scripts/gen_docs.sh screens` \
         (ROUGHTUI_UPDATE_DOCS=1 cargo test --test docs_blocks).",
        failures.join("\n")
    );
}
