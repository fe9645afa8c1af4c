//! The layers of docs/development.md, checked: each module of the
//! application uses only modules on the floors below its own (and those
//! beside it where the drawing says so), each library crate knows nothing
//! of the application, no module of a crate is part of an import circle,
//! and no source file (of `src/` and the crates' `src/`) is over 600 lines.
//!
//! A module's uses are the `crate::NAME` paths of its code: test modules
//! (after `#[cfg(test)]`, and `*_tests.rs` files), comments and string
//! literals are not code that runs, so they are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The application's floors, from the ground up; a module may use any
/// module on a lower floor.
const FLOORS: &[&[&str]] = &[
    &["physical"],
    &["surface"],
    &["scene"],
    &["snapshot"],
    &["presets"],
    &["figure", "contact"],
    &["cli", "class"],
    &["export"],
    &["tui"],
    &["serve", "bench"],
];

/// Uses within a floor or upwards that the drawing allows, with why.
/// None today: every floor only looks down.
const ALLOWED: &[(&str, &str, &str)] = &[];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The code of a file: no test module, comments or string literals.
fn code(text: &str) -> String {
    let text = match text.find("#[cfg(test)]") {
        Some(i) => &text[..i],
        None => text,
    };
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    let mut in_str = false;
    while let Some(c) = chars.next() {
        if in_str {
            match c {
                '\\' => {
                    chars.next();
                }
                '"' => in_str = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => in_str = true,
            '/' if chars.peek() == Some(&'/') => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        out.push('\n');
                        break;
                    }
                }
            }
            // A char literal holding a quote ('"') is not a string.
            '\'' => {
                out.push(c);
                let rest: String = chars.clone().take(3).collect();
                if rest.starts_with("\"'") || rest.starts_with("\\\"") {
                    chars.next();
                }
            }
            c => out.push(c),
        }
    }
    out
}

/// The `crate::NAME` modules a piece of code names (also inside
/// `crate::{a, b::c}` groups).
fn uses(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let after = &rest[i + "crate::".len()..];
        let before_ok = rest[..i]
            .chars()
            .last()
            .is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
        if before_ok {
            if let Some(group) = after.strip_prefix('{') {
                let end = group.find('}').unwrap_or(group.len());
                for item in group[..end].split(',') {
                    let name: String = item
                        .trim()
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    if !name.is_empty() {
                        out.insert(name);
                    }
                }
            } else {
                let name: String = after
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    out.insert(name);
                }
            }
        }
        rest = after;
    }
    out
}

/// Each top module of the crate at `src` and the top modules its code uses.
fn module_uses(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in files {
        let rel = f.strip_prefix(src).unwrap();
        let top = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if ["lib", "main"].contains(&top.as_str()) || f.to_string_lossy().ends_with("_tests.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        let used = out.entry(top.clone()).or_default();
        for m in uses(&code(&text)) {
            if m != top {
                used.insert(m);
            }
        }
    }
    out
}

fn floor(m: &str) -> Option<usize> {
    FLOORS.iter().position(|f| f.contains(&m))
}

#[test]
fn the_application_only_looks_down() {
    let graph = module_uses(&Path::new(ROOT).join("src"));
    let mut wrong = Vec::new();
    for (m, used) in &graph {
        let Some(own) = floor(m) else {
            wrong.push(format!("src/{m} is on no floor of tests/layers.rs"));
            continue;
        };
        for u in used {
            let Some(theirs) = floor(u) else {
                wrong.push(format!("{m} uses crate::{u}, which is on no floor"));
                continue;
            };
            let allowed = ALLOWED.iter().any(|(a, b, _)| a == m && b == u);
            if theirs >= own && !allowed {
                wrong.push(format!(
                    "{m} (floor {own}) uses {u} (floor {theirs}): a layer may only look down"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // The floors are real: every one of them is there.
    for f in FLOORS.iter().flat_map(|f| f.iter()) {
        assert!(graph.contains_key(*f), "floor module {f} is missing");
    }
}

#[test]
fn the_crates_know_nothing_of_the_application() {
    for c in [
        "rough-model",
        "rough-surface",
        "rough-contact",
        "rough-study",
        "rough-fft",
    ] {
        let dir = Path::new(ROOT).join("crates").join(c);
        let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).unwrap();
        assert!(
            !manifest
                .lines()
                .any(|l| l.trim_start().starts_with("roughtui")),
            "{c}'s Cargo.toml depends on the application"
        );
        let mut files = Vec::new();
        rust_files(&dir.join("src"), &mut files);
        for f in files {
            let text = std::fs::read_to_string(&f).unwrap();
            assert!(
                !code(&text).contains("roughtui::"),
                "{} uses the application",
                f.display()
            );
        }
    }
}

/// A cycle among `graph`'s modules, if there is one.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        path: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(m.to_string(), 1);
        path.push(m.to_string());
        for n in graph.get(m).into_iter().flatten() {
            match state.get(n.as_str()) {
                Some(1) => {
                    let at = path.iter().position(|p| p == n).unwrap();
                    let mut c = path[at..].to_vec();
                    c.push(n.clone());
                    return Some(c);
                }
                Some(_) => {}
                None => {
                    if let Some(c) = visit(n, graph, state, path) {
                        return Some(c);
                    }
                }
            }
        }
        path.pop();
        state.insert(m.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for m in graph.keys() {
        if !state.contains_key(m) {
            if let Some(c) = visit(m, graph, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

/// The paths a use tree names, from its start in `s`: `a::b` one,
/// `a::{b, c::{d, e}}` three; `self` in a group is the path before it.
fn use_tree(s: &str) -> Vec<Vec<String>> {
    fn word(s: &[char], i: &mut usize) -> String {
        let start = *i;
        while *i < s.len() && (s[*i].is_alphanumeric() || s[*i] == '_') {
            *i += 1;
        }
        s[start..*i].iter().collect()
    }
    fn blank(s: &[char], i: &mut usize) {
        while *i < s.len() && s[*i].is_whitespace() {
            *i += 1;
        }
    }
    fn tree(s: &[char], i: &mut usize) -> Vec<Vec<String>> {
        let mut prefix = Vec::new();
        loop {
            blank(s, i);
            if s.get(*i) == Some(&'{') {
                *i += 1;
                let mut out = Vec::new();
                loop {
                    blank(s, i);
                    if s.get(*i).is_none_or(|c| *c == '}') {
                        *i += 1;
                        return out;
                    }
                    for p in tree(s, i) {
                        out.push([prefix.clone(), p].concat());
                    }
                    blank(s, i);
                    // `as name` and the like end an item.
                    while *i < s.len() && !matches!(s[*i], ',' | '}') {
                        *i += 1;
                    }
                    if s.get(*i) == Some(&',') {
                        *i += 1;
                    }
                }
            }
            let w = word(s, i);
            if w.is_empty() {
                return vec![prefix];
            }
            if w != "self" {
                prefix.push(w);
            }
            if s[*i..].starts_with(&[':', ':']) {
                *i += 2;
            } else {
                return vec![prefix];
            }
        }
    }
    let s: Vec<char> = s.chars().collect();
    tree(&s, &mut 0)
}

/// Each file of the crate at `src` as its module path (`formats::readers::x3p`;
/// a `mod.rs` is its folder's module) and the modules of the crate its code
/// uses: its `crate::`, `super::` and `self::` paths, each to the longest
/// module it names, and the modules it declares by their bare names
/// (`sniff::format`). What a module takes from the folder's module it sits
/// in (`super::Thing` of its `mod.rs`) is part of being inside it, not a
/// use; the crate's root (`lib.rs`) only declares and re-exports, as in
/// [`module_uses`].
fn file_uses(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let module = |f: &Path| -> Vec<String> {
        let rel = f.strip_prefix(src).unwrap().with_extension("");
        let mut m: Vec<String> = rel
            .components()
            .map(|c| c.as_os_str().to_string_lossy().to_string())
            .collect();
        if m.last()
            .is_some_and(|l| l == "mod" || l == "lib" || l == "main")
        {
            m.pop();
        }
        m
    };
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module(f)).collect();
    let longest = |path: Vec<String>| -> Vec<String> {
        (0..=path.len())
            .rev()
            .map(|k| path[..k].to_vec())
            .find(|p| modules.contains(p))
            .unwrap_or_default()
    };
    let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':');
    let mut out = BTreeMap::new();
    for f in &files {
        let own = module(f);
        if own.is_empty() || f.to_string_lossy().ends_with("_tests.rs") {
            continue;
        }
        let code = code(&std::fs::read_to_string(f).unwrap());
        let children: Vec<String> = code
            .lines()
            .filter_map(|l| {
                let l = l.trim().strip_suffix(';')?;
                let name = l
                    .strip_prefix("mod ")
                    .or_else(|| l.split_once(" mod ").map(|x| x.1))?;
                Some(name.trim().to_string())
            })
            .collect();
        let mut used = BTreeSet::new();
        for (at, _) in code.char_indices() {
            let rest = &code[at..];
            if ident(code[..at].chars().last()) {
                continue;
            }
            let (base, path) = if let Some(p) = rest.strip_prefix("crate::") {
                (Vec::new(), p)
            } else if rest.starts_with("super::") || rest.starts_with("self::") {
                let mut base = own.clone();
                let mut p = rest;
                if let Some(q) = p.strip_prefix("self::") {
                    p = q;
                }
                while let Some(q) = p.strip_prefix("super::") {
                    base.pop();
                    p = q;
                }
                (base, p)
            } else if let Some(c) = children
                .iter()
                .find(|c| rest.starts_with(&format!("{c}::")))
            {
                (own.clone(), &rest[..c.len()])
            } else {
                continue;
            };
            for p in use_tree(path) {
                let m = longest([base.clone(), p].concat());
                if !m.is_empty() && !own.starts_with(&m) {
                    used.insert(m.join("::"));
                }
            }
        }
        out.insert(own.join("::"), used);
    }
    out
}

#[test]
fn no_module_of_a_crate_is_in_an_import_circle() {
    for c in [
        "rough-model",
        "rough-surface",
        "rough-contact",
        "rough-study",
    ] {
        let src = Path::new(ROOT).join("crates").join(c).join("src");
        // Its top modules (a folder is one), then each file.
        let graph = module_uses(&src);
        assert!(graph.len() > 2, "{c}: too few modules found");
        if let Some(cycle) = circle(&graph) {
            panic!("{c}: modules import each other: {}", cycle.join(" → "));
        }
        if let Some(cycle) = circle(&file_uses(&src)) {
            panic!("{c}: modules import each other: {}", cycle.join(" → "));
        }
    }
}

#[test]
fn the_file_reader_follows_paths_to_their_modules() {
    assert_eq!(
        use_tree("a::{self, b::{c, D as E}, f}::g; x"),
        [
            vec!["a".to_string()],
            vec!["a".into(), "b".into(), "c".into()],
            vec!["a".into(), "b".into(), "D".into()],
            vec!["a".into(), "f".into()],
        ]
    );
    let graph = file_uses(&Path::new(ROOT).join("crates/rough-surface/src"));
    let uses = |m: &str| graph[m].iter().map(String::as_str).collect::<Vec<_>>();
    // `use crate::formats::readers::grid::{self, Grid}` and its kin.
    assert!(
        uses("read").contains(&"formats::readers::grid"),
        "{:?}",
        uses("read")
    );
    // `use super::bin::{...}` beside it; `sniff::Format` in the folder's own module.
    assert!(uses("formats::readers::sur").contains(&"formats::readers::bin"));
    assert!(
        uses("formats").contains(&"formats::sniff"),
        "{:?}",
        uses("formats")
    );
}

#[test]
fn no_source_file_is_over_600_lines() {
    let mut files = Vec::new();
    rust_files(&Path::new(ROOT).join("src"), &mut files);
    for c in [
        "rough-model",
        "rough-surface",
        "rough-contact",
        "rough-study",
        "rough-fft",
    ] {
        rust_files(
            &Path::new(ROOT).join("crates").join(c).join("src"),
            &mut files,
        );
    }
    let mut long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > 600).then(|| format!("{} has {n} lines", f.display()))
        })
        .collect();
    long.sort();
    assert!(long.is_empty(), "{}", long.join("\n"));
}

#[test]
fn the_reader_sees_uses_as_code_has_them() {
    let c = code("use crate::a::B; // crate::c\nlet s = \"crate::d\";\nuse crate::{e, f::g};\n#[cfg(test)]\nuse crate::h;");
    let u = uses(&c);
    assert_eq!(
        u.into_iter().collect::<Vec<_>>(),
        ["a", "e", "f"].map(String::from)
    );
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("a".to_string(), ["b".to_string()].into()),
        ("b".to_string(), ["a".to_string()].into()),
    ]
    .into();
    assert_eq!(circle(&graph).unwrap(), ["a", "b", "a"]);
}
