//! The Maze experiment's parameters (section 6.3.1) and what a trial
//! records, and the Maze as a domain of the five agents
//! ([`crate::shaping::Domain`]): SARSA(λ) over the same tile coding of
//! (x, y) with the thesis's parameters, shaping scale 100 for SIS, DIS and
//! SBS and 10 for HAT; the RE-IRL reward scaled by κ (the `irl-scale`
//! reading).

use rlfd_lfd::irl::{LinearReward, StateVariables};
use rlfd_rl::agent::EpisodeOutcome;
use rlfd_rl::features::{TileCoder, TileIndexing};
use rlfd_rl::shaping::{StateActionFunction, TerminalPotential};
use rlfd_rl::{SarsaLambda, TdParams, TraceKind};
use serde::{Deserialize, Serialize};

use super::layout::LayoutId;
use super::{Maze, MazeLayout, MazeRewards};
use crate::shaping::{Agent, AgentInputs, Baseline, Domain, Ends, HatBonus, ShapingParams, Trial};

/// The Maze's baseline: SARSA(λ), the thesis's SAR.
pub const BASELINE: Baseline = Baseline { slug: "sarsa", label: "SAR" };

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
    /// Φ at the goal for SIS's static potential (the `terminal-potential`
    /// reading; DIS keeps 0, see `rlfd_rl::shaping`).
    pub terminal_potential: TerminalPotential,
    /// Φ at the goal for HAT's and SBS's look-ahead advice (the
    /// `advice-terminal` reading).
    pub advice_terminal: TerminalPotential,
    /// The walls (the `maze-layout` reading).
    pub layout: LayoutId,
    /// How HAT uses its rules (the `hat-bonus` reading).
    pub hat_bonus: HatBonus,
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
            advice_terminal: TerminalPotential::Zero,
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

/// What one Maze trial records: returns as f64, steps as u32, and the
/// episodes that hit the step cap.
pub type MazeTrial = Trial<f64, u32, MazeEnds>;

/// How the Maze's episodes ended.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MazeEnds {
    /// Episodes that hit the step cap instead of the goal.
    pub failures: u32,
    /// Which episodes (from 1) those were: every other episode that ran to
    /// its end reached the goal (a goal at the cap's last step counts as a
    /// goal). Absent from records of no capped episode.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub capped: Vec<u32>,
}

impl MazeEnds {
    /// Whether episode `episode` (from 1) reached the goal rather than the cap.
    pub fn reached_goal(&self, episode: u32) -> bool {
        !self.capped.contains(&episode)
    }
}

impl Ends<Maze> for MazeEnds {
    type Return = f64;
    type Steps = u32;

    fn stored(outcome: &EpisodeOutcome) -> (f64, u32) {
        (outcome.env_return, outcome.steps as u32)
    }

    fn count(&mut self, episode: u32, outcome: &EpisodeOutcome, _env: &Maze) {
        if !outcome.terminal {
            self.failures += 1;
            self.capped.push(episode);
        }
    }
}

impl Domain for MazeParams {
    type Env = Maze;
    type Features = TileCoder;
    type Learner = SarsaLambda;
    type Potential<P: StateActionFunction> = P;
    type Similarity = rlfd_lfd::similarity::SimilarityPotential;
    type Trial = MazeTrial;

    const BASELINE: Baseline = BASELINE;
    const ACTIONS: usize = 4;

    fn episodes(&self) -> usize {
        self.episodes
    }

    fn max_steps(&self) -> usize {
        self.max_steps
    }

    fn env(&self) -> Maze {
        Maze::new(MazeLayout::of(self.layout), 2, MazeRewards::THESIS)
    }

    fn features(&self) -> TileCoder {
        self.tile_coder()
    }

    fn learner(&self, features: usize) -> SarsaLambda {
        SarsaLambda::new(features, 4, self.td(), self.traces)
    }

    fn shaping(&self) -> ShapingParams {
        ShapingParams {
            scale: self.shaping_scale,
            hat_scale: self.hat_scale,
            beta: self.beta,
            terminal_potential: self.terminal_potential,
            advice_terminal: self.advice_terminal,
            hat_bonus: self.hat_bonus,
        }
    }

    /// R_IRL scaled by κ (the `irl-scale` reading).
    fn irl_reward(&self, fitted: &LinearReward<StateVariables>) -> LinearReward<StateVariables> {
        LinearReward::new(fitted.weights().iter().map(|w| w * self.irl_scale).collect(), StateVariables { dim: 2 })
    }

    fn potential<P: StateActionFunction>(&self, p: P) -> P {
        p
    }

    /// The k-d tree's search (the Maze's two variables).
    fn similarity(&self, general: &rlfd_lfd::similarity::SimilarityPotential) -> Self::Similarity {
        general.clone()
    }
}

/// Runs one trial of `agent` in the Maze.
pub fn run_trial(agent: Agent, params: &MazeParams, inputs: &AgentInputs, seed: u64) -> MazeTrial {
    crate::shaping::run_trial(agent, params, Some(inputs), seed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maze::Move;

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
        let rules = Ripper::fit(&crate::shaping::inputs::ripper_params(), &data).unwrap();
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
        let trial = run_trial(Agent::Hat, &params, &inputs, 7);
        // From (0.08, 0.60) up: 19 free moves to y = 0.98, then 31 blocked ones (−11 each).
        let forced_return = -19.0 - 31.0 * 11.0;
        assert_eq!(&trial.returns[..2], &[forced_return, forced_return]);
        assert_eq!(trial.ends.capped, vec![1, 2, 3]);
        let q_init = run_trial(Agent::Hat, &MazeParams { hat_bonus: HatBonus::QInit, ..params }, &inputs, 7);
        assert_ne!(q_init.returns[0], forced_return);
    }

    #[test]
    fn a_trial_is_stored_as_round_2_stored_it() {
        // The record's JSON is part of the store's bytes: the fields in
        // their order, the capped episodes and divergence only when present.
        let mut t = MazeTrial {
            returns: vec![-1.0, 2.5],
            steps: vec![3, 4],
            ends: MazeEnds { failures: 1, capped: vec![2] },
            diverged_at: None,
        };
        let json = serde_json::to_string(&t).unwrap();
        assert_eq!(json, r#"{"returns":[-1.0,2.5],"steps":[3,4],"failures":1,"capped":[2]}"#);
        assert_eq!(serde_json::from_str::<MazeTrial>(&json).unwrap(), t);
        t.ends = MazeEnds::default();
        t.diverged_at = Some(2);
        let json = serde_json::to_string(&t).unwrap();
        assert_eq!(json, r#"{"returns":[-1.0,2.5],"steps":[3,4],"failures":0,"diverged_at":2}"#);
        assert_eq!(serde_json::from_str::<MazeTrial>(&json).unwrap(), t);
    }
}
