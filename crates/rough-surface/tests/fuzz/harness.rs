//! What a hostile-file test needs beside [`crate::fuzz`]'s allocator and
//! mutation: the refusals, the cuts, and the check of one mutated file.

// Each test binary uses what it needs of it.
#![allow(dead_code)]

use std::sync::atomic::{AtomicUsize, Ordering};

use rough_surface::{parse_named, read_grid_named, Options};

/// Every allocation of a hostile-file test stays below this (the largest
/// file is 4 MB, its heights 2.5 MB; a mutated header can claim at most
/// what the file holds; the HDF5 reader's chunk cache holds 16 MB at most).
pub const CEILING: usize = 64 << 20;

/// The refusal of `b` (a file named `name`) as a line; that no
/// allocation passed [`CEILING`].
pub fn refuse(name: &str, b: &[u8]) -> String {
    let e = read_grid_named(b, name, &Options::default()).expect_err("refused");
    assert!(largest() < CEILING);
    let line = e.1.to_string();
    assert!(!line.contains('\n'), "{line}");
    line
}

/// File `full` (named `name`) cut short at several places — in its
/// header, a quarter and half way, and (with `last`) by its last byte —
/// each refused, naming `format`; cut at `early` bytes, before what tells
/// it apart (its magic, an Igor wave's 384 bytes of headers and their
/// checksum), it is text or a binary file not read.
pub fn truncated(full: &[u8], name: &str, format: &str, last: bool, early: &[usize]) {
    let mut cuts = vec![600, full.len() / 4, full.len() / 2];
    if last {
        cuts.push(full.len() - 1);
    }
    for cut in cuts {
        let e = refuse(name, &full[..cut.min(full.len() - 1)]);
        assert!(e.starts_with(format), "{name} cut at {cut}: {e}");
    }
    for &cut in early {
        let e = refuse(name, &full[..cut]);
        let told = e.starts_with(format) || e.starts_with("a binary file");
        assert!(told || e.starts_with("text: "), "{name} cut at {cut}: {e}");
    }
}

/// The bytes of the file at `path` (unpacked when its name ends in `.gz`).
pub fn file_bytes(path: &std::path::Path) -> Vec<u8> {
    let b = std::fs::read(path).unwrap();
    if path.extension().is_none_or(|e| e != "gz") {
        return b;
    }
    let mut out = Vec::new();
    std::io::Read::read_to_end(&mut flate2::read::GzDecoder::new(&b[..]), &mut out).unwrap();
    out
}

/// `v` written into `b` at `at`.
pub fn put(b: &mut [u8], at: usize, v: &[u8]) {
    b[at..at + v.len()].copy_from_slice(v);
}

/// Mutated files a file: `FUZZ_CASES`, 48 by default.
pub fn cases() -> u32 {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(48)
}

/// The largest allocation so far ([`crate::fuzz::Counting`]'s record).
pub fn largest() -> usize {
    crate::fuzz::LARGEST.load(Ordering::Relaxed)
}

static RUNS: AtomicUsize = AtomicUsize::new(0);
static REFUSED: AtomicUsize = AtomicUsize::new(0);

/// `original` changed by `ops` (and, one time in five, cut short at
/// `cut`), read as a file named `name`: a refusal must be one line, a grid
/// must hold its points; a file under 100 KB goes through the whole
/// pipeline too. The reason when not.
pub fn read_mutated(
    original: &[u8],
    name: &str,
    ops: &[(u8, usize, u8)],
    cut: usize,
) -> Result<(), String> {
    let mut b = crate::fuzz::mutate(original, ops);
    if cut.is_multiple_of(5) && !b.is_empty() {
        b.truncate(cut % b.len());
    }
    let r = read_grid_named(&b, name, &Options::default());
    RUNS.fetch_add(1, Ordering::Relaxed);
    match &r {
        Err((_, p)) => {
            REFUSED.fetch_add(1, Ordering::Relaxed);
            let line = p.to_string();
            if line.is_empty() || line.contains('\n') {
                return Err(format!("not one line: {line:?}"));
            }
        }
        Ok(g) if g.z.len() != g.nx * g.ny => {
            return Err(format!("{} heights for {} × {}", g.z.len(), g.nx, g.ny))
        }
        Ok(_) => {}
    }
    if original.len() < 100_000 {
        let _ = parse_named(&b, name, &Options::default());
    }
    Ok(())
}

/// How many mutated files were read and refused, and the largest
/// allocation, for the record.
pub fn counts() -> String {
    format!(
        "fuzz: {} mutated files read, {} refused; largest allocation {} bytes",
        RUNS.load(Ordering::Relaxed),
        REFUSED.load(Ordering::Relaxed),
        largest()
    )
}

/// The mutation fuzz of a test binary's example files: `$files` (an
/// array of names) each mutated `FUZZ_CASES` times (48 by default), from
/// `FUZZ_SEED`'s seed, each file's bytes (`$bytes(name)`) read once; each
/// mutated file checked by [`read_mutated`] (named without a `.gz`) and
/// no allocation past [`CEILING`]. Then `zz_fuzz_counts`, which prints
/// [`counts`] (after the fuzz when the tests run single-threaded).
#[macro_export]
macro_rules! mutation_fuzz {
    ($files:expr, $bytes:expr) => {
        proptest::proptest! {
            #![proptest_config(proptest::test_runner::Config {
                cases: $crate::harness::cases() * $files.len() as u32,
                rng_seed: $crate::fuzz::seed(),
                ..proptest::test_runner::Config::default()
            })]

            #[test]
            fn mutated_files_never_panic(
                which in 0..$files.len(),
                ops in proptest::collection::vec(
                    (
                        proptest::prelude::any::<u8>(),
                        proptest::prelude::any::<usize>(),
                        proptest::prelude::any::<u8>(),
                    ),
                    1..6,
                ),
                cut in proptest::prelude::any::<usize>(),
            ) {
                thread_local!(static CACHE: std::cell::RefCell<Vec<Option<Vec<u8>>>> =
                    std::cell::RefCell::new(vec![None; $files.len()]));
                let name = $files[which];
                let original = CACHE.with(|c| {
                    c.borrow_mut()[which].get_or_insert_with(|| $bytes(name)).clone()
                });
                $crate::harness::read_mutated(&original, name.trim_end_matches(".gz"), &ops, cut)
                    .map_err(proptest::test_runner::TestCaseError::fail)?;
                proptest::prop_assert!($crate::harness::largest() < $crate::harness::CEILING);
            }
        }

        #[test]
        fn zz_fuzz_counts() {
            // Printed for the record (run after the fuzz when single-threaded).
            eprintln!("{}", $crate::harness::counts());
        }
    };
}
