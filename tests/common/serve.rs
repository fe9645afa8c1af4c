//! A `roughtui serve` on a free loopback port for the SSH tests, and the
//! OpenSSH client options they share. The server is killed on drop.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use super::tmux::{have_tool, BIN};

/// Whether the OpenSSH client is here (see [`have_tool`]; CI sets
/// ROUGHTUI_REQUIRE_SSH and installs openssh-client).
pub fn have_ssh() -> bool {
    have_tool(
        "ssh",
        "ROUGHTUI_REQUIRE_SSH",
        "the SSH test (apt-get install openssh-client)",
    )
}

pub struct Server {
    pub child: Child,
    pub port: u16,
    /// What the server printed before it started accepting.
    pub banner: String,
    pub dir: PathBuf,
    /// What it printed since (the console log), read as it comes.
    log: Arc<Mutex<String>>,
}

impl Server {
    /// `roughtui serve` in `dir` (host key `dir/host_key`) with `args`.
    pub fn start(dir: &Path, args: &[&str]) -> Server {
        Server::start_env(dir, args, &[])
    }

    /// The same with environment variables set.
    pub fn start_env(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Server {
        let mut child = Command::new(BIN)
            .envs(env.iter().copied())
            .current_dir(dir)
            .args(["serve", "--listen", "127.0.0.1:0", "--host-key"])
            .arg(dir.join("host_key"))
            .args(args)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let mut out = BufReader::new(child.stdout.take().unwrap());
        let mut banner = String::new();
        let mut port = None;
        for _ in 0..8 {
            let mut line = String::new();
            if out.read_line(&mut line).unwrap() == 0 {
                break;
            }
            if let Some(rest) = line.strip_prefix("roughtui serve: listening on ") {
                port = rest.trim().rsplit(':').next().and_then(|p| p.parse().ok());
            }
            banner.push_str(&line);
            if line.starts_with("students:") {
                break;
            }
        }
        let port = port.unwrap_or_else(|| panic!("no address in:\n{banner}"));
        let log = Arc::new(Mutex::new(String::new()));
        let sink = Arc::clone(&log);
        std::thread::spawn(move || {
            for line in out.lines() {
                let Ok(line) = line else { break };
                let mut l = sink.lock().unwrap();
                l.push_str(&line);
                l.push('\n');
            }
        });
        Server {
            child,
            port,
            banner,
            dir: dir.to_path_buf(),
            log,
        }
    }

    /// The console log so far.
    pub fn log(&self) -> String {
        self.log.lock().unwrap().clone()
    }

    /// Waits (`secs` at most) until the console log satisfies `pred`.
    pub fn wait_log(&self, what: &str, secs: u64, pred: impl Fn(&str) -> bool) -> String {
        let start = Instant::now();
        loop {
            let l = self.log();
            if pred(&l) {
                return l;
            }
            assert!(
                start.elapsed() < Duration::from_secs(secs),
                "timed out waiting for {what}; the console shows:\n{l}"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// The OpenSSH options to reach this server as `user` (no config file,
    /// no known_hosts, no agent, no prompts), then `extra`.
    pub fn ssh_args(&self, user: &str, extra: &[&str]) -> Vec<String> {
        let mut v: Vec<String> = [
            "-F",
            "/dev/null",
            "-o",
            "StrictHostKeyChecking=no",
            "-o",
            "UserKnownHostsFile=/dev/null",
            "-o",
            "LogLevel=ERROR",
            "-o",
            "BatchMode=yes",
            "-o",
            "IdentityAgent=none",
            "-p",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        v.push(self.port.to_string());
        v.extend(extra.iter().map(|s| s.to_string()));
        v.push(format!("{user}@127.0.0.1"));
        v
    }

    /// The same as one shell command line.
    pub fn ssh_line(&self, user: &str, extra: &[&str]) -> String {
        let mut s = String::from("ssh");
        for a in self.ssh_args(user, extra) {
            s.push(' ');
            s.push_str(&super::tmux::sh_quote(&a));
        }
        s
    }

    /// A field of /proc/PID/status of the server, e.g. `Threads`.
    pub fn proc_status(&self, field: &str) -> u64 {
        super::client::proc_status(self.pid(), field)
    }

    /// Open file descriptors of the server.
    pub fn fds(&self) -> usize {
        std::fs::read_dir(format!("/proc/{}/fd", self.pid()))
            .unwrap()
            .count()
    }

    /// CPU time (user + system) of the server, in clock ticks.
    pub fn cpu_ticks(&self) -> u64 {
        super::client::cpu_ticks(self.pid())
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
