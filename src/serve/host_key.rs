//! The server's host key: an Ed25519 key in OpenSSH format, generated on
//! first use (mode 0600, written atomically, never over an existing file)
//! and reused after every restart, so students' known_hosts keep matching.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use russh::keys::ssh_key::private::Ed25519Keypair;
use russh::keys::ssh_key::LineEnding;
use russh::keys::{HashAlg, PrivateKey};

/// The host key file: `--host-key`, else `$XDG_CONFIG_HOME/roughtui/host_ed25519`,
/// else `~/.config/roughtui/host_ed25519`.
pub fn default_path() -> anyhow::Result<PathBuf> {
    let base = match std::env::var_os("XDG_CONFIG_HOME").filter(|v| !v.is_empty()) {
        Some(x) => PathBuf::from(x),
        None => match std::env::var_os("HOME").filter(|v| !v.is_empty()) {
            Some(h) => PathBuf::from(h).join(".config"),
            None => bail!("no place for the host key: set --host-key, XDG_CONFIG_HOME or HOME"),
        },
    };
    Ok(base.join("roughtui").join("host_ed25519"))
}

/// The key at `path`, generated there if absent. `generated` tells which.
pub fn load_or_create(path: &Path) -> anyhow::Result<(PrivateKey, bool)> {
    match std::fs::metadata(path) {
        Ok(meta) => {
            check_mode(path, &meta)?;
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("cannot read the host key {}", path.display()))?;
            let key = PrivateKey::from_openssh(text.as_bytes()).map_err(|e| {
                anyhow::anyhow!(
                    "the host key {} is not an OpenSSH private key: {e}",
                    path.display()
                )
            })?;
            if key.is_encrypted() {
                bail!(
                    "the host key {} is encrypted: give one without a passphrase",
                    path.display()
                );
            }
            Ok((key, false))
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok((create(path)?, true)),
        Err(e) => Err(e).with_context(|| format!("cannot read the host key {}", path.display())),
    }
}

/// `SHA256:…`, as `ssh` shows it when it asks to trust the host.
pub fn fingerprint(key: &PrivateKey) -> String {
    key.public_key().fingerprint(HashAlg::Sha256).to_string()
}

#[cfg(unix)]
fn check_mode(path: &Path, meta: &std::fs::Metadata) -> anyhow::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    let mode = meta.permissions().mode() & 0o777;
    if mode & 0o077 != 0 {
        bail!(
            "the host key {} is readable by others (mode {mode:o}): run chmod 600 on it",
            path.display()
        );
    }
    Ok(())
}

#[cfg(not(unix))]
fn check_mode(_: &Path, _: &std::fs::Metadata) -> anyhow::Result<()> {
    Ok(())
}

fn create(path: &Path) -> anyhow::Result<PrivateKey> {
    let mut seed = [0u8; 32];
    std::fs::File::open("/dev/urandom")
        .and_then(|mut f| f.read_exact(&mut seed))
        .context("cannot read random bytes for a new host key")?;
    let key = PrivateKey::from(Ed25519Keypair::from_seed(&seed));
    seed.fill(0);
    let text = key
        .to_openssh(LineEnding::LF)
        .map_err(|e| anyhow::anyhow!("cannot encode the host key: {e}"))?;
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
    if let Some(dir) = dir {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    // Written under a temporary name, then linked into place: the key file
    // appears whole or not at all, and an existing one is never replaced.
    let tmp = path.with_extension(format!("tmp{}", std::process::id()));
    let result = write_private(&tmp, text.as_bytes()).and_then(|()| {
        std::fs::hard_link(&tmp, path)
            .with_context(|| format!("cannot create the host key {}", path.display()))
    });
    let _ = std::fs::remove_file(&tmp);
    result?;
    Ok(key)
}

fn write_private(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    let mut opts = std::fs::OpenOptions::new();
    opts.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        opts.mode(0o600);
    }
    let mut f = opts
        .open(path)
        .with_context(|| format!("cannot write {}", path.display()))?;
    f.write_all(bytes)?;
    f.sync_all()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_once_then_reused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("sub").join("host_ed25519");
        let (a, made) = load_or_create(&path).unwrap();
        assert!(made);
        let (b, made) = load_or_create(&path).unwrap();
        assert!(!made);
        assert_eq!(fingerprint(&a), fingerprint(&b));
        assert!(fingerprint(&a).starts_with("SHA256:"));
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o777;
            assert_eq!(mode, 0o600);
            std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o644)).unwrap();
            let e = load_or_create(&path).unwrap_err().to_string();
            assert!(e.contains("readable by others (mode 644)"), "{e}");
        }
    }

    #[test]
    fn garbage_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("k");
        write_private(&path, b"not a key").unwrap();
        let e = load_or_create(&path).unwrap_err().to_string();
        assert!(e.contains("is not an OpenSSH private key"), "{e}");
        assert_eq!(std::fs::read(&path).unwrap(), b"not a key");
    }
}
