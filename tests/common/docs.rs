//! What the documentation tests share: the pages, a folder holding the
//! files the documented commands name, and shell words.

use std::path::{Path, PathBuf};

pub const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// `README.md` and `docs/*.md`, sorted.
pub fn pages() -> Vec<PathBuf> {
    let mut files = vec![PathBuf::from(ROOT).join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(Path::new(ROOT).join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
}

/// A page's path as the messages name it (`docs/explorer.md`).
pub fn name(path: &Path) -> String {
    path.strip_prefix(ROOT).unwrap().display().to_string()
}

/// Shell words: blanks split, quotes group, `~/` is the test's home.
pub fn words(command: &str, home: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quote = None;
    let mut started = false;
    for c in command.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                started = true;
            }
            (None, c) if c.is_whitespace() => {
                if started {
                    out.push(std::mem::take(&mut word));
                    started = false;
                }
            }
            (None, c) => {
                word.push(c);
                started = true;
            }
        }
    }
    if started {
        out.push(word);
    }
    for w in &mut out {
        if let Some(rest) = w.strip_prefix("~/") {
            *w = home.join(rest).display().to_string();
        }
    }
    out
}

/// A folder with what the documentation's commands name: the repository's
/// `surfaces/`, `presets/` and `lessons/`, a snapshot `my-set.ron`, the
/// surfaces `steel.txt` and `afm.txt` (the shipped example's map), a
/// header-less line scan `scan.txt`, an x3p `scan.x3p` and a Gwyddion
/// file of four channels `afm.gwy` (rough-surface's test data), files
/// of formats refused with advice (`scan.nc`, `h.npy`, `cloud.xyz`) and a
/// lecturer's public key.
pub fn workspace() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for sub in ["surfaces", "presets", "lessons"] {
        let from = Path::new(ROOT).join(sub);
        if from.is_dir() {
            std::os::unix::fs::symlink(&from, dir.path().join(sub)).unwrap();
        }
    }
    let example = Path::new(ROOT).join("surfaces/example.txt");
    for name in ["steel.txt", "afm.txt"] {
        std::fs::copy(&example, dir.path().join(name)).unwrap();
    }
    std::fs::copy(
        Path::new(ROOT).join("presets/fig2.ron"),
        dir.path().join("my-set.ron"),
    )
    .unwrap();
    let scan: String = (0..512)
        .map(|i| {
            let x = i as f64 / 512.0 * std::f64::consts::TAU;
            format!("{:e}\n", 1e-8 * (3.0 * x).sin() + 2e-9 * (37.0 * x).cos())
        })
        .collect();
    std::fs::write(dir.path().join("scan.txt"), scan).unwrap();
    let formats = Path::new(ROOT).join("crates/rough-surface/tests/data/formats");
    for (from, to) in [("sur_d.x3p", "scan.x3p"), ("three.gwy", "afm.gwy")] {
        std::fs::copy(formats.join(from), dir.path().join(to)).unwrap();
    }
    // Files of formats roughtui refuses with advice (docs/surfaces.md).
    std::fs::write(dir.path().join("scan.nc"), b"CDF\x01\0\0\0\0").unwrap();
    std::fs::write(dir.path().join("h.npy"), b"\x93NUMPY\x01\x00v\x00{}").unwrap();
    std::fs::write(
        dir.path().join("cloud.xyz"),
        "# a point cloud\n0 0 1\n0.5 0.2 3\n1 0.7 2\n0.1 0.9 4\n0.3 0.3 1\n",
    )
    .unwrap();
    let key = "ssh-ed25519 AAAAC3NzaC1lZDI1NTE5AAAAIOMqqnkVzrm0SdG6UOoqKLsabgH5C9okWi0dh2l9GKJl lecturer@example\n";
    std::fs::write(dir.path().join("lecturer.pub"), key).unwrap();
    std::fs::create_dir_all(dir.path().join("home/.ssh")).unwrap();
    std::fs::write(dir.path().join("home/.ssh/id_ed25519.pub"), key).unwrap();
    dir
}
