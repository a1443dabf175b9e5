//! Watkins's Q(λ): off-policy TD(λ) control (Watkins 1989; Sutton & Barto
//! 1998, §7.6). The target bootstraps from the greedy action `a*` at `s'`
//! (the behaviour's `a'` when it ties for the maximum), and the traces are
//! cut when `a'` is not greedy (see [`crate::td_lambda`] for the update).
//!
//! "Greedy" is judged on the values the agent selects with (learned values
//! plus any action-selection bias of look-ahead shaping), so that the target
//! follows the policy being learned.

use crate::policy::greedy_preferring;
use crate::td_lambda::{LinearTdLambda, TargetRule};

/// Watkins's rule: bootstrap from the greedy action, cut traces after an exploratory one.
#[derive(Clone, Copy, Debug)]
pub struct Watkins;

impl TargetRule for Watkins {
    #[inline]
    fn target(next_action: usize, selection_values: &[f64]) -> usize {
        greedy_preferring(selection_values, next_action)
    }

    #[inline]
    fn keeps_traces(target: usize, next_action: usize) -> bool {
        target == next_action
    }
}

/// Watkins's Q(λ) with linear function approximation and sparse traces.
pub type WatkinsQLambda = LinearTdLambda<Watkins>;
