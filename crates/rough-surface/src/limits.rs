//! What a reader accepts at most.

/// Files larger than this are refused before they are read (512 MiB).
pub const MAX_BYTES: u64 = 512 << 20;
