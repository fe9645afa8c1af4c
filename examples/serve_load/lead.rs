//! The lecturer leads: a key every [`EVERY`] moves the marker, and every
//! follower (the idle students and, after the reveal, the pollers) is to
//! see it. Measures the key-to-frame time at each follower, the bytes each
//! gets, the server's CPU, and how many frames the server rendered for it
//! (from the console's `frames:` line): with shared frames, one per
//! terminal shape; with `ROUGHTUI_SHARED_FRAMES=off`, one per follower.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use client::cpu_ticks;

use super::client;
use super::student::Frames;

/// The lecturer's keys, and how often.
pub const KEYS: usize = 40;
pub const EVERY: Duration = Duration::from_millis(250);

/// The console's latest `frames:` line (the server writes one with each
/// summary).
pub type Counts = Arc<Mutex<Option<String>>>;

/// Rendered for followers, taken by others, drawn alone, from a
/// `frames:` line.
fn parse(line: &str) -> (u64, u64, u64) {
    let nums: Vec<u64> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    (
        nums.first().copied().unwrap_or(0),
        nums.get(1).copied().unwrap_or(0),
        nums.get(2).copied().unwrap_or(0),
    )
}

/// The counts once the class is quiet (a summary comes every 200 ms).
async fn settled(counts: &Counts) -> anyhow::Result<(u64, u64, u64)> {
    tokio::time::sleep(Duration::from_millis(800)).await;
    let line = counts.lock().unwrap().clone();
    let line = line.ok_or_else(|| anyhow::anyhow!("the server wrote no frames: line"))?;
    Ok(parse(&line))
}

/// Leads the class through [`KEYS`] keys; the report's lines.
pub async fn run(
    lect: &russh::ChannelWriteHalf<russh::client::Msg>,
    pid: u32,
    followers: &[Frames],
    counts: &Counts,
) -> anyhow::Result<Vec<String>> {
    let c0 = settled(counts).await?;
    let cpu0 = cpu_ticks(pid);
    let mut sent = Vec::new();
    let mut next = tokio::time::Instant::now();
    for k in 0..KEYS {
        next += EVERY;
        // Right then left: every key changes the scene.
        let key: &[u8] = if k % 2 == 0 { b"l" } else { b"h" };
        sent.push(Instant::now());
        lect.data(key).await?;
        tokio::time::sleep_until(next).await;
    }
    let cpu = (cpu_ticks(pid) - cpu0) as f64 / 100.0;
    let c1 = settled(counts).await?;
    // Each key's frame at each follower: the first to come before the
    // next key.
    let (mut lat, mut bytes, mut missed) = (Vec::new(), 0usize, 0usize);
    for f in followers {
        let f = f.lock().unwrap();
        for (i, t) in sent.iter().enumerate() {
            let end = sent.get(i + 1).copied().unwrap_or(*t + EVERY);
            let mut window = f.iter().filter(|(at, _)| at >= t && *at < end);
            match window.next() {
                Some((at, n)) => {
                    lat.push((*at - *t).as_secs_f64() * 1e3);
                    bytes += n + window.map(|w| w.1).sum::<usize>();
                }
                None => missed += 1,
            }
        }
    }
    lat.sort_by(f64::total_cmp);
    let pct = |p: f64| super::percentile(&lat, p);
    let n = followers.len();
    let per_key = |a: u64, b: u64| (b - a) as f64 / KEYS as f64;
    Ok(vec![
        format!(
            "the lecturer leads: {KEYS} keys (one every {EVERY:?}) to {n} followers: key-to-frame p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms over {} frames ({missed} missed); {:.0} bytes per follower per key",
            pct(0.5),
            pct(0.99),
            lat.last().copied().unwrap_or(f64::NAN),
            lat.len(),
            bytes as f64 / (n * KEYS) as f64
        ),
        format!(
            "  per key: {:.1} frames rendered for followers, {:.1} taken by others, {:.1} drawn alone (the lecturer's one among them); server CPU {cpu:.2} s ({:.1} ms per key)",
            per_key(c0.0, c1.0),
            per_key(c0.1, c1.1),
            per_key(c0.2, c1.2),
            cpu * 1e3 / KEYS as f64
        ),
    ])
}
