//! What the agents learn from the demonstrations (section 6.2), in any
//! domain: the RE-IRL reward (SIS, DIS), the RIPPER rules (HAT) and the
//! similarity potential (SBS), with the settings both domains share.
//!
//! - **RE-IRL**: reward features are the state variables; feature counts are
//!   undiscounted sums over demonstrations of equal length (each domain says
//!   how it makes them equal); the baseline is 1,000 rollouts of the
//!   uniformly random policy, of the same length; the tolerance is
//!   Hoeffding's with δ = 0.05 and each variable's range; the features are
//!   scaled to their ranges. θ maximises the dual within the ball ‖θ‖ ≤ 1 by
//!   accelerated proximal gradient ascent until the optimality residual is
//!   below 10⁻⁹ (see `rlfd_lfd::irl`), then is set to unit length, so the
//!   domain's shaping scale sets the potential's size. Unit length was the
//!   project's choice before any learner ran; round 2 replaced the fixed-step
//!   subgradient ascent (3,000 steps of 10⁻⁴, renormalised after each, which
//!   never settled where the softmax over the baseline is a hard max) with
//!   this convergent form of the same problem.
//! - **RIPPER**: the thesis's tool, Weka 3.6's JRip with its defaults
//!   (`RipperParams::weka_3_6`: `-F 3 -N 2.0 -O 2 -S 1` drawing from Weka's
//!   own `java.util.Random`, so the rules are those Weka prints for the same
//!   data), on every demonstrated (state, action) pair. (Round 2 drew JRip's
//!   splits from a ChaCha8 stream: the same algorithm, other rules.)
//! - **SBS**: the same pairs, with the domain's Gaussian widths.

use rlfd_lfd::demonstration::DemonstrationSet;
use rlfd_lfd::irl::{
    IrlError, IrlFeatureScale, IrlFit, LinearReward, Normalisation, RelativeEntropyIrl, RelativeEntropyIrlParams,
    StateVariables, Stopping, Tolerance, rollout_uniform,
};
use rlfd_lfd::ripper::{Attribute, Dataset, DecisionList, Ripper, RipperError, RipperParams};
use rlfd_lfd::similarity::{SimilarityError, SimilarityPotential};
use rlfd_rl::Environment;
use serde::Serialize;
use thiserror::Error;

/// What the shaped agents learn from: the demonstrations' products.
#[derive(Clone, Debug)]
pub struct AgentInputs {
    /// `R_IRL(s) = θᵀ s` over the state variables, from RE-IRL.
    pub irl_reward: LinearReward<StateVariables>,
    /// RIPPER's decision list over the demonstrated (state, action) pairs.
    pub rules: DecisionList,
    /// The SBS potential over the demonstrated pairs.
    pub similarity: SimilarityPotential,
}

/// Why the demonstrations cannot be turned into agent inputs.
#[derive(Debug, Error)]
pub enum InputError {
    /// The demonstrations do not fit the domain.
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

/// RE-IRL's settings, the same in both domains (see the module docs).
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

/// RE-IRL on demonstrations of equal length `horizon` (`equal`), their
/// state variables as features with the given `ranges`, against `baseline`
/// rollouts of the uniform policy in `walker` drawn from `rng`: the fit and
/// `R_IRL(s) = θᵀ s`.
pub fn fit_irl<E: Environment>(
    settings: &IrlSettings,
    equal: &DemonstrationSet,
    horizon: usize,
    ranges: Vec<f64>,
    walker: &mut E,
    rng: &mut rlfd_rl::random::SimRng,
) -> Result<(IrlFit, LinearReward<StateVariables>), InputError> {
    let features = StateVariables { dim: ranges.len() };
    let irl = RelativeEntropyIrl::new(settings.params(ranges))?;
    let expert = irl.feature_counts_of(equal, &features)?;
    let baseline = rollout_uniform(walker, rng, settings.baseline_trajectories, horizon, &features, 1.0);
    let fit = irl.fit(&expert, &baseline, horizon)?;
    let reward = LinearReward::new(fit.weights.clone(), features);
    Ok((fit, reward))
}

/// The RIPPER the chapter learns its rules with: Weka 3.6's JRip, as the thesis.
/// θ of the same RE-IRL fit under other draws of the uniform-policy
/// baseline (issue 27, item 4): how much of θ is the baseline sample's.
#[derive(Clone, Debug, PartialEq)]
pub struct IrlDraws {
    /// θ over the scaled features (unit length), one per draw.
    pub scaled_weights: Vec<Vec<f64>>,
    /// How many draws' maximisers lie on the bound ‖θ‖ = bound (where the
    /// unbounded dual, the paper's, has no maximiser).
    pub on_bound: usize,
    /// How many draws' ascents converged.
    pub converged: usize,
}

/// [`fit_irl`] once per seed of `seeds`, each drawing its own baseline.
///
/// Each draw rolls out in its own copy of `walker` (every rollout starts
/// with a reset drawn from the draw's own stream, so the copy's past does
/// not matter) and the draws run in parallel, collected in `seeds`' order:
/// the same fits as one after the other in one walker. They are the
/// report's only (no agent learns from them), and about half of what a
/// chapter 6 run spends outside its trials.
pub fn fit_irl_draws<E: Environment + Clone + Send + Sync>(
    settings: &IrlSettings,
    equal: &DemonstrationSet,
    horizon: usize,
    ranges: &[f64],
    walker: &E,
    seeds: impl IntoIterator<Item = u64>,
) -> Result<IrlDraws, InputError> {
    use rayon::prelude::*;
    let seeds: Vec<u64> = seeds.into_iter().collect();
    let fits: Vec<IrlFit> = seeds
        .par_iter()
        .map(|&seed| {
            let mut walker = walker.clone();
            let mut rng = rlfd_rl::random::seeded(seed);
            fit_irl(settings, equal, horizon, ranges.to_vec(), &mut walker, &mut rng).map(|(fit, _)| fit)
        })
        .collect::<Result<_, _>>()?;
    let mut draws = IrlDraws { scaled_weights: Vec::new(), on_bound: 0, converged: 0 };
    for fit in fits {
        draws.on_bound += usize::from(fit.on_bound);
        draws.converged += usize::from(fit.converged);
        draws.scaled_weights.push(fit.scaled_weights);
    }
    Ok(draws)
}

pub fn ripper_params() -> RipperParams {
    RipperParams::weka_3_6()
}

/// The demonstrated (state, action) pairs as RIPPER's dataset (numeric
/// `attributes`, the class `Action` with `class_names`), and the rules
/// [`ripper_params`] learns from it.
pub fn fit_rules(
    demos: &DemonstrationSet,
    attributes: Vec<Attribute>,
    class_names: Vec<String>,
) -> Result<(Dataset, DecisionList), InputError> {
    let (rows, labels): (Vec<Vec<f64>>, Vec<usize>) = demos.state_action_pairs().map(|(s, a)| (s.to_vec(), a)).unzip();
    let data = Dataset::new(attributes, rows, "Action", class_names, labels)?;
    let rules = Ripper::fit(&ripper_params(), &data)?;
    Ok((data, rules))
}
