//! The Mario experiment's parameters (section 6.3.2) and what a trial
//! records, and Mario as a domain of the five agents
//! ([`crate::shaping::Domain`]): Watkins's Q(λ) over the same hashed tile
//! coding of the 27 state variables with the thesis's parameters (32
//! tilings, α = 0.01/32, γ = 0.9, λ = 0.5, ε = 0.05), every shaping at
//! scale 1.
//!
//! The thesis gives one shaping scale for Mario ("scaling = 1 for the
//! shaping reward"), so HAT's bonus is 1 too (also under the `hat-bonus`
//! reading's persistent Value Bonus, see [`crate::shaping::HatBonus`]). Its β for Mario is written
//! "β = 0.05" where the Maze's is "0.05/#tiles"; we take it as written: 0.05
//! per active feature.
//!
//! Tile coding (our choices, fixed before any learner ran): each of the 32
//! tilings covers all 27 variables at once (tiles3's asymmetric offsets),
//! hashed into 2^18 weights per action; tile widths 2 for the booleans and
//! the directions (so a tiling tells two neighbouring values apart in half
//! the tilings and generalises across them in the other half) and 4 cells
//! for the closest enemy's offsets. Because the state is discrete, the tile
//! indices and the HAT and SBS potentials of a state are memoised in small
//! direct-mapped caches keyed by the packed state ([`crate::mario::observation::pack`]):
//! a speed measure that changes no value.

use std::cell::RefCell;

use rlfd_lfd::irl::{LinearReward, StateVariables};
use rlfd_rl::agent::EpisodeOutcome;
use rlfd_rl::features::{ActiveFeatures, FeatureMap, FirstTouch, TileCoder, TileIndexing};
use rlfd_rl::shaping::{StateActionFunction, TerminalPotential};
use rlfd_rl::{TdParams, TraceKind, WatkinsQLambda};
use serde::{Deserialize, Serialize};

use super::observation::{CLOSEST, STATE_VARIABLES, pack};
use super::similarity::PackedSimilarity;
use super::{ACTIONS, LevelParams, MarioEnv};
use crate::shaping::{Agent, AgentInputs, Baseline, Domain, Ends, HatBonus, ShapingParams, Trial};

/// Mario's baseline: Watkins's Q(λ), the thesis's QLR.
pub const BASELINE: Baseline = Baseline { slug: "q-lambda", label: "QLR" };

/// The Mario experiment's parameters (section 6.3.2), with the project's
/// documented choices where the thesis is silent.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MarioParams {
    /// Trials per agent (thesis: 10).
    pub trials: u32,
    /// Episodes per trial (thesis: 20,000).
    pub episodes: usize,
    /// The levels (not in the thesis; see `mario::demonstrator` for the choice).
    pub level: LevelParams,
    /// Tilings (thesis: "number of tiles = 32", read as 32 tilings).
    pub tilings: usize,
    /// Tile width of the boolean variables and the directions (our choice).
    pub boolean_width: f64,
    /// Tile width of the closest enemy's offsets, in cells (our choice).
    pub distance_width: f64,
    /// Weights per action in the hashed tile table (our choice: 2^18).
    pub hash_size: usize,
    /// Step size per tiling (thesis: α = 0.01/#tiles).
    pub alpha: f64,
    /// DIS's secondary step size per active feature (thesis: β = 0.05).
    pub beta: f64,
    /// Discount (thesis: 0.9).
    pub gamma: f64,
    /// Trace decay (thesis: 0.5).
    pub lambda: f64,
    /// Exploration (thesis: ε-greedy, 0.05).
    pub epsilon: f64,
    /// Scale of every shaping signal (thesis: 1).
    pub shaping_scale: f64,
    /// SBS's Gaussian width for the booleans and directions (our choice: half a tile).
    pub sbs_sigma_boolean: f64,
    /// SBS's Gaussian width for the closest enemy's offsets (our choice: half a tile).
    pub sbs_sigma_distance: f64,
    /// Eligibility traces (not in the thesis; replacing, as the Maze).
    pub traces: TraceKind,
    /// Step cap of an episode (the game's timer ends every episode by 3,000 ticks; a guard).
    pub max_steps: usize,
    /// Φ at a terminal state for SIS's static potential (the
    /// `terminal-potential` reading; DIS keeps 0).
    pub terminal_potential: TerminalPotential,
    /// Φ at a terminal state for HAT's and SBS's look-ahead advice (the
    /// `advice-terminal` reading).
    pub advice_terminal: TerminalPotential,
    /// HAT's bonus B (the `hat-scale` reading: the thesis gives Mario's
    /// shaping scale, 1, and no B for its HAT).
    pub hat_scale: f64,
    /// How HAT uses its rules (the `hat-bonus` reading).
    pub hat_bonus: HatBonus,
}

impl MarioParams {
    /// The thesis's scale: 5 agents × 10 trials × 20,000 episodes.
    pub fn paper() -> Self {
        MarioParams {
            trials: 10,
            episodes: 20_000,
            level: LevelParams::EXPERIMENT,
            tilings: 32,
            boolean_width: 2.0,
            distance_width: 4.0,
            hash_size: 1 << 18,
            alpha: 0.01 / 32.0,
            beta: 0.05,
            gamma: 0.9,
            lambda: 0.5,
            epsilon: 0.05,
            shaping_scale: 1.0,
            sbs_sigma_boolean: 1.0,
            sbs_sigma_distance: 2.0,
            traces: TraceKind::Replacing,
            max_steps: 3000,
            terminal_potential: TerminalPotential::Literal,
            advice_terminal: TerminalPotential::Zero,
            hat_scale: 10.0,
            hat_bonus: HatBonus::QInit,
        }
    }

    /// The quick scale: every agent, table and figure in seconds.
    pub fn quick() -> Self {
        MarioParams { trials: 3, episodes: 120, ..Self::paper() }
    }

    /// The learners' TD parameters.
    pub fn td(&self) -> TdParams {
        TdParams { alpha: self.alpha, gamma: self.gamma, lambda: self.lambda, epsilon: self.epsilon }
    }

    /// Tile width of each of the 27 variables.
    pub fn widths(&self) -> [f64; STATE_VARIABLES] {
        let mut w = [self.boolean_width; STATE_VARIABLES];
        w[CLOSEST] = self.distance_width;
        w[CLOSEST + 1] = self.distance_width;
        w
    }

    /// SBS's σ for each of the 27 variables.
    pub fn sbs_sigma(&self) -> [f64; STATE_VARIABLES] {
        let mut s = [self.sbs_sigma_boolean; STATE_VARIABLES];
        s[CLOSEST] = self.sbs_sigma_distance;
        s[CLOSEST + 1] = self.sbs_sigma_distance;
        s
    }

    /// The hashed tile coder over the 27 variables.
    pub fn tile_coder(&self) -> TileCoder {
        TileCoder::new(self.tilings, &self.widths(), TileIndexing::Hashed { size: self.hash_size })
            .expect("Mario's tile coding parameters are valid")
    }
}

/// What one Mario trial records: points per episode (the environment's
/// return; integer in the game), ticks per episode, and the levels finished.
pub type MarioTrial = Trial<i32, u16, MarioEnds>;

/// How Mario's episodes ended.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MarioEnds {
    /// Episodes that finished the level.
    pub wins: u32,
}

impl Ends<MarioEnv> for MarioEnds {
    type Return = i32;
    type Steps = u16;

    fn stored(outcome: &EpisodeOutcome) -> (i32, u16) {
        (outcome.env_return as i32, outcome.steps as u16)
    }

    fn count(&mut self, _episode: u32, _outcome: &EpisodeOutcome, env: &MarioEnv) {
        if env.world().status() == super::Status::Won {
            self.wins += 1;
        }
    }
}

impl MarioTrial {
    /// Agent steps over the trial.
    pub fn total_steps(&self) -> u64 {
        self.steps.iter().map(|&s| u64::from(s)).sum()
    }

    /// The returns as floats.
    pub fn returns_f64(&self) -> Vec<f64> {
        self.returns.iter().map(|&r| f64::from(r)).collect()
    }
}

/// Slots of the feature memo (direct-mapped), as a power of two.
const FEATURE_SLOTS_LOG2: u32 = 14;

/// Slots of the potential memo (direct-mapped), as a power of two: a miss
/// costs SBS a scan of every demonstrated state, and a trial meets some
/// 10^5 states, so this one is larger (2^18 slots, 27 MiB a trial). At
/// 2^14 slots two thirds of SBS's misses in its first 1,000 episodes were
/// conflicts (106,847 misses against 35,165 at 2^20).
const POTENTIAL_SLOTS_LOG2: u32 = 18;

fn slot_of(key: u64, log2: u32) -> usize {
    (key.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> (64 - log2)) as usize
}

/// A feature map memoising another's active features per packed discrete state.
#[derive(Clone, Debug)]
pub struct MemoFeatures<F> {
    inner: F,
    width: usize,
    memo: RefCell<(Vec<u64>, Vec<u32>)>,
}

impl<F: FeatureMap> MemoFeatures<F> {
    /// Memoises `inner`, whose features must be binary.
    pub fn new(inner: F) -> Self {
        let width = inner.max_active();
        let slots = 1 << FEATURE_SLOTS_LOG2;
        MemoFeatures { memo: RefCell::new((vec![u64::MAX; slots], vec![0; slots * width])), inner, width }
    }
}

impl<F: FeatureMap> FeatureMap for MemoFeatures<F> {
    fn num_features(&self) -> usize {
        self.inner.num_features()
    }

    fn max_active(&self) -> usize {
        self.width
    }

    #[inline]
    fn features(&self, state: &[f64], out: &mut ActiveFeatures) {
        let Some(key) = pack(state) else {
            return self.inner.features(state, out);
        };
        let slot = slot_of(key, FEATURE_SLOTS_LOG2);
        let mut memo = self.memo.borrow_mut();
        let (keys, indices) = &mut *memo;
        let cells = &mut indices[slot * self.width..(slot + 1) * self.width];
        if keys[slot] == key {
            out.values.clear();
            out.indices.clear();
            out.indices.extend_from_slice(cells);
            return;
        }
        self.inner.features(state, out);
        if out.values.is_empty() && out.indices.len() == self.width {
            cells.copy_from_slice(&out.indices);
            keys[slot] = key;
        }
    }
}

/// A state-action function memoised per packed discrete state.
#[derive(Clone, Debug)]
pub struct MemoPotential<P> {
    inner: P,
    memo: RefCell<(Vec<u64>, Vec<f64>)>,
}

impl<P: StateActionFunction> MemoPotential<P> {
    /// Memoises `inner` (12 actions).
    pub fn new(inner: P) -> Self {
        let slots = 1 << POTENTIAL_SLOTS_LOG2;
        MemoPotential { inner, memo: RefCell::new((vec![u64::MAX; slots], vec![0.0; slots * ACTIONS])) }
    }
}

impl<P: StateActionFunction> StateActionFunction for MemoPotential<P> {
    #[inline]
    fn values(&self, state: &[f64], out: &mut [f64]) {
        let Some(key) = pack(state) else {
            return self.inner.values(state, out);
        };
        let slot = slot_of(key, POTENTIAL_SLOTS_LOG2);
        let mut memo = self.memo.borrow_mut();
        let (keys, values) = &mut *memo;
        let cells = &mut values[slot * ACTIONS..(slot + 1) * ACTIONS];
        if keys[slot] == key && out.len() == ACTIONS {
            out.copy_from_slice(cells);
            return;
        }
        self.inner.values(state, out);
        if out.len() == ACTIONS {
            cells.copy_from_slice(out);
            keys[slot] = key;
        }
    }
}

/// The feature map every Mario agent uses: the hashed tiles, renumbered in
/// order of first appearance (neighbouring weight rows for a state's tiles;
/// the same learning, see [`FirstTouch`]), memoised per state.
pub type MarioFeatures = MemoFeatures<FirstTouch<TileCoder>>;

impl Domain for MarioParams {
    type Env = MarioEnv;
    type Features = MarioFeatures;
    type Learner = WatkinsQLambda;
    type Potential<P: StateActionFunction> = MemoPotential<P>;
    type Similarity = PackedSimilarity;
    type Trial = MarioTrial;

    const BASELINE: Baseline = BASELINE;
    const ACTIONS: usize = ACTIONS;

    fn episodes(&self) -> usize {
        self.episodes
    }

    fn max_steps(&self) -> usize {
        self.max_steps
    }

    fn env(&self) -> MarioEnv {
        MarioEnv::new(self.level)
    }

    fn features(&self) -> MarioFeatures {
        MemoFeatures::new(FirstTouch::new(self.tile_coder()))
    }

    fn learner(&self, features: usize) -> WatkinsQLambda {
        WatkinsQLambda::new(features, ACTIONS, self.td(), self.traces).traces_by_generation()
    }

    /// The thesis's one scale for the shaping rewards, and HAT's own B.
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

    /// R_IRL as fitted.
    fn irl_reward(&self, fitted: &LinearReward<StateVariables>) -> LinearReward<StateVariables> {
        fitted.clone()
    }

    /// Memoised per packed state.
    fn potential<P: StateActionFunction>(&self, p: P) -> MemoPotential<P> {
        MemoPotential::new(p)
    }

    /// Searched over packed states (the same values, see [`PackedSimilarity`]).
    fn similarity(&self, general: &rlfd_lfd::similarity::SimilarityPotential) -> PackedSimilarity {
        PackedSimilarity::new(general.clone())
    }
}

/// Runs one trial of `agent` in Mario; the shaped agents need `inputs`.
///
/// # Panics
/// If a shaped agent is given no inputs (a caller's logic error).
pub fn run_trial(agent: Agent, params: &MarioParams, inputs: Option<&AgentInputs>, seed: u64) -> MarioTrial {
    crate::shaping::run_trial(agent, params, inputs, seed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn memoised_features_equal_the_tile_coder_s() {
        let params = MarioParams::paper();
        let coder = params.tile_coder();
        let memo = MemoFeatures::new(params.tile_coder());
        let mut env = MarioEnv::new(params.level);
        let mut rng = seeded(4);
        use rlfd_rl::Environment;
        env.reset(&mut rng);
        let (mut a, mut b) = (ActiveFeatures::default(), ActiveFeatures::default());
        for _ in 0..3000 {
            coder.features(env.state(), &mut a);
            memo.features(env.state(), &mut b);
            assert_eq!(a, b);
            assert_eq!(a.len(), 32);
            if env.step(rlfd_rl::random::below(&mut rng, ACTIONS), &mut rng).terminal {
                env.reset(&mut rng);
            }
        }
    }

    #[test]
    fn q_lambda_trials_are_reproducible_and_learn_something() {
        let params = MarioParams { episodes: 3, ..MarioParams::paper() };
        let a = run_trial(Agent::Baseline, &params, None, 9);
        assert_eq!(a, run_trial(Agent::Baseline, &params, None, 9));
        assert_eq!(a.returns.len(), 3);
        assert!(a.steps.iter().all(|&s| (1..=3000).contains(&s)));
    }

    #[test]
    fn a_trial_is_stored_as_round_2_stored_it() {
        let t = MarioTrial {
            returns: vec![-3, 1024],
            steps: vec![7, 3000],
            ends: MarioEnds { wins: 1 },
            diverged_at: None,
        };
        let json = serde_json::to_string(&t).unwrap();
        assert_eq!(json, r#"{"returns":[-3,1024],"steps":[7,3000],"wins":1}"#);
        assert_eq!(serde_json::from_str::<MarioTrial>(&json).unwrap(), t);
    }
}
