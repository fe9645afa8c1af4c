//! The pressure cap: one hardness everywhere, or one per node (the size
//! effect node by node), and the three sets a node belongs to.

/// The pressure cap: one hardness for every node, or one per node.
pub(crate) trait Cap: Sync {
    /// The cap of node `i`.
    fn at(&self, i: usize) -> f64;
    /// The largest cap.
    fn max(&self) -> f64;
    /// The mean cap (what the cap is reported as).
    fn mean(&self) -> f64;
}

/// One hardness everywhere.
pub(crate) struct Uniform(pub f64);

impl Cap for Uniform {
    #[inline(always)]
    fn at(&self, _: usize) -> f64 {
        self.0
    }
    fn max(&self) -> f64 {
        self.0
    }
    fn mean(&self) -> f64 {
        self.0
    }
}

/// A hardness per node.
pub(crate) struct PerNode<'a> {
    pub caps: &'a [f64],
    pub max: f64,
    pub mean: f64,
}

impl Cap for PerNode<'_> {
    #[inline(always)]
    fn at(&self, i: usize) -> f64 {
        self.caps[i]
    }
    fn max(&self) -> f64 {
        self.max
    }
    fn mean(&self) -> f64 {
        self.mean
    }
}

/// Where a node stands against its bounds.
#[derive(Clone, Copy, PartialEq)]
pub(crate) enum Set {
    Zero,
    Free,
    Cap,
}

#[inline(always)]
pub(crate) fn class(p: f64, cap: f64) -> Set {
    if p <= 0.0 {
        Set::Zero
    } else if p >= cap {
        Set::Cap
    } else {
        Set::Free
    }
}
