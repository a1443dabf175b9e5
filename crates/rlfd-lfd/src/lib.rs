//! Learning from demonstration: what a learner can take from a human's
//! demonstrations.
//!
//! What it is: [`demonstration`] holds demonstrations (trajectories of state
//! vectors, with actions where known) and reads and writes them as CSV or
//! JSON Lines with errors that name the file, line and field; [`irl`] is
//! Relative Entropy IRL (Boularias et al. 2011), which recovers a linear
//! reward from demonstrations without a model (the thesis's SIS and DIS start
//! from it); [`similarity`] is the similarity-based shaping potential of
//! Brys et al. 2015 (SBS); [`ripper`] is RIPPER as Weka's JRip implements it,
//! the rule learner that summarises demonstrations for HAT (with Weka 3.6's
//! own random stream on request, for Weka's very rules); [`hat`] holds the
//! three ways Human-Agent Transfer uses such a summary (Value Bonus and its
//! Q-initialisation form, Extra Action, Probabilistic Policy Reuse).
//!
//! What it is not: no domain, no experiment, no file other than the
//! demonstration files a caller asks for. Shaping itself (how a potential
//! becomes a reward) lives in `rlfd-rl`; this crate only builds potentials
//! and rewards from demonstrations.

pub mod demonstration;
pub mod hat;
pub mod irl;
pub mod ripper;
pub mod similarity;
