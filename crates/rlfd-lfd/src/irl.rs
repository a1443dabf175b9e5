//! Relative Entropy Inverse Reinforcement Learning (Boularias, Kober &
//! Peters, AISTATS 2011), model-free, as the thesis's section 6.2 uses it.
//!
//! A trajectory `τ` has feature counts `f^τ = Σ_{t=0}^{H−1} γ^t f(s_t)` (the
//! first state weighted `γ^0`). RE-IRL looks for the distribution over
//! trajectories closest in relative entropy to a baseline `Q` whose expected
//! feature counts match the expert's `f̂` within `ε`; its solution is
//! `P(τ | θ) ∝ Q(τ) exp(θᵀ f^τ)`, and `θ` maximises the concave dual
//!
//! ```text
//! g(θ) = θᵀ f̂ − ln( (1/N) Σ_τ exp(θᵀ f^τ) ) − Σ_i ε_i |θ_i|
//! ```
//!
//! over N baseline trajectories from the uniform policy. With a uniformly
//! random sampling policy the importance ratio `U(τ)/π(τ)` is 1 and the
//! dynamics cancel, so no model is needed.
//!
//! **How θ is found.** The paper ascends `g` by subgradient steps. A fixed
//! step on the non-smooth `g` does not converge: where feature counts are
//! large the softmax over the baseline becomes a hard max and θ oscillates
//! between two points, so a fixed iteration budget decides θ by its parity.
//! Here `g` is split into its smooth part `h(θ) = θᵀ f̂ − ln mean exp(θᵀ f^τ)`
//! and the L1 term, and maximised by accelerated proximal gradient ascent
//! (FISTA, Beck & Teboulle 2009) with a backtracking step and a
//! function-value restart (O'Donoghue & Candès 2015): the ascent step on `h`
//! is followed by the soft-threshold step of the L1 term, which is the
//! paper's subgradient step where θ_i ≠ 0 and sets θ_i = 0 exactly where
//! `|∂h/∂θ_i| ≤ ε_i`. Every accepted iterate increases `g`. The fit stops when
//! the first-order optimality residual `‖θ − prox(θ + ∇h/L)‖∞ · L` (zero
//! exactly at the maximum) is below [`Stopping::tolerance`] times
//! `max(1, ‖f̂‖∞)`, or after [`Stopping::max_iterations`] (then
//! [`IrlFit::converged`] is false and callers say so). No wall-clock bound:
//! a fit is a pure function of its inputs.
//!
//! **Feature scaling.** Features may be divided by their ranges before the
//! fit ([`IrlFeatureScale::Ranges`]), so a variable that spans 16 units and
//! one that spans 1 weigh alike in θ's norm; ε is scaled with them. The
//! recovered reward is reported over the raw features
//! ([`IrlFit::weights`] = θ_i / r_i) and over the scaled ones
//! ([`IrlFit::scaled_weights`]).
//!
//! **Size.** RE-IRL's θ carries the size of a tilt of a trajectory
//! distribution, not of a per-step reward; with [`Normalisation::UnitL2`] the
//! maximiser is rescaled once, at the end, to unit length in the scaled
//! features (the reward's direction; its size is then the caller's).
//!
//! The recovered reward is linear, `R(s) = wᵀ f(s)` ([`LinearReward`]).
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

/// Whether the fitted θ is rescaled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Normalisation {
    /// θ as the dual's maximiser gives it.
    None,
    /// The maximiser rescaled once, at the end, to unit L2 length in the
    /// scaled features: the reward's direction, its size left to the caller.
    UnitL2,
}

/// How features are scaled before the fit.
#[derive(Clone, Debug, PartialEq)]
pub enum IrlFeatureScale {
    /// As they are.
    None,
    /// Each feature divided by its range `r_i > 0` (the reward's weights over
    /// the raw features are then θ_i / r_i).
    Ranges(Vec<f64>),
}

/// When the ascent stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stopping {
    /// The optimality residual, relative to `max(1, ‖f̂‖∞)` in the scaled
    /// features, below which the fit has converged.
    pub tolerance: f64,
    /// The most iterations (the fit then reports it did not converge).
    pub max_iterations: usize,
}

impl Stopping {
    /// The project's rule, fixed before any learner ran: a residual of 10⁻⁹
    /// of the expert's largest feature count, within 100,000 iterations.
    pub const DEFAULT: Stopping = Stopping { tolerance: 1e-9, max_iterations: 100_000 };
}

/// RE-IRL's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct RelativeEntropyIrlParams {
    /// Discount γ of the feature counts.
    pub discount: f64,
    /// The constraint tolerances ε (over the raw features).
    pub tolerance: Tolerance,
    /// Scaling of the features before the fit.
    pub feature_scale: IrlFeatureScale,
    /// An upper bound ρ on ‖θ‖₂ in the scaled features, or none. Where the
    /// expert's counts (relaxed by ε) lie outside the baseline's hull, the
    /// dual has no maximiser (g grows without bound along a direction) and
    /// only a bound gives the ascent a point to converge to; where the
    /// maximiser lies inside the ball, the bound changes nothing.
    pub norm_bound: Option<f64>,
    /// When the ascent stops.
    pub stopping: Stopping,
    /// Rescaling of the fitted θ.
    pub normalisation: Normalisation,
}

/// How many of the last iterates [`IrlFit::stability`] looks back over.
pub const STABILITY_WINDOW: usize = 10;

/// The result of a fit.
#[derive(Clone, Debug, PartialEq)]
pub struct IrlFit {
    /// The reward's weights over the raw features: `R(s) = Σ_i w_i f_i(s)`.
    pub weights: Vec<f64>,
    /// θ over the scaled features (after the normalisation).
    pub scaled_weights: Vec<f64>,
    /// ‖θ‖₂ of the dual's maximiser, before the normalisation.
    pub fitted_norm: f64,
    /// The expert's mean feature counts `f̂` (raw features).
    pub expert_feature_counts: Vec<f64>,
    /// The ε used, per scaled feature.
    pub tolerance: Vec<f64>,
    /// The dual objective g(θ_k) at θ_0 = 0 and after every iteration.
    pub objective: Vec<f64>,
    /// Whether the optimality residual fell below the tolerance.
    pub converged: bool,
    /// Whether the maximiser lies on the norm bound (the unbounded dual's
    /// case: see [`RelativeEntropyIrlParams::norm_bound`]).
    pub on_bound: bool,
    /// The optimality residual at the end (relative, as [`Stopping::tolerance`]).
    pub residual: f64,
    /// How settled θ is: the largest change of any normalised scaled weight
    /// between the converged θ and each of the [`STABILITY_WINDOW`] iterates
    /// that continuing the ascent past convergence gives (without
    /// convergence: the last iterates before the stop).
    pub stability: f64,
    /// Iterations taken.
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
        if !(params.stopping.tolerance.is_finite() && params.stopping.tolerance > 0.0) {
            return Err(IrlError::Parameter("the stopping tolerance must be a finite number > 0"));
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
        if let Some(rho) = params.norm_bound
            && !(rho.is_finite() && rho > 0.0)
        {
            return Err(IrlError::Parameter("the norm bound must be a finite number > 0"));
        }
        if let IrlFeatureScale::Ranges(r) = &params.feature_scale
            && r.iter().any(|x| !x.is_finite() || *x <= 0.0)
        {
            return Err(IrlError::Parameter("feature ranges must be finite and > 0"));
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
        let scale = match &self.params.feature_scale {
            IrlFeatureScale::None => vec![1.0; k],
            IrlFeatureScale::Ranges(r) if r.len() == k => r.clone(),
            IrlFeatureScale::Ranges(_) => return Err(IrlError::Parameter("one feature range per feature")),
        };
        let mut f_hat = vec![0.0; k];
        for f in expert {
            for (m, x) in f_hat.iter_mut().zip(f) {
                *m += x;
            }
        }
        for m in &mut f_hat {
            *m /= expert.len() as f64;
        }
        let eps: Vec<f64> = self.tolerance(k, horizon, expert.len())?.iter().zip(&scale).map(|(e, s)| e / s).collect();
        let problem = Dual {
            f_hat: f_hat.iter().zip(&scale).map(|(f, s)| f / s).collect(),
            baseline: baseline.iter().map(|f| f.iter().zip(&scale).map(|(x, s)| x / s).collect()).collect(),
            eps,
            norm_bound: self.params.norm_bound,
        };
        let ascent = problem.maximise(self.params.stopping);
        let theta = ascent.theta;
        if theta.iter().any(|t| !t.is_finite()) {
            return Err(IrlError::NonFinite("the fitted weights"));
        }
        let fitted_norm = dot(&theta, &theta).sqrt();
        let unit = |t: &[f64]| -> Vec<f64> {
            let n = dot(t, t).sqrt();
            t.iter().map(|x| if n > 0.0 { x / n } else { 0.0 }).collect()
        };
        let final_direction = unit(&theta);
        let stability = ascent
            .recent
            .iter()
            .map(|t| unit(t).iter().zip(&final_direction).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max))
            .fold(0.0, f64::max);
        let scaled_weights = match self.params.normalisation {
            Normalisation::None => theta,
            Normalisation::UnitL2 => final_direction,
        };
        Ok(IrlFit {
            weights: scaled_weights.iter().zip(&scale).map(|(t, s)| t / s).collect(),
            scaled_weights,
            fitted_norm,
            expert_feature_counts: f_hat,
            tolerance: problem.eps,
            iterations: ascent.objective.len() - 1,
            objective: ascent.objective,
            converged: ascent.converged,
            on_bound: self.params.norm_bound.is_some_and(|rho| fitted_norm >= rho * (1.0 - 1e-9)),
            residual: ascent.residual,
            stability,
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

/// RE-IRL's dual over scaled feature counts.
struct Dual {
    f_hat: Vec<f64>,
    baseline: Vec<Vec<f64>>,
    eps: Vec<f64>,
    norm_bound: Option<f64>,
}

/// What the ascent ends with.
struct Ascent {
    theta: Vec<f64>,
    objective: Vec<f64>,
    converged: bool,
    residual: f64,
    /// After convergence, the [`STABILITY_WINDOW`] iterates that continuing
    /// the ascent gives; without it, the last iterates before the final one.
    recent: std::collections::VecDeque<Vec<f64>>,
}

impl Dual {
    /// `h(θ)` and its gradient into `gradient`; `logits` is scratch.
    fn smooth(&self, theta: &[f64], logits: &mut [f64], gradient: &mut [f64]) -> f64 {
        let mut max = f64::NEG_INFINITY;
        for (l, f) in logits.iter_mut().zip(&self.baseline) {
            *l = dot(theta, f);
            max = max.max(*l);
        }
        let mut z = 0.0;
        for l in logits.iter_mut() {
            *l = libm::exp(*l - max);
            z += *l;
        }
        gradient.copy_from_slice(&self.f_hat);
        for (w, f) in logits.iter().zip(&self.baseline) {
            let p = w / z;
            for (g, x) in gradient.iter_mut().zip(f) {
                *g -= p * x;
            }
        }
        let log_mean_exp = max + libm::log(z) - libm::log(self.baseline.len() as f64);
        dot(theta, &self.f_hat) - log_mean_exp
    }

    fn l1(&self, theta: &[f64]) -> f64 {
        theta.iter().zip(&self.eps).map(|(t, e)| e * t.abs()).sum()
    }

    /// `prox(y + ∇h(y)/L)`: the ascent step, the soft threshold, then the
    /// projection on the ball ‖θ‖₂ ≤ ρ. The composition is the prox of the
    /// sum because the L1 norm is positively homogeneous and the ball's
    /// indicator a function of ‖θ‖₂ (Yu, "On decomposing the proximal map",
    /// NIPS 2013, Theorem 4).
    fn step(&self, y: &[f64], gradient: &[f64], lipschitz: f64, out: &mut [f64]) {
        for (((o, &y), &g), &e) in out.iter_mut().zip(y).zip(gradient).zip(&self.eps) {
            let v = y + g / lipschitz;
            let cut = e / lipschitz;
            *o = if v > cut {
                v - cut
            } else if v < -cut {
                v + cut
            } else {
                0.0
            };
        }
        if let Some(rho) = self.norm_bound {
            let norm = dot(out, out).sqrt();
            if norm > rho {
                for o in out.iter_mut() {
                    *o *= rho / norm;
                }
            }
        }
    }

    /// Accelerated proximal gradient ascent (see the module docs).
    fn maximise(&self, stopping: Stopping) -> Ascent {
        let k = self.f_hat.len();
        let scale = self.f_hat.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        let mut logits = vec![0.0; self.baseline.len()];
        let (mut grad_y, mut grad_x) = (vec![0.0; k], vec![0.0; k]);
        let mut theta = vec![0.0; k];
        let mut y = theta.clone();
        let mut candidate = vec![0.0; k];
        let mut probe = vec![0.0; k];
        let mut momentum = 1.0f64;
        let mut lipschitz = 1.0f64;
        let mut objective = vec![self.smooth(&theta, &mut logits, &mut grad_x) - self.l1(&theta)];
        let mut recent = std::collections::VecDeque::with_capacity(STABILITY_WINDOW + 1);
        let mut residual = f64::INFINITY;
        let mut converged: Option<Vec<f64>> = None;
        let mut continued = Vec::new();
        for _ in 0..stopping.max_iterations + STABILITY_WINDOW {
            if converged.is_none() && objective.len() > stopping.max_iterations {
                break;
            }
            // Backtracking on the gradient's Lipschitz condition: grow L until
            // ‖∇h(c) − ∇h(y)‖ ≤ L ‖c − y‖. Gradients, not function values,
            // decide, so the ascent is not stopped by the rounding of
            // ln Σ exp near the maximum.
            self.smooth(&y, &mut logits, &mut grad_y);
            lipschitz = (lipschitz / 2.0).max(1e-300);
            loop {
                self.step(&y, &grad_y, lipschitz, &mut candidate);
                self.smooth(&candidate, &mut logits, &mut probe);
                let (mut dg, mut dx) = (0.0, 0.0);
                for (((c, yv), gc), gy) in candidate.iter().zip(&y).zip(&probe).zip(&grad_y) {
                    dg += (gc - gy) * (gc - gy);
                    dx += (c - yv) * (c - yv);
                }
                if dg <= lipschitz * lipschitz * dx || lipschitz > 1e300 {
                    break;
                }
                lipschitz *= 2.0;
            }
            if converged.is_none() {
                if recent.len() == STABILITY_WINDOW {
                    recent.pop_front();
                }
                recent.push_back(theta.clone());
            }
            // Gradient restart (O'Donoghue & Candès): drop the momentum when
            // the step turns against the last move.
            let against: f64 = candidate.iter().zip(&y).zip(&theta).map(|((c, yv), t)| (c - yv) * (c - t)).sum();
            let next = if against < 0.0 { 1.0 } else { (1.0 + (1.0 + 4.0 * momentum * momentum).sqrt()) / 2.0 };
            let beta = if against < 0.0 { 0.0 } else { (momentum - 1.0) / next };
            for ((yv, c), t) in y.iter_mut().zip(&candidate).zip(&theta) {
                *yv = c + beta * (c - t);
            }
            momentum = next;
            theta.copy_from_slice(&candidate);
            let h = self.smooth(&theta, &mut logits, &mut grad_x);
            if converged.is_some() {
                // Past convergence: only watch how far θ still moves.
                continued.push(theta.clone());
                if continued.len() == STABILITY_WINDOW {
                    break;
                }
                continue;
            }
            objective.push(h - self.l1(&theta));
            // Optimality residual at θ, with the current step.
            self.step(&theta, &grad_x, lipschitz, &mut probe);
            residual = theta.iter().zip(&probe).map(|(t, p)| (t - p).abs()).fold(0.0, f64::max) * lipschitz / scale;
            if residual <= stopping.tolerance {
                converged = Some(theta.clone());
            }
            if dot(&theta, &theta) > 1e200 {
                // An unbounded dual: θ doubles every few steps; stop before
                // it overflows (not converged).
                break;
            }
        }
        match converged {
            Some(theta) => Ascent { theta, objective, converged: true, residual, recent: continued.into() },
            None => Ascent { theta, objective, converged: false, residual, recent },
        }
    }
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
        RelativeEntropyIrlParams {
            discount: 1.0,
            tolerance,
            feature_scale: IrlFeatureScale::None,
            norm_bound: None,
            stopping: Stopping::DEFAULT,
            normalisation,
        }
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
        assert!(fit.converged && fit.residual <= Stopping::DEFAULT.tolerance, "residual {}", fit.residual);
        assert_eq!(fit.expert_feature_counts, mean);
        assert!(
            fit.objective.iter().all(|g| *g <= fit.objective[fit.iterations] + 1e-12),
            "the last iterate is the best (up to rounding)"
        );
    }

    #[test]
    fn unit_normalisation_recovers_the_direction() {
        let theta_star = [1.2, 0.9];
        let (baseline, mean) = synthetic(&theta_star, 3000, 12);
        let irl = RelativeEntropyIrl::new(params(Tolerance::Zero, Normalisation::UnitL2)).unwrap();
        let fit = irl.fit(&[mean], &baseline, 1).unwrap();
        let norm = theta_star.iter().map(|x| x * x).sum::<f64>().sqrt();
        let cos = dot(&fit.weights, &theta_star) / norm;
        assert!(cos > 0.999, "cosine {cos}, weights {:?}", fit.weights);
        assert!((dot(&fit.weights, &fit.weights) - 1.0).abs() < 1e-12);
    }

    /// Trajectory-like counts: `horizon` steps of features with very different
    /// ranges (one in [0, 1], one in [0, 16], as Mario's position and
    /// closest-enemy variables), and the expert mean under a known θ*.
    fn long_trajectories(
        theta_star_scaled: &[f64],
        ranges: &[f64],
        horizon: usize,
        n: usize,
        seed: u64,
    ) -> (Vec<Vec<f64>>, Vec<f64>) {
        let mut rng = seeded(seed);
        let baseline: Vec<Vec<f64>> = (0..n)
            .map(|_| ranges.iter().map(|r| (0..horizon).map(|_| r * uniform01(&mut rng)).sum::<f64>()).collect())
            .collect();
        let raw_star: Vec<f64> = theta_star_scaled.iter().zip(ranges).map(|(t, r)| t / r).collect();
        let logits: Vec<f64> = baseline.iter().map(|f| dot(&raw_star, f)).collect();
        let max = logits.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let w: Vec<f64> = logits.iter().map(|l| (l - max).exp()).collect();
        let z: f64 = w.iter().sum();
        let mut mean = vec![0.0; ranges.len()];
        for (wi, f) in w.iter().zip(&baseline) {
            for (m, x) in mean.iter_mut().zip(f) {
                *m += wi / z * x;
            }
        }
        (baseline, mean)
    }

    #[test]
    fn recovers_known_weights_over_features_of_very_different_ranges() {
        let ranges = [1.0, 16.0, 2.0];
        let theta_star = [0.09, -0.06, 0.03];
        let (baseline, mean) = long_trajectories(&theta_star, &ranges, 900, 2000, 21);
        for scale in [IrlFeatureScale::None, IrlFeatureScale::Ranges(ranges.to_vec())] {
            let irl = RelativeEntropyIrl::new(RelativeEntropyIrlParams {
                feature_scale: scale.clone(),
                ..params(Tolerance::Zero, Normalisation::None)
            })
            .unwrap();
            let fit = irl.fit(std::slice::from_ref(&mean), &baseline, 900).unwrap();
            assert!(fit.converged, "{scale:?}: residual {} after {} iterations", fit.residual, fit.iterations);
            for ((w, t), r) in fit.weights.iter().zip(&theta_star).zip(&ranges) {
                assert!((w * r - t).abs() < 1e-5, "{scale:?}: {:?} vs {theta_star:?}", fit.scaled_weights);
            }
            assert!(fit.stability < 1e-4, "{scale:?}: θ still moving by {}", fit.stability);
        }
    }

    #[test]
    fn a_hard_max_baseline_converges_instead_of_oscillating() {
        // Counts in the thousands make the baseline softmax a hard max: a
        // fixed subgradient step alternates between two points here.
        let ranges = [1.0, 16.0];
        let (baseline, _) = long_trajectories(&[0.0, 0.0], &ranges, 950, 300, 22);
        let expert = vec![vec![700.0, 5000.0], vec![720.0, 5400.0]];
        let irl = RelativeEntropyIrl::new(RelativeEntropyIrlParams {
            feature_scale: IrlFeatureScale::Ranges(ranges.to_vec()),
            stopping: Stopping { max_iterations: 20_000, ..Stopping::DEFAULT },
            ..params(Tolerance::Hoeffding { delta: 0.05, feature_ranges: ranges.to_vec() }, Normalisation::UnitL2)
        })
        .unwrap();
        // Without a bound the dual has no maximiser: g keeps growing, and the
        // fit says it did not converge.
        let unbounded = irl.fit(&expert, &baseline, 950).unwrap();
        assert!(!unbounded.converged);
        assert!(unbounded.fitted_norm > 1.0);
        let irl = RelativeEntropyIrl::new(RelativeEntropyIrlParams { norm_bound: Some(1.0), ..irl.params().clone() })
            .unwrap();
        let fit = irl.fit(&expert, &baseline, 950).unwrap();
        assert!(fit.converged, "residual {} after {} iterations", fit.residual, fit.iterations);
        assert!(fit.on_bound);
        assert!(fit.stability < 1e-6, "θ still moving by {}", fit.stability);
        assert!(fit.objective.last() > fit.objective.first());
        assert!((dot(&fit.scaled_weights, &fit.scaled_weights) - 1.0).abs() < 1e-12);
        // The expert goes further in x than any baseline walk: x weighs positive.
        assert!(fit.scaled_weights[0] > 0.0, "{:?}", fit.scaled_weights);
    }

    #[test]
    fn a_tolerance_wider_than_the_gap_gives_zero_weights() {
        // Soft thresholding sets θ exactly to 0 where |∂h/∂θ| ≤ ε at θ = 0.
        let (baseline, mean) = synthetic(&[0.01, -0.01], 500, 23);
        let fit = RelativeEntropyIrl::new(params(Tolerance::PerFeature(vec![1.0, 1.0]), Normalisation::UnitL2))
            .unwrap()
            .fit(&[mean], &baseline, 1)
            .unwrap();
        assert_eq!(fit.weights, vec![0.0, 0.0]);
        assert!(fit.converged);
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
            stopping: Stopping { max_iterations: 0, ..Stopping::DEFAULT },
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
                stopping: Stopping { tolerance: 0.0, ..Stopping::DEFAULT },
                ..params(Tolerance::Zero, Normalisation::None)
            })
            .is_err()
        );
        assert!(
            RelativeEntropyIrl::new(RelativeEntropyIrlParams {
                feature_scale: IrlFeatureScale::Ranges(vec![0.0]),
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
