//! Load test of `roughtui serve` on loopback, a lecture hall's worth: a
//! lecturer and 150 students (the default `--max-sessions`), 60 of them
//! on phones (the page's phone layout: a picture drawn by the export's SVG
//! code and its texts, as a WebSocket text message per change), 40 on the
//! web page's terminal (WebSocket, as xterm.js speaks) and 50 over SSH —
//! 20 pressing a key every 100 ms for 20 s (10 SSH, 10 web), 30 who answer
//! a poll all at once (10 each way), 100 idle (30 SSH, 20 web, 50
//! phones). 5 s in, the lecturer opens a poll (`v`); 3 s later the 30
//! press Enter together; 4 s later the lecturer reveals (`v`); at the end
//! saves the answers (`S`), which must count 30; then leads the 130 who
//! follow, a key every 250 ms (`lead.rs`), terminals and phones reported
//! apart. Reports
//! key-to-frame p50/p99 of the typing students (in all, over SSH, over
//! the web, with the bytes of frames per key), the poll's delivery times,
//! the server's RSS (per idle session, SSH, web and phones apart), its CPU, and
//! the bytes sent to idle sessions (outside the poll's question and reveal
//! and within them), and the lecturer's keys to the followers: their
//! key-to-frame, bytes, the server's CPU and frames rendered per key.
//! `ROUGHTUI_SHARED_FRAMES=off` (passed on to the server) makes every
//! follower render its own frame, to compare. Stops by itself: the whole run is bounded (two and a
//! half minutes), and the server is killed however the run ends.
//!
//! ```sh
//! cargo build --release
//! cargo run --release --example serve_load [-- PATH-TO-ROUGHTUI]
//! ```

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

use client::{cpu_ticks, proc_status};
use student::{Frames, Student, Via};

/// Students typing, over SSH and over the web's terminal.
const TYPING: (usize, usize) = (10, 10);
/// Students answering a poll and idle, over SSH, the web's terminal and
/// on phones.
const POLLED: [usize; 3] = [10, 10, 10];
const IDLE: [usize; 3] = [30, 20, 50];
const VIAS: [Via; 3] = [Via::Ssh, Via::Web, Via::Phone];
const RUN: Duration = Duration::from_secs(20);
const EVERY: Duration = Duration::from_millis(100);
/// When, from the start of the typing, the lecturer asks, the class
/// answers and the lecturer reveals.
const ASK: Duration = Duration::from_secs(5);
const ANSWER: Duration = Duration::from_secs(8);
const REVEAL: Duration = Duration::from_secs(12);

#[path = "../../tests/common/client.rs"]
mod client;
mod lead;
mod student;

/// Logs `n` students in over `via`, twenty at a time, each drained of its
/// first screen.
async fn join(
    ports: (u16, u16),
    via: Via,
    prefix: &str,
    n: usize,
) -> anyhow::Result<Vec<(Via, Student)>> {
    let mut out = Vec::new();
    // Twenty at a time: a room logging in, not a flood.
    for chunk in (0..n).collect::<Vec<_>>().chunks(20) {
        let mut tasks = Vec::new();
        for &i in chunk {
            let name = format!("{prefix}{i}");
            tasks.push(tokio::spawn(async move {
                let mut s = Student::new(via, ports, &name).await?;
                s.drain(Duration::from_millis(300)).await;
                anyhow::Ok((via, s))
            }));
        }
        for t in tasks {
            out.push(t.await??);
        }
    }
    Ok(out)
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

/// The whole run, at most: setting up 301 sessions, 20 s of typing, the
/// saved answers and the report.
const DEADLINE: Duration = Duration::from_secs(150);

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
            .args([
                "serve",
                "--listen",
                "127.0.0.1:0",
                "--web",
                "127.0.0.1:0",
                "--host-key",
            ])
            .arg(dir.path().join("host_key"))
            .arg("--lecturer-keys")
            .arg(&keys)
            // (The default --max-sessions and --max-per-address, 150, take
            // the whole class from one address.)
            // The console's summary (with its frames: line) five times a
            // second.
            .env("ROUGHTUI_SUMMARY_MS", "200")
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| anyhow::anyhow!("cannot run {bin} ({e}): cargo build --release first"))?,
    );
    let pid = server.0.id();
    let (mut port, mut web) = (0u16, 0u16);
    let mut out = BufReader::new(server.0.stdout.take().unwrap()).lines();
    for line in out.by_ref() {
        let line = line?;
        let last = |rest: &str| rest.rsplit(':').next().unwrap_or("0").parse::<u16>();
        if let Some(rest) = line.strip_prefix("roughtui serve: listening on ") {
            port = last(rest)?;
        }
        if let Some(rest) = line.strip_prefix("web: listening on ") {
            web = last(rest)?;
        }
        if line.starts_with("join address") {
            break;
        }
    }
    anyhow::ensure!(port != 0 && web != 0, "the server printed no addresses");
    // The rest of the console is read away, its latest frames: line kept.
    let counts: lead::Counts = Arc::default();
    {
        let counts = Arc::clone(&counts);
        std::thread::spawn(move || {
            for line in out.map_while(Result::ok) {
                if line.contains("frames: ") {
                    *counts.lock().unwrap() = Some(line);
                }
            }
        });
    }
    tokio::time::sleep(Duration::from_millis(200)).await;

    let (_lh, mut lch) = client::lecturer(port, key, 100, 30).await?;
    while let Ok(Some(_)) = tokio::time::timeout(Duration::from_millis(300), lch.wait()).await {}
    let (mut lread, lect) = lch.split();
    let lect_frames: Frames = Arc::default();
    {
        let f = Arc::clone(&lect_frames);
        tokio::spawn(async move {
            while let Some(msg) = lread.wait().await {
                if let russh::ChannelMsg::Data { data } = msg {
                    f.lock().unwrap().push((Instant::now(), data.len()));
                }
            }
        });
    }

    // Idle students, SSH then web, the server's memory before and after
    // each (the first screen's line goes after HINT_FOR: that frame
    // belongs to the session's start, not to idling).
    let ports = (port, web);
    let mut rss = vec![proc_status(pid, "VmRSS")];
    let mut idle = Vec::new();
    for (via, n) in VIAS.into_iter().zip(IDLE) {
        idle.extend(join(ports, via, &format!("idle{via:?}"), n).await?);
        rss.push(proc_status(pid, "VmRSS"));
    }
    let rss0 = rss[0];
    let mut polled = Vec::new();
    for (via, n) in VIAS.into_iter().zip(POLLED) {
        polled.extend(join(ports, via, &format!("p{via:?}"), n).await?);
    }
    tokio::time::sleep(roughtui::serve::term::HINT_FOR).await;
    for (_, s) in idle.iter_mut().chain(polled.iter_mut()) {
        s.drain(Duration::from_millis(20)).await;
    }
    let idle: Vec<_> = idle.into_iter().map(|(via, s)| (via, s.record())).collect();

    let cpu0 = cpu_ticks(pid);
    let t0 = Instant::now();
    let start = tokio::time::Instant::now();
    let mut tasks = Vec::new();
    for i in 0..TYPING.0 + TYPING.1 {
        let on_web = i >= TYPING.0;
        tasks.push(tokio::spawn(async move {
            let mut s = if on_web {
                Student::web(web, &format!("ws{i}")).await?
            } else {
                Student::ssh(port, &format!("s{i}")).await?
            };
            s.drain(Duration::from_millis(300)).await;
            let (mut lat, mut bytes) = (Vec::new(), 0usize);
            let mut next = tokio::time::Instant::now();
            let end = Instant::now() + RUN;
            let mut k = 0usize;
            while Instant::now() < end {
                next += EVERY;
                // Right then left: every key changes the scene.
                let key: &[u8] = if k.is_multiple_of(2) { b"l" } else { b"h" };
                k += 1;
                let sent = Instant::now();
                s.send(key).await?;
                let (at, n) = s.next_frame().await?;
                lat.push(ms(at - sent));
                // Whatever else came (a frame in parts, the poll's own
                // frames), so that the next key waits for its own frame.
                bytes += n + s.drain(Duration::from_millis(15)).await;
                tokio::time::sleep_until(next).await;
            }
            anyhow::Ok((on_web, lat, bytes))
        }));
    }
    // The pollers: asked at ASK, all answer at ANSWER (Enter), revealed at
    // REVEAL; each notes when the question, its answer's frame and the
    // reveal arrived.
    let (asked_at, answered_at, revealed_at) = (start + ASK, start + ANSWER, start + REVEAL);
    let n_polled = polled.len();
    let go = Arc::new(tokio::sync::Barrier::new(n_polled));
    let mut pollers = Vec::new();
    for (i, (via, mut s)) in polled.into_iter().enumerate() {
        let go = Arc::clone(&go);
        pollers.push(tokio::spawn(async move {
            tokio::time::sleep_until(asked_at).await;
            let (asked, _) = s.next_frame().await?;
            s.drain(Duration::from_millis(200)).await;
            tokio::time::sleep_until(answered_at).await;
            go.wait().await;
            // A few steps of the marker and Enter, in one go.
            let keys: &[u8] = match i % 3 {
                0 => b"\r",
                1 => b"l\r",
                _ => b"ll\r",
            };
            let sent = Instant::now();
            s.send(keys).await?;
            let answered = s.next_frame().await?.0 - sent;
            tokio::time::sleep_until(revealed_at).await;
            let (revealed, _) = s.next_frame().await?;
            let _rest = s.drain(Duration::from_millis(200)).await;
            anyhow::Ok((asked, answered, revealed, (via, s)))
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
    // Key-to-frame and bytes per key, SSH and web apart.
    let (mut lat, mut lat_ssh, mut lat_web) = (Vec::new(), Vec::new(), Vec::new());
    let (mut bytes, mut keys_n) = ([0usize; 2], [0usize; 2]);
    for t in tasks {
        let (on_web, l, b) = t.await??;
        keys_n[usize::from(on_web)] += l.len();
        bytes[usize::from(on_web)] += b;
        lat.extend(&l);
        if on_web {
            lat_web.extend(l)
        } else {
            lat_ssh.extend(l)
        }
    }
    let wall = t0.elapsed().as_secs_f64();
    let cpu = (cpu_ticks(pid) - cpu0) as f64 / 100.0;
    let (mut ask, mut ans, mut rev) = (Vec::new(), Vec::new(), Vec::new());
    let mut keep = Vec::new();
    for p in pollers {
        let (a, b, c, s) = p.await??;
        ask.push(ms(a - asked_sent));
        ans.push(ms(b));
        rev.push(ms(c - revealed_sent));
        keep.push(s);
    }
    // The lecturer saves the answers: a row per poller.
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
    let others = TYPING.0 + TYPING.1 + IDLE.iter().sum::<usize>();
    anyhow::ensure!(
        rows == n_polled && silent == others,
        "the lecturer saved {rows} answers and {silent} without, not {n_polled} and {others}"
    );
    let lecturer_bytes: usize = lect_frames.lock().unwrap().iter().map(|f| f.1).sum();

    // The lecturer leads the idle and the pollers, who follow again:
    // terminals and phones.
    let polled: Vec<_> = keep.into_iter().map(|(via, s)| (via, s.record())).collect();
    let group = |phones: bool| -> Vec<student::Frames> {
        idle.iter()
            .chain(&polled)
            .filter(|(via, _)| (*via == Via::Phone) == phones)
            .map(|(_, (_, f))| Arc::clone(f))
            .collect()
    };
    let groups = [
        ("terminals (SSH and web)", group(false)),
        ("phones", group(true)),
    ];
    let led_from = Instant::now();
    let rss_led0 = proc_status(pid, "VmRSS");
    let led = lead::run(&lect, pid, &groups, &counts).await?;
    let rss_led = proc_status(pid, "VmRSS");

    // Idle sessions: bytes outside the poll's two moments, and within.
    let poll_window = |t: Instant| {
        let near = |at: Instant| t >= at && t < at + Duration::from_secs(1);
        near(asked_sent) || near(revealed_sent)
    };
    let (mut outside, mut within, mut frames) = (0usize, 0usize, 0usize);
    for (_, (_, f)) in &idle {
        // (Before the lecturer leads.)
        for (t, n) in f.lock().unwrap().iter().filter(|(t, _)| *t < led_from) {
            if poll_window(*t) {
                within += n;
                frames += 1;
            } else {
                outside += n;
            }
        }
    }
    for v in [
        &mut lat,
        &mut lat_ssh,
        &mut lat_web,
        &mut ask,
        &mut ans,
        &mut rev,
    ] {
        v.sort_by(f64::total_cmp);
    }
    let n_idle: usize = IDLE.iter().sum();
    let total = TYPING.0 + TYPING.1 + n_polled + n_idle + 1;
    println!(
        "sessions: a lecturer, {} typing (a key every {EVERY:?} for {RUN:?}; {} over the web), {n_polled} answering a poll at once ({} over the web, {} on phones), {n_idle} idle ({} over the web, {} on phones): {total} in all, {} on phones",
        TYPING.0 + TYPING.1,
        TYPING.1,
        POLLED[1],
        POLLED[2],
        IDLE[1],
        IDLE[2],
        POLLED[2] + IDLE[2]
    );
    let p = |v: &[f64]| {
        (
            percentile(v, 0.5),
            percentile(v, 0.99),
            v.last().copied().unwrap_or(f64::NAN),
        )
    };
    let (a, b, c) = p(&lat);
    println!(
        "key-to-frame: {} keys, p50 {a:.2} ms, p99 {b:.2} ms, max {c:.2} ms",
        lat.len()
    );
    for (name, v, i) in [("SSH", &lat_ssh, 0), ("web", &lat_web, 1)] {
        let (a, b, c) = p(v);
        println!(
            "  over {name}: {} keys, p50 {a:.2} ms, p99 {b:.2} ms, max {c:.2} ms; {:.0} bytes of frames per key",
            v.len(),
            bytes[i] as f64 / keys_n[i].max(1) as f64
        );
    }
    println!(
        "poll: the question reached the {n_polled} in p50 {:.1} ms, max {:.1} ms; Enter-to-frame p50 {:.1} ms, max {:.1} ms; the reveal in p50 {:.1} ms, max {:.1} ms; {rows} answers saved; the lecturer was sent {lecturer_bytes} bytes",
        percentile(&ask, 0.5),
        ask.last().copied().unwrap_or(f64::NAN),
        percentile(&ans, 0.5),
        ans.last().copied().unwrap_or(f64::NAN),
        percentile(&rev, 0.5),
        rev.last().copied().unwrap_or(f64::NAN),
    );
    let mb = |kb: u64| kb as f64 / 1024.0;
    let per: Vec<String> = VIAS
        .iter()
        .enumerate()
        .map(|(i, via)| {
            format!(
                "{:.1} MB with {} idle more over {via:?} ({:.2} MB each)",
                mb(rss[i + 1]),
                IDLE[i],
                mb(rss[i + 1].saturating_sub(rss[i])) / IDLE[i] as f64
            )
        })
        .collect();
    println!(
        "server RSS: {:.1} MB with the lecturer, {}; {:.1} MB peak with {total} sessions ({:.2} MB a session); {:.1} MB before the lecturer led, {:.1} MB after",
        mb(rss0),
        per.join(", "),
        mb(rss_peak),
        mb(rss_peak.saturating_sub(rss0)) / (total - 1) as f64,
        mb(rss_led0),
        mb(rss_led),
    );
    println!(
        "server CPU: {cpu:.1} s over {wall:.1} s ({:.0}% of one core)",
        cpu / wall * 100.0
    );
    println!(
        "bytes sent to the {n_idle} idle sessions: {outside} outside the poll; {within} in {frames} frames for its question and reveal ({} per session)",
        within / n_idle
    );
    for line in led {
        println!("{line}");
    }
    drop(polled);
    drop(idle);
    drop(server);
    Ok(())
}
