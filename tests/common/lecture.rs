//! A lecture's helpers for the SSH tests: the lecturer's key and command
//! line, the CSVs written, a tmux pane's terminal modes.

use std::path::{Path, PathBuf};
use std::process::Command;

use super::room::Room;
use super::serve::Server;

/// A lecturer's key pair in `dir`: the private key's path.
pub fn lecturer_key(dir: &Path) -> PathBuf {
    let key = dir.join("lect");
    assert!(Command::new("ssh-keygen")
        .args(["-q", "-t", "ed25519", "-N", "", "-f"])
        .arg(&key)
        .status()
        .unwrap()
        .success());
    key
}

/// The lecturer's OpenSSH command line.
pub fn lecturer_line(srv: &Server, key: &Path) -> String {
    let k = key.to_str().unwrap();
    srv.ssh_line("lecturer", &["-t", "-i", k, "-o", "IdentitiesOnly=yes"])
}

/// The CSV files in `dir`, by name.
pub fn csvs(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    v.sort();
    v
}

/// A pane's terminal modes: whether it is in the alternate screen and
/// whether its cursor shows.
pub fn modes(room: &Room, name: &str) -> (bool, bool) {
    let t = format!("room:{name}");
    let o = room.tmux(&["display", "-p", "-t", &t, "#{alternate_on} #{cursor_flag}"]);
    let s = String::from_utf8_lossy(&o.stdout);
    let mut f = s.split_whitespace().map(|w| w == "1");
    (f.next().unwrap(), f.next().unwrap())
}
