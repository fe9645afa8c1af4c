//! What one read allows beyond the defaults, for the passes deep inside it
//! (the fill of undefined points refuses above its share): set for the
//! read on its thread by [`with`], read where it is needed.

use std::cell::Cell;

std::thread_local! {
    /// `--max-undefined` of the read under way on this thread.
    static MAX_UNDEFINED: Cell<Option<f64>> = const { Cell::new(None) };
}

/// The share of undefined points the read under way allows, if it
/// overrides the default.
pub(crate) fn max_undefined() -> Option<f64> {
    MAX_UNDEFINED.with(|m| m.get())
}

/// Runs `f` with a read's allowances in force on this thread: the share
/// of undefined points it fills (its options' `max_undefined`).
pub(crate) fn with<R>(max_undefined: Option<f64>, f: impl FnOnce() -> R) -> R {
    let before = MAX_UNDEFINED.with(|m| m.replace(max_undefined));
    let r = f();
    MAX_UNDEFINED.with(|m| m.set(before));
    r
}
