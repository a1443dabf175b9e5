//! Dynamic potential-based advice (Harutyunyan, Devlin, Vrancx & Nowé 2015):
//! the thesis's Dynamic IRL Shaping (DIS), eqs. 6.6–6.8.
//!
//! A secondary action-value function `Φ†` over the learner's own features is
//! learned on-policy by one-step SARSA on the reward `−R†(s)` with step size
//! `β`, and serves as the potential. For a transition `(s, a) → (s', a')`:
//!
//! ```text
//! φ_old ← Φ†(s, a)
//! δ† ← −R†(s) + γ Φ†(s', a') − Φ†(s, a)        (Φ†(terminal, ·) = 0)
//! Φ†(s, a) ← Φ†(s, a) + β δ†
//! F ← γ Φ†(s', a') − φ_old                     (after the update)
//! ```
//!
//! When `Φ†` has converged, `E[F] = R†`: the expert's reward is delivered as
//! potential-based shaping. The order (update before computing `F`, with the
//! old `Φ†(s, a)`) follows the published algorithm. `a'` is always the
//! behaviour's next action: `Φ†` is learned on-policy even when the main
//! learner is Q(λ). The secondary learner has no traces (the thesis says
//! "SARSA"); its step size `β` is per active feature, like `α`.

use super::{Selection, Shaping, StateFunction, Transition, Visit};
use crate::linear::LinearActionValues;

/// Shaping by a potential learned from an expert reward `R†`.
#[derive(Clone, Debug)]
pub struct DynamicShaping<R> {
    phi: LinearActionValues,
    expert_reward: R,
    beta: f64,
    scale: f64,
    selection: Selection,
}

impl<R: StateFunction> DynamicShaping<R> {
    /// `Φ†` over `num_features × num_actions` weights, all 0, learned from `expert_reward` (= R†).
    pub fn new(
        num_features: usize,
        num_actions: usize,
        expert_reward: R,
        beta: f64,
        scale: f64,
        selection: Selection,
    ) -> Self {
        DynamicShaping {
            phi: LinearActionValues::new(num_features, num_actions, 0.0),
            expert_reward,
            beta,
            scale,
            selection,
        }
    }

    /// The learned secondary values `Φ†` (unscaled).
    pub fn secondary_values(&self) -> &LinearActionValues {
        &self.phi
    }

    /// The expert reward `R†`.
    pub fn expert_reward(&self) -> &R {
        &self.expert_reward
    }
}

impl<R: StateFunction> Shaping for DynamicShaping<R> {
    #[inline]
    fn biases_selection(&self) -> bool {
        self.selection == Selection::Corrected
    }

    #[inline]
    fn potentials(&mut self, visit: &Visit<'_>, out: &mut [f64]) {
        self.phi.values(visit.features, out);
        for v in out.iter_mut() {
            *v *= self.scale;
        }
    }

    #[inline]
    fn reward(&mut self, t: &Transition<'_>) -> f64 {
        let phi_old = self.phi.value(t.from.features, t.action);
        let r_dagger = -self.expert_reward.value(t.from.state);
        let f = match &t.next {
            Some(n) => {
                let phi_next = self.phi.value(n.visit.features, n.action);
                let delta = r_dagger + t.gamma * phi_next - phi_old;
                self.phi.add_to(t.from.features, t.action, self.beta * delta);
                t.gamma * self.phi.value(n.visit.features, n.action) - phi_old
            }
            None => {
                let delta = r_dagger - phi_old;
                self.phi.add_to(t.from.features, t.action, self.beta * delta);
                -phi_old
            }
        };
        self.scale * f
    }
}
