//! How many threads the parallel passes use.

/// Threads for the parallel passes (parse, plane, window, FFTs, Sq): the
/// machine's cores, at most four; asked once (the answer reads cgroup
/// files).
pub(crate) fn count() -> usize {
    static N: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *N.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get().min(4)))
}
