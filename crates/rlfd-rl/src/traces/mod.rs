//! Sparse eligibility traces.
//!
//! With tile coding only a few hundred of the weights carry a non-negligible
//! trace at any time, so the traces are a list of `(weight index, trace)`
//! entries plus a dense slot table for O(1) lookup. Decaying touches only the
//! listed entries and drops those below a threshold: decaying every weight's
//! trace each step would cost the whole weight vector per step.
//!
//! The threshold follows the Keepaway benchmark's `LinearSarsaAgent`
//! (`minimumTrace = 0.01`) and Sutton's tile-coding Sarsa(λ) code: a trace
//! below 0.01 is treated as 0.
//!
//! [`GenerationTraces`] keeps replacing traces of binary features (tile
//! coding) by the step that set them, with the same numbers (see
//! [`generations`]); the TD learners use it where it applies.

pub mod generations;

pub use generations::GenerationTraces;

/// How a visited feature's trace is set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TraceKind {
    /// `e ← φ` for the taken action, and the traces of the other actions at
    /// the same features are cleared (Singh & Sutton 1996; what the Keepaway
    /// benchmark and Sutton's tile-coding code do).
    Replacing,
    /// `e ← e + φ`.
    Accumulating,
}

/// The default threshold below which a trace is dropped.
pub const MIN_TRACE: f64 = 0.01;

const NONE: u32 = u32::MAX;

/// Eligibility traces kept as a sparse list.
///
/// Each entry has a *key*, a weight index and a trace. Built with
/// [`SparseTraces::per_weight`], the key is the weight itself (any number of
/// actions may be traced at one feature: accumulating traces). Built with
/// [`SparseTraces::per_feature`], the key is the feature, and
/// [`SparseTraces::replace`] overwrites the feature's one entry: replacing
/// traces that clear the other actions at the same feature, for the price of
/// one lookup instead of one per action.
#[derive(Clone, Debug)]
pub struct SparseTraces {
    entries: Vec<Entry>,
    slot: Vec<u32>,
    threshold: f64,
}

/// One traced weight; kept together so that a push or a swap-remove moves one
/// 16-byte record.
#[derive(Clone, Copy, Debug)]
struct Entry {
    key: u32,
    index: u32,
    value: f64,
}

impl SparseTraces {
    /// Traces keyed by weight, for `num_weights` weights.
    pub fn per_weight(num_weights: usize, threshold: f64) -> Self {
        Self::with_keys(num_weights, threshold)
    }

    /// Traces keyed by feature (at most one traced action per feature), for `num_features` features.
    pub fn per_feature(num_features: usize, threshold: f64) -> Self {
        Self::with_keys(num_features, threshold)
    }

    fn with_keys(num_keys: usize, threshold: f64) -> Self {
        assert!(num_keys < NONE as usize, "too many trace keys for u32 slots");
        SparseTraces { entries: Vec::with_capacity(1024), slot: vec![NONE; num_keys], threshold }
    }

    /// Number of non-zero traces.
    #[inline]
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// No trace is set.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The trace of weight `weight` (0 if none).
    pub fn get(&self, weight: usize) -> f64 {
        self.entries.iter().find(|e| e.index as usize == weight).map_or(0.0, |e| e.value)
    }

    /// Sets the entry of `key` to (`weight`, `v`), replacing whatever it held.
    #[inline]
    pub fn replace(&mut self, key: usize, weight: usize, v: f64) {
        let slot = &mut self.slot[key];
        if *slot == NONE {
            *slot = self.entries.len() as u32;
            self.entries.push(Entry { key: key as u32, index: weight as u32, value: v });
        } else {
            let e = &mut self.entries[*slot as usize];
            e.index = weight as u32;
            e.value = v;
        }
    }

    /// Sets the trace of weight `weight` to `v` (traces keyed per weight).
    #[inline]
    pub fn set(&mut self, weight: usize, v: f64) {
        self.replace(weight, weight, v);
    }

    /// Adds `v` to the trace of weight `weight` (traces keyed per weight).
    #[inline]
    pub fn add(&mut self, weight: usize, v: f64) {
        match self.slot[weight] {
            NONE => self.replace(weight, weight, v),
            s => self.entries[s as usize].value += v,
        }
    }

    /// Removes the entry of `key`, if any.
    #[inline]
    pub fn remove(&mut self, key: usize) {
        let s = self.slot[key];
        if s != NONE {
            self.swap_remove(s as usize);
        }
    }

    #[inline]
    fn swap_remove(&mut self, s: usize) {
        let gone = self.entries.swap_remove(s);
        self.slot[gone.key as usize] = NONE;
        if let Some(moved) = self.entries.get(s) {
            self.slot[moved.key as usize] = s as u32;
        }
    }

    /// Multiplies every trace by `factor` and drops those below the threshold.
    #[inline]
    pub fn decay(&mut self, factor: f64) {
        let mut s = 0;
        while s < self.entries.len() {
            let v = self.entries[s].value * factor;
            if v.abs() < self.threshold {
                self.swap_remove(s);
            } else {
                self.entries[s].value = v;
                s += 1;
            }
        }
    }

    /// Removes every trace.
    #[inline]
    pub fn clear(&mut self) {
        for e in &self.entries {
            self.slot[e.key as usize] = NONE;
        }
        self.entries.clear();
    }

    /// `w[i] += step * e[i]` for every traced weight.
    #[inline]
    pub fn apply(&self, weights: &mut [f64], step: f64) {
        for e in &self.entries {
            weights[e.index as usize] += step * e.value;
        }
    }

    /// `w[i] += step * e[i]` for every traced weight, then `e ← factor · e`
    /// with traces below the threshold dropped: [`SparseTraces::apply`] and
    /// [`SparseTraces::decay`] in one pass over the entries.
    #[inline]
    pub fn apply_and_decay(&mut self, weights: &mut [f64], step: f64, factor: f64) {
        let mut s = 0;
        while s < self.entries.len() {
            let e = self.entries[s];
            weights[e.index as usize] += step * e.value;
            let v = e.value * factor;
            if v.abs() < self.threshold {
                self.swap_remove(s);
            } else {
                self.entries[s].value = v;
                s += 1;
            }
        }
    }

    /// The `(weight index, trace)` entries, in no particular order.
    pub fn iter(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.entries.iter().map(|e| (e.index as usize, e.value))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn set_add_remove_decay() {
        let mut t = SparseTraces::per_weight(10, 0.01);
        t.set(3, 1.0);
        t.add(3, 0.5);
        t.add(7, 1.0);
        assert_eq!(t.get(3), 1.5);
        assert_eq!(t.len(), 2);
        t.remove(3);
        assert_eq!(t.get(3), 0.0);
        assert_eq!(t.get(7), 1.0);
        t.decay(0.25); // 0.25
        t.decay(0.25); // 0.0625
        t.decay(0.25); // 0.015625
        assert_eq!(t.len(), 1);
        t.decay(0.25); // below 0.01: dropped
        assert!(t.is_empty());
        assert_eq!(t.get(7), 0.0);
    }

    #[test]
    fn per_feature_keys_hold_one_action() {
        // Feature 2 of a 3-action table: weights 6, 7, 8.
        let mut t = SparseTraces::per_feature(4, 0.01);
        t.replace(2, 6, 1.0);
        t.replace(2, 8, 1.0);
        assert_eq!(t.len(), 1);
        assert_eq!((t.get(6), t.get(8)), (0.0, 1.0));
        t.replace(0, 1, 0.5);
        t.remove(2);
        assert_eq!(t.iter().collect::<Vec<_>>(), vec![(1, 0.5)]);
    }

    proptest! {
        // The sparse traces behave exactly like a dense trace vector with the
        // same threshold rule.
        #[test]
        fn matches_a_dense_model(ops in proptest::collection::vec((0u8..5, 0usize..20, 0.0f64..2.0), 0..200)) {
            let mut sparse = SparseTraces::per_weight(20, 0.01);
            let mut dense = [0.0f64; 20];
            for (op, i, v) in ops {
                match op {
                    0 => { sparse.set(i, v); dense[i] = v; }
                    1 => { sparse.add(i, v); dense[i] += v; }
                    2 => { sparse.remove(i); dense[i] = 0.0; }
                    3 => {
                        let f = v / 2.0;
                        sparse.decay(f);
                        for d in dense.iter_mut() { let x = *d * f; *d = if x.abs() < 0.01 { 0.0 } else { x }; }
                    }
                    _ => { sparse.clear(); dense = [0.0; 20]; }
                }
                for (i, &d) in dense.iter().enumerate() {
                    prop_assert_eq!(sparse.get(i), d);
                }
                let mut w = [0.0f64; 20];
                sparse.apply(&mut w, 2.0);
                for (i, &d) in dense.iter().enumerate() {
                    prop_assert_eq!(w[i], 2.0 * d);
                }
            }
        }
    }
}
