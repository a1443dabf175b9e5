//! The five agents of the Maze experiment (section 6.3) and their parameters.
//!
//! Every agent is SARSA(λ) over the same tile coding with the thesis's
//! parameters; they differ only in the shaping signal:
//!
//! | agent | shaping | scale |
//! |---|---|---|
//! | SARSA | none | – |
//! | SIS | static potential `Φ(s) = R_IRL(s)` (eq. 6.2) | 100 |
//! | DIS | dynamic potential `Φ†` learned by SARSA on `−R_IRL` (eqs. 6.6–6.8), selection uncorrected | 100 |
//! | HAT | Q-initialisation from the RIPPER rules: look-ahead advice `Φ(s, a) = 1[a = π_rules(s)]` with Wiewiora's correction | 10 |
//! | SBS | Q-initialisation from the similarity potential of Brys et al. (look-ahead advice with the correction) | 100 |
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
use rlfd_lfd::ripper::DecisionList;
use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::features::{FeatureMap, TileCoder, TileIndexing};
use rlfd_rl::shaping::{
    DynamicShaping, LookAheadShaping, NoShaping, Selection, Shaping, StateActionFunction, StaticShaping,
    TerminalPotential, Transition, Visit,
};
use rlfd_rl::{Agent, Environment, SarsaLambda, TdParams, TraceKind};
use serde::{Deserialize, Serialize};

use crate::maze::layout::LayoutId;
use crate::maze::{Maze, MazeLayout, MazeRewards};

/// An agent of the Maze experiment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MazeAgent {
    /// SARSA(λ) without shaping (the thesis's SAR).
    Sarsa,
    /// Static IRL Shaping.
    Sis,
    /// Dynamic IRL Shaping.
    Dis,
    /// Human-Agent Transfer (Value Bonus as Q-initialisation).
    Hat,
    /// Similarity-based shaping.
    Sbs,
}

impl MazeAgent {
    /// The agents in the thesis's table order.
    pub const ALL: [MazeAgent; 5] = [MazeAgent::Sarsa, MazeAgent::Sis, MazeAgent::Dis, MazeAgent::Hat, MazeAgent::Sbs];

    /// The condition name in result paths (`sarsa`, `sis`, …).
    pub fn slug(self) -> &'static str {
        match self {
            MazeAgent::Sarsa => "sarsa",
            MazeAgent::Sis => "sis",
            MazeAgent::Dis => "dis",
            MazeAgent::Hat => "hat",
            MazeAgent::Sbs => "sbs",
        }
    }

    /// The thesis's label (`SAR`, `SIS`, …).
    pub fn label(self) -> &'static str {
        match self {
            MazeAgent::Sarsa => "SAR",
            MazeAgent::Sis => "SIS",
            MazeAgent::Dis => "DIS",
            MazeAgent::Hat => "HAT",
            MazeAgent::Sbs => "SBS",
        }
    }
}

/// The Maze experiment's parameters (section 6.3.1), with the project's
/// documented choices where the thesis is silent.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MazeParams {
    /// Trials per agent (thesis: 25).
    pub trials: u32,
    /// Episodes per trial (thesis: 150).
    pub episodes: usize,
    /// Step cap of an episode (thesis: 6,000, "terminates with failure").
    pub max_steps: usize,
    /// Tilings (thesis: "number of tiles = 32", read as 32 tilings over (x, y)).
    pub tilings: usize,
    /// Tile width in both dimensions (not in the thesis; chosen: 0.1, ten
    /// tiles across the unit square per tiling, before any learner ran).
    pub tile_width: f64,
    /// Step size per tiling (thesis: α = 0.25/#tiles).
    pub alpha: f64,
    /// DIS's secondary step size per tiling (thesis: β = 0.05/#tiles).
    pub beta: f64,
    /// Discount (thesis: 1.0).
    pub gamma: f64,
    /// Trace decay (thesis: 0.25).
    pub lambda: f64,
    /// Exploration (thesis: ε-greedy, 0.02).
    pub epsilon: f64,
    /// Scale of the SIS, DIS and SBS shaping (thesis: 100).
    pub shaping_scale: f64,
    /// Scale of HAT's bonus (thesis: 10).
    pub hat_scale: f64,
    /// SBS's Gaussian width per state variable (not in the thesis; chosen: 0.05, half a tile).
    pub sbs_sigma: f64,
    /// Eligibility traces (not in the thesis; replacing, as the tile-coding codebases of the time).
    pub traces: TraceKind,
    /// Factor κ on the RE-IRL reward that SIS and DIS use (the `irl-scale`
    /// reading: 1 by default; the thesis does not say how large its IRL
    /// reward was).
    pub irl_scale: f64,
    /// Φ at the goal for the static potentials of SIS, HAT and SBS (the
    /// `terminal-potential` reading; DIS keeps 0, see `rlfd_rl::shaping`).
    pub terminal_potential: TerminalPotential,
    /// The walls (the `maze-layout` reading).
    pub layout: LayoutId,
    /// How HAT uses its rules (the `hat-bonus` reading).
    pub hat_bonus: HatBonus,
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

impl MazeParams {
    /// The thesis's scale: 5 agents × 25 trials × 150 episodes.
    pub fn paper() -> Self {
        MazeParams {
            trials: 25,
            episodes: 150,
            max_steps: 6000,
            tilings: 32,
            tile_width: 0.1,
            alpha: 0.25 / 32.0,
            beta: 0.05 / 32.0,
            gamma: 1.0,
            lambda: 0.25,
            epsilon: 0.02,
            shaping_scale: 100.0,
            hat_scale: 10.0,
            sbs_sigma: 0.05,
            traces: TraceKind::Replacing,
            irl_scale: 1.0,
            terminal_potential: TerminalPotential::Literal,
            layout: LayoutId::LowDetour,
            hat_bonus: HatBonus::QInit,
        }
    }

    /// The quick scale: every agent, table and figure in seconds.
    pub fn quick() -> Self {
        MazeParams { trials: 4, episodes: 30, ..Self::paper() }
    }

    /// The learners' TD parameters.
    pub fn td(&self) -> TdParams {
        TdParams { alpha: self.alpha, gamma: self.gamma, lambda: self.lambda, epsilon: self.epsilon }
    }

    /// The tile coder over (x, y) in the unit square.
    pub fn tile_coder(&self) -> TileCoder {
        TileCoder::new(
            self.tilings,
            &[self.tile_width, self.tile_width],
            TileIndexing::Dense { lower: vec![0.0, 0.0], upper: vec![1.0, 1.0] },
        )
        .expect("the Maze's tile coding parameters are valid")
    }
}

/// What the agents learn from: the demonstrations' products.
#[derive(Clone, Debug)]
pub struct AgentInputs {
    /// `R_IRL(s) = θᵀ (x, y)`, from RE-IRL.
    pub irl_reward: LinearReward<StateVariables>,
    /// RIPPER's decision list over the demonstrated (x, y) → move pairs.
    pub rules: DecisionList,
    /// The SBS potential over the demonstrated pairs.
    pub similarity: SimilarityPotential,
}

/// What one trial records per episode.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MazeTrial {
    /// The environment's return of each episode.
    pub returns: Vec<f64>,
    /// Steps of each episode.
    pub steps: Vec<u32>,
    /// Episodes that hit the step cap instead of the goal.
    pub failures: u32,
    /// Which episodes (from 1) those were: every other episode that ran to
    /// its end reached the goal (a goal at the cap's last step counts as a
    /// goal). Absent from records of no capped episode.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub capped: Vec<u32>,
    /// The episode (from 1) in which the learner diverged, the trial's last;
    /// `None` (and absent from the record) when it did not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub diverged_at: Option<u32>,
}

/// Runs one trial of `agent`.
pub fn run_trial(agent: MazeAgent, params: &MazeParams, inputs: &AgentInputs, seed: u64) -> MazeTrial {
    let coder = params.tile_coder();
    let learner = SarsaLambda::new(coder.num_features(), 4, params.td(), params.traces);
    let n = coder.num_features();
    let irl_reward = LinearReward::new(
        inputs.irl_reward.weights().iter().map(|w| w * params.irl_scale).collect(),
        StateVariables { dim: 2 },
    );
    match agent {
        MazeAgent::Sarsa => episodes(Agent::new(coder, learner, NoShaping), params, seed),
        MazeAgent::Sis => {
            let shaping = StaticShaping::new(irl_reward, params.shaping_scale).with_terminal(params.terminal_potential);
            episodes(Agent::new(coder, learner, shaping), params, seed)
        }
        MazeAgent::Dis => {
            let shaping =
                DynamicShaping::new(n, 4, irl_reward, params.beta, params.shaping_scale, Selection::Uncorrected);
            episodes(Agent::new(coder, learner, shaping), params, seed)
        }
        MazeAgent::Hat => {
            let advice = RuleAdvice::new(inputs.rules.clone());
            match params.hat_bonus {
                HatBonus::QInit => {
                    let shaping = LookAheadShaping::new(advice, params.hat_scale, Selection::Corrected)
                        .with_terminal(params.terminal_potential, 4);
                    episodes(Agent::new(coder, learner, shaping), params, seed)
                }
                HatBonus::Persistent { forced_episodes } => {
                    let shaping = PersistentBonus::new(advice, params.hat_scale, forced_episodes, 4);
                    episodes(Agent::new(coder, learner, shaping), params, seed)
                }
            }
        }
        MazeAgent::Sbs => {
            let shaping = LookAheadShaping::new(inputs.similarity.clone(), params.shaping_scale, Selection::Corrected)
                .with_terminal(params.terminal_potential, 4);
            episodes(Agent::new(coder, learner, shaping), params, seed)
        }
    }
}

fn episodes<S: Shaping>(mut agent: Agent<TileCoder, SarsaLambda, S>, params: &MazeParams, seed: u64) -> MazeTrial {
    let mut rng = rlfd_rl::random::seeded(seed);
    let mut env = Maze::new(MazeLayout::of(params.layout), 2, MazeRewards::THESIS);
    debug_assert_eq!(env.num_actions(), 4);
    let mut trial = MazeTrial {
        returns: Vec::with_capacity(params.episodes),
        steps: Vec::with_capacity(params.episodes),
        failures: 0,
        capped: Vec::new(),
        diverged_at: None,
    };
    for episode in 1..=params.episodes {
        let outcome = agent.run_episode(&mut env, &mut rng, params.max_steps);
        trial.returns.push(outcome.env_return);
        trial.steps.push(outcome.steps as u32);
        if outcome.diverged {
            trial.diverged_at = Some(episode as u32);
            break;
        }
        if !outcome.terminal {
            trial.failures += 1;
            trial.capped.push(episode as u32);
        }
    }
    trial
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maze::Move;
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

    #[test]
    fn a_persistent_hat_follows_its_rules_in_the_forced_episodes() {
        use rlfd_lfd::ripper::{Attribute, Dataset, Ripper};
        // Rules that say "up" everywhere: the forced episodes walk up into the border.
        let data = Dataset::new(
            vec![Attribute::numeric("x"), Attribute::numeric("y")],
            (0..20).map(|i| vec![f64::from(i) / 20.0, 0.5]).collect(),
            "Action",
            Move::ALL.iter().map(|m| m.name().to_string()).collect(),
            vec![Move::Up as usize; 20],
        )
        .unwrap();
        let rules = Ripper::fit(&crate::inputs::ripper_params(), &data).unwrap();
        let sim = rlfd_lfd::similarity::SimilarityPotential::new(
            std::iter::once((&[0.1, 0.6][..], 0usize)),
            4,
            &[0.05, 0.05],
        )
        .unwrap();
        let inputs = AgentInputs {
            irl_reward: LinearReward::new(vec![1.0, 0.0], StateVariables { dim: 2 }),
            rules,
            similarity: sim,
        };
        let params = MazeParams {
            episodes: 3,
            max_steps: 50,
            hat_bonus: HatBonus::Persistent { forced_episodes: 2 },
            ..MazeParams::paper()
        };
        let trial = run_trial(MazeAgent::Hat, &params, &inputs, 7);
        // From (0.08, 0.60) up: 19 free moves to y = 0.98, then 31 blocked ones (−11 each).
        let forced_return = -19.0 - 31.0 * 11.0;
        assert_eq!(&trial.returns[..2], &[forced_return, forced_return]);
        assert_eq!(trial.capped, vec![1, 2, 3]);
        let q_init = run_trial(MazeAgent::Hat, &MazeParams { hat_bonus: HatBonus::QInit, ..params }, &inputs, 7);
        assert_ne!(q_init.returns[0], forced_return);
    }
}
