//! The mutation fuzzes' seed: fixed, so that a run is reproducible and
//! CI's verdict is the code's, not the draw's; `FUZZ_SEED=N` draws another
//! fixed sequence and `FUZZ_SEED=random` a fresh one each run (how new
//! failures are found: each one found is kept in the test's
//! `.proptest-regressions` file, which every run replays first).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use proptest::test_runner::RngSeed;

/// The seed when `FUZZ_SEED` is not set.
pub const DEFAULT_SEED: u64 = 20_261_126;

pub fn seed() -> RngSeed {
    match std::env::var("FUZZ_SEED").as_deref() {
        Ok("random") => RngSeed::Random,
        Ok(n) => RngSeed::Fixed(n.trim().parse().unwrap_or(DEFAULT_SEED)),
        Err(_) => RngSeed::Fixed(DEFAULT_SEED),
    }
}

/// The system allocator, recording the largest single allocation (a test
/// binary makes it its `#[global_allocator]`).
pub struct Counting;

/// The largest single allocation so far.
pub static LARGEST: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        LARGEST.fetch_max(l.size(), Ordering::Relaxed);
        System.alloc(l)
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        System.dealloc(p, l)
    }
    unsafe fn alloc_zeroed(&self, l: Layout) -> *mut u8 {
        LARGEST.fetch_max(l.size(), Ordering::Relaxed);
        System.alloc_zeroed(l)
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, n: usize) -> *mut u8 {
        LARGEST.fetch_max(n, Ordering::Relaxed);
        System.realloc(p, l, n)
    }
}

#[allow(dead_code)]
/// A file changed: bytes set or flipped, a piece cut out or repeated;
/// half the changes in its first 64 KiB, where the headers are.
pub fn mutate(b: &[u8], ops: &[(u8, usize, u8)]) -> Vec<u8> {
    let mut b = b.to_vec();
    for &(op, at, v) in ops {
        if b.is_empty() {
            break;
        }
        let span = if op & 0x80 != 0 {
            b.len().min(1 << 16)
        } else {
            b.len()
        };
        let i = at % span;
        match op % 4 {
            0 => b[i] = v,
            1 => b[i] ^= 1 << (v % 8),
            2 => {
                let n = (v as usize).min(b.len() - i);
                b.drain(i..i + n);
            }
            _ => {
                let piece = b[i..(i + v as usize).min(b.len())].to_vec();
                b.splice(i..i, piece);
            }
        }
    }
    b
}
