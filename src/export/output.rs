//! `--output FILE`: a file written whole or not at all. The text goes to a
//! hidden temporary file beside FILE (`.NAME.PID-NANOS.tmp`), flushed to
//! disk, then linked to FILE — which fails if FILE exists, so that nothing
//! is overwritten even by a task that started at the same time. A run
//! killed midway leaves only the temporary file, which does not look like
//! a finished one (nor matches `*.csv`).

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context};

/// The temporary file `path` is written through.
fn temporary(path: &Path) -> anyhow::Result<PathBuf> {
    let name = path
        .file_name()
        .with_context(|| format!("--output {}: not a file name", path.display()))?;
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    Ok(path.with_file_name(format!(
        ".{}.{}-{nanos}.tmp",
        name.to_string_lossy(),
        std::process::id()
    )))
}

/// Refuses an existing `path`: roughtui never overwrites a file.
pub fn refuse_existing(path: &Path) -> anyhow::Result<()> {
    if path.exists() {
        bail!(
            "--output {}: the file exists; roughtui does not overwrite a file (remove it or \
             choose another name)",
            path.display()
        );
    }
    Ok(())
}

/// Runs `write` into `path`, whole or not at all.
pub fn write_to(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    refuse_existing(path)?;
    let tmp = temporary(path)?;
    let result = (|| -> anyhow::Result<()> {
        let file = std::fs::File::create(&tmp)
            .with_context(|| format!("--output {}: cannot write beside it", path.display()))?;
        let mut out = std::io::BufWriter::with_capacity(1 << 16, file);
        write(&mut out)?;
        let file = out.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        // A link fails where the name exists: no file is overwritten.
        match std::fs::hard_link(&tmp, path) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => refuse_existing(path),
            // A file system without links: rename, the name checked first.
            Err(_) => {
                refuse_existing(path)?;
                std::fs::rename(&tmp, path)?;
                Ok(())
            }
        }
    })();
    let _ = std::fs::remove_file(&tmp);
    result.with_context(|| format!("--output {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_written_whole_and_never_overwritten() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.csv");
        write_to(&path, |w: &mut dyn Write| Ok(w.write_all(b"x,y\n")?)).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "x,y\n");
        let e = write_to(&path, |w: &mut dyn Write| Ok(w.write_all(b"z\n")?)).unwrap_err();
        assert!(format!("{e:#}").contains("the file exists"), "{e:#}");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "x,y\n");
        // A failed run leaves nothing behind.
        let other = dir.path().join("b.csv");
        let e = write_to(&other, |w: &mut dyn Write| {
            w.write_all(b"half")?;
            bail!("the solver failed")
        });
        assert!(e.is_err());
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1, "{names:?}");
    }
}
