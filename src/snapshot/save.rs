//! Writing snapshots: never replacing a file, never leaving half of one.
//!
//! [`save_new`] writes a temporary file in the target folder, then hard-links
//! it under the first free name (`stem.ron`, `stem-2.ron`, …; a link fails
//! rather than replace a file that appeared meanwhile) and removes the
//! temporary file, also on failure.

use std::fs::{File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{SystemTime, UNIX_EPOCH};

use super::error::shown;
use crate::scene::{State, MAX_NAME_CHARS};

/// Longest accepted file stem for [`save_new`], in bytes.
pub const MAX_STEM_BYTES: usize = 200;

/// `{name}-{YYYYMMDD-HHMMSS}` (UTC) for a save at `time`. Characters of
/// `name` other than letters, digits, `-`, `_` and `.` become `_`, a leading
/// `.` is dropped, and an empty name becomes `snapshot`.
pub fn default_stem(name: &str, time: SystemTime) -> String {
    let mut base: String = name
        .chars()
        .take(MAX_NAME_CHARS)
        .map(|c| {
            if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect::<String>()
        .trim_start_matches('.')
        .to_string();
    if base.is_empty() {
        base = "snapshot".into();
    }
    let secs = time.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rem) = (secs / 86_400, secs % 86_400);
    // Civil date from days since 1970-01-01 (Howard Hinnant's algorithm).
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{base}-{y:04}{m:02}{d:02}-{:02}{:02}{:02}",
        rem / 3600,
        rem / 60 % 60,
        rem % 60
    )
}

/// The scene's name for a snapshot saved under `stem`: the stem without
/// the `-YYYYMMDD-HHMMSS` that [`default_stem`] appends, so that saving
/// with the offered name keeps the scene called "fig2" (and a picture
/// saved next is `fig2-map-…svg`, with one time stamp). A stem that is
/// nothing but a time stamp stays whole.
pub fn scene_name(stem: &str) -> &str {
    let is_stamp = |t: &str| {
        let b = t.as_bytes();
        b.len() == 16
            && b[0] == b'-'
            && b[9] == b'-'
            && b[1..9].iter().chain(&b[10..]).all(u8::is_ascii_digit)
    };
    match stem.len().checked_sub(16) {
        Some(at) if at > 0 && stem.is_char_boundary(at) && is_stamp(&stem[at..]) => &stem[..at],
        _ => stem,
    }
}

/// The stem a user typed, checked: surrounding blanks and a trailing `.ron`
/// are dropped; empty names, paths, control characters, a leading `.` and
/// over-long names are refused.
pub fn check_stem(stem: &str) -> Result<&str, String> {
    let s = stem.trim();
    let s = s.strip_suffix(".ron").unwrap_or(s);
    let why = if s.is_empty() {
        "it is empty".to_string()
    } else if s.contains('/') || s.contains('\\') {
        "it must be a file name, not a path (no '/' or '\\')".to_string()
    } else if s.chars().any(char::is_control) {
        "it contains a control character".to_string()
    } else if s.starts_with('.') {
        "it must not start with '.'".to_string()
    } else if s.len() > MAX_STEM_BYTES {
        format!("it is {} bytes long: at most {MAX_STEM_BYTES}", s.len())
    } else {
        return Ok(s);
    };
    Err(format!("bad file name {:?}: {why}", stem))
}

static SAVE_SEQ: AtomicU64 = AtomicU64::new(0);

/// Writes `state` to `dir/{stem}.ron`, never overwriting: if that name is
/// taken, `{stem}-2.ron`, `{stem}-3.ron`, …. The text goes to a temporary
/// file in `dir` first and is linked into place without replacing anything;
/// the temporary file is removed whatever happens. `stem` is checked by
/// [`check_stem`], and the state by [`State::check`] (so that whatever is
/// saved loads back). Returns the path written.
pub fn save_new(dir: &Path, stem: &str, state: &State) -> anyhow::Result<PathBuf> {
    // What could not be loaded back is not written.
    state
        .check()
        .map_err(|e| anyhow::anyhow!("cannot save snapshot: {e}"))?;
    save_with(
        dir,
        (stem, "ron", "snapshot"),
        state.to_ron_in(Some(dir)).as_bytes(),
        |f, b| f.write_all(b),
    )
}

/// Writes `bytes` to `dir/{stem}.{ext}` under the rules of [`save_new`]
/// (never overwriting, a temporary file linked into place); `what` names
/// the file in errors ("picture"). Returns the path written.
pub fn save_file_new(
    dir: &Path,
    stem: &str,
    ext: &str,
    what: &str,
    bytes: &[u8],
) -> anyhow::Result<PathBuf> {
    save_with(dir, (stem, ext, what), bytes, |f, b| f.write_all(b))
}
/// [`save_new`] with the write step given, so that tests can make it fail.
fn save_with(
    dir: &Path,
    (stem, ext, what): (&str, &str, &str),
    bytes: &[u8],
    write: impl Fn(&mut File, &[u8]) -> io::Result<()>,
) -> anyhow::Result<PathBuf> {
    let stem = check_stem(stem).map_err(|e| anyhow::anyhow!("cannot save {what}: {e}"))?;
    let d = shown(dir);
    let in_dir = |e: io::Error| anyhow::anyhow!("cannot save {what} in {d}: {e}");

    // 1. A fresh temporary file of our own.
    let (tmp, mut file) = {
        let mut tries = 0;
        loop {
            let seq = SAVE_SEQ.fetch_add(1, Ordering::Relaxed);
            let tmp = dir.join(format!(".roughtui-{}-{seq}.tmp", std::process::id()));
            match OpenOptions::new().write(true).create_new(true).open(&tmp) {
                Ok(f) => break (tmp, f),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 100 => tries += 1,
                Err(e) => return Err(in_dir(e)),
            }
        }
    };
    if let Err(e) = write(&mut file, bytes).and_then(|()| file.sync_all()) {
        drop(file);
        let _ = std::fs::remove_file(&tmp);
        return Err(in_dir(e));
    }
    drop(file);

    // 2. Linked under the first free name: a link never replaces a file, also
    //    one that appeared since we looked.
    let result = (|| {
        for n in 1..10_000u32 {
            let target = dir.join(if n == 1 {
                format!("{stem}.{ext}")
            } else {
                format!("{stem}-{n}.{ext}")
            });
            match std::fs::hard_link(&tmp, &target) {
                Ok(()) => return Ok(target),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(e)
                    if matches!(
                        e.kind(),
                        io::ErrorKind::Unsupported | io::ErrorKind::PermissionDenied
                    ) =>
                {
                    // No hard links here (e.g. FAT): create the target
                    // exclusively and write it directly.
                    match write_exclusive(&target, bytes, &write) {
                        Ok(true) => return Ok(target),
                        Ok(false) => continue,
                        Err(e) => return Err(in_dir(e)),
                    }
                }
                Err(e) => return Err(in_dir(e)),
            }
        }
        anyhow::bail!("cannot save {what} in {d}: too many {what}s named {stem}")
    })();
    let _ = std::fs::remove_file(&tmp);
    if result.is_ok() {
        // Make the new directory entry durable; not all systems allow it.
        let _ = File::open(dir).and_then(|f| f.sync_all());
    }
    result
}

/// Creates `target` (only if absent) and writes `bytes`; `Ok(false)` if it
/// exists. A partly written target is removed.
fn write_exclusive(
    target: &Path,
    bytes: &[u8],
    write: &impl Fn(&mut File, &[u8]) -> io::Result<()>,
) -> io::Result<bool> {
    let mut f = match OpenOptions::new().write(true).create_new(true).open(target) {
        Ok(f) => f,
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => return Ok(false),
        Err(e) => return Err(e),
    };
    if let Err(e) = write(&mut f, bytes).and_then(|()| f.sync_all()) {
        drop(f);
        let _ = std::fs::remove_file(target);
        return Err(e);
    }
    Ok(true)
}

#[cfg(test)]
mod name_tests {
    use super::scene_name;

    #[test]
    fn the_time_stamp_is_not_the_name() {
        assert_eq!(scene_name("fig2-20261125-094445"), "fig2");
        assert_eq!(scene_name("my run-20261125-094445"), "my run");
        assert_eq!(scene_name("steel"), "steel");
        assert_eq!(scene_name("-20261125-094445"), "-20261125-094445");
        assert_eq!(scene_name("fig2-2026112-094445"), "fig2-2026112-094445");
        assert_eq!(scene_name("ζ-20261125-094445"), "ζ");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files_in(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn failed_write_leaves_no_file_behind() {
        let dir = tempfile::tempdir().unwrap();
        let err = save_with(
            dir.path(),
            ("full", "ron", "snapshot"),
            b"(version: 1)",
            |f, b| {
                f.write_all(&b[..4])?;
                Err(io::Error::from_raw_os_error(28)) // ENOSPC
            },
        )
        .unwrap_err()
        .to_string();
        assert!(err.contains("cannot save snapshot in"), "{err}");
        assert!(err.contains(&dir.path().display().to_string()), "{err}");
        assert!(err.contains("No space left on device"), "{err}");
        assert_eq!(files_in(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn a_file_created_during_the_save_is_not_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let theirs = dir.path().join("race.ron");
        let path = save_with(
            dir.path(),
            ("race", "ron", "snapshot"),
            b"ours\n",
            |f, b| {
                // Someone else takes the name after any check we could have made.
                std::fs::write(&theirs, "theirs\n")?;
                f.write_all(b)
            },
        )
        .unwrap();
        assert_eq!(path, dir.path().join("race-2.ron"));
        assert_eq!(std::fs::read_to_string(&theirs).unwrap(), "theirs\n");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "ours\n");
        assert_eq!(files_in(dir.path()), ["race-2.ron", "race.ron"]);
    }

    #[test]
    fn exclusive_fallback_writes_once_and_cleans_up_on_failure() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("x.ron");
        let ok = |f: &mut File, b: &[u8]| f.write_all(b);
        assert!(write_exclusive(&target, b"one", &ok).unwrap());
        assert!(!write_exclusive(&target, b"two", &ok).unwrap());
        assert_eq!(std::fs::read(&target).unwrap(), b"one");
        let fail = |_: &mut File, _: &[u8]| Err(io::Error::from_raw_os_error(28));
        let other = dir.path().join("y.ron");
        assert!(write_exclusive(&other, b"three", &fail).is_err());
        assert!(!other.exists());
    }

    #[test]
    fn stems_carry_utc_date_and_time() {
        let t = UNIX_EPOCH + std::time::Duration::from_secs(1_795_275_012);
        assert_eq!(default_stem("fig2", t), "fig2-20261121-153012");
    }
}
