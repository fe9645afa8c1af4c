//! Load test of `roughtui serve` on loopback, a lecture hall's worth: a
//! lecturer and 100 students — 50 pressing a key every 100 ms for 20 s, 30
//! who answer a poll all at once, 20 idle. 5 s in, the lecturer opens a
//! poll (`v`); 3 s later the 30 press Enter together; 4 s later the
//! lecturer reveals (`v`); at the end saves the answers (`S`), which must
//! count 30. Reports key-to-frame p50/p99 of the typing students, the
//! poll's delivery times, the server's RSS (per idle session), its CPU, and
//! the bytes sent to idle sessions (outside the poll's question and reveal
//! and within them). Stops by itself: the whole run is bounded (a minute
//! and a half), and the server is killed however the run ends.
//!
//! ```sh
//! cargo build --release
//! cargo run --release --example serve_load [-- PATH-TO-ROUGHTUI]
//! ```

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use russh::ChannelMsg;

use client::{cpu_ticks, proc_status, Client};

const ACTIVE: usize = 50;
const POLLED: usize = 30;
const IDLE: usize = 20;
const RUN: Duration = Duration::from_secs(20);
const EVERY: Duration = Duration::from_millis(100);
/// When, from the start of the typing, the lecturer asks, the class
/// answers and the lecturer reveals.
const ASK: Duration = Duration::from_secs(5);
const ANSWER: Duration = Duration::from_secs(8);
const REVEAL: Duration = Duration::from_secs(12);

#[path = "../tests/common/client.rs"]
mod client;

async fn connect(port: u16, user: String) -> anyhow::Result<Client> {
    Ok(client::student(port, &user, 100, 30).await?)
}

/// Reads until no data came for `quiet`; the bytes read.
async fn drain(ch: &mut russh::Channel<russh::client::Msg>, quiet: Duration) -> usize {
    let mut n = 0;
    while let Ok(Some(msg)) = tokio::time::timeout(quiet, ch.wait()).await {
        if let ChannelMsg::Data { data } = msg {
            n += data.len();
        }
    }
    n
}

/// Waits for the next frame (5 s at most); when it came.
async fn next_frame(ch: &mut russh::Channel<russh::client::Msg>) -> anyhow::Result<Instant> {
    loop {
        match tokio::time::timeout(Duration::from_secs(5), ch.wait()).await {
            Ok(Some(ChannelMsg::Data { .. })) => return Ok(Instant::now()),
            Ok(Some(_)) => {}
            _ => anyhow::bail!("no frame within 5 s"),
        }
    }
}

/// Every frame a session gets, with when, until the channel closes.
type Frames = Arc<Mutex<Vec<(Instant, usize)>>>;

fn record(mut ch: russh::ChannelReadHalf) -> Frames {
    let frames: Frames = Arc::default();
    let f = Arc::clone(&frames);
    tokio::spawn(async move {
        while let Some(msg) = ch.wait().await {
            if let ChannelMsg::Data { data } = msg {
                f.lock().unwrap().push((Instant::now(), data.len()));
            }
        }
    });
    frames
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The whole run, at most: setting up 101 sessions, 20 s of typing, the
/// saved answers and the report.
const DEADLINE: Duration = Duration::from_secs(90);

/// The server, killed when dropped (on an error or the deadline too).
struct Server(std::process::Child);

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[tokio::main(flavor = "multi_thread", worker_threads = 2)]
async fn main() -> anyhow::Result<()> {
    match tokio::time::timeout(DEADLINE, run()).await {
        Ok(r) => r,
        Err(_) => anyhow::bail!("the load test did not finish within {DEADLINE:?}"),
    }
}

async fn run() -> anyhow::Result<()> {
    let bin = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "target/release/roughtui".into());
    // The server runs in a scratch folder (where the answers are saved).
    let bin = std::fs::canonicalize(&bin)
        .map_err(|e| anyhow::anyhow!("cannot find {bin} ({e}): cargo build --release first"))?;
    let bin = bin.display().to_string();
    let dir = tempfile::tempdir()?;
    let (key, public) = client::new_key();
    let keys = dir.path().join("lecturer.pub");
    std::fs::write(&keys, public)?;
    let mut server = Server(
        Command::new(&bin)
            .current_dir(dir.path())
            .args(["serve", "--listen", "127.0.0.1:0", "--host-key"])
            .arg(dir.path().join("host_key"))
            .arg("--lecturer-keys")
            .arg(&keys)
            .args([
                "--max-sessions",
                "200",
                "--max-per-address",
                "200",
                "--quiet",
            ])
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| anyhow::anyhow!("cannot run {bin} ({e}): cargo build --release first"))?,
    );
    let pid = server.0.id();
    let mut port = 0;
    for line in BufReader::new(server.0.stdout.take().unwrap()).lines() {
        let line = line?;
        if let Some(rest) = line.strip_prefix("roughtui serve: listening on ") {
            port = rest.rsplit(':').next().unwrap_or("0").parse()?;
            break;
        }
    }
    anyhow::ensure!(port != 0, "the server printed no address");
    tokio::time::sleep(Duration::from_millis(200)).await;

    let (_lh, mut lch) = client::lecturer(port, key, 100, 30).await?;
    drain(&mut lch, Duration::from_millis(300)).await;
    let (lread, lect) = lch.split();
    let lect_frames = record(lread);

    let rss0 = proc_status(pid, "VmRSS");
    let mut idle = Vec::new();
    for i in 0..IDLE {
        let (h, mut ch) = connect(port, format!("idle{i}")).await?;
        drain(&mut ch, Duration::from_millis(300)).await;
        idle.push((h, ch));
    }
    // The first screen's line on switching the drawing goes after
    // HINT_FOR: that frame belongs to the session's start, not to idling.
    tokio::time::sleep(roughtui::serve::term::HINT_FOR).await;
    for (_, ch) in &mut idle {
        drain(ch, Duration::from_millis(300)).await;
    }
    let rss_idle = proc_status(pid, "VmRSS");
    let mut polled = Vec::new();
    for i in 0..POLLED {
        let (h, mut ch) = connect(port, format!("p{i}")).await?;
        drain(&mut ch, Duration::from_millis(300)).await;
        polled.push((h, ch));
    }
    // The first screen's line on switching the drawing goes after
    // HINT_FOR: that frame belongs to the session's start, not to idling.
    tokio::time::sleep(roughtui::serve::term::HINT_FOR).await;
    for (_, ch) in idle.iter_mut().chain(polled.iter_mut()) {
        drain(ch, Duration::from_millis(300)).await;
    }
    let idle: Vec<_> = idle
        .into_iter()
        .map(|(h, ch)| {
            let (read, write) = ch.split();
            (h, write, record(read))
        })
        .collect();

    let cpu0 = cpu_ticks(pid);
    let t0 = Instant::now();
    let start = tokio::time::Instant::now();
    let mut tasks = Vec::new();
    for i in 0..ACTIVE {
        tasks.push(tokio::spawn(async move {
            let (_h, mut ch) = connect(port, format!("s{i}")).await?;
            drain(&mut ch, Duration::from_millis(300)).await;
            let mut lat = Vec::new();
            let mut next = tokio::time::Instant::now();
            let end = Instant::now() + RUN;
            let mut k = 0usize;
            while Instant::now() < end {
                next += EVERY;
                // Right then left: every key changes the scene.
                let key: &[u8] = if k.is_multiple_of(2) { b"l" } else { b"h" };
                k += 1;
                let sent = Instant::now();
                ch.data(key).await?;
                lat.push(ms(next_frame(&mut ch).await? - sent));
                // Whatever else came (a frame in parts, the poll's own
                // frames), so that the next key waits for its own frame.
                drain(&mut ch, Duration::from_millis(15)).await;
                tokio::time::sleep_until(next).await;
            }
            anyhow::Ok(lat)
        }));
    }
    // The pollers: asked at ASK, all answer at ANSWER (Enter), revealed at
    // REVEAL; each notes when the question, its answer's frame and the
    // reveal arrived.
    let (asked_at, answered_at, revealed_at) = (start + ASK, start + ANSWER, start + REVEAL);
    let go = Arc::new(tokio::sync::Barrier::new(POLLED));
    let mut pollers = Vec::new();
    for (i, (h, mut ch)) in polled.into_iter().enumerate() {
        let go = Arc::clone(&go);
        pollers.push(tokio::spawn(async move {
            let _h = h;
            tokio::time::sleep_until(asked_at).await;
            let asked = next_frame(&mut ch).await?;
            drain(&mut ch, Duration::from_millis(200)).await;
            tokio::time::sleep_until(answered_at).await;
            go.wait().await;
            // A few steps of the marker and Enter, in one go.
            let keys: &[u8] = match i % 3 {
                0 => b"\r",
                1 => b"l\r",
                _ => b"ll\r",
            };
            let sent = Instant::now();
            ch.data(keys).await?;
            let answered = next_frame(&mut ch).await? - sent;
            tokio::time::sleep_until(revealed_at).await;
            let revealed = next_frame(&mut ch).await?;
            let _rest = drain(&mut ch, Duration::from_millis(200)).await;
            anyhow::Ok((asked, answered, revealed, ch))
        }));
    }
    tokio::time::sleep_until(asked_at).await;
    let asked_sent = Instant::now();
    lect.data(&b"v"[..]).await?;
    tokio::time::sleep_until(revealed_at).await;
    let revealed_sent = Instant::now();
    lect.data(&b"v"[..]).await?;

    let mut rss_peak = 0;
    while t0.elapsed() < RUN + Duration::from_secs(1) {
        tokio::time::sleep(Duration::from_millis(500)).await;
        rss_peak = rss_peak.max(proc_status(pid, "VmRSS"));
    }
    let mut lat = Vec::new();
    for t in tasks {
        lat.extend(t.await??);
    }
    let wall = t0.elapsed().as_secs_f64();
    let cpu = (cpu_ticks(pid) - cpu0) as f64 / 100.0;
    let (mut ask, mut ans, mut rev) = (Vec::new(), Vec::new(), Vec::new());
    let mut keep = Vec::new();
    for p in pollers {
        let (a, b, c, ch) = p.await??;
        ask.push(ms(a - asked_sent));
        ans.push(ms(b));
        rev.push(ms(c - revealed_sent));
        keep.push(ch);
    }
    // The lecturer saves the answers: 30 rows.
    lect.data(&b"S"[..]).await?;
    let (mut rows, mut silent) = (0, 0);
    for _ in 0..50 {
        tokio::time::sleep(Duration::from_millis(100)).await;
        let csv = std::fs::read_dir(dir.path())?
            .filter_map(|e| e.ok())
            .find(|e| e.path().extension().is_some_and(|x| x == "csv"));
        if let Some(f) = csv {
            // Past the header: a row per answer, then a "no answer" row
            // per student who gave none.
            let text = std::fs::read_to_string(f.path())?;
            rows = text
                .lines()
                .skip(1)
                .filter(|l| !l.contains(",no answer,"))
                .count();
            silent = text.lines().filter(|l| l.contains(",no answer,")).count();
            break;
        }
    }
    anyhow::ensure!(
        rows == POLLED && silent == ACTIVE + IDLE,
        "the lecturer saved {rows} answers and {silent} without, not {POLLED} and {}",
        ACTIVE + IDLE
    );
    let lecturer_bytes: usize = lect_frames.lock().unwrap().iter().map(|f| f.1).sum();

    // Idle sessions: bytes outside the poll's two moments, and within.
    let poll_window = |t: Instant| {
        let near = |at: Instant| t >= at && t < at + Duration::from_secs(1);
        near(asked_sent) || near(revealed_sent)
    };
    let (mut outside, mut within, mut frames) = (0usize, 0usize, 0usize);
    for (_, _, f) in &idle {
        for (t, n) in f.lock().unwrap().iter() {
            if poll_window(*t) {
                within += n;
                frames += 1;
            } else {
                outside += n;
            }
        }
    }
    for v in [&mut lat, &mut ask, &mut ans, &mut rev] {
        v.sort_by(f64::total_cmp);
    }
    println!(
        "sessions: a lecturer, {ACTIVE} typing (a key every {EVERY:?} for {RUN:?}), {POLLED} answering a poll at once, {IDLE} idle"
    );
    println!(
        "key-to-frame: {} keys, p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
        lat.len(),
        percentile(&lat, 0.5),
        percentile(&lat, 0.99),
        lat.last().copied().unwrap_or(f64::NAN)
    );
    println!(
        "poll: the question reached the {POLLED} in p50 {:.1} ms, max {:.1} ms; Enter-to-frame p50 {:.1} ms, max {:.1} ms; the reveal in p50 {:.1} ms, max {:.1} ms; {rows} answers saved; the lecturer was sent {lecturer_bytes} bytes",
        percentile(&ask, 0.5),
        ask.last().copied().unwrap_or(f64::NAN),
        percentile(&ans, 0.5),
        ans.last().copied().unwrap_or(f64::NAN),
        percentile(&rev, 0.5),
        rev.last().copied().unwrap_or(f64::NAN),
    );
    println!(
        "server RSS: {:.1} MB with the lecturer, {:.1} MB with {IDLE} idle more ({:.2} MB per idle session), {:.1} MB peak with {} sessions",
        rss0 as f64 / 1024.0,
        rss_idle as f64 / 1024.0,
        (rss_idle.saturating_sub(rss0)) as f64 / 1024.0 / IDLE as f64,
        rss_peak as f64 / 1024.0,
        ACTIVE + POLLED + IDLE + 1
    );
    println!(
        "server CPU: {cpu:.1} s over {wall:.1} s ({:.0}% of one core)",
        cpu / wall * 100.0
    );
    println!(
        "bytes sent to the {IDLE} idle sessions: {outside} outside the poll; {within} in {frames} frames for its question and reveal ({} per session)",
        within / IDLE
    );
    drop(keep);
    drop(server);
    Ok(())
}
