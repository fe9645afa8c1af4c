//! What a reader accepts at most, and what a Hurst fit needs at least.

/// Files larger than this are refused before they are read (512 MiB).
pub const MAX_BYTES: u64 = 512 << 20;

/// Fewest points of a Hurst fit that says anything ([`crate::spectrum::fit`]; the
/// default band keeps them, [`crate::spectrum::band`]).
pub const MIN_FIT_POINTS: usize = 4;
/// The narrowest band, decades of q, a Hurst fit is judged over.
pub const MIN_FIT_DECADES: f64 = 0.5;
