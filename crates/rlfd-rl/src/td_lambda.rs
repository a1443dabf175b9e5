//! Linear TD(λ) control with sparse traces: the machinery SARSA(λ)
//! ([`crate::SarsaLambda`]) and Watkins's Q(λ) ([`crate::WatkinsQLambda`])
//! share. They differ only in the action the target bootstraps from and in
//! whether an exploratory step cuts the traces: a [`TargetRule`].
//!
//! For a transition `(s, a, r, s', a')` with bootstrap action `b`:
//!
//! ```text
//! e(s, a) ← φ(s)            (replacing: other actions' traces at φ(s) cleared)
//! δ ← r + γ Q(s', b) − Q(s, a)         (δ ← r − Q(s, a) at a terminal s')
//! w ← w + α δ e
//! e ← γ λ e, traces below 0.01 dropped (or e ← 0 when the rule cuts them)
//! ```
//!
//! `Q(s, a)` is evaluated with the current weights at every step; `Q(s', ·)`
//! is the vector the agent evaluated when choosing `a'`, before this update.

use std::marker::PhantomData;

use crate::agent::TdControl;
use crate::features::ActiveFeatures;
use crate::linear::LinearActionValues;
use crate::params::TdParams;
use crate::traces::{MIN_TRACE, SparseTraces, TraceKind};

/// How a TD control method picks its bootstrap action and treats its traces.
pub trait TargetRule {
    /// The action the target bootstraps from, given the behaviour's next
    /// action and the values it was selected with.
    fn target(next_action: usize, selection_values: &[f64]) -> usize;
    /// Whether the traces survive the step (else they are cut to 0).
    fn keeps_traces(target: usize, next_action: usize) -> bool;
}

/// Linear TD(λ) control over `num_features × num_actions` weights.
#[derive(Clone, Debug)]
pub struct LinearTdLambda<R> {
    q: LinearActionValues,
    traces: SparseTraces,
    params: TdParams,
    kind: TraceKind,
    rule: PhantomData<R>,
}

impl<R: TargetRule> LinearTdLambda<R> {
    /// A learner over `num_features` features with all weights 0.
    pub fn new(num_features: usize, num_actions: usize, params: TdParams, kind: TraceKind) -> Self {
        let q = LinearActionValues::new(num_features, num_actions, 0.0);
        let traces = q.new_traces(kind, MIN_TRACE);
        LinearTdLambda { q, traces, params, kind, rule: PhantomData }
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

impl<R: TargetRule> TdControl for LinearTdLambda<R> {
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
        R::target(next_action, selection_values)
    }

    #[inline]
    fn learn(&mut self, features: &ActiveFeatures, action: usize, reward: f64, next: Option<(&[f64], usize, usize)>) {
        let q_sa = self.q.value_and_mark(&mut self.traces, features, action, self.kind);
        let step = |delta: f64| self.params.alpha * delta;
        match next {
            Some((next_values, target, next_action)) => {
                let delta = reward + self.params.gamma * next_values[target] - q_sa;
                if R::keeps_traces(target, next_action) {
                    self.q.apply_and_decay(&mut self.traces, step(delta), self.params.gamma * self.params.lambda);
                } else {
                    self.q.apply(&self.traces, step(delta));
                    self.traces.clear();
                }
            }
            None => self.q.apply(&self.traces, step(reward - q_sa)),
        }
    }
}
