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

/// Rendered for followers, taken by others, drawn alone, sent as bytes
/// another session wrote, and phones' pages drawn and taken by others,
/// from a `frames:` line.
fn parse(line: &str) -> [u64; 6] {
    // (Past the log's time of day.)
    let line = line.split_once("frames: ").map_or("", |(_, rest)| rest);
    let nums: Vec<u64> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    std::array::from_fn(|i| nums.get(i).copied().unwrap_or(0))
}

/// The counts once the class is quiet (a summary comes every 200 ms).
async fn settled(counts: &Counts) -> anyhow::Result<[u64; 6]> {
    tokio::time::sleep(Duration::from_millis(800)).await;
    let line = counts.lock().unwrap().clone();
    let line = line.ok_or_else(|| anyhow::anyhow!("the server wrote no frames: line"))?;
    Ok(parse(&line))
}

/// Each key's frame at each of `followers`: the key-to-frame times (ms)
/// of the first frame to come before the next key, the bytes of all that
/// came in that time, and the keys whose frame did not come in it.
fn measure(sent: &[Instant], followers: &[Frames]) -> (Vec<f64>, usize, usize) {
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
    (lat, bytes, missed)
}

/// Leads the class through [`KEYS`] keys; the report's lines, one for the
/// followers in all and one for each group of them (terminals, phones).
pub async fn run(
    lect: &russh::ChannelWriteHalf<russh::client::Msg>,
    pid: u32,
    groups: &[(&str, Vec<Frames>)],
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
    let all: Vec<Frames> = groups.iter().flat_map(|g| g.1.iter().cloned()).collect();
    let mut lines = Vec::new();
    for (name, followers) in
        std::iter::once(("followers", &all)).chain(groups.iter().map(|g| (g.0, &g.1)))
    {
        let (lat, bytes, missed) = measure(&sent, followers);
        let pct = |p: f64| super::percentile(&lat, p);
        let n = followers.len();
        let head = if name == "followers" {
            format!("the lecturer leads: {KEYS} keys (one every {EVERY:?}) to {n} followers:")
        } else {
            format!("  {n} {name}:")
        };
        lines.push(format!(
            "{head} key-to-frame p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms over {} frames ({missed} missed); {:.0} bytes per follower per key",
            pct(0.5),
            pct(0.99),
            lat.last().copied().unwrap_or(f64::NAN),
            lat.len(),
            bytes as f64 / (n * KEYS).max(1) as f64
        ));
    }
    let per_key = |i: usize| (c1[i] - c0[i]) as f64 / KEYS as f64;
    lines.push(format!(
        "  per key: {:.1} frames rendered for followers, {:.1} taken by others ({:.1} of them sent as the bytes another wrote), {:.1} drawn alone (the lecturer's one among them); server CPU {cpu:.2} s ({:.1} ms per key)",
        per_key(0),
        per_key(1),
        per_key(3),
        per_key(2),
        cpu * 1e3 / KEYS as f64
    ));
    lines.push(format!(
        "  per key: {:.1} phone pages drawn (a picture and its texts), {:.1} taken by other phones",
        per_key(4),
        per_key(5)
    ));
    Ok(lines)
}
