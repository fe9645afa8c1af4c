//! The mutation fuzzes' seed: fixed, so that a run is reproducible and
//! CI's verdict is the code's, not the draw's; `FUZZ_SEED=N` draws another
//! fixed sequence and `FUZZ_SEED=random` a fresh one each run (how new
//! failures are found: each one found is kept in the test's
//! `.proptest-regressions` file, which every run replays first).

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
