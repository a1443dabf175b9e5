//! Linear action values: `Q(s, a) = Σ_k w[k, a] φ_k(s)`.
//!
//! Weights are stored feature-major (`w[k * A + a]`), so the values of all
//! actions at one state read `A` adjacent weights per active feature.

use crate::features::ActiveFeatures;
use crate::traces::{GenerationTraces, SparseTraces, TraceKind};

/// A weight table over `num_features × num_actions`.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearActionValues {
    weights: Vec<f64>,
    num_actions: usize,
}

impl LinearActionValues {
    /// All weights start at `initial` (0 in every experiment of the thesis).
    pub fn new(num_features: usize, num_actions: usize, initial: f64) -> Self {
        assert!(num_actions > 0, "a learner needs at least one action");
        LinearActionValues { weights: vec![initial; num_features * num_actions], num_actions }
    }

    /// Number of actions.
    #[inline]
    pub fn num_actions(&self) -> usize {
        self.num_actions
    }

    /// Number of weights (features × actions).
    #[inline]
    pub fn num_weights(&self) -> usize {
        self.weights.len()
    }

    /// The weights, feature-major.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The weights, feature-major, for initialisation schemes.
    pub fn weights_mut(&mut self) -> &mut [f64] {
        &mut self.weights
    }

    /// Weight index of (feature, action).
    #[inline]
    pub fn weight_index(&self, feature: u32, action: usize) -> usize {
        feature as usize * self.num_actions + action
    }

    /// `Q(s, a)`.
    #[inline]
    pub fn value(&self, features: &ActiveFeatures, action: usize) -> f64 {
        let a_n = self.num_actions;
        let mut q = 0.0;
        if features.is_binary() {
            for &k in &features.indices {
                q += self.weights[k as usize * a_n + action];
            }
        } else {
            for (&k, &v) in features.indices.iter().zip(&features.values) {
                q += self.weights[k as usize * a_n + action] * v;
            }
        }
        q
    }

    /// `Q(s, ·)` into `out` (length `num_actions`).
    #[inline]
    pub fn values(&self, features: &ActiveFeatures, out: &mut [f64]) {
        // Fixed-size inner loops for the action counts of the thesis's domains
        // (4 in the Maze, 3 in Keepaway, 12 in Mario) let the compiler unroll
        // and vectorise them.
        match self.num_actions {
            2 => self.values_fixed::<2>(features, out),
            3 => self.values_fixed::<3>(features, out),
            4 => self.values_fixed::<4>(features, out),
            12 => self.values_fixed::<12>(features, out),
            _ => self.values_any(features, out),
        }
    }

    #[inline]
    fn values_fixed<const A: usize>(&self, features: &ActiveFeatures, out: &mut [f64]) {
        let mut acc = [0.0f64; A];
        if features.is_binary() {
            for &k in &features.indices {
                let row: &[f64; A] =
                    self.weights[k as usize * A..k as usize * A + A].try_into().expect("row of A weights");
                for a in 0..A {
                    acc[a] += row[a];
                }
            }
        } else {
            for (&k, &v) in features.indices.iter().zip(&features.values) {
                let row: &[f64; A] =
                    self.weights[k as usize * A..k as usize * A + A].try_into().expect("row of A weights");
                for a in 0..A {
                    acc[a] += row[a] * v;
                }
            }
        }
        out[..A].copy_from_slice(&acc);
    }

    fn values_any(&self, features: &ActiveFeatures, out: &mut [f64]) {
        let a_n = self.num_actions;
        out.fill(0.0);
        for (j, &k) in features.indices.iter().enumerate() {
            let v = features.value(j);
            let row = &self.weights[k as usize * a_n..k as usize * a_n + a_n];
            for (o, w) in out.iter_mut().zip(row) {
                *o += w * v;
            }
        }
    }

    /// Traces suited to `kind` for this table: keyed per feature for
    /// replacing traces, per weight for accumulating ones.
    pub fn new_traces(&self, kind: TraceKind, threshold: f64) -> SparseTraces {
        match kind {
            TraceKind::Replacing => SparseTraces::per_feature(self.weights.len() / self.num_actions, threshold),
            TraceKind::Accumulating => SparseTraces::per_weight(self.weights.len(), threshold),
        }
    }

    /// `Q(s, a)` and marking (s, a) in the traces, in one pass over the
    /// features (one loop per feature kind and trace kind, so the inner loop
    /// carries no branch on either).
    #[inline]
    pub fn value_and_mark(
        &self,
        traces: &mut SparseTraces,
        features: &ActiveFeatures,
        action: usize,
        kind: TraceKind,
    ) -> f64 {
        let a_n = self.num_actions;
        let mut q = 0.0;
        match (features.is_binary(), kind) {
            (true, TraceKind::Replacing) => {
                for &k in &features.indices {
                    let i = k as usize * a_n + action;
                    q += self.weights[i];
                    traces.replace(k as usize, i, 1.0);
                }
            }
            (true, TraceKind::Accumulating) => {
                for &k in &features.indices {
                    let i = k as usize * a_n + action;
                    q += self.weights[i];
                    traces.add(i, 1.0);
                }
            }
            (false, TraceKind::Replacing) => {
                for (&k, &v) in features.indices.iter().zip(&features.values) {
                    let i = k as usize * a_n + action;
                    q += self.weights[i] * v;
                    traces.replace(k as usize, i, v);
                }
            }
            (false, TraceKind::Accumulating) => {
                for (&k, &v) in features.indices.iter().zip(&features.values) {
                    let i = k as usize * a_n + action;
                    q += self.weights[i] * v;
                    traces.add(i, v);
                }
            }
        }
        q
    }

    /// `Q(s, a)` for binary features and marking (s, a) in this step's
    /// generation (replacing traces); `None` (nothing marked) when the
    /// generations are full (see [`GenerationTraces::mark_state`]).
    #[inline]
    pub fn value_and_mark_generation(
        &self,
        traces: &mut GenerationTraces,
        features: &ActiveFeatures,
        action: usize,
    ) -> Option<f64> {
        debug_assert!(features.is_binary());
        let a_n = self.num_actions;
        traces.mark_state(&features.indices, |k| (k as usize * a_n + action) as u32, &self.weights)
    }

    /// Marks (s, a) in traces made by [`LinearActionValues::new_traces`] for the same `kind`.
    #[inline]
    pub fn mark(&self, traces: &mut SparseTraces, features: &ActiveFeatures, action: usize, kind: TraceKind) {
        let a_n = self.num_actions;
        match kind {
            TraceKind::Replacing => {
                for (j, &k) in features.indices.iter().enumerate() {
                    traces.replace(k as usize, k as usize * a_n + action, features.value(j));
                }
            }
            TraceKind::Accumulating => {
                for (j, &k) in features.indices.iter().enumerate() {
                    traces.add(k as usize * a_n + action, features.value(j));
                }
            }
        }
    }

    /// `w += step · φ(s)` for action `a` (a one-step update without traces).
    #[inline]
    pub fn add_to(&mut self, features: &ActiveFeatures, action: usize, step: f64) {
        let a_n = self.num_actions;
        for (j, &k) in features.indices.iter().enumerate() {
            self.weights[k as usize * a_n + action] += step * features.value(j);
        }
    }

    /// `w += step · e` over the traces, then `e ← factor · e` (one pass).
    #[inline]
    pub fn apply_and_decay(&mut self, traces: &mut SparseTraces, step: f64, factor: f64) {
        traces.apply_and_decay(&mut self.weights, step, factor);
    }

    /// `w += step · e` over the traces.
    #[inline]
    pub fn apply(&mut self, traces: &SparseTraces, step: f64) {
        traces.apply(&mut self.weights, step);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_sum_weights_of_active_features() {
        let mut q = LinearActionValues::new(4, 2, 0.0);
        q.weights_mut().copy_from_slice(&[1.0, 10.0, 2.0, 20.0, 3.0, 30.0, 4.0, 40.0]);
        let f = ActiveFeatures { indices: vec![0, 2], values: vec![] };
        let mut out = [0.0; 2];
        q.values(&f, &mut out);
        assert_eq!(out, [4.0, 40.0]);
        assert_eq!(q.value(&f, 1), 40.0);
        let g = ActiveFeatures { indices: vec![1, 3], values: vec![0.5, 2.0] };
        q.values(&g, &mut out);
        assert_eq!(out, [9.0, 90.0]);
        assert_eq!(q.value(&g, 0), 9.0);
    }

    #[test]
    fn replacing_marks_clear_other_actions() {
        let q = LinearActionValues::new(3, 3, 0.0);
        let f = ActiveFeatures { indices: vec![1], values: vec![] };
        let mut t = q.new_traces(TraceKind::Replacing, 0.01);
        q.mark(&mut t, &f, 0, TraceKind::Replacing);
        q.mark(&mut t, &f, 2, TraceKind::Replacing);
        assert_eq!(t.get(3), 0.0);
        assert_eq!(t.get(5), 1.0);
        let mut t = q.new_traces(TraceKind::Accumulating, 0.01);
        q.mark(&mut t, &f, 2, TraceKind::Accumulating);
        q.mark(&mut t, &f, 2, TraceKind::Accumulating);
        q.mark(&mut t, &f, 0, TraceKind::Accumulating);
        assert_eq!((t.get(3), t.get(5)), (1.0, 2.0));
    }
}
