//! How a user teaches Int-RL: reward after actions, guidance before them,
//! and what they do when they see no progress.
//!
//! The thesis (section 4.4) lists Int-RL's assumptions and finds them met:
//! "1. A positive feedback will follow most correct actions, 2. A negative
//! feedback will follow most incorrect actions. 3. Guidance will be given in
//! order to narrow down the choice of the action it precedes … all of the
//! assumptions listed above held when users taught the task", and "Many
//! users could not see an improvement in learning until the end of the
//! experiment, which led some to stop rewarding or to vary their reward
//! strategy". The model:
//! - a watched action (probability `attention`) is rewarded +1 if the user
//!   judged it right ([`super::perception`]), −1 if wrong;
//! - before an action, with probability `attention ×`
//!   [`RewardModel::guide_probability`], the user guides: one action the user
//!   judges wrong is taken out of the robot's choice (guidance narrows the
//!   choice; "the user cannot give a specific action command");
//! - every `patience` seconds the user compares the share of actions judged
//!   right with the previous period; if it has not risen, they vary their
//!   strategy: from rewarding both ways to rewarding only right actions or
//!   to stopping (even odds), and from rewarding only right actions to
//!   stopping.

use rand::Rng;
use rlfd_rl::random::{below, bernoulli};
use serde::{Deserialize, Serialize};

use super::traits::UserTraits;
use crate::dbug::{Action, seconds_to_ticks};

/// The Int-RL teaching model's constants (ours).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RewardModel {
    /// Probability of guiding before an action when watching.
    pub guide_probability: f64,
    /// Seconds into a pickup or sweep before the user recognises it (a
    /// wait is recognised when it ends).
    pub recognise_seconds: f64,
    /// Probability of stopping (rather than rewarding only right actions) at a first change.
    pub stop_probability: f64,
}

impl RewardModel {
    /// Guidance half the time when watching; an arm motion recognised after 1 s; even odds.
    pub const fn thesis() -> RewardModel {
        RewardModel { guide_probability: 0.5, recognise_seconds: 1.0, stop_probability: 0.5 }
    }

    /// Ticks from an action's start until the user can judge it.
    pub fn recognise_ticks(&self, a: Action) -> u32 {
        match a {
            Action::Wait => a.duration_ticks(),
            _ => seconds_to_ticks(self.recognise_seconds),
        }
    }
}

/// The user's reward strategy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum RewardStrategy {
    /// +1 for right, −1 for wrong.
    Both,
    /// +1 for right only.
    PositiveOnly,
    /// No more rewards.
    Stopped,
}

/// One user's Int-RL teaching state.
#[derive(Clone, Debug)]
pub struct RewardTeacher {
    model: RewardModel,
    pub strategy: RewardStrategy,
    seen: u32,
    right: u32,
    last_rate: Option<f64>,
    next_check: u32,
    period: u32,
    /// Strategy changes so far.
    pub changes: u32,
}

impl RewardTeacher {
    /// A user starting to reward both ways.
    pub fn new(model: RewardModel, traits: &UserTraits) -> RewardTeacher {
        let period = seconds_to_ticks(traits.patience.min(1e6)).max(1);
        RewardTeacher {
            model,
            strategy: RewardStrategy::Both,
            seen: 0,
            right: 0,
            last_rate: None,
            next_check: period,
            period,
            changes: 0,
        }
    }

    /// Guidance before an action: the allowed actions, or all `false` for none.
    pub fn guidance<R: Rng + ?Sized>(&self, traits: &UserTraits, believed: Action, rng: &mut R) -> [bool; 3] {
        if !bernoulli(rng, traits.attention * self.model.guide_probability) {
            return [false; 3];
        }
        let wrong: Vec<usize> = (0..3).filter(|&a| a != believed.index()).collect();
        let mut allowed = [true; 3];
        allowed[wrong[below(rng, wrong.len())]] = false;
        allowed
    }

    /// The user's reaction to an action they judged: the reward to give, if any.
    pub fn reward(&mut self, judged_right: bool) -> Option<f64> {
        self.seen += 1;
        self.right += u32::from(judged_right);
        match (self.strategy, judged_right) {
            (RewardStrategy::Both, true) | (RewardStrategy::PositiveOnly, true) => Some(1.0),
            (RewardStrategy::Both, false) => Some(-1.0),
            _ => None,
        }
    }

    /// Every `patience` seconds: vary the strategy if the share judged right did not rise.
    pub fn check_progress<R: Rng + ?Sized>(&mut self, tick: u32, rng: &mut R) {
        if tick < self.next_check {
            return;
        }
        self.next_check = tick + self.period;
        let rate = if self.seen > 0 { f64::from(self.right) / f64::from(self.seen) } else { 0.0 };
        if self.last_rate.is_some_and(|last| rate <= last) {
            self.strategy = match self.strategy {
                RewardStrategy::Both if bernoulli(rng, self.model.stop_probability) => RewardStrategy::Stopped,
                RewardStrategy::Both => RewardStrategy::PositiveOnly,
                _ => RewardStrategy::Stopped,
            };
            self.changes += 1;
        }
        self.last_rate = Some(rate);
        self.seen = 0;
        self.right = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn rewards_follow_the_strategy_and_stall_changes_it() {
        let traits = UserTraits { patience: 10.0, ..UserTraits::ideal() };
        let mut t = RewardTeacher::new(RewardModel::thesis(), &traits);
        let mut rng = seeded(1);
        assert_eq!(t.reward(true), Some(1.0));
        assert_eq!(t.reward(false), Some(-1.0));
        t.check_progress(100, &mut rng); // first period: 50 % right, nothing to compare with
        assert_eq!(t.strategy, RewardStrategy::Both);
        t.reward(false);
        t.reward(true);
        t.check_progress(200, &mut rng); // 50 % again: no progress
        assert_ne!(t.strategy, RewardStrategy::Both);
        assert_eq!(t.changes, 1);
        let g = t.guidance(&traits, Action::Pickup, &mut rng);
        assert!(g == [false; 3] || (g[0] && g.iter().filter(|&&a| a).count() == 2));
    }
}
