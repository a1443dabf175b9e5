//! From the Maze demonstrations to what the agents learn from (section 6.2;
//! the methods in [`crate::shaping::inputs`]).
//!
//! - **RE-IRL** (SIS, DIS): the demonstrations are padded to equal length by
//!   repeating their last observation (the thesis: "we appended the last
//!   observation of the shorter demonstrations repeatedly"); reward features
//!   are the state variables (x, y), whose ranges are 1 (the unit square);
//!   the baseline's rollouts start from the start, at the demonstrations' own
//!   step (0.01) and length. θ at unit length, so the shaping scale of 100
//!   (and the `irl-scale` reading) sets the potential's size. The report
//!   prints θ, the objective's curve and θ's stability.
//! - **RIPPER** (HAT): on the demonstrated (x, y) → move pairs, the move of
//!   each step being the one between consecutive states, with Weka's
//!   stratified 10-fold cross-validation of the same JRip.
//! - **SBS**: the same pairs, Gaussian widths σ = 0.05 in x and y.

use rlfd_harness::{TrialKey, derive_seed};
use rlfd_lfd::demonstration::DemonstrationSet;
use rlfd_lfd::irl::IrlFit;
use rlfd_lfd::ripper::{Attribute, CrossValidation, stratified_cross_validation};
use rlfd_lfd::similarity::SimilarityPotential;
use rlfd_rl::random::seeded;

use super::layout::LayoutId;
use super::params::MazeParams;
use super::{Maze, MazeLayout, MazeRewards, Move};
use crate::CHAPTER;
use crate::shaping::inputs::{self, AgentInputs, InputError, IrlDraws, IrlSettings, ripper_params};

/// Everything derived from the demonstrations, with diagnostics for the report.
#[derive(Clone, Debug)]
pub struct PreparedInputs {
    /// What the agents use.
    pub agents: AgentInputs,
    /// The RE-IRL fit (θ over (x, y)).
    pub irl: IrlFit,
    /// The same fit under [`IRL_DRAWS`] other baseline draws (for the
    /// report: θ's spread over the baseline sample).
    pub irl_draws: IrlDraws,
    /// Observations per padded demonstration (RE-IRL's horizon).
    pub horizon: usize,
    /// RE-IRL's settings.
    pub irl_settings: IrlSettings,
    /// RIPPER's stratified 10-fold cross-validation on the demonstrated pairs.
    pub rules_cv: CrossValidation,
}

/// RIPPER's stratified cross-validation folds (the report's accuracy).
pub const RULES_CV_FOLDS: usize = 10;

/// How many other baseline draws RE-IRL is refitted on for the report
/// (report-only: no agent learns from them).
pub const IRL_DRAWS: usize = 10;

/// The fewest demonstrated (state, move) pairs [`prepare`] accepts: one per
/// fold of RIPPER's [`RULES_CV_FOLDS`]-fold cross-validation (whose smallest
/// training part, 9, then also holds JRip's 3 grow/prune folds).
pub const MIN_PAIRS: usize = RULES_CV_FOLDS;

/// The fewest states a demonstration may have: a start and one move. A
/// single observation is no walk, and RE-IRL's feature counts of it are the
/// start repeated over the horizon (the project's rule: the thesis's
/// demonstrations are hundreds of steps long).
pub const MIN_LENGTH: usize = 2;

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
    // The baseline moves at the demonstrations' recording step (see `maze::demonstrator`).
    let mut walker = Maze::new(MazeLayout::of(params.layout), 1, MazeRewards::THESIS);
    let mut rng = seeded(derive_seed(master_seed, &TrialKey::new(CHAPTER, "maze", "irl-baseline", 0)));
    let (fit, irl_reward) = inputs::fit_irl(&settings, &padded, horizon, vec![1.0, 1.0], &mut walker, &mut rng)?;
    // The other draws are keyed as further trials of the same baseline, so
    // the run's own draw (trial 0) is not among them.
    let draw_seeds =
        (1..=IRL_DRAWS as u32).map(|k| derive_seed(master_seed, &TrialKey::new(CHAPTER, "maze", "irl-baseline", k)));
    let irl_draws = inputs::fit_irl_draws(&settings, &padded, horizon, &[1.0, 1.0], &walker, draw_seeds)?;

    // RIPPER and SBS on the demonstrated pairs.
    let class_names = Move::ALL.iter().map(|m| m.name().to_string()).collect();
    let (data, rules) = inputs::fit_rules(demos, vec![Attribute::numeric("x"), Attribute::numeric("y")], class_names)?;
    let rules_cv = stratified_cross_validation(&ripper_params(), &data, RULES_CV_FOLDS, 1)?;
    let similarity = SimilarityPotential::new(demos.state_action_pairs(), 4, &[params.sbs_sigma, params.sbs_sigma])?;

    Ok(PreparedInputs {
        agents: AgentInputs { irl_reward, rules, similarity },
        irl: fit,
        irl_draws,
        horizon,
        irl_settings: settings,
        rules_cv,
    })
}
