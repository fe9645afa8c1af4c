//! Load test of `roughtui serve` on loopback: 50 sessions each pressing a
//! key every 100 ms for 20 s, plus 10 idle sessions. Reports key-to-frame
//! p50/p99, the server's RSS (total, per idle session), its CPU, and the
//! bytes sent to idle sessions.
//!
//! ```sh
//! cargo build --release
//! cargo run --release --example serve_load [-- PATH-TO-ROUGHTUI]
//! ```

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use russh::ChannelMsg;

use client::{cpu_ticks, proc_status, Client};

const ACTIVE: usize = 50;
const IDLE: usize = 10;
const RUN: Duration = Duration::from_secs(20);
const EVERY: Duration = Duration::from_millis(100);

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

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

#[tokio::main(flavor = "multi_thread", worker_threads = 2)]
async fn main() -> anyhow::Result<()> {
    let bin = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "target/release/roughtui".into());
    let dir = tempfile::tempdir()?;
    let mut server = Command::new(&bin)
        .args(["serve", "--listen", "127.0.0.1:0", "--host-key"])
        .arg(dir.path().join("host_key"))
        .args(["--max-sessions", "100", "--max-per-address", "100"])
        .stdout(Stdio::piped())
        .spawn()
        .map_err(|e| anyhow::anyhow!("cannot run {bin} ({e}): cargo build --release first"))?;
    let pid = server.id();
    let mut port = 0;
    for line in BufReader::new(server.stdout.take().unwrap()).lines() {
        let line = line?;
        if let Some(rest) = line.strip_prefix("roughtui serve: listening on ") {
            port = rest.rsplit(':').next().unwrap_or("0").parse()?;
            break;
        }
    }
    anyhow::ensure!(port != 0, "the server printed no address");
    tokio::time::sleep(Duration::from_millis(200)).await;
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

    let cpu0 = cpu_ticks(pid);
    let t0 = Instant::now();
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
                loop {
                    match tokio::time::timeout(Duration::from_secs(5), ch.wait()).await {
                        Ok(Some(ChannelMsg::Data { .. })) => break,
                        Ok(Some(_)) => {}
                        _ => anyhow::bail!("no frame within 5 s"),
                    }
                }
                lat.push(sent.elapsed().as_secs_f64() * 1e3);
                tokio::time::sleep_until(next).await;
            }
            anyhow::Ok(lat)
        }));
    }
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
    let mut idle_bytes = 0;
    for (_, ch) in &mut idle {
        idle_bytes += drain(ch, Duration::from_millis(50)).await;
    }
    lat.sort_by(f64::total_cmp);
    println!("sessions: {ACTIVE} active (a key every {EVERY:?} for {RUN:?}) + {IDLE} idle");
    println!(
        "key-to-frame: {} keys, p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
        lat.len(),
        percentile(&lat, 0.5),
        percentile(&lat, 0.99),
        lat.last().copied().unwrap_or(f64::NAN)
    );
    println!(
        "server RSS: {:.1} MB at start, {:.1} MB with {IDLE} idle ({:.2} MB per idle session), {:.1} MB peak with {} sessions",
        rss0 as f64 / 1024.0,
        rss_idle as f64 / 1024.0,
        (rss_idle.saturating_sub(rss0)) as f64 / 1024.0 / IDLE as f64,
        rss_peak as f64 / 1024.0,
        ACTIVE + IDLE
    );
    println!(
        "server CPU: {cpu:.1} s over {wall:.1} s ({:.0}% of one core)",
        cpu / wall * 100.0
    );
    println!("bytes sent to idle sessions during the run: {idle_bytes}");
    let _ = server.kill();
    let _ = server.wait();
    Ok(())
}
