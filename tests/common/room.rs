//! A lecture room in one tmux server: a window per person, each running a
//! shell command (an `ssh` to the server), read and typed into by name.
//! Torn down on drop.

use std::process::{Command, Output};
use std::time::{Duration, Instant};

pub struct Room {
    socket: String,
}

impl Room {
    /// A room whose windows are `size` unless said otherwise.
    pub fn new(name: &str, size: (u16, u16)) -> Room {
        let room = Room {
            socket: format!("roughtui-room-{name}-{}", std::process::id()),
        };
        let (w, h) = (size.0.to_string(), size.1.to_string());
        let out = room.tmux(&[
            "new-session",
            "-d",
            "-s",
            "room",
            "-n",
            "door",
            "-x",
            &w,
            "-y",
            &h,
            "sleep 3600",
        ]);
        assert!(out.status.success(), "tmux: {out:?}");
        room
    }

    pub fn tmux(&self, args: &[&str]) -> Output {
        Command::new("tmux")
            .args(["-L", &self.socket, "-f", "/dev/null"])
            .args(args)
            .output()
            .unwrap()
    }

    /// A window named `name` running `cmd` (kept open after it ends).
    pub fn open(&self, name: &str, cmd: &str) {
        let cmd = format!("{cmd}; sleep 3600");
        let out = self.tmux(&["new-window", "-d", "-t", "room", "-n", name, &cmd]);
        assert!(out.status.success(), "tmux: {out:?}");
    }

    pub fn resize(&self, name: &str, (w, h): (u16, u16)) {
        let t = format!("room:{name}");
        let (w, h) = (w.to_string(), h.to_string());
        self.tmux(&["resize-window", "-t", &t, "-x", &w, "-y", &h]);
    }

    pub fn capture(&self, name: &str) -> String {
        let t = format!("room:{name}");
        let o = self.tmux(&["capture-pane", "-p", "-t", &t]);
        String::from_utf8_lossy(&o.stdout).into_owned()
    }

    pub fn keys(&self, name: &str, keys: &[&str]) {
        let t = format!("room:{name}");
        let mut args = vec!["send-keys", "-t", &t];
        args.extend(keys);
        assert!(self.tmux(&args).status.success());
    }

    /// Waits (`secs` at most) until the window shows what `pred` wants.
    pub fn wait(&self, name: &str, what: &str, secs: u64, pred: impl Fn(&str) -> bool) -> String {
        self.wait_all(&[name], what, secs, pred).remove(0)
    }

    /// Waits (`secs` at most, for all together) until every window of
    /// `names` shows what `pred` wants; their screens.
    pub fn wait_all<S: AsRef<str>>(
        &self,
        names: &[S],
        what: &str,
        secs: u64,
        pred: impl Fn(&str) -> bool,
    ) -> Vec<String> {
        let start = Instant::now();
        let mut screens = vec![String::new(); names.len()];
        let mut done = vec![false; names.len()];
        loop {
            for (i, n) in names.iter().enumerate() {
                if !done[i] {
                    screens[i] = self.capture(n.as_ref());
                    done[i] = pred(&screens[i]);
                }
            }
            if done.iter().all(|d| *d) {
                return screens;
            }
            if start.elapsed() > Duration::from_secs(secs) {
                let i = done.iter().position(|d| !d).unwrap_or(0);
                panic!(
                    "timed out waiting for {what} in {} ({} of {} not there); it shows:\n{}",
                    names[i].as_ref(),
                    done.iter().filter(|d| !**d).count(),
                    names.len(),
                    screens[i]
                );
            }
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for Room {
    fn drop(&mut self) {
        let _ = self.tmux(&["kill-server"]);
    }
}
