//! The server console's log: a line per join and leave, a summary a
//! minute while students are connected (`--quiet`: none of it). Lines go
//! to a thread of their own that writes stdout, so a console that does not
//! keep up (or a closed pipe) never stalls a session: past [`BACKLOG`]
//! lines waiting, new ones are dropped and counted.

use std::io::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{sync_channel, SyncSender, TrySendError};
use std::sync::Arc;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// Lines that may wait for the console.
pub const BACKLOG: usize = 1024;

/// How often the summary is written. For tests, `ROUGHTUI_SUMMARY_MS`
/// shortens it.
pub const SUMMARY_EVERY: Duration = Duration::from_secs(60);

pub fn summary_every() -> Duration {
    std::env::var("ROUGHTUI_SUMMARY_MS")
        .ok()
        .and_then(|v| v.parse().ok())
        .map_or(SUMMARY_EVERY, Duration::from_millis)
        .clamp(Duration::from_millis(100), SUMMARY_EVERY)
}

#[derive(Clone, Debug)]
pub struct Log {
    tx: Option<SyncSender<String>>,
    dropped: Arc<AtomicU64>,
}

impl Log {
    /// A log writing to stdout, or none at all when `quiet`.
    pub fn new(quiet: bool) -> Log {
        let dropped = Arc::new(AtomicU64::new(0));
        if quiet {
            return Log { tx: None, dropped };
        }
        let (tx, rx) = sync_channel::<String>(BACKLOG);
        std::thread::spawn(move || {
            let mut out = std::io::stdout();
            for line in rx.iter() {
                if writeln!(out, "{line}").and_then(|()| out.flush()).is_err() {
                    // Nobody reads the console: keep taking lines, write none.
                    for _ in rx.iter() {}
                    return;
                }
            }
        });
        Log {
            tx: Some(tx),
            dropped,
        }
    }

    /// Whether lines are written.
    pub fn on(&self) -> bool {
        self.tx.is_some()
    }

    /// Writes `text` after the time of day (UTC).
    pub fn line(&self, text: &str) {
        let Some(tx) = &self.tx else { return };
        let dropped = self.dropped.swap(0, Ordering::Relaxed);
        let mut line = format!("{} {text}", clock(SystemTime::now()));
        if dropped > 0 {
            line.push_str(&format!(" ({dropped} earlier lines dropped)"));
        }
        if let Err(TrySendError::Full(_)) = tx.try_send(line) {
            self.dropped.fetch_add(dropped + 1, Ordering::Relaxed);
        }
    }
}

/// `HH:MM:SS` of `t` in UTC.
pub fn clock(t: SystemTime) -> String {
    let s = t.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs()) % 86_400;
    format!("{:02}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_is_utc() {
        let t = UNIX_EPOCH + Duration::from_secs(1_795_275_012);
        assert_eq!(clock(t), "15:30:12");
    }

    #[test]
    fn a_quiet_log_writes_nothing() {
        let l = Log::new(true);
        assert!(!l.on());
        l.line("nothing");
    }
}
