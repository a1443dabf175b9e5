//! From demonstrations to what the agents learn from (section 6.2): the
//! RE-IRL reward, the RIPPER rules and the similarity potential.
//!
//! - **RE-IRL** (SIS, DIS): the demonstrations are padded to equal length by
//!   repeating their last observation (the thesis: "we appended the last
//!   observation of the shorter demonstrations repeatedly"); reward features
//!   are the state variables (x, y); feature counts are undiscounted sums
//!   (γ = 1, the task's discount); the baseline is 1,000 rollouts of the
//!   uniformly random policy from the start, at the demonstrations' own step
//!   (0.01) and length; the tolerance is Hoeffding's with δ = 0.05; the
//!   features are scaled to their ranges (1 in the unit square). θ maximises
//!   the dual within the ball ‖θ‖ ≤ 1 by accelerated proximal gradient ascent
//!   until the optimality residual is below 10⁻⁹ (see `rlfd_lfd::irl`), then
//!   is set to unit length, so the shaping scale of 100 (and the `irl-scale`
//!   reading) sets the potential's size. Unit length was the project's choice
//!   before any learner ran; round 2 replaced the fixed-step subgradient
//!   ascent (3,000 steps of 10⁻⁴, renormalised after each, which never
//!   settled where the softmax over the baseline is a hard max) with this
//!   convergent form of the same problem. The report prints θ, the
//!   objective's curve and θ's stability.
//! - **RIPPER** (HAT): the thesis's tool, Weka 3.6's JRip with its defaults
//!   (`RipperParams::weka_3_6`: `-F 3 -N 2.0 -O 2 -S 1` drawing from Weka's
//!   own `java.util.Random`, so the rules and the 10-fold cross-validation
//!   are those Weka prints for the same data), on the demonstrated (x, y) →
//!   move pairs, the move of each step being the one between consecutive
//!   states. (Round 2 drew JRip's splits from a ChaCha8 stream: the same
//!   algorithm, other rules.)
//! - **SBS**: the same pairs, Gaussian widths σ = 0.05 in x and y.

use rlfd_harness::{Fingerprint, TrialKey, derive_seed};
use rlfd_lfd::demonstration::DemonstrationSet;
use rlfd_lfd::irl::{
    IrlError, IrlFeatureScale, IrlFit, LinearReward, Normalisation, RelativeEntropyIrl, RelativeEntropyIrlParams,
    StateVariables, Stopping, Tolerance, rollout_uniform,
};
use rlfd_lfd::ripper::{
    Attribute, CrossValidation, Dataset, Ripper, RipperError, RipperParams, stratified_cross_validation,
};
use rlfd_lfd::similarity::{SimilarityError, SimilarityPotential};
use rlfd_rl::random::seeded;
use serde::Serialize;
use thiserror::Error;

use crate::CHAPTER;
use crate::agents::{AgentInputs, MazeParams};
use crate::maze::layout::LayoutId;
use crate::maze::{Maze, MazeLayout, MazeRewards, Move};

/// Why the demonstrations cannot be turned into agent inputs.
#[derive(Debug, Error)]
pub enum InputError {
    /// The demonstrations do not fit the Maze.
    #[error("demonstrations: {0}")]
    Demonstrations(String),
    /// RE-IRL refused its input.
    #[error("RE-IRL")]
    Irl(#[from] IrlError),
    /// RIPPER refused its input.
    #[error("RIPPER")]
    Ripper(#[from] RipperError),
    /// The similarity potential refused its input.
    #[error("SBS")]
    Similarity(#[from] SimilarityError),
}

/// RE-IRL's settings, the Maze's and Mario's (see the module docs).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct IrlSettings {
    /// Baseline rollouts of the uniform policy.
    pub baseline_trajectories: usize,
    /// Hoeffding's δ.
    pub delta: f64,
    /// The bound ρ on ‖θ‖ in the scaled features.
    pub norm_bound: f64,
    /// The optimality residual at which the ascent stops.
    pub tolerance: f64,
    /// The most iterations.
    pub max_iterations: usize,
}

impl IrlSettings {
    /// The settings of both domains.
    pub fn thesis() -> Self {
        IrlSettings {
            baseline_trajectories: 1000,
            delta: 0.05,
            norm_bound: 1.0,
            tolerance: Stopping::DEFAULT.tolerance,
            max_iterations: Stopping::DEFAULT.max_iterations,
        }
    }

    /// RE-IRL's parameters for features with the given ranges.
    pub fn params(&self, ranges: Vec<f64>) -> RelativeEntropyIrlParams {
        RelativeEntropyIrlParams {
            discount: 1.0,
            tolerance: Tolerance::Hoeffding { delta: self.delta, feature_ranges: ranges.clone() },
            feature_scale: IrlFeatureScale::Ranges(ranges),
            norm_bound: Some(self.norm_bound),
            stopping: Stopping { tolerance: self.tolerance, max_iterations: self.max_iterations },
            normalisation: Normalisation::UnitL2,
        }
    }
}

/// Everything derived from the demonstrations, with diagnostics for the report.
#[derive(Clone, Debug)]
pub struct PreparedInputs {
    /// What the agents use.
    pub agents: AgentInputs,
    /// The RE-IRL fit (θ over (x, y)).
    pub irl: IrlFit,
    /// Observations per padded demonstration (RE-IRL's horizon).
    pub horizon: usize,
    /// RE-IRL's settings.
    pub irl_settings: IrlSettings,
    /// RIPPER's stratified 10-fold cross-validation on the demonstrated pairs.
    pub rules_cv: CrossValidation,
    /// Fingerprint of the demonstrations and everything derived from them.
    pub fingerprint: Fingerprint,
}

/// RIPPER's stratified cross-validation folds (the report's accuracy).
pub const RULES_CV_FOLDS: usize = 10;

/// The fewest demonstrated (state, move) pairs [`prepare`] accepts: one per
/// fold of RIPPER's [`RULES_CV_FOLDS`]-fold cross-validation (whose smallest
/// training part, 9, then also holds JRip's 3 grow/prune folds).
pub const MIN_PAIRS: usize = RULES_CV_FOLDS;

/// The fewest states a demonstration may have: a start and one move. A
/// single observation is no walk, and RE-IRL's feature counts of it are the
/// start repeated over the horizon (the project's rule: the thesis's
/// demonstrations are hundreds of steps long).
pub const MIN_LENGTH: usize = 2;

/// The RIPPER the chapter learns its rules with: Weka 3.6's JRip, as the thesis.
pub fn ripper_params() -> RipperParams {
    RipperParams::weka_3_6()
}

/// Whether demonstrations can serve as the Maze's (the layout `layout`): states (x, y) in the
/// maze's free space, the four moves as actions, every demonstration at
/// least [`MIN_LENGTH`] states long and at least [`MIN_PAIRS`] demonstrated
/// pairs in all. The error is one sentence naming the first problem (with
/// the trajectory and step, numbered from 0 as in the files). [`prepare`]
/// checks this first; callers reading a file check it before any trial runs.
pub fn check(demos: &DemonstrationSet, layout: LayoutId) -> Result<(), InputError> {
    let refuse = |message: String| Err(InputError::Demonstrations(message));
    if demos.dimension() != 2 {
        return refuse(format!("Maze states have 2 values (x, y), these have {}", demos.dimension()));
    }
    if !demos.has_actions() || demos.num_actions() != Some(4) {
        return refuse("Maze demonstrations need their moves as actions 0..4 (left, right, up, down)".into());
    }
    let layout = MazeLayout::of(layout);
    for (t, trajectory) in demos.trajectories().iter().enumerate() {
        for (step, state) in trajectory.states().enumerate() {
            let (x, y) = (state[0], state[1]);
            if !((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y)) {
                return refuse(format!("trajectory {t}, step {step}: state ({x}, {y}) lies outside the unit square"));
            }
            if layout.is_blocked_at(x, y) {
                return refuse(format!("trajectory {t}, step {step}: state ({x}, {y}) lies inside a wall of the maze"));
            }
        }
        if trajectory.len() < MIN_LENGTH {
            return refuse(format!(
                "trajectory {t} holds {} state, but a demonstration needs at least {MIN_LENGTH} (a start and one move)",
                trajectory.len()
            ));
        }
    }
    let pairs = demos.state_action_pairs().count();
    if pairs < MIN_PAIRS {
        return refuse(format!(
            "only {pairs} states have an action (a demonstrated move), but RIPPER's {RULES_CV_FOLDS}-fold cross-validation needs at least {MIN_PAIRS}"
        ));
    }
    Ok(())
}

/// Derives the agents' inputs from demonstrations of the Maze `params.layout`
/// (states (x, y), actions = moves), after [`check`].
pub fn prepare(master_seed: u64, params: &MazeParams, demos: &DemonstrationSet) -> Result<PreparedInputs, InputError> {
    check(demos, params.layout)?;

    // RE-IRL on the padded demonstrations.
    let settings = IrlSettings::thesis();
    let padded = demos.pad_to_equal_length();
    let horizon = padded.require_equal_lengths().map_err(|e| InputError::Demonstrations(e.to_string()))?;
    let features = StateVariables { dim: 2 };
    let irl = RelativeEntropyIrl::new(settings.params(vec![1.0, 1.0]))?;
    let expert = irl.feature_counts_of(&padded, &features)?;
    // The baseline moves at the demonstrations' recording step (see `maze::demonstrator`).
    let mut walker = Maze::new(MazeLayout::of(params.layout), 1, MazeRewards::THESIS);
    let mut rng = seeded(derive_seed(master_seed, &TrialKey::new(CHAPTER, "maze", "irl-baseline", 0)));
    let baseline = rollout_uniform(&mut walker, &mut rng, settings.baseline_trajectories, horizon, &features, 1.0);
    let fit = irl.fit(&expert, &baseline, horizon)?;
    let irl_reward = LinearReward::new(fit.weights.clone(), features);

    // RIPPER and SBS on the demonstrated pairs.
    let (rows, labels): (Vec<Vec<f64>>, Vec<usize>) = demos.state_action_pairs().map(|(s, a)| (s.to_vec(), a)).unzip();
    let class_names = Move::ALL.iter().map(|m| m.name().to_string()).collect();
    let data =
        Dataset::new(vec![Attribute::numeric("x"), Attribute::numeric("y")], rows, "Action", class_names, labels)?;
    let ripper = ripper_params();
    let rules = Ripper::fit(&ripper, &data)?;
    let rules_cv = stratified_cross_validation(&ripper, &data, RULES_CV_FOLDS, 1)?;
    let similarity = SimilarityPotential::new(demos.state_action_pairs(), 4, &[params.sbs_sigma, params.sbs_sigma])?;

    let mut csv = Vec::new();
    demos.write_csv(&mut csv).expect("writing to memory");
    let fingerprint = Fingerprint::new()
        .bytes(&csv)
        .str(&format!("{settings:?}"))
        .str(&format!("{:?}", fit.weights))
        .str(&rules.to_string());
    Ok(PreparedInputs {
        agents: AgentInputs { irl_reward, rules, similarity },
        irl: fit,
        horizon,
        irl_settings: settings,
        rules_cv,
        fingerprint,
    })
}
