//! Watkins's Q(λ) with linear function approximation and sparse traces.
//!
//! As SARSA(λ) (see [`crate::sarsa`]) but off-policy: the target bootstraps
//! from the greedy action `a*` at `s'` (the behaviour's `a'` when it ties for
//! the maximum), and the traces are cut when the behaviour's `a'` is not
//! greedy (Watkins 1989; Sutton & Barto 1998, §7.6):
//!
//! ```text
//! e(s, a) ← φ(s)
//! δ ← r + γ Q(s', a*) − Q(s, a)
//! w ← w + α δ e
//! e ← γ λ e if a' = a*, else e ← 0
//! ```
//!
//! "Greedy" is judged on the values the agent selects with (learned values
//! plus any action-selection bias of look-ahead shaping), so that the target
//! follows the policy being learned.

use crate::agent::TdControl;
use crate::features::ActiveFeatures;
use crate::linear::LinearActionValues;
use crate::params::TdParams;
use crate::policy::greedy_preferring;
use crate::traces::{MIN_TRACE, SparseTraces, TraceKind};

/// Off-policy TD(λ) control (Watkins).
#[derive(Clone, Debug)]
pub struct WatkinsQLambda {
    q: LinearActionValues,
    traces: SparseTraces,
    params: TdParams,
    kind: TraceKind,
}

impl WatkinsQLambda {
    /// A learner over `num_features` features with all weights 0.
    pub fn new(num_features: usize, num_actions: usize, params: TdParams, kind: TraceKind) -> Self {
        let q = LinearActionValues::new(num_features, num_actions, 0.0);
        let traces = q.new_traces(kind, MIN_TRACE);
        WatkinsQLambda { q, traces, params, kind }
    }

    /// The learned action values.
    pub fn action_values_table(&self) -> &LinearActionValues {
        &self.q
    }

    /// Number of traces currently held (for tests and benches).
    pub fn trace_count(&self) -> usize {
        self.traces.len()
    }
}

impl TdControl for WatkinsQLambda {
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
    fn target_action(&self, next_action: usize, selection_values: &[f64]) -> usize {
        greedy_preferring(selection_values, next_action)
    }

    #[inline]
    fn learn(&mut self, features: &ActiveFeatures, action: usize, reward: f64, next: Option<(&[f64], usize, usize)>) {
        let q_sa = self.q.value_and_mark(&mut self.traces, features, action, self.kind);
        let delta = match next {
            None => reward - q_sa,
            Some((next_values, target, _)) => reward + self.params.gamma * next_values[target] - q_sa,
        };
        match next {
            Some((_, target, next_action)) if target == next_action => self.q.apply_and_decay(
                &mut self.traces,
                self.params.alpha * delta,
                self.params.gamma * self.params.lambda,
            ),
            _ => {
                self.q.apply(&self.traces, self.params.alpha * delta);
                self.traces.clear();
            }
        }
    }
}
