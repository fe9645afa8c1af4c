//! tmux for the real-terminal tests: one tmux server per pane, torn down on
//! drop; the pane stays after the program exits so its screen can be read.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

pub const BIN: &str = env!("CARGO_BIN_EXE_roughtui");

pub fn have_tmux() -> bool {
    have_tool("tmux", "ROUGHTUI_REQUIRE_TMUX", "the real-terminal test")
}

/// Whether `tool -V` runs here. When it does not, the test says so and
/// passes, unless `require` is set in the environment (as in CI): then it
/// fails, so CI never skips a test for a missing tool.
pub fn have_tool(tool: &str, require: &str, what: &str) -> bool {
    let ok = Command::new(tool)
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        assert!(
            std::env::var_os(require).is_none(),
            "{tool} is required ({require} is set) but missing"
        );
        eprintln!("{tool} not found: skipping {what}");
    }
    ok
}

/// One tmux server running one roughtui, torn down on drop.
pub struct Pane {
    socket: String,
    status: PathBuf,
    _scratch: tempfile::TempDir,
}

pub fn sh_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', r"'\''"))
}

/// The shell command that runs roughtui in `cwd` with `env` and `args`;
/// in a UTF-8 locale (C.UTF-8) unless `env` names one, so that the
/// explorer draws its default braille whatever the test's own locale.
fn command(cwd: &Path, env: &[(&str, &str)], args: &[&str]) -> String {
    let mut cmd = format!("cd {} && env", sh_quote(cwd.to_str().unwrap()));
    let locale = ["LC_ALL", "LC_CTYPE", "LANG"];
    if !env.iter().any(|(k, _)| locale.contains(k)) {
        cmd.push_str(" LC_ALL=C.UTF-8");
    }
    for (k, v) in env {
        cmd.push_str(&format!(" {k}={}", sh_quote(v)));
    }
    cmd.push_str(&format!(" {}", sh_quote(BIN)));
    for a in args {
        cmd.push_str(&format!(" {}", sh_quote(a)));
    }
    cmd
}

impl Pane {
    pub fn start(
        name: &str,
        cwd: &Path,
        size: (u16, u16),
        env: &[(&str, &str)],
        args: &[&str],
    ) -> Pane {
        Pane::start_shell(name, size, &command(cwd, env, args))
    }

    /// As [`Pane::start`], with a shell redirection (`</dev/null`) after the
    /// command.
    pub fn start_redirected(
        name: &str,
        cwd: &Path,
        size: (u16, u16),
        args: &[&str],
        redirect: &str,
    ) -> Pane {
        let cmd = format!("{}{redirect}", command(cwd, &[], args));
        Pane::start_shell(name, size, &cmd)
    }

    /// The process id of roughtui (the pane's shell's only child), read
    /// from /proc so that no `ps` is needed.
    pub fn program_pid(&self) -> u32 {
        let shell = self.display("#{pane_pid}");
        let children: Vec<u32> = std::fs::read_dir("/proc")
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().to_str()?.parse::<u32>().ok())
            .filter(|pid| {
                std::fs::read_to_string(format!("/proc/{pid}/status")).is_ok_and(|st| {
                    st.lines()
                        .any(|l| l.strip_prefix("PPid:").map(str::trim) == Some(shell.as_str()))
                })
            })
            .collect();
        assert_eq!(
            children.len(),
            1,
            "children of the pane's shell: {children:?}"
        );
        children[0]
    }

    /// Sends `signal` (HUP, TERM …) to roughtui, with the shell's own kill.
    pub fn signal(&self, signal: &str) {
        let pid = self.program_pid();
        let ok = Command::new("sh")
            .args(["-c", &format!("kill -{signal} {pid}")])
            .status()
            .unwrap()
            .success();
        assert!(ok, "kill -{signal} {pid}");
    }

    /// A pane running the shell command `cmd`; its exit status is kept.
    pub fn start_shell(name: &str, size: (u16, u16), cmd: &str) -> Pane {
        let scratch = tempfile::tempdir().unwrap();
        let status = scratch.path().join("status");
        let socket = format!("roughtui-test-{name}-{}", std::process::id());
        // Keep the pane after exit so its screen can be read.
        let cmd = format!(
            "{cmd}; echo $? > {}; sleep 600",
            sh_quote(status.to_str().unwrap())
        );
        let p = Pane {
            socket,
            status,
            _scratch: scratch,
        };
        let (w, h) = (size.0.to_string(), size.1.to_string());
        let out = p.tmux(&["new-session", "-d", "-s", "t", "-x", &w, "-y", &h, &cmd]);
        assert!(out.status.success(), "tmux: {out:?}");
        p
    }

    pub fn tmux(&self, args: &[&str]) -> Output {
        Command::new("tmux")
            .args(["-L", &self.socket, "-f", "/dev/null"])
            .args(args)
            .output()
            .unwrap()
    }

    pub fn capture(&self) -> String {
        let o = self.tmux(&["capture-pane", "-p", "-t", "t"]);
        String::from_utf8_lossy(&o.stdout).into_owned()
    }

    pub fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", "t"];
        args.extend(keys);
        assert!(self.tmux(&args).status.success());
    }

    pub fn display(&self, format: &str) -> String {
        let o = self.tmux(&["display-message", "-p", "-t", "t", format]);
        String::from_utf8_lossy(&o.stdout).trim().to_string()
    }

    /// Polls the pane until `pred` holds (20 s at most: a loaded 2-core
    /// machine can hold a resize back for seconds), then gives the screen
    /// 40 ms more and returns it as it is then, if `pred` still holds: a
    /// capture can come while the program is still writing a frame, and
    /// what the test reads next (the colours, a count of cells) would be
    /// half of it.
    pub fn wait_for(&self, what: &str, pred: impl Fn(&str) -> bool) -> String {
        let start = Instant::now();
        loop {
            let s = self.capture();
            if pred(&s) {
                std::thread::sleep(Duration::from_millis(40));
                let whole = self.capture();
                if pred(&whole) {
                    return whole;
                }
                continue;
            }
            assert!(
                start.elapsed() < Duration::from_secs(20),
                "timed out waiting for {what}; the pane shows:\n{s}"
            );
            std::thread::sleep(Duration::from_millis(30));
        }
    }

    pub fn wait_text(&self, text: &str) -> String {
        self.wait_for(text, |s| s.contains(text))
    }

    pub fn exit_status(&self) -> i32 {
        let start = Instant::now();
        loop {
            if let Ok(s) = std::fs::read_to_string(&self.status) {
                if let Ok(n) = s.trim().parse() {
                    return n;
                }
            }
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "roughtui did not exit; the pane shows:\n{}",
                self.capture()
            );
            std::thread::sleep(Duration::from_millis(30));
        }
    }

    /// Bytes the program writes to the terminal while `act` runs.
    pub fn bytes_written(&self, act: impl FnOnce()) -> u64 {
        let log = self._scratch.path().join("pipe");
        let _ = std::fs::remove_file(&log);
        let cmd = format!("cat >> {}", sh_quote(log.to_str().unwrap()));
        assert!(self
            .tmux(&["pipe-pane", "-o", "-t", "t", &cmd])
            .status
            .success());
        std::thread::sleep(Duration::from_millis(200));
        act();
        std::thread::sleep(Duration::from_millis(300));
        self.tmux(&["pipe-pane", "-t", "t"]);
        std::thread::sleep(Duration::from_millis(100));
        std::fs::metadata(&log).map_or(0, |m| m.len())
    }
}

impl Drop for Pane {
    fn drop(&mut self) {
        let _ = self.tmux(&["kill-server"]);
    }
}

/// Braille cells on a screen: how much of the chart is drawn.
pub fn braille(s: &str) -> usize {
    s.chars()
        .filter(|c| ('\u{2801}'..='\u{28FF}').contains(c))
        .count()
}
