//! Real OpenSSH students who answer the class code: the code comes from
//! an SSH_ASKPASS program, the first frame is read from a pipe.

use std::io::Read;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command};
use std::time::{Duration, Instant};

use super::serve::Server;

/// A program that prints `code`, for SSH_ASKPASS.
pub fn askpass(dir: &Path, name: &str, code: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, format!("#!/bin/sh\necho '{code}'\n")).unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o755)).unwrap();
    p
}

/// The server's OpenSSH options without BatchMode (which turns off
/// keyboard-interactive), the class code coming from `askpass`.
pub fn code_ssh(srv: &Server, user: &str, askpass: &Path, extra: &[&str]) -> Command {
    let mut args = srv.ssh_args(user, extra);
    let i = args.iter().position(|a| a == "BatchMode=yes").unwrap();
    args.drain(i - 1..=i);
    let mut c = Command::new("ssh");
    c.args(args)
        .env("SSH_ASKPASS", askpass)
        .env("SSH_ASKPASS_REQUIRE", "force")
        .env_remove("DISPLAY");
    c
}

/// Reads `child`'s stdout until its first frame (at the 1×1 window of a
/// pipe), then keeps draining it in the background.
pub fn first_frame(child: &mut Child) {
    let mut out = child.stdout.take().unwrap();
    let mut buf = [0u8; 4096];
    let mut seen = Vec::new();
    while !String::from_utf8_lossy(&seen).contains("\x1b[1;1H") {
        let n = out.read(&mut buf).unwrap();
        assert!(n > 0, "no frame; got {:?}", String::from_utf8_lossy(&seen));
        seen.extend_from_slice(&buf[..n]);
    }
    std::thread::spawn(move || while out.read(&mut buf).is_ok_and(|n| n > 0) {});
}

/// Waits (`secs` at most) for `child` to end: its status code and stderr.
pub fn finish(mut child: Child, secs: u64) -> (i32, String) {
    let start = Instant::now();
    loop {
        if let Some(st) = child.try_wait().unwrap() {
            let mut err = String::new();
            if let Some(mut e) = child.stderr.take() {
                let _ = e.read_to_string(&mut err);
            }
            return (st.code().unwrap_or(-1), err);
        }
        if start.elapsed() > Duration::from_secs(secs) {
            let _ = child.kill();
            panic!("ssh did not end");
        }
        std::thread::sleep(Duration::from_millis(30));
    }
}
