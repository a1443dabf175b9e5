//! The keepers' learners (section 5.3.1): each keeper its own Sarsa agent
//! over Gaussian RBF features of the 13 state variables, choosing a
//! macro-action when it has the ball, optionally biased by a rule summary
//! of a demonstration through one of HAT's three methods (section 5.2).
//!
//! - [`features`]: the RBF layout (a documented reconstruction);
//! - [`keeper`]: one keeper's SMDP Sarsa agent and its HAT method;
//! - [`team`]: three keepers playing and learning, the jumpstart evaluation
//!   and a 30-simulated-hour trial.
//!
//! **The update** (SMDP Sarsa, the keepaway benchmark's `LinearSarsaAgent`
//! with the thesis's constants). A keeper decides only when it has the ball.
//! Between its decision in `s` (action `a`) and its next one in `s'`
//! (action `a'`), `r` simulator cycles pass, the time the ball stayed in
//! play since its action; with γ = 1 the SMDP target needs no discounting
//! over the macro-action's duration:
//!
//! ```text
//! δ = r + Q(s', a') − Q(s, a)           (δ = r − Q(s, a) when the episode ends first)
//! w ← w + (α / 13) δ e,   e = φ(s) for a (replacing traces, decayed by γλ)
//! ```
//!
//! That is exactly the shared `SarsaLambda`'s update with reward `r` and
//! γ = 1, so the shared learner is used as is, one per keeper; the keeper
//! supplies `r` from the simulator's record of its last action. α = 0.05 is
//! spread over the 13 variables (each variable's bumps sum to about 1.25,
//! as one tile per tiling sums to 1 in the benchmark's tile coding, where
//! α is divided by the number of tilings), so one update moves `Q(s, a)` by
//! about `α δ`. λ is not in the thesis: the keepaway code's default, 0.

pub mod features;
pub mod keeper;
pub mod team;

use rlfd_rl::{TdParams, TraceKind};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::keepaway::STATE_VARS;

pub use features::RbfLayout;
pub use keeper::KeeperAgent;
pub use team::{LearningTrial, TrialParams, play_episode, run_learning_trial};

/// A parameter of a learner outside its domain.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("learner parameter `{name}` = {value} is invalid: {expected}")]
pub struct LearnerParamError {
    /// The field.
    pub name: &'static str,
    /// Its value.
    pub value: String,
    /// What it should be.
    pub expected: &'static str,
}

/// The Sarsa keepers' parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnerParams {
    /// Step size α, spread over the 13 state variables (thesis: 0.05, "to be consistent with past work").
    pub alpha: f64,
    /// ε of the ε-greedy behaviour (thesis: 0.10).
    pub epsilon: f64,
    /// Trace decay λ (not in the thesis; the keepaway code's default 0).
    pub lambda: f64,
    /// Discount (1: the episodic SMDP of the benchmark).
    pub gamma: f64,
    /// Eligibility traces (replacing, as the benchmark's learner).
    pub traces: TraceKind,
    /// The RBF features.
    pub rbf: RbfLayout,
}

impl LearnerParams {
    /// The thesis's keepers.
    pub fn thesis() -> Self {
        LearnerParams {
            alpha: 0.05,
            epsilon: 0.10,
            lambda: 0.0,
            gamma: 1.0,
            traces: TraceKind::Replacing,
            rbf: RbfLayout::reconstruction(),
        }
    }

    /// The shared learner's parameters: α per unit feature = α / 13.
    pub fn td(&self) -> Result<TdParams, LearnerParamError> {
        let td = TdParams {
            alpha: self.alpha / STATE_VARS as f64,
            gamma: self.gamma,
            lambda: self.lambda,
            epsilon: self.epsilon,
        };
        td.check().map_err(|e| LearnerParamError { name: e.name, value: e.value, expected: e.expected })
    }

    /// Checks every field.
    pub fn check(&self) -> Result<(), LearnerParamError> {
        self.td()?;
        let bad = |name, v: f64, expected| Err(LearnerParamError { name, value: v.to_string(), expected });
        if !(self.rbf.sigma_per_width.is_finite() && self.rbf.sigma_per_width > 0.0) {
            return bad("rbf.sigma_per_width", self.rbf.sigma_per_width, "a finite number > 0");
        }
        if !(self.rbf.cutoff.is_finite() && self.rbf.cutoff > 0.0) {
            return bad("rbf.cutoff", self.rbf.cutoff, "a finite number > 0");
        }
        Ok(())
    }
}

/// When Probabilistic Policy Reuse decays ψ (mirrors `rlfd_lfd::hat::DecayUnit`, serialisable).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PsiDecayUnit {
    /// After every decision.
    Step,
    /// After every episode (HAT's default).
    Episode,
}

impl PsiDecayUnit {
    /// The shared crate's unit.
    pub fn shared(self) -> rlfd_lfd::hat::DecayUnit {
        match self {
            PsiDecayUnit::Step => rlfd_lfd::hat::DecayUnit::Step,
            PsiDecayUnit::Episode => rlfd_lfd::hat::DecayUnit::Episode,
        }
    }
}

/// How a keeper uses the rule summary (section 5.2).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Sarsa alone.
    NoPrior,
    /// Value Bonus: the rules' action is selected as if its value were `bonus`
    /// higher, and taken outright for the first `forced_episodes` (thesis: B = 10, C = 100).
    ValueBonus {
        /// The bonus B.
        bonus: f64,
        /// The forced period C (episodes).
        forced_episodes: usize,
    },
    /// Extra Action: a fourth action "do what the rules say", taken outright
    /// for the first `forced_episodes` (thesis: C = 100).
    ExtraAction {
        /// The forced period C (episodes).
        forced_episodes: usize,
    },
    /// Probabilistic Policy Reuse: follow the rules with probability ψ, else
    /// act ε-greedily; ψ starts at `psi` and is multiplied by `decay` per `unit`.
    PolicyReuse {
        /// Initial ψ.
        psi: f64,
        /// Factor per unit (thesis: 0.999).
        decay: f64,
        /// Per decision or per episode (default: per episode).
        unit: PsiDecayUnit,
    },
}

impl Method {
    /// Value Bonus with the thesis's B = 10 and C = 100.
    pub const VALUE_BONUS: Method = Method::ValueBonus { bonus: 10.0, forced_episodes: 100 };
    /// Extra Action with the thesis's C = 100.
    pub const EXTRA_ACTION: Method = Method::ExtraAction { forced_episodes: 100 };
    /// PPR with ψ from 1, decay 0.999 per episode.
    pub const POLICY_REUSE: Method = Method::PolicyReuse { psi: 1.0, decay: 0.999, unit: PsiDecayUnit::Episode };

    /// Whether the method needs rules.
    pub fn uses_rules(&self) -> bool {
        !matches!(self, Method::NoPrior)
    }

    /// The thesis's name.
    pub fn label(&self) -> &'static str {
        match self {
            Method::NoPrior => "No Prior",
            Method::ValueBonus { .. } => "Value Bonus",
            Method::ExtraAction { .. } => "Extra Action",
            Method::PolicyReuse { .. } => "Probabilistic Policy Reuse",
        }
    }

    /// Checks the method's constants.
    pub fn check(&self) -> Result<(), LearnerParamError> {
        let bad = |name, v: f64, expected| Err(LearnerParamError { name, value: v.to_string(), expected });
        match *self {
            Method::ValueBonus { bonus, .. } if !bonus.is_finite() => bad("bonus", bonus, "a finite number"),
            Method::PolicyReuse { psi, .. } if !(0.0..=1.0).contains(&psi) => bad("psi", psi, "a probability"),
            Method::PolicyReuse { decay, .. } if !(0.0..=1.0).contains(&decay) => {
                bad("decay", decay, "a factor in [0, 1]")
            }
            _ => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_parameters_check_and_spread_alpha() {
        let p = LearnerParams::thesis();
        p.check().unwrap();
        assert!((p.td().unwrap().alpha - 0.05 / 13.0).abs() < 1e-15);
        let bad = LearnerParams { epsilon: 1.5, ..LearnerParams::thesis() };
        assert_eq!(bad.check().unwrap_err().name, "epsilon");
        assert!(Method::PolicyReuse { psi: 2.0, decay: 0.9, unit: PsiDecayUnit::Episode }.check().is_err());
        assert!(Method::POLICY_REUSE.check().is_ok() && Method::VALUE_BONUS.uses_rules());
    }
}
