//! Relative Entropy Inverse Reinforcement Learning (Boularias, Kober &
//! Peters, AISTATS 2011), model-free, as the thesis's section 6.2 uses it.
//!
//! A trajectory `τ` has feature counts `f^τ = Σ_{t=0}^{H−1} γ^t f(s_t)` (the
//! first state weighted `γ^0`). RE-IRL looks for the distribution over
//! trajectories closest in relative entropy to a baseline `Q` whose expected
//! feature counts match the expert's `f̂` within `ε`; its solution is
//! `P(τ | θ) ∝ Q(τ) exp(θᵀ f^τ)`, and `θ` maximises the dual
//! `g(θ) = θᵀ f̂ − ln Z(θ) − Σ_i ε_i |θ_i|` by subgradient ascent:
//!
//! ```text
//! ∇_i = f̂_i − Σ_τ w_τ f_i^τ / Σ_τ w_τ − α_i ε_i,   α_i = sign(θ_i) (+1 at 0)
//! w_τ = exp(θᵀ f^τ)   over N baseline trajectories from the uniform policy
//! θ ← θ + η ∇   (optionally renormalised to unit L2 norm)
//! ```
//!
//! With a uniformly random sampling policy the importance ratio `U(τ)/π(τ)`
//! is 1 and the dynamics cancel, so no model is needed: the weights are a
//! softmax of `θᵀ f^τ`, computed with the log-sum-exp shift. The iteration
//! budget is fixed and there is no wall-clock bound: a fit is a pure function
//! of its inputs. The recovered reward is linear, `R(s) = θᵀ f(s)`
//! ([`LinearReward`]).
//!
//! Not here: sampling the baseline trajectories (a domain rolls them out; see
//! [`rollout_uniform`]), and any use of the reward (shaping is in `rlfd-rl`).

use rand::Rng;
use rlfd_rl::Environment;
use rlfd_rl::random::below;
use rlfd_rl::shaping::StateFunction;
use thiserror::Error;

use crate::demonstration::DemonstrationSet;

/// Why a fit cannot run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IrlError {
    /// No expert trajectories or no baseline trajectories.
    #[error("RE-IRL needs at least one {0} trajectory")]
    Empty(&'static str),
    /// Trajectories of different lengths where RE-IRL needs equal ones.
    #[error(
        "RE-IRL needs trajectories of equal length: {which} trajectory {index} has {found} observations, expected {expected} (pad or prune the demonstrations first)"
    )]
    UnequalLengths {
        /// "expert" or "baseline".
        which: &'static str,
        /// Position of the offending trajectory.
        index: usize,
        /// Its length.
        found: usize,
        /// The first trajectory's length.
        expected: usize,
    },
    /// Feature vectors of different dimensions.
    #[error("feature counts of {which} trajectory {index} have {found} features, expected {expected}")]
    Dimension {
        /// "expert" or "baseline".
        which: &'static str,
        /// Position of the offending trajectory.
        index: usize,
        /// Its dimension.
        found: usize,
        /// The expected dimension.
        expected: usize,
    },
    /// A non-finite feature count or parameter.
    #[error("{0} is not finite")]
    NonFinite(&'static str),
    /// A parameter outside its domain.
    #[error("invalid RE-IRL parameter: {0}")]
    Parameter(&'static str),
}

/// The L1 tolerances `ε_i` of the feature-matching constraints.
#[derive(Clone, Debug, PartialEq)]
pub enum Tolerance {
    /// `ε = 0`: exact matching, no regulariser.
    Zero,
    /// One value per feature.
    PerFeature(Vec<f64>),
    /// Hoeffding's bound with confidence `1 − δ`, as in the paper (p. 184):
    /// `ε_i = (f_i^max − f_i^min) · (γ^{H+1} − 1)/(γ − 1) · sqrt(−ln(1 − δ) / (2 |D_E|))`,
    /// with the geometric sum read as `H + 1` when `γ = 1`.
    Hoeffding {
        /// `δ` in (0, 1).
        delta: f64,
        /// Range of each feature `f_i^max − f_i^min` over the state space.
        feature_ranges: Vec<f64>,
    },
}

/// Whether θ is rescaled after every step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Normalisation {
    /// Plain subgradient ascent.
    None,
    /// θ ← θ / ‖θ‖₂ after every step (common in implementations, not in the
    /// paper): the reward's direction is learned, its scale is left to the
    /// shaping scale.
    UnitL2,
}

/// RE-IRL's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct RelativeEntropyIrlParams {
    /// Step size η of the subgradient ascent.
    pub step_size: f64,
    /// Number of steps (a fixed budget).
    pub iterations: usize,
    /// Discount γ of the feature counts.
    pub discount: f64,
    /// The constraint tolerances ε.
    pub tolerance: Tolerance,
    /// Rescaling of θ after each step.
    pub normalisation: Normalisation,
}

/// The result of a fit.
#[derive(Clone, Debug, PartialEq)]
pub struct IrlFit {
    /// The reward weights θ.
    pub weights: Vec<f64>,
    /// The expert's mean feature counts `f̂`.
    pub expert_feature_counts: Vec<f64>,
    /// The ε used, per feature.
    pub tolerance: Vec<f64>,
    /// ‖θ_n − θ_{n−1}‖₂ of the last step (how settled the fit is).
    pub last_step_norm: f64,
    /// ‖∇‖₂ at the last step.
    pub last_gradient_norm: f64,
    /// Steps taken.
    pub iterations: usize,
}

/// Relative Entropy IRL over precomputed feature counts.
#[derive(Clone, Debug)]
pub struct RelativeEntropyIrl {
    params: RelativeEntropyIrlParams,
}

impl RelativeEntropyIrl {
    /// Checks the parameters.
    pub fn new(params: RelativeEntropyIrlParams) -> Result<Self, IrlError> {
        if !(params.step_size.is_finite() && params.step_size > 0.0) {
            return Err(IrlError::Parameter("step_size must be a finite number > 0"));
        }
        if !(0.0..=1.0).contains(&params.discount) {
            return Err(IrlError::Parameter("discount must be in [0, 1]"));
        }
        match &params.tolerance {
            Tolerance::PerFeature(e) if e.iter().any(|x| !x.is_finite() || *x < 0.0) => {
                return Err(IrlError::Parameter("tolerances must be finite and ≥ 0"));
            }
            Tolerance::Hoeffding { delta, feature_ranges }
                if !(*delta > 0.0 && *delta < 1.0) || feature_ranges.iter().any(|r| !r.is_finite() || *r < 0.0) =>
            {
                return Err(IrlError::Parameter("Hoeffding needs 0 < delta < 1 and finite ranges ≥ 0"));
            }
            _ => {}
        }
        Ok(RelativeEntropyIrl { params })
    }

    /// The parameters.
    pub fn params(&self) -> &RelativeEntropyIrlParams {
        &self.params
    }

    /// Feature counts of every trajectory of `set` (which must have equal lengths).
    pub fn feature_counts_of(
        &self,
        set: &DemonstrationSet,
        features: &dyn RewardFeatures,
    ) -> Result<Vec<Vec<f64>>, IrlError> {
        let expected = set.trajectories().first().map_or(0, |t| t.len());
        set.trajectories()
            .iter()
            .enumerate()
            .map(|(index, t)| {
                if t.len() != expected {
                    return Err(IrlError::UnequalLengths { which: "expert", index, found: t.len(), expected });
                }
                Ok(feature_counts(t.states(), features, self.params.discount))
            })
            .collect()
    }

    /// Fits θ from expert and baseline feature counts (one vector per trajectory).
    /// `horizon` is the trajectories' length (for Hoeffding's ε).
    pub fn fit(&self, expert: &[Vec<f64>], baseline: &[Vec<f64>], horizon: usize) -> Result<IrlFit, IrlError> {
        let k = expert.first().ok_or(IrlError::Empty("expert"))?.len();
        if baseline.is_empty() {
            return Err(IrlError::Empty("baseline"));
        }
        for (which, set) in [("expert", expert), ("baseline", baseline)] {
            for (index, f) in set.iter().enumerate() {
                if f.len() != k {
                    return Err(IrlError::Dimension { which, index, found: f.len(), expected: k });
                }
                if f.iter().any(|x| !x.is_finite()) {
                    return Err(IrlError::NonFinite("a feature count"));
                }
            }
        }
        let mut f_hat = vec![0.0; k];
        for f in expert {
            for (m, x) in f_hat.iter_mut().zip(f) {
                *m += x;
            }
        }
        for m in &mut f_hat {
            *m /= expert.len() as f64;
        }
        let eps = self.tolerance(k, horizon, expert.len())?;

        let mut theta = vec![0.0; k];
        let mut logits = vec![0.0; baseline.len()];
        let mut gradient = vec![0.0; k];
        let (mut last_step_norm, mut last_gradient_norm) = (0.0, 0.0);
        for _ in 0..self.params.iterations {
            // Softmax weights of the baseline trajectories, shifted for stability.
            let mut max = f64::NEG_INFINITY;
            for (l, f) in logits.iter_mut().zip(baseline) {
                *l = dot(&theta, f);
                max = max.max(*l);
            }
            let mut z = 0.0;
            for l in logits.iter_mut() {
                *l = libm::exp(*l - max);
                z += *l;
            }
            gradient.copy_from_slice(&f_hat);
            for (w, f) in logits.iter().zip(baseline) {
                for (g, x) in gradient.iter_mut().zip(f) {
                    *g -= w / z * x;
                }
            }
            for ((g, &t), &e) in gradient.iter_mut().zip(&theta).zip(&eps) {
                *g -= if t >= 0.0 { e } else { -e };
            }
            let previous = theta.clone();
            for (t, g) in theta.iter_mut().zip(&gradient) {
                *t += self.params.step_size * g;
            }
            if self.params.normalisation == Normalisation::UnitL2 {
                let norm = dot(&theta, &theta).sqrt();
                if norm > 0.0 {
                    for t in &mut theta {
                        *t /= norm;
                    }
                }
            }
            last_step_norm = theta.iter().zip(&previous).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
            last_gradient_norm = dot(&gradient, &gradient).sqrt();
        }
        if theta.iter().any(|t| !t.is_finite()) {
            return Err(IrlError::NonFinite("the fitted weights (lower the step size)"));
        }
        Ok(IrlFit {
            weights: theta,
            expert_feature_counts: f_hat,
            tolerance: eps,
            last_step_norm,
            last_gradient_norm,
            iterations: self.params.iterations,
        })
    }

    fn tolerance(&self, k: usize, horizon: usize, experts: usize) -> Result<Vec<f64>, IrlError> {
        Ok(match &self.params.tolerance {
            Tolerance::Zero => vec![0.0; k],
            Tolerance::PerFeature(e) if e.len() == k => e.clone(),
            Tolerance::PerFeature(_) => return Err(IrlError::Parameter("one tolerance per feature")),
            Tolerance::Hoeffding { delta, feature_ranges } => {
                if feature_ranges.len() != k {
                    return Err(IrlError::Parameter("one feature range per feature"));
                }
                let g = self.params.discount;
                let geometric = if g == 1.0 {
                    (horizon + 1) as f64
                } else {
                    (libm::pow(g, (horizon + 1) as f64) - 1.0) / (g - 1.0)
                };
                let root = (-libm::log(1.0 - delta) / (2.0 * experts as f64)).sqrt();
                feature_ranges.iter().map(|r| r * geometric * root).collect()
            }
        })
    }
}

#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The reward features `f(s)` RE-IRL weighs.
pub trait RewardFeatures {
    /// Number of features.
    fn dim(&self) -> usize;
    /// Writes `f(state)` into `out` (length [`RewardFeatures::dim`]).
    fn features(&self, state: &[f64], out: &mut [f64]);
}

/// The state variables themselves as features (the thesis: "in our
/// representation, we only use the state variables").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateVariables {
    /// Length of the state vector.
    pub dim: usize,
}

impl RewardFeatures for StateVariables {
    fn dim(&self) -> usize {
        self.dim
    }
    fn features(&self, state: &[f64], out: &mut [f64]) {
        out.copy_from_slice(state);
    }
}

/// `Σ_t γ^t f(s_t)` over a sequence of states.
pub fn feature_counts<'a>(
    states: impl IntoIterator<Item = &'a [f64]>,
    features: &dyn RewardFeatures,
    discount: f64,
) -> Vec<f64> {
    let mut total = vec![0.0; features.dim()];
    let mut f = vec![0.0; features.dim()];
    let mut weight = 1.0;
    for s in states {
        features.features(s, &mut f);
        for (t, x) in total.iter_mut().zip(&f) {
            *t += weight * x;
        }
        weight *= discount;
    }
    total
}

/// Feature counts of `n` rollouts of the uniformly random policy from the
/// environment's start, each of exactly `horizon` observations (an episode
/// that ends early repeats its last observation, as the thesis pads its
/// demonstrations). These are RE-IRL's baseline samples.
pub fn rollout_uniform<E: Environment, R: Rng + ?Sized>(
    env: &mut E,
    rng: &mut R,
    n: usize,
    horizon: usize,
    features: &dyn RewardFeatures,
    discount: f64,
) -> Vec<Vec<f64>> {
    let mut out = Vec::with_capacity(n);
    let mut f = vec![0.0; features.dim()];
    let actions = env.num_actions();
    for _ in 0..n {
        env.reset(rng);
        let mut total = vec![0.0; features.dim()];
        let mut weight = 1.0;
        let mut done = false;
        for _ in 0..horizon {
            features.features(env.state(), &mut f);
            for (t, x) in total.iter_mut().zip(&f) {
                *t += weight * x;
            }
            weight *= discount;
            if !done {
                done = env.step(below(rng, actions), rng).terminal;
            }
        }
        out.push(total);
    }
    out
}

/// A linear reward `R(s) = θᵀ f(s)`: RE-IRL's output, usable as a potential.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearReward<F> {
    weights: Vec<f64>,
    features: F,
}

impl<F: RewardFeatures> LinearReward<F> {
    /// A reward with the given weights over `features`.
    pub fn new(weights: Vec<f64>, features: F) -> Self {
        assert_eq!(weights.len(), features.dim(), "one weight per reward feature");
        LinearReward { weights, features }
    }

    /// The weights θ.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }
}

impl<F: RewardFeatures> StateFunction for LinearReward<F> {
    #[inline]
    fn value(&self, state: &[f64]) -> f64 {
        // Small, fixed dimensions in the thesis (2 in the Maze, 27 in Mario):
        // a stack buffer avoids an allocation per call.
        let mut buf = [0.0f64; 64];
        let k = self.weights.len();
        assert!(k <= buf.len(), "LinearReward supports up to 64 features");
        self.features.features(state, &mut buf[..k]);
        dot(&self.weights, &buf[..k])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::{seeded, standard_normal, uniform01};

    fn params(tolerance: Tolerance, normalisation: Normalisation) -> RelativeEntropyIrlParams {
        RelativeEntropyIrlParams { step_size: 0.5, iterations: 4000, discount: 1.0, tolerance, normalisation }
    }

    /// Baseline feature counts, and the expert mean they give under P(τ) ∝ exp(θ*ᵀ f).
    fn synthetic(theta_star: &[f64], n: usize, seed: u64) -> (Vec<Vec<f64>>, Vec<f64>) {
        let mut rng = seeded(seed);
        let k = theta_star.len();
        let baseline: Vec<Vec<f64>> = (0..n).map(|_| (0..k).map(|_| standard_normal(&mut rng)).collect()).collect();
        let logits: Vec<f64> = baseline.iter().map(|f| dot(theta_star, f)).collect();
        let max = logits.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let w: Vec<f64> = logits.iter().map(|l| (l - max).exp()).collect();
        let z: f64 = w.iter().sum();
        let mut mean = vec![0.0; k];
        for (wi, f) in w.iter().zip(&baseline) {
            for (m, x) in mean.iter_mut().zip(f) {
                *m += wi / z * x;
            }
        }
        (baseline, mean)
    }

    #[test]
    fn recovers_known_reward_weights() {
        // With ε = 0 the dual's maximum is where E_P[f] = f̂; when f̂ is the
        // mean under P_θ* on the same samples, that maximum is θ* itself.
        let theta_star = [0.8, -0.5, 0.3];
        let (baseline, mean) = synthetic(&theta_star, 3000, 11);
        let irl = RelativeEntropyIrl::new(params(Tolerance::Zero, Normalisation::None)).unwrap();
        let fit = irl.fit(std::slice::from_ref(&mean), &baseline, 1).unwrap();
        for (w, t) in fit.weights.iter().zip(&theta_star) {
            assert!((w - t).abs() < 1e-6, "{:?} vs {theta_star:?}", fit.weights);
        }
        assert!(fit.last_gradient_norm < 1e-8);
        assert_eq!(fit.expert_feature_counts, mean);
    }

    #[test]
    fn unit_normalisation_recovers_the_direction() {
        let theta_star = [1.2, 0.9];
        let (baseline, mean) = synthetic(&theta_star, 3000, 12);
        let irl = RelativeEntropyIrl::new(RelativeEntropyIrlParams {
            step_size: 0.05,
            ..params(Tolerance::Zero, Normalisation::UnitL2)
        })
        .unwrap();
        let fit = irl.fit(&[mean], &baseline, 1).unwrap();
        let norm = theta_star.iter().map(|x| x * x).sum::<f64>().sqrt();
        let cos = dot(&fit.weights, &theta_star) / norm;
        assert!(cos > 0.999, "cosine {cos}, weights {:?}", fit.weights);
        assert!((dot(&fit.weights, &fit.weights) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn tolerance_shrinks_the_weights() {
        let theta_star = [0.8, -0.5];
        let (baseline, mean) = synthetic(&theta_star, 2000, 13);
        let exact = RelativeEntropyIrl::new(params(Tolerance::Zero, Normalisation::None))
            .unwrap()
            .fit(std::slice::from_ref(&mean), &baseline, 1)
            .unwrap();
        let loose = RelativeEntropyIrl::new(params(Tolerance::PerFeature(vec![0.05, 0.05]), Normalisation::None))
            .unwrap()
            .fit(&[mean], &baseline, 1)
            .unwrap();
        assert!(loose.weights[0].abs() < exact.weights[0].abs());
        assert!(loose.weights[1].abs() < exact.weights[1].abs());
        assert_eq!(loose.weights[0].signum(), exact.weights[0].signum());
    }

    #[test]
    fn hoeffding_tolerance_follows_the_formula() {
        let irl = RelativeEntropyIrl::new(RelativeEntropyIrlParams {
            discount: 0.9,
            iterations: 0,
            ..params(Tolerance::Hoeffding { delta: 0.05, feature_ranges: vec![2.0] }, Normalisation::None)
        })
        .unwrap();
        let fit = irl.fit(&[vec![0.0]], &[vec![0.0]], 10).unwrap();
        // One expert trajectory: 2 |D_E| = 2.
        let expected = 2.0 * (0.9f64.powi(11) - 1.0) / (0.9 - 1.0) * (-(0.95f64).ln() / 2.0).sqrt();
        assert!((fit.tolerance[0] - expected).abs() < 1e-12);
    }

    #[test]
    fn feature_counts_are_discounted_sums() {
        let states: Vec<Vec<f64>> = vec![vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0, 6.0]];
        let c = feature_counts(states.iter().map(Vec::as_slice), &StateVariables { dim: 2 }, 0.5);
        assert_eq!(c, vec![1.0 + 1.5 + 1.25, 2.0 + 2.0 + 1.5]);
    }

    #[test]
    fn bad_input_is_an_error() {
        let irl = RelativeEntropyIrl::new(params(Tolerance::Zero, Normalisation::None)).unwrap();
        assert_eq!(irl.fit(&[], &[vec![1.0]], 1), Err(IrlError::Empty("expert")));
        assert_eq!(irl.fit(&[vec![1.0]], &[], 1), Err(IrlError::Empty("baseline")));
        assert!(matches!(
            irl.fit(&[vec![1.0]], &[vec![1.0, 2.0]], 1),
            Err(IrlError::Dimension { which: "baseline", .. })
        ));
        assert_eq!(irl.fit(&[vec![f64::NAN]], &[vec![1.0]], 1), Err(IrlError::NonFinite("a feature count")));
        assert!(
            RelativeEntropyIrl::new(RelativeEntropyIrlParams {
                step_size: 0.0,
                ..params(Tolerance::Zero, Normalisation::None)
            })
            .is_err()
        );
        let set = DemonstrationSet::new(
            vec!["x".into()],
            None,
            vec![
                crate::demonstration::Trajectory::from_states(&[[0.0], [1.0]], None).unwrap(),
                crate::demonstration::Trajectory::from_states(&[[0.0]], None).unwrap(),
            ],
        )
        .unwrap();
        let e = irl.feature_counts_of(&set, &StateVariables { dim: 1 }).unwrap_err();
        assert_eq!(
            e.to_string(),
            "RE-IRL needs trajectories of equal length: expert trajectory 1 has 1 observations, expected 2 (pad or prune the demonstrations first)"
        );
        let _ = uniform01(&mut seeded(0));
    }

    #[test]
    fn linear_reward_is_a_dot_product() {
        let r = LinearReward::new(vec![2.0, -1.0], StateVariables { dim: 2 });
        assert_eq!(r.value(&[0.5, 0.25]), 0.75);
    }
}
