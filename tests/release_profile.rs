//! The installed binary carries no debug information, and profiling has
//! its own profile (the release build with line tables) that the callgrind
//! script uses.

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The lines of `[section]` in Cargo.toml, trimmed.
fn section(toml: &str, name: &str) -> Vec<String> {
    let head = format!("[{name}]");
    toml.lines()
        .skip_while(|l| l.trim() != head)
        .skip(1)
        .take_while(|l| !l.trim_start().starts_with('['))
        .map(|l| l.trim().to_string())
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .collect()
}

#[test]
fn release_has_no_debug_information_and_profiling_has_its_own_profile() {
    let toml = std::fs::read_to_string(format!("{ROOT}/Cargo.toml")).unwrap();
    let release = section(&toml, "profile.release");
    assert!(
        release.contains(&"debug = false".to_string()),
        "{release:?}"
    );
    assert!(
        release.contains(&"strip = \"debuginfo\"".to_string()),
        "{release:?}"
    );
    let profiling = section(&toml, "profile.profiling");
    assert!(
        profiling.contains(&"inherits = \"release\"".to_string()),
        "{profiling:?}"
    );
    assert!(
        profiling.contains(&"debug = 1".to_string()),
        "{profiling:?}"
    );
    let script = std::fs::read_to_string(format!("{ROOT}/scripts/bench_callgrind.sh")).unwrap();
    assert!(
        script.contains("bin=target/profiling/examples/cost"),
        "{script}"
    );
    // `cargo install --locked` needs the lock file in the repository.
    assert!(std::path::Path::new(&format!("{ROOT}/Cargo.lock")).is_file());
}
