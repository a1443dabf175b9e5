//! Function approximation: turning a state vector into a few active features.
//!
//! A [`FeatureMap`] writes the active features of a state into a reusable
//! [`ActiveFeatures`] buffer (indices, and values for non-binary features), so
//! the learning loop allocates nothing per step.

mod first_touch;
mod rbf;
mod tile_coding;

pub use first_touch::FirstTouch;
pub use rbf::{RbfFeatures, RbfParams};
pub use tile_coding::{TILE_HASH_DESCRIPTION, TileCoder, TileIndexing};

/// The sparse feature vector of one state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ActiveFeatures {
    /// Indices of the active features, in `0..num_features`.
    pub indices: Vec<u32>,
    /// Their values; empty for binary feature maps (every active value is 1).
    pub values: Vec<f64>,
}

impl ActiveFeatures {
    /// A buffer with room for `capacity` active features.
    pub fn with_capacity(capacity: usize) -> Self {
        ActiveFeatures { indices: Vec::with_capacity(capacity), values: Vec::with_capacity(capacity) }
    }

    /// Whether every active feature has value 1.
    #[inline]
    pub fn is_binary(&self) -> bool {
        self.values.is_empty()
    }

    /// Number of active features.
    #[inline]
    pub fn len(&self) -> usize {
        self.indices.len()
    }

    /// No feature is active.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.indices.is_empty()
    }

    /// The value of the `k`-th active feature.
    #[inline]
    pub fn value(&self, k: usize) -> f64 {
        if self.values.is_empty() { 1.0 } else { self.values[k] }
    }

    /// Empties the buffer, keeping its memory.
    #[inline]
    pub fn clear(&mut self) {
        self.indices.clear();
        self.values.clear();
    }
}

/// A map from state vectors to sparse features.
pub trait FeatureMap {
    /// Number of distinct features (weights per action).
    fn num_features(&self) -> usize;
    /// Upper bound on the number of features active at once.
    fn max_active(&self) -> usize;
    /// Writes the active features of `state` into `out` (cleared first).
    fn features(&self, state: &[f64], out: &mut ActiveFeatures);
}
