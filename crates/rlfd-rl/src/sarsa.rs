//! SARSA(λ): on-policy TD(λ) control (Rummery & Niranjan 1994; Sutton &
//! Barto 1998, Fig. 8.8). The target bootstraps from the behaviour's own next
//! action `a'`, and the traces always decay (see [`crate::td_lambda`] for the
//! update).

use crate::td_lambda::{LinearTdLambda, TargetRule};

/// The on-policy rule: bootstrap from `a'`, keep the traces.
#[derive(Clone, Copy, Debug)]
pub struct OnPolicy;

impl TargetRule for OnPolicy {
    #[inline]
    fn target(next_action: usize, _selection_values: &[f64]) -> usize {
        next_action
    }

    #[inline]
    fn keeps_traces(_target: usize, _next_action: usize) -> bool {
        true
    }
}

/// SARSA(λ) with linear function approximation and sparse traces.
pub type SarsaLambda = LinearTdLambda<OnPolicy>;
