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
//! What it is not: it knows no domain of the thesis and no experiment, does no
//! IO, reads no clock and owns no global random generator. Every random draw
//! comes from a generator the caller passes in ([`random::SimRng`]).
//! Learners and simulators are infallible once their parameters are checked;
//! parameter structs have a `check` returning [`ParamError`].

pub mod agent;
pub mod environment;
pub mod features;
pub mod linear;
pub mod mdp;
pub mod params;
pub mod policy;
pub mod q_lambda;
pub mod random;
pub mod sarsa;
pub mod shaping;
pub mod tabular;
pub mod td_lambda;
pub mod traces;

pub use agent::{Agent, EpisodeOutcome};
pub use environment::{Environment, Step};
pub use linear::LinearActionValues;
pub use params::{ParamError, TdParams};
pub use q_lambda::WatkinsQLambda;
pub use sarsa::SarsaLambda;
pub use tabular::TabularQ;
pub use traces::{SparseTraces, TraceKind};

/// The learner interface [`Agent`] drives: linear TD control over active features.
pub use agent::TdControl;
