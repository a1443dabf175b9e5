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
//! A RIPPER fit as the thesis ran it (Weka 3.6 JRip's options and random
//! stream), summarising ten demonstrated (x, action) pairs as a decision list:
//!
//! ```
//! use rlfd_lfd::ripper::{Attribute, Dataset, Ripper, RipperParams};
//!
//! // Move right (1) left of x = 3, left (0) from there on, three times over.
//! let rows: Vec<Vec<f64>> = (0..30).map(|i| vec![f64::from(i % 10)]).collect();
//! let labels = rows.iter().map(|x| usize::from(x[0] < 3.0)).collect();
//! let data = Dataset::new(vec![Attribute::numeric("x")], rows, "move", vec!["left".into(), "right".into()], labels)?;
//! let rules = Ripper::fit(&RipperParams::weka_3_6(), &data)?;
//! assert_eq!(rules.to_string(), "if (x <= 2.00) -> move = right\nelse -> move = left");
//! assert_eq!(rules.predict(&[2.0]), 1);
//! # Ok::<(), rlfd_lfd::ripper::RipperError>(())
//! ```
//!
//! What it is not: no domain, no experiment, no file other than the
//! demonstration files a caller asks for. Shaping itself (how a potential
//! becomes a reward) lives in `rlfd-rl`; this crate only builds potentials
//! and rewards from demonstrations.

/// Demonstrations in memory and in files (from `rlfd-env`, the format every domain shares).
pub use rlfd_env::demonstration;
pub mod hat;
pub mod irl;
pub mod ripper;
pub mod similarity;
