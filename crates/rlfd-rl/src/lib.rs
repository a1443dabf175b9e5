//! Reinforcement-learning building blocks for the reproduction: episodic
//! environments, function approximation, temporal-difference control and
//! potential-based reward shaping.
//!
//! What it is: the engine the chapter crates run. An [`Environment`] is an
//! episodic task with discrete actions and a real-valued state vector; a
//! [`features::FeatureMap`] ([`features::TileCoder`], [`features::RbfFeatures`])
//! turns a state into sparse active features; [`SarsaLambda`] and
//! [`WatkinsQLambda`] learn linear action values over them with sparse
//! eligibility traces; [`shaping`] adds potential-based shaping rewards (static
//! state potentials after Ng et al. 1999, state-action look-ahead advice after
//! Wiewiora et al. 2003, and dynamic potentials learned by a secondary SARSA
//! after Harutyunyan et al. 2015); [`Agent`] drives one episode at a time;
//! [`TabularQ`] is plain tabular Q-learning; [`mdp`] holds finite MDPs and
//! value iteration, used to check the shaping theorems (the thesis's claim
//! C6.11).
//!
//! A SARSA(λ) agent with a tile coder learning a 20-cell corridor (start at
//! 0, goal at 19, −1 per step):
//!
//! ```
//! use rand::Rng;
//! use rlfd_rl::features::{FeatureMap, TileCoder, TileIndexing};
//! use rlfd_rl::random::seeded;
//! use rlfd_rl::shaping::NoShaping;
//! use rlfd_rl::traces::TraceKind;
//! use rlfd_rl::{Agent, Environment, SarsaLambda, Step, TdParams};
//!
//! struct Corridor { pos: usize, state: [f64; 1] }
//!
//! impl Environment for Corridor {
//!     fn num_actions(&self) -> usize { 2 }
//!     fn state_dim(&self) -> usize { 1 }
//!     fn reset<R: Rng + ?Sized>(&mut self, _rng: &mut R) { self.pos = 0; self.state = [0.0]; }
//!     fn state(&self) -> &[f64] { &self.state }
//!     fn step<R: Rng + ?Sized>(&mut self, action: usize, _rng: &mut R) -> Step {
//!         self.pos = if action == 1 { self.pos + 1 } else { self.pos.saturating_sub(1) };
//!         self.state = [self.pos as f64];
//!         Step { reward: -1.0, terminal: self.pos == 19 }
//!     }
//! }
//!
//! let coder = TileCoder::new(1, &[1.0], TileIndexing::Dense { lower: vec![0.0], upper: vec![20.0] })?;
//! let params = TdParams { alpha: 0.5, gamma: 1.0, lambda: 0.5, epsilon: 0.05 }.check()?;
//! let learner = SarsaLambda::new(coder.num_features(), 2, params, TraceKind::Replacing);
//! let mut agent = Agent::new(coder, learner, NoShaping);
//! let (mut env, mut rng) = (Corridor { pos: 0, state: [0.0] }, seeded(5));
//! let first = agent.run_episode(&mut env, &mut rng, 10_000);
//! let mut last = first;
//! for _ in 0..200 {
//!     last = agent.run_episode(&mut env, &mut rng, 10_000);
//! }
//! assert!(first.steps > 40 && last.steps <= 22, "{} then {} steps", first.steps, last.steps);
//! # Ok::<(), rlfd_rl::ParamError>(())
//! ```
//!
//! What it is not: it knows no domain of the thesis and no experiment, does no
//! IO, reads no clock and owns no global random generator. Every random draw
//! comes from a generator the caller passes in ([`random::SimRng`]).
//! Learners and simulators are infallible once their parameters are checked;
//! parameter structs have a `check` returning [`ParamError`].

pub mod agent;
/// The episodic task interface (from `rlfd-env`, which every domain depends on).
pub use rlfd_env::environment;
/// The seeded generator and its draws (from `rlfd-env`).
pub use rlfd_env::random;
pub mod features;
pub mod linear;
pub mod mdp;
pub mod params;
pub mod policy;
pub mod q_lambda;
pub mod sarsa;
pub mod shaping;
pub mod tabular;
pub mod td_lambda;
pub mod traces;

pub use agent::{Agent, DIVERGENCE_BOUND, EpisodeOutcome};
pub use environment::{Environment, Step};
pub use linear::LinearActionValues;
pub use params::{ParamError, TdParams};
pub use q_lambda::WatkinsQLambda;
pub use sarsa::SarsaLambda;
pub use tabular::TabularQ;
pub use traces::{SparseTraces, TraceKind};

/// The learner interface [`Agent`] drives: linear TD control over active features.
pub use agent::TdControl;
