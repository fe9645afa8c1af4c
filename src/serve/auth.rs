//! Who may come in as whom: students with any user name and no password
//! (SSH "none"); the lecturer as user `lecturer` with a key listed in
//! `--lecturer-keys`. The name is reserved because OpenSSH tries "none"
//! first: without the reservation a lecturer would come in as a student.

use std::path::Path;

use anyhow::{bail, Context};
use russh::keys::ssh_key::AuthorizedKeys;
use russh::keys::PublicKey;

/// The user name of the lecturer.
pub const LECTURER: &str = "lecturer";

/// The keys that make a lecturer (none: no lecturer, all explore alone).
#[derive(Clone, Debug, Default)]
pub struct LecturerKeys(Vec<PublicKey>);

/// The part a connection plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    Student,
    Lecturer,
}

impl LecturerKeys {
    /// The keys of an authorized_keys file (options before a key are
    /// allowed and ignored).
    pub fn read(path: &Path) -> anyhow::Result<LecturerKeys> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("cannot read the lecturer keys {}", path.display()))?;
        let mut keys = Vec::new();
        for (i, entry) in AuthorizedKeys::new(&text).enumerate() {
            let entry = entry.map_err(|e| {
                anyhow::anyhow!(
                    "{}: key {} is not in authorized_keys format: {e}",
                    path.display(),
                    i + 1
                )
            })?;
            keys.push(entry.public_key().clone());
        }
        if keys.is_empty() {
            bail!("{} holds no public key", path.display());
        }
        Ok(LecturerKeys(keys))
    }

    /// Whether there is a lecturer at all.
    pub fn any(&self) -> bool {
        !self.0.is_empty()
    }

    /// Whether `user` offering `key` is the lecturer.
    pub fn admits(&self, user: &str, key: &PublicKey) -> bool {
        user == LECTURER && self.0.iter().any(|k| k.key_data() == key.key_data())
    }

    /// Whether `user` may come in without a key, as a student.
    pub fn admits_student(&self, user: &str) -> bool {
        !(self.any() && user == LECTURER)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const KEY: &str = "ssh-ed25519 AAAAC3NzaC1lZDI1NTE5AAAAIDfM4eF6a0n6n8tZzN2cC7j2hFQy1jM1n8b1QjvQ2M3f lecturer@test";

    #[test]
    fn lecturer_needs_a_listed_key() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("keys");
        std::fs::write(&path, format!("# the lecturer\n\nno-pty {KEY}\n")).unwrap();
        let keys = LecturerKeys::read(&path).unwrap();
        let key = PublicKey::from_openssh(KEY).unwrap();
        assert!(keys.admits(LECTURER, &key));
        assert!(!keys.admits("alice", &key));
        assert!(!keys.admits_student(LECTURER));
        assert!(keys.admits_student("alice"));
        // Without lecturer keys the name is an ordinary student's.
        assert!(LecturerKeys::default().admits_student(LECTURER));
        assert!(!LecturerKeys::default().admits(LECTURER, &key));
    }

    #[test]
    fn bad_files_are_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("keys");
        std::fs::write(&path, "ssh-ed25519 notbase64!!\n").unwrap();
        let e = LecturerKeys::read(&path).unwrap_err().to_string();
        assert!(e.contains("key 1 is not in authorized_keys format"), "{e}");
        std::fs::write(&path, "# nothing\n").unwrap();
        let e = LecturerKeys::read(&path).unwrap_err().to_string();
        assert!(e.contains("holds no public key"), "{e}");
    }
}
