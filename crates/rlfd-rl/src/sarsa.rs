//! SARSA(λ) with linear function approximation and sparse traces.
//!
//! For a transition `(s, a, r, s', a')` (Sutton & Barto 1998, Fig. 8.8):
//!
//! ```text
//! e(s, a) ← φ(s)            (replacing: other actions' traces at φ(s) cleared)
//! δ ← r + γ Q(s', a') − Q(s, a)
//! w ← w + α δ e
//! e ← γ λ e                 (traces below 0.01 dropped)
//! ```
//!
//! and at a terminal transition `δ ← r − Q(s, a)`. `Q(s, a)` is evaluated
//! with the current weights at every step; `Q(s', ·)` is the vector the agent
//! evaluated for choosing `a'`, before this update.

use crate::agent::TdControl;
use crate::features::ActiveFeatures;
use crate::linear::LinearActionValues;
use crate::params::TdParams;
use crate::traces::{MIN_TRACE, SparseTraces, TraceKind};

/// On-policy TD(λ) control.
#[derive(Clone, Debug)]
pub struct SarsaLambda {
    q: LinearActionValues,
    traces: SparseTraces,
    params: TdParams,
    kind: TraceKind,
}

impl SarsaLambda {
    /// A learner over `num_features` features with all weights 0.
    pub fn new(num_features: usize, num_actions: usize, params: TdParams, kind: TraceKind) -> Self {
        let q = LinearActionValues::new(num_features, num_actions, 0.0);
        let traces = q.new_traces(kind, MIN_TRACE);
        SarsaLambda { q, traces, params, kind }
    }

    /// The learned action values.
    pub fn action_values_table(&self) -> &LinearActionValues {
        &self.q
    }

    /// The learned action values, for initialisation schemes.
    pub fn action_values_table_mut(&mut self) -> &mut LinearActionValues {
        &mut self.q
    }

    /// Number of traces currently held (for tests and benches).
    pub fn trace_count(&self) -> usize {
        self.traces.len()
    }
}

impl TdControl for SarsaLambda {
    fn num_actions(&self) -> usize {
        self.q.num_actions()
    }

    fn params(&self) -> &TdParams {
        &self.params
    }

    #[inline]
    fn action_values(&self, features: &ActiveFeatures, out: &mut [f64]) {
        self.q.values(features, out);
    }

    fn begin_episode(&mut self) {
        self.traces.clear();
    }

    #[inline]
    fn target_action(&self, next_action: usize, _selection_values: &[f64]) -> usize {
        next_action
    }

    #[inline]
    fn learn(&mut self, features: &ActiveFeatures, action: usize, reward: f64, next: Option<(&[f64], usize, usize)>) {
        let q_sa = self.q.value_and_mark(&mut self.traces, features, action, self.kind);
        let delta = match next {
            None => reward - q_sa,
            Some((next_values, target, _)) => reward + self.params.gamma * next_values[target] - q_sa,
        };
        if next.is_some() {
            self.q.apply_and_decay(&mut self.traces, self.params.alpha * delta, self.params.gamma * self.params.lambda);
        } else {
            self.q.apply(&self.traces, self.params.alpha * delta);
        }
    }
}
