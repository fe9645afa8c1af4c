//! The solver's passes over a grid, cut into a fixed number of chunks and
//! run on rayon's pool (both cores of a two-core machine) when the grid is
//! large. The chunks' partial sums are added in chunk order, so a result
//! does not depend on how many cores there are or which ran what.

/// Chunks a pass is cut into (whatever the number of cores).
pub(crate) const CHUNKS: usize = 16;

/// Grids of fewer nodes run their passes on the calling thread alone (the
/// pool's hand-over would cost more than the pass).
pub(crate) const SERIAL_BELOW: usize = 1 << 15;

/// The length of a chunk of an `n`-element pass.
pub(crate) fn chunk_len(n: usize) -> usize {
    n.div_ceil(CHUNKS).max(1)
}

/// The smallest number of chunks one task takes: all of them for small
/// passes (no split), one for large.
pub(crate) fn min_len(n: usize) -> usize {
    if n < SERIAL_BELOW {
        CHUNKS
    } else {
        1
    }
}
