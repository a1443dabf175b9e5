//! Chapter 6's method, written once for both domains: the five agents
//! ([`agents`]: SARSA(λ) or Q(λ) alone, SIS, DIS, HAT, SBS over any
//! environment and feature map), what they learn from the demonstrations
//! ([`inputs`]: RE-IRL, RIPPER, the similarity potential) and how their
//! trials run through the harness ([`trials`]: conditions, stored trials,
//! a reading's levels). The Maze and Mario halves ([`crate::maze`],
//! [`crate::mario`]) supply their domain, parameters and demonstrations.

pub mod agents;
pub mod inputs;
pub mod trials;

pub use agents::{
    Agent, Baseline, Domain, Ends, HatBonus, PersistentBonus, ShapingParams, Trial, TrialRecord, run_trial,
};
pub use inputs::{AgentInputs, InputError, IrlSettings};
