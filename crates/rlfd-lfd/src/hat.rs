//! Human-Agent Transfer (HAT; Taylor, Suay & Chernova, AAMAS 2011): three
//! ways for a learner to use a summary policy `π_sum: s → a` of human
//! demonstrations (a RIPPER decision list in the thesis).
//!
//! - [`ValueBonus`]: in state `s`, the agent selects actions as if
//!   `Q(s, π_sum(s))` were `B` higher, for the first `D` episodes. Applied
//!   once, at the start, with no episode limit it becomes *Q-initialisation*
//!   (the thesis's chapter 6 baseline): see [`RuleAdvice`], the potential
//!   `Φ(s, a) = 1[a = π_sum(s)]` which, scaled by `B` and used as
//!   look-ahead advice with Wiewiora's correction, makes the agent learn
//!   exactly as one whose action values start at `B · 1[a = π_sum(s)]`.
//! - [`ExtraAction`]: a pseudo-action "do what the rules say" is added to
//!   the action set and learned like any other; for the first `C` episodes the
//!   agent is made to take it.
//! - [`ProbabilisticPolicyReuse`] (π-reuse, Fernández & Veloso 2006): with
//!   probability `ψ` the agent executes `π_sum(s)`, else it acts ε-greedily;
//!   `ψ` decays by a factor after every step or every episode.
//!
//! These are behaviour-policy components with their schedules; the chapter's
//! agent loop decides when to ask them. Nothing here learns.

use rand::Rng;
use rlfd_rl::random::uniform01;
use rlfd_rl::shaping::StateActionFunction;

use crate::ripper::DecisionList;

/// A summary policy: an action for every state.
pub trait StatePolicy {
    /// The action the policy takes in `state`.
    fn action(&self, state: &[f64]) -> usize;
}

impl StatePolicy for DecisionList {
    fn action(&self, state: &[f64]) -> usize {
        self.predict(state)
    }
}

/// `Φ(s, a) = 1` if `a = π_sum(s)`, else 0: the rule summary as a
/// state-action potential (scale it by the bonus `B`).
#[derive(Clone, Debug)]
pub struct RuleAdvice<P> {
    policy: P,
}

impl<P: StatePolicy> RuleAdvice<P> {
    /// Advice from a summary policy.
    pub fn new(policy: P) -> Self {
        RuleAdvice { policy }
    }

    /// The summary policy.
    pub fn policy(&self) -> &P {
        &self.policy
    }
}

impl<P: StatePolicy> StateActionFunction for RuleAdvice<P> {
    #[inline]
    fn values(&self, state: &[f64], out: &mut [f64]) {
        out.fill(0.0);
        let a = self.policy.action(state);
        if let Some(v) = out.get_mut(a) {
            *v = 1.0;
        }
    }
}

/// HAT's Value Bonus: `B` added to the rule's action when selecting, for the first `episodes` episodes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValueBonus {
    /// The bonus `B` (the thesis's Keepaway: 10).
    pub bonus: f64,
    /// For how many episodes it applies (the thesis's Keepaway: `C` = 100).
    pub episodes: usize,
}

impl ValueBonus {
    /// Adds the bonus to `values[rule_action]` if `episode` (from 0) is within the bonus period.
    #[inline]
    pub fn bias(&self, episode: usize, rule_action: usize, values: &mut [f64]) {
        if episode < self.episodes {
            values[rule_action] += self.bonus;
        }
    }
}

/// HAT's Extra Action: one more action meaning "follow the rules", forced early on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExtraAction {
    /// Number of primitive actions; the extra action is numbered `primitive_actions`.
    pub primitive_actions: usize,
    /// For how many episodes the agent must take the extra action (the thesis's Keepaway: 100).
    pub forced_episodes: usize,
}

impl ExtraAction {
    /// Actions the learner chooses among (primitive ones plus the extra one).
    pub fn learner_actions(&self) -> usize {
        self.primitive_actions + 1
    }

    /// The extra action's number.
    pub fn extra(&self) -> usize {
        self.primitive_actions
    }

    /// Whether the agent must take the extra action in `episode` (from 0).
    pub fn forced(&self, episode: usize) -> bool {
        episode < self.forced_episodes
    }

    /// The primitive action a learner's choice stands for.
    pub fn resolve(&self, choice: usize, state: &[f64], rules: &impl StatePolicy) -> usize {
        if choice == self.extra() { rules.action(state) } else { choice }
    }
}

/// When ψ decays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DecayUnit {
    /// After every step (Fernández & Veloso's π-reuse decays within an episode).
    Step,
    /// After every episode (HAT and CHAT; the default).
    Episode,
}

/// Probabilistic Policy Reuse: reuse the rules with a decaying probability ψ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProbabilisticPolicyReuse {
    psi: f64,
    decay: f64,
    unit: DecayUnit,
}

impl ProbabilisticPolicyReuse {
    /// Starts at ψ = `initial` and multiplies it by `decay` after every `unit`
    /// (the thesis's Keepaway: ψ decay 0.999 per episode, from ψ = 1).
    pub fn new(initial: f64, decay: f64, unit: DecayUnit) -> Self {
        assert!((0.0..=1.0).contains(&initial) && (0.0..=1.0).contains(&decay), "ψ and its decay are probabilities");
        ProbabilisticPolicyReuse { psi: initial, decay, unit }
    }

    /// The current reuse probability ψ.
    pub fn psi(&self) -> f64 {
        self.psi
    }

    /// Draws whether to follow the rules now (one uniform draw).
    #[inline]
    pub fn reuse<R: Rng + ?Sized>(&self, rng: &mut R) -> bool {
        uniform01(rng) < self.psi
    }

    /// Call after every step.
    #[inline]
    pub fn end_step(&mut self) {
        if self.unit == DecayUnit::Step {
            self.psi *= self.decay;
        }
    }

    /// Call after every episode.
    #[inline]
    pub fn end_episode(&mut self) {
        if self.unit == DecayUnit::Episode {
            self.psi *= self.decay;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    struct Threshold;
    impl StatePolicy for Threshold {
        fn action(&self, state: &[f64]) -> usize {
            usize::from(state[0] > 0.5)
        }
    }

    #[test]
    fn rule_advice_is_one_hot() {
        let advice = RuleAdvice::new(Threshold);
        let mut out = [9.0; 3];
        advice.values(&[0.7], &mut out);
        assert_eq!(out, [0.0, 1.0, 0.0]);
        advice.values(&[0.2], &mut out);
        assert_eq!(out, [1.0, 0.0, 0.0]);
    }

    #[test]
    fn value_bonus_applies_only_in_its_period() {
        let vb = ValueBonus { bonus: 10.0, episodes: 100 };
        let mut q = [1.0, 2.0, 3.0];
        vb.bias(99, 0, &mut q);
        assert_eq!(q, [11.0, 2.0, 3.0]);
        vb.bias(100, 0, &mut q);
        assert_eq!(q, [11.0, 2.0, 3.0]);
    }

    #[test]
    fn extra_action_resolves_to_the_rules() {
        let ea = ExtraAction { primitive_actions: 3, forced_episodes: 100 };
        assert_eq!(ea.learner_actions(), 4);
        assert_eq!(ea.resolve(3, &[0.9], &Threshold), 1);
        assert_eq!(ea.resolve(2, &[0.9], &Threshold), 2);
        assert!(ea.forced(99) && !ea.forced(100));
    }

    #[test]
    fn reuse_probability_decays_per_unit() {
        let mut per_episode = ProbabilisticPolicyReuse::new(1.0, 0.999, DecayUnit::Episode);
        per_episode.end_step();
        assert_eq!(per_episode.psi(), 1.0);
        for _ in 0..1000 {
            per_episode.end_episode();
        }
        assert!((per_episode.psi() - 0.999f64.powi(1000)).abs() < 1e-12);
        let mut per_step = ProbabilisticPolicyReuse::new(0.5, 0.5, DecayUnit::Step);
        per_step.end_episode();
        per_step.end_step();
        assert_eq!(per_step.psi(), 0.25);
        let mut rng = seeded(1);
        let n = 100_000;
        let hits = (0..n).filter(|_| per_step.reuse(&mut rng)).count();
        assert!((hits as f64 / n as f64 - 0.25).abs() < 0.01);
    }
}
