//! The five agents of section 6.3, in any domain: one learner over one
//! feature map, differing only in the shaping signal.
//!
//! | agent | shaping |
//! |---|---|
//! | baseline (the Maze's SARSA(λ), Mario's Q(λ)) | none |
//! | SIS | static potential `Φ(s) = R_IRL(s)` (eq. 6.2) |
//! | DIS | dynamic potential `Φ†` learned by SARSA on `−R_IRL` (eqs. 6.6–6.8), selection uncorrected |
//! | HAT | Q-initialisation from the RIPPER rules: look-ahead advice `Φ(s, a) = 1[a = π_rules(s)]` with Wiewiora's correction |
//! | SBS | Q-initialisation from the similarity potential of Brys et al. (look-ahead advice with the correction) |
//!
//! A domain ([`Domain`], implemented by each half's parameters) supplies the
//! environment, the feature map, the learner, the scales and what a trial
//! records; [`run_trial`] assembles the agent and runs its episodes. The
//! agent is monomorphised for each domain and shaping: no dynamic dispatch
//! and no allocation per step (the episode driver is `rlfd_rl::Agent`).
//!
//! The thesis describes its HAT and SBS agents as initialising the
//! Q-function ("The HAT algorithm initializes the Q-function with the
//! potential function at the very beginning"; "the SBS approach implements
//! Q-function initialization"). Look-ahead advice with the action-selection
//! correction is exactly that, for any function approximator (see
//! `rlfd_rl::shaping`). The `hat-bonus` reading's alternative is chapter 5's
//! Value Bonus read as written ([`HatBonus::Persistent`], [`PersistentBonus`]):
//! the bonus on the rules' action at every choice, the rules' action forced
//! for the first C episodes.

use rlfd_lfd::hat::RuleAdvice;
use rlfd_lfd::irl::{LinearReward, StateVariables};
use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::agent::{EpisodeOutcome, TdControl};
use rlfd_rl::features::FeatureMap;
use rlfd_rl::shaping::{
    DynamicShaping, LookAheadShaping, NoShaping, Selection, Shaping, StateActionFunction, StaticShaping,
    TerminalPotential, Transition, Visit,
};
use rlfd_rl::{Agent as Learning, Environment};
use serde::{Deserialize, Serialize};

use super::inputs::AgentInputs;

/// One of the five agents of chapter 6.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
pub enum Agent {
    /// The learner without shaping: the Maze's SARSA(λ) (the thesis's
    /// SAR), Mario's Watkins Q(λ) (the thesis's QLR).
    Baseline,
    /// Static IRL Shaping.
    Sis,
    /// Dynamic IRL Shaping.
    Dis,
    /// Human-Agent Transfer (Value Bonus as Q-initialisation).
    Hat,
    /// Similarity-based shaping.
    Sbs,
}

/// What a domain calls its unshaped learner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Baseline {
    /// The condition name in result paths (`sarsa`, `q-lambda`).
    pub slug: &'static str,
    /// The thesis's label (`SAR`, `QLR`).
    pub label: &'static str,
}

impl Agent {
    /// The agents in the thesis's table order.
    pub const ALL: [Agent; 5] = [Agent::Baseline, Agent::Sis, Agent::Dis, Agent::Hat, Agent::Sbs];

    /// The condition name in result paths (`sis`, …; the baseline's is the domain's).
    pub fn slug(self, baseline: Baseline) -> &'static str {
        match self {
            Agent::Baseline => baseline.slug,
            Agent::Sis => "sis",
            Agent::Dis => "dis",
            Agent::Hat => "hat",
            Agent::Sbs => "sbs",
        }
    }

    /// The thesis's label (`SIS`, …; the baseline's is the domain's).
    pub fn label(self, baseline: Baseline) -> &'static str {
        match self {
            Agent::Baseline => baseline.label,
            Agent::Sis => "SIS",
            Agent::Dis => "DIS",
            Agent::Hat => "HAT",
            Agent::Sbs => "SBS",
        }
    }
}

/// The scales and settings of the shaping signals in a domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapingParams {
    /// Scale of the SIS, DIS and SBS shaping.
    pub scale: f64,
    /// Scale of HAT's bonus.
    pub hat_scale: f64,
    /// DIS's secondary step size per active feature.
    pub beta: f64,
    /// Φ at a terminal state for SIS's static potential (the
    /// `terminal-potential` reading; DIS keeps 0, see `rlfd_rl::shaping`).
    pub terminal_potential: TerminalPotential,
    /// Φ at a terminal state for HAT's and SBS's look-ahead advice (the
    /// `advice-terminal` reading: zero, their Q-initialisation, by default).
    pub advice_terminal: TerminalPotential,
    /// How HAT uses its rules.
    pub hat_bonus: HatBonus,
}

/// What one trial records per episode, in any domain: the environment's
/// return and the steps of each episode as the domain stores them (`R`,
/// `S`), what the domain counts of how its episodes ended (`C`, stored
/// beside them), and where the learner diverged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Trial<R, S, C> {
    /// The environment's return of each episode.
    pub returns: Vec<R>,
    /// Steps of each episode.
    pub steps: Vec<S>,
    /// How the episodes ended, as the domain counts it.
    #[serde(flatten)]
    pub ends: C,
    /// The episode (from 1) in which the learner diverged, the trial's last;
    /// `None` (and absent from the record) when it did not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub diverged_at: Option<u32>,
}

/// How a domain records an episode that ended in its environment `E`: its
/// return and steps as stored, and what it counts of the ending.
pub trait Ends<E>: Default {
    /// A stored return.
    type Return;
    /// A stored step count.
    type Steps;
    /// The episode's return and steps as stored.
    fn stored(outcome: &EpisodeOutcome) -> (Self::Return, Self::Steps);
    /// Counts episode `episode` (from 1), which ran to its end (it did not
    /// diverge) as `outcome` in `env`.
    fn count(&mut self, episode: u32, outcome: &EpisodeOutcome, env: &E);
}

/// What a trial records of its episodes.
pub trait TrialRecord<E> {
    /// An empty record with room for `episodes` episodes.
    fn with_capacity(episodes: usize) -> Self;
    /// Records episode `episode` (from 1), which ended as `outcome` in `env`
    /// (a diverged episode, the trial's last, as such).
    fn record(&mut self, episode: u32, outcome: &EpisodeOutcome, env: &E);
    /// The episode (from 1) in which the learner diverged, if it did.
    fn diverged_at(&self) -> Option<u32>;
}

impl<E, R, S, C: Ends<E, Return = R, Steps = S>> TrialRecord<E> for Trial<R, S, C> {
    fn with_capacity(episodes: usize) -> Self {
        Trial {
            returns: Vec::with_capacity(episodes),
            steps: Vec::with_capacity(episodes),
            ends: C::default(),
            diverged_at: None,
        }
    }

    fn record(&mut self, episode: u32, outcome: &EpisodeOutcome, env: &E) {
        let (r, s) = C::stored(outcome);
        self.returns.push(r);
        self.steps.push(s);
        if outcome.diverged {
            self.diverged_at = Some(episode);
        } else {
            self.ends.count(episode, outcome, env);
        }
    }

    fn diverged_at(&self) -> Option<u32> {
        self.diverged_at
    }
}

/// A domain the five agents learn in (implemented by its parameters).
pub trait Domain {
    /// The environment.
    type Env: Environment;
    /// The feature map of the learner (and of DIS's secondary learner).
    type Features: FeatureMap;
    /// The TD learner.
    type Learner: TdControl;
    /// HAT's and SBS's state-action potentials as the domain evaluates them
    /// (e.g. memoised per state).
    type Potential<P: StateActionFunction>: StateActionFunction;
    /// SBS's similarity potential as the domain computes it (the same
    /// values; e.g. searched the domain's own way).
    type Similarity: StateActionFunction;
    /// What a trial records.
    type Trial: TrialRecord<Self::Env>;

    /// What the domain calls its baseline.
    const BASELINE: Baseline;
    /// Actions of the environment.
    const ACTIONS: usize;

    /// Episodes per trial.
    fn episodes(&self) -> usize;
    /// Step cap of an episode.
    fn max_steps(&self) -> usize;
    /// A fresh environment for a trial.
    fn env(&self) -> Self::Env;
    /// A fresh feature map.
    fn features(&self) -> Self::Features;
    /// A fresh learner over `features` features.
    fn learner(&self, features: usize) -> Self::Learner;
    /// The shaping signals' scales and settings.
    fn shaping(&self) -> ShapingParams;
    /// The RE-IRL reward SIS and DIS shape with, from the demonstrations' fit.
    fn irl_reward(&self, fitted: &LinearReward<StateVariables>) -> LinearReward<StateVariables>;
    /// HAT's and SBS's potential `p` as the domain evaluates it.
    fn potential<P: StateActionFunction>(&self, p: P) -> Self::Potential<P>;
    /// SBS's similarity potential from the demonstrations' one.
    fn similarity(&self, general: &SimilarityPotential) -> Self::Similarity;
}

/// Runs one trial of `agent` in the domain `params`; the shaped agents learn
/// from `inputs`.
///
/// # Panics
/// If a shaped agent is given no inputs (a caller's logic error).
pub fn run_trial<D: Domain>(agent: Agent, params: &D, inputs: Option<&AgentInputs>, seed: u64) -> D::Trial {
    let features = params.features();
    let n = features.num_features();
    let learner = params.learner(n);
    let s = params.shaping();
    let need = || inputs.expect("the shaped agents learn from the demonstrations' products");
    match agent {
        Agent::Baseline => episodes(Learning::new(features, learner, NoShaping), params, seed),
        Agent::Sis => {
            let shaping =
                StaticShaping::new(params.irl_reward(&need().irl_reward), s.scale).with_terminal(s.terminal_potential);
            episodes(Learning::new(features, learner, shaping), params, seed)
        }
        Agent::Dis => {
            let reward = params.irl_reward(&need().irl_reward);
            let shaping = DynamicShaping::new(n, D::ACTIONS, reward, s.beta, s.scale, Selection::Uncorrected);
            episodes(Learning::new(features, learner, shaping), params, seed)
        }
        Agent::Hat => {
            let advice = params.potential(RuleAdvice::new(need().rules.clone()));
            match s.hat_bonus {
                HatBonus::QInit => {
                    let shaping = LookAheadShaping::new(advice, s.hat_scale, Selection::Corrected)
                        .with_terminal(s.advice_terminal, D::ACTIONS);
                    episodes(Learning::new(features, learner, shaping), params, seed)
                }
                HatBonus::Persistent { forced_episodes } => {
                    let shaping = PersistentBonus::new(advice, s.hat_scale, forced_episodes, D::ACTIONS);
                    episodes(Learning::new(features, learner, shaping), params, seed)
                }
            }
        }
        Agent::Sbs => {
            let potential = params.potential(params.similarity(&need().similarity));
            let shaping = LookAheadShaping::new(potential, s.scale, Selection::Corrected)
                .with_terminal(s.advice_terminal, D::ACTIONS);
            episodes(Learning::new(features, learner, shaping), params, seed)
        }
    }
}

/// The baseline agent of a domain learning on from call to call: a learner
/// as a long trial runs it once its first episodes have grown its weights,
/// traces and memoised features (for `cargo xtask bench`; a trial's first
/// episodes, which a new learner runs, touch less memory).
pub struct Continuing<D: Domain> {
    agent: Learning<D::Features, D::Learner, NoShaping>,
    env: D::Env,
    rng: rlfd_rl::random::SimRng,
    max_steps: usize,
}

impl<D: Domain> Continuing<D> {
    /// A new baseline learner of `params`, its episodes drawn from `seed`.
    pub fn new(params: &D, seed: u64) -> Self {
        let features = params.features();
        let learner = params.learner(features.num_features());
        Continuing {
            agent: Learning::new(features, learner, NoShaping),
            env: params.env(),
            rng: rlfd_rl::random::seeded(seed),
            max_steps: params.max_steps(),
        }
    }

    /// Plays `n` more learning episodes; returns their agent steps.
    pub fn episodes(&mut self, n: usize) -> u64 {
        (0..n).map(|_| self.agent.run_episode(&mut self.env, &mut self.rng, self.max_steps).steps as u64).sum()
    }
}

fn episodes<D: Domain, S: Shaping>(mut agent: Learning<D::Features, D::Learner, S>, params: &D, seed: u64) -> D::Trial {
    let mut rng = rlfd_rl::random::seeded(seed);
    let mut env = params.env();
    debug_assert_eq!(env.num_actions(), D::ACTIONS);
    let mut trial = D::Trial::with_capacity(params.episodes());
    for episode in 1..=params.episodes() {
        let outcome = agent.run_episode(&mut env, &mut rng, params.max_steps());
        trial.record(episode as u32, &outcome, &env);
        if outcome.diverged {
            break;
        }
    }
    trial
}

/// How HAT uses its rules (the `hat-bonus` reading; the bonus B is the
/// chapter's HAT scale under both).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HatBonus {
    /// Q initialised with `B·1[a = rules(s)]`: look-ahead advice with
    /// Wiewiora's correction (chapter 6's "initializes the Q-function").
    #[default]
    QInit,
    /// Chapter 5's Value Bonus as written: `B` added to the rules' action at
    /// every choice (never learned from), the rules' action taken outright
    /// for the first `forced_episodes` episodes.
    Persistent {
        /// The forced period C (chapter 5: 100).
        forced_episodes: usize,
    },
}

/// Chapter 5's Value Bonus as written, as a [`Shaping`]: the bonus
/// `scale·Φ(s, ·)` (Φ the rules' one-hot advice) is added to the learned
/// values whenever the agent chooses, and contributes no reward, so the
/// learner's values stay those of the environment's reward and the bonus
/// never washes out; for the first `forced_episodes` episodes the rules'
/// action (the advice's largest value) is taken outright. A Q(λ) learner's
/// greedy action, which its target and trace cutting use, is the greedy
/// action on these biased values: the values the agent calculates.
#[derive(Clone, Debug)]
pub struct PersistentBonus<P> {
    advice: P,
    scale: f64,
    forced_episodes: usize,
    episode: usize,
    scratch: Vec<f64>,
}

impl<P: StateActionFunction> PersistentBonus<P> {
    /// The bonus `scale · advice` with `forced_episodes` forced episodes, over `actions` actions.
    pub fn new(advice: P, scale: f64, forced_episodes: usize, actions: usize) -> Self {
        PersistentBonus { advice, scale, forced_episodes, episode: 0, scratch: vec![0.0; actions] }
    }
}

impl<P: StateActionFunction> Shaping for PersistentBonus<P> {
    fn biases_selection(&self) -> bool {
        true
    }

    fn begin_episode(&mut self) {
        self.episode += 1;
    }

    #[inline]
    fn potentials(&mut self, visit: &Visit<'_>, out: &mut [f64]) {
        self.advice.values(visit.state, out);
        for v in out.iter_mut() {
            *v *= self.scale;
        }
    }

    #[inline]
    fn reward(&mut self, _transition: &Transition<'_>) -> f64 {
        0.0
    }

    #[inline]
    fn forced_action(&mut self, visit: &Visit<'_>) -> Option<usize> {
        if self.episode > self.forced_episodes {
            return None;
        }
        self.advice.values(visit.state, &mut self.scratch);
        // The first largest value: the rules' action of a one-hot advice.
        let mut best = 0;
        for (a, &v) in self.scratch.iter().enumerate() {
            if v > self.scratch[best] {
                best = a;
            }
        }
        Some(best)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::features::ActiveFeatures;

    /// Advice for action 2 everywhere.
    struct Two;
    impl StateActionFunction for Two {
        fn values(&self, _state: &[f64], out: &mut [f64]) {
            out.fill(0.0);
            out[2] = 1.0;
        }
    }

    #[test]
    fn the_persistent_bonus_biases_every_choice_forces_c_episodes_and_pays_nothing() {
        let mut bonus = PersistentBonus::new(Two, 10.0, 2, 4);
        let features = ActiveFeatures::default();
        let visit = Visit { state: &[0.5, 0.5], features: &features };
        let mut pot = [0.0; 4];
        assert!(bonus.biases_selection());
        for episode in 1..=4 {
            bonus.begin_episode();
            bonus.potentials(&visit, &mut pot);
            assert_eq!(pot, [0.0, 0.0, 10.0, 0.0]);
            let forced = bonus.forced_action(&visit);
            assert_eq!(forced, (episode <= 2).then_some(2), "episode {episode}");
            let t = Transition {
                from: visit,
                action: 2,
                potentials: &pot,
                next: None,
                terminal_state: Some(&[0.95, 0.95]),
                gamma: 1.0,
            };
            assert_eq!(bonus.reward(&t), 0.0);
        }
    }
}
