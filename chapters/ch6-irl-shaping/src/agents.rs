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
//! `rlfd_rl::shaping`).

use rlfd_lfd::hat::RuleAdvice;
use rlfd_lfd::irl::{LinearReward, StateVariables};
use rlfd_lfd::ripper::DecisionList;
use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::features::{FeatureMap, TileCoder, TileIndexing};
use rlfd_rl::shaping::{
    DynamicShaping, LookAheadShaping, NoShaping, Selection, Shaping, StaticShaping, TerminalPotential,
};
use rlfd_rl::{Agent, Environment, SarsaLambda, TdParams, TraceKind};
use serde::{Deserialize, Serialize};

use crate::maze::Maze;

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
    /// Factor κ on the RE-IRL reward that SIS and DIS use (1 in the main
    /// experiment; the sensitivity experiment varies it, since the thesis
    /// does not say how large its IRL reward was).
    pub irl_scale: f64,
    /// Φ at the goal for the static potentials of SIS, HAT and SBS (the
    /// `terminal-potential` reading; DIS keeps 0, see `rlfd_rl::shaping`).
    pub terminal_potential: TerminalPotential,
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
            let shaping =
                LookAheadShaping::new(RuleAdvice::new(inputs.rules.clone()), params.hat_scale, Selection::Corrected)
                    .with_terminal(params.terminal_potential, 4);
            episodes(Agent::new(coder, learner, shaping), params, seed)
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
    let mut env = Maze::thesis_agent();
    debug_assert_eq!(env.num_actions(), 4);
    let mut trial = MazeTrial {
        returns: Vec::with_capacity(params.episodes),
        steps: Vec::with_capacity(params.episodes),
        failures: 0,
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
        }
    }
    trial
}
