//! Three learning keepers against the hand-coded takers: one episode
//! ([`play_episode`]) and one learning trial ([`run_learning_trial`]).
//!
//! A trial first measures the **jumpstart** policy: `eval_episodes` episodes
//! with learning switched off, the agents as they start (weights 0, ψ = 1,
//! forced periods in force), on a random stream of its own so that the
//! training that follows does not depend on how long the evaluation was.
//! Then it **trains** for `hours` simulated hours: whole episodes until their
//! cycles reach `hours · 36,000` (the last episode finishes), recording each
//! episode's duration in cycles. The thesis's 30 hours are 1,080,000 cycles.
//! At the start and whenever the training passes an integral hour it also
//! plays `greedy_episodes` episodes **greedily** (the learned policy without
//! exploring, forced periods or reuse, and without learning) on a game and a
//! random stream of their own, so the training does not depend on them: the
//! evaluation curve shown beside the online one.

use rand::Rng;
use rlfd_harness::seed::splitmix64;
use rlfd_lfd::ripper::DecisionList;
use rlfd_rl::features::{FeatureMap, RbfFeatures};
use rlfd_rl::random::seeded;
use serde::{Deserialize, Serialize};

use super::{KeeperAgent, LearnerParamError, LearnerParams, Method};
use crate::keepaway::{CYCLES_PER_HOUR, KEEPERS, Keepaway, STATE_VARS, Status};

/// A learning trial's parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrialParams {
    /// Simulated hours of training (thesis: 30).
    pub hours: f64,
    /// Episodes of the jumpstart evaluation (thesis: 1,000).
    pub eval_episodes: usize,
    /// Episodes of each greedy evaluation (at hour 0 and every integral hour; 0: none).
    pub greedy_episodes: usize,
    /// The keepers' learner.
    pub learner: LearnerParams,
    /// How the rules are used.
    pub method: Method,
}

/// What one trial records.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearningTrial {
    /// Mean duration (cycles) of the jumpstart evaluation's episodes.
    pub jumpstart_cycles: f64,
    /// Episodes in that evaluation.
    pub jumpstart_episodes: usize,
    /// The training episodes' durations, in order (cycles).
    pub durations: Vec<u32>,
    /// Mean duration (cycles) of the greedy evaluation at hours 0, 1, 2, … (empty without one).
    pub greedy_cycles: Vec<f64>,
}

impl LearningTrial {
    /// Simulated hours the training took.
    pub fn hours(&self) -> f64 {
        self.durations.iter().map(|&d| u64::from(d)).sum::<u64>() as f64 / CYCLES_PER_HOUR as f64
    }
}

/// The random stream of the jumpstart evaluation, derived from the trial's seed.
const EVALUATION_STREAM: u64 = 0x6a75_6d70_7374_6172; // "jumpstar"

/// The random stream of the greedy evaluations, derived from the trial's seed.
const GREEDY_STREAM: u64 = 0x6772_6565_6479_6576; // "greedyev"

/// Plays one episode with the three keepers; with `learn`, they learn from it.
/// Returns the duration in cycles.
pub fn play_episode<R: Rng + ?Sized>(
    game: &mut Keepaway,
    keepers: &mut [KeeperAgent; KEEPERS],
    features: &RbfFeatures,
    rules: Option<&DecisionList>,
    learn: bool,
    rng: &mut R,
) -> u32 {
    game.reset(rng);
    for k in keepers.iter_mut() {
        k.begin_episode();
    }
    let mut state = [0.0; STATE_VARS];
    let mut status = game.run(rng);
    loop {
        match status {
            Status::Decision(k) => {
                game.state_vars(k, &mut state);
                let reward = game.last_action_cycle(k).map_or(0.0, |c| f64::from(game.cycle() - c));
                let action = keepers[k].decide(features, &state, reward, rules, learn, rng);
                status = game.act(action, rng);
            }
            Status::Ended(_) => {
                let end = game.cycle();
                for (k, keeper) in keepers.iter_mut().enumerate() {
                    let reward = game.last_action_cycle(k).map(|c| f64::from(end - c));
                    keeper.end_episode(reward, learn);
                }
                return end;
            }
        }
    }
}

/// Runs one trial (see the module docs) from `seed`.
pub fn run_learning_trial(
    params: &TrialParams,
    rules: Option<&DecisionList>,
    seed: u64,
) -> Result<LearningTrial, LearnerParamError> {
    if params.method.uses_rules() && rules.is_none() {
        return Err(LearnerParamError {
            name: "method",
            value: params.method.label().into(),
            expected: "rules to follow (this method biases learning with a rule summary)",
        });
    }
    if !(params.hours.is_finite() && params.hours >= 0.0) {
        return Err(LearnerParamError { name: "hours", value: params.hours.to_string(), expected: "a number ≥ 0" });
    }
    let features = params.learner.rbf.features();
    let new_keeper =
        || KeeperAgent::new(&params.learner, &params.method, features.num_features(), features.max_active());
    let mut keepers = [new_keeper()?, new_keeper()?, new_keeper()?];
    // The evaluation plays a game of its own, so the training's game (its
    // players' see phases and body directions) does not depend on its length.
    let mut eval_game = Keepaway::benchmark();
    let mut eval_rng = seeded(splitmix64(seed ^ EVALUATION_STREAM));
    let mut total = 0u64;
    for _ in 0..params.eval_episodes {
        total += u64::from(play_episode(&mut eval_game, &mut keepers, &features, rules, false, &mut eval_rng));
    }
    let jumpstart_cycles =
        if params.eval_episodes == 0 { f64::NAN } else { total as f64 / params.eval_episodes as f64 };

    let mut game = Keepaway::benchmark();
    let mut greedy_game = Keepaway::benchmark();
    let mut greedy_rng = seeded(splitmix64(seed ^ GREEDY_STREAM));
    let mut greedy_cycles = Vec::new();
    let mut greedy = |keepers: &mut [KeeperAgent; KEEPERS], out: &mut Vec<f64>| {
        if params.greedy_episodes == 0 {
            return;
        }
        for k in keepers.iter_mut() {
            k.set_greedy(true);
        }
        let mut total = 0u64;
        for _ in 0..params.greedy_episodes {
            total += u64::from(play_episode(&mut greedy_game, keepers, &features, rules, false, &mut greedy_rng));
        }
        for k in keepers.iter_mut() {
            k.set_greedy(false);
        }
        out.push(total as f64 / params.greedy_episodes as f64);
    };
    greedy(&mut keepers, &mut greedy_cycles);

    let budget = (params.hours * CYCLES_PER_HOUR as f64).round() as u64;
    let mut rng = seeded(seed);
    let mut durations = Vec::with_capacity((budget / 60) as usize + 1);
    let mut used = 0u64;
    let mut next_hour = CYCLES_PER_HOUR;
    while used < budget {
        let d = play_episode(&mut game, &mut keepers, &features, rules, true, &mut rng);
        used += u64::from(d);
        durations.push(d);
        while used >= next_hour && next_hour <= budget {
            greedy(&mut keepers, &mut greedy_cycles);
            next_hour += CYCLES_PER_HOUR;
        }
    }
    Ok(LearningTrial { jumpstart_cycles, jumpstart_episodes: params.eval_episodes, durations, greedy_cycles })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(hours: f64) -> TrialParams {
        TrialParams {
            hours,
            eval_episodes: 50,
            greedy_episodes: 5,
            learner: LearnerParams::thesis(),
            method: Method::NoPrior,
        }
    }

    #[test]
    fn a_trial_fills_its_hours_and_is_deterministic() {
        let t = run_learning_trial(&params(0.2), None, 7).unwrap();
        assert!(t.hours() >= 0.2 && t.hours() < 0.21, "{}", t.hours());
        assert_eq!(t.jumpstart_episodes, 50);
        // With all weights 0 the keepers act uniformly at random: the Random benchmark.
        assert!(t.jumpstart_cycles > 30.0 && t.jumpstart_cycles < 90.0, "{}", t.jumpstart_cycles);
        assert_eq!(t, run_learning_trial(&params(0.2), None, 7).unwrap());
        // The evaluation has its own stream: training does not depend on its length.
        let shorter =
            run_learning_trial(&TrialParams { eval_episodes: 3, greedy_episodes: 1, ..params(0.2) }, None, 7).unwrap();
        assert_eq!(shorter.durations, t.durations);
        // A greedy evaluation at the start only (0.2 h has no integral hour).
        assert_eq!(t.greedy_cycles.len(), 1);
        let two = run_learning_trial(&params(2.0), None, 7).unwrap();
        assert_eq!(two.greedy_cycles.len(), 3);
    }

    #[test]
    fn methods_with_rules_need_rules() {
        let p = TrialParams { method: Method::POLICY_REUSE, ..params(0.1) };
        assert_eq!(run_learning_trial(&p, None, 1).unwrap_err().name, "method");
    }
}
