//! A russh client for the server tests and the load test
//! (`examples/serve_load/` includes this file): a student logged in with
//! "none" or the lecturer by key, and an explorer started at a given size;
//! and what /proc says about the server process.

use std::sync::Arc;

use russh::client;
use russh::keys::PublicKeyOrCertificate;

/// Accepts any host key (the tests make a fresh one each time).
pub struct Trusting;

impl client::Handler for Trusting {
    type Error = russh::Error;
    async fn check_server_key(&mut self, _: &PublicKeyOrCertificate) -> Result<bool, Self::Error> {
        Ok(true)
    }
}

/// The connection (dropping it closes it) and the session channel.
pub type Client = (client::Handle<Trusting>, russh::Channel<client::Msg>);

/// Logs in as `user` and starts the explorer at `cols`×`rows`.
pub async fn student(port: u16, user: &str, cols: u32, rows: u32) -> Result<Client, russh::Error> {
    let config = Arc::new(client::Config::default());
    let mut h = client::connect(config, ("127.0.0.1", port), Trusting).await?;
    if !h.authenticate_none(user).await?.success() {
        return Err(russh::Error::NotAuthenticated);
    }
    let ch = h.channel_open_session().await?;
    ch.request_pty(true, "xterm", cols, rows, 0, 0, &[]).await?;
    ch.request_shell(true).await?;
    Ok((h, ch))
}

/// Logs in as the lecturer with `key` and starts the explorer at
/// `cols`×`rows`.
pub async fn lecturer(
    port: u16,
    key: russh::keys::PrivateKey,
    cols: u32,
    rows: u32,
) -> Result<Client, russh::Error> {
    let config = Arc::new(client::Config::default());
    let mut h = client::connect(config, ("127.0.0.1", port), Trusting).await?;
    let key = russh::keys::PrivateKeyWithHashAlg::new(Arc::new(key), None);
    if !h.authenticate_publickey("lecturer", key).await?.success() {
        return Err(russh::Error::NotAuthenticated);
    }
    let ch = h.channel_open_session().await?;
    ch.request_pty(true, "xterm", cols, rows, 0, 0, &[]).await?;
    ch.request_shell(true).await?;
    Ok((h, ch))
}

/// A new Ed25519 key, and its public half in authorized_keys form.
pub fn new_key() -> (russh::keys::PrivateKey, String) {
    use std::io::Read;
    let mut seed = [0u8; 32];
    std::fs::File::open("/dev/urandom")
        .and_then(|mut f| f.read_exact(&mut seed))
        .unwrap();
    let key = russh::keys::PrivateKey::from(
        russh::keys::ssh_key::private::Ed25519Keypair::from_seed(&seed),
    );
    let public = key.public_key().to_openssh().unwrap();
    (key, public)
}

/// A field of /proc/PID/status, e.g. `Threads` or `VmRSS` (in kB); 0 if absent.
pub fn proc_status(pid: u32, field: &str) -> u64 {
    let s = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    s.lines()
        .find_map(|l| l.strip_prefix(&format!("{field}:")))
        .and_then(|v| v.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or(0)
}

/// CPU time (user + system) of process `pid`, in clock ticks.
pub fn cpu_ticks(pid: u32) -> u64 {
    let s = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    let after = &s[s.rfind(')').map_or(0, |i| i + 2)..];
    let f: Vec<&str> = after.split_whitespace().collect();
    let tick = |i: usize| f.get(i).and_then(|v| v.parse::<u64>().ok()).unwrap_or(0);
    tick(11) + tick(12)
}
