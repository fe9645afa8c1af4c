//! What a hostile-file test needs: an allocator that records the largest
//! allocation (each test binary declares it its global allocator) and
//! files changed at random.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, recording the largest single allocation.
pub struct Counting;

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

/// The largest allocation so far.
pub fn largest() -> usize {
    LARGEST.load(Ordering::Relaxed)
}

/// A file changed: bytes set or flipped, a piece cut out or repeated;
/// the changes whose op has its top bit set fall in the first 64 KiB,
/// where the headers are.
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
