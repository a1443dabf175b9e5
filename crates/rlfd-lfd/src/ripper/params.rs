//! RIPPER's parameters, [`RipperParams`], with Weka JRip's defaults as the
//! named constructors [`RipperParams::weka_defaults`] (drawing from ChaCha8)
//! and [`RipperParams::weka_3_6`] (drawing from `java.util.Random` as Weka
//! 3.6 does), and a single [`RipperParams::check`] that every fit runs first.
//!
//! Each field names the JRip option it mirrors (JRip.java at Weka commit
//! 0b4f0571: `-F`, `-N`, `-O`, `-S`, `-E`, `-P`); [`RipperRandom`] is ours,
//! the choice of generator. There is no `Default`: a caller says which
//! parameter set it means.

use serde::{Deserialize, Serialize};

use super::RipperError;

/// Whether a rule whose error rate on the data it covers reaches 1/2 stops
/// the rule set (JRip's `checkErr`, option `-E` turns it off).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ErrorRateCheck {
    /// Stop (and, in the final DL reduction, delete rules) at error ≥ 0.5.
    /// Weka's default.
    StopAtHalf,
    /// Rely on the description length alone.
    Ignore,
}

/// Whether rules are grown on part of the data and pruned on the rest
/// (JRip's `usePruning`, option `-P` turns it off).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Pruning {
    /// Incremental reduced-error pruning on one fold out of `folds`, and
    /// the optimisation stage. Weka's default.
    Irep,
    /// Grow on all the data, never prune, skip the optimisation stage.
    Off,
}

/// The random generator a fit (and a cross-validation) draws from. Both
/// make the same draws at the same points, in Weka's order; they differ in
/// the stream, so on noisy data they give different grow/prune splits and
/// may give different rules.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum RipperRandom {
    /// One `rand_chacha::ChaCha8Rng` seeded with [`RipperParams::seed`]
    /// (`seed_from_u64`); the class order draws from a generator seeded with
    /// its first `u64`. Reproducible for a seed, independent of the data's
    /// text, but not Weka's stream: the rules need not be Weka's. What
    /// [`RipperParams::weka_defaults`] uses, and what the chapters' stored
    /// results were made with.
    ChaCha8,
    /// A clone of `java.util.Random` ([`JavaRandom`](super::JavaRandom))
    /// seeded exactly as Weka 3.6.14's JRip seeds itself with `-S seed`
    /// ([`JavaRandom::for_instances`](super::JavaRandom::for_instances):
    /// the seed plus the hash of the text of one instance drawn with it,
    /// the class written last), the seed read as a Java `long`. RIPPER then
    /// makes Weka's draws from Weka's stream and prints Weka's rules (see the
    /// module docs for the one known, rare difference). Cross-validation
    /// draws its folds from `new Random(seed)` as
    /// `Evaluation.crossValidateModel` does.
    Weka,
}

/// Parameters of [`Ripper::fit`](super::Ripper::fit).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RipperParams {
    /// Number of folds F the data are split into before each rule is grown:
    /// F − 1 folds grow the rule, one fold prunes it (`-F`, default 3).
    /// Also the minimum number of training instances. At least 2.
    pub folds: usize,
    /// minNo: the minimum total weight of positive instances a new condition
    /// must cover, or growing stops (`-N`, default 2.0). Finite, ≥ 0.
    pub min_no: f64,
    /// Number of runs of the optimisation stage (`-O`, default 2).
    pub optimizations: usize,
    /// Seed of the one random generator of a fit: it orders classes of equal
    /// frequency and shuffles every grow/prune split (`-S`, default 1). With
    /// [`RipperRandom::ChaCha8`] equal seeds give equal rules here, not
    /// Weka's; with [`RipperRandom::Weka`] the seed is Weka's `-S` (as a
    /// Java `long`: values above `i64::MAX` wrap to negative ones).
    pub seed: u64,
    /// The error-rate stopping test (`-E`, default [`ErrorRateCheck::StopAtHalf`]).
    pub error_rate_check: ErrorRateCheck,
    /// Pruning and optimisation (`-P`, default [`Pruning::Irep`]).
    pub pruning: Pruning,
    /// The generator `seed` seeds (not a JRip option): see [`RipperRandom`].
    pub random: RipperRandom,
}

impl RipperParams {
    /// Weka JRip's defaults, as used by the thesis (chapters 5 and 6):
    /// `-F 3 -N 2.0 -O 2 -S 1`, error check and pruning on, drawing from
    /// [`RipperRandom::ChaCha8`]. The chapters' stored rules come from these;
    /// [`Self::weka_3_6`] gives the rules Weka itself prints.
    pub fn weka_defaults() -> Self {
        Self {
            folds: 3,
            min_no: 2.0,
            optimizations: 2,
            seed: 1,
            error_rate_check: ErrorRateCheck::StopAtHalf,
            pruning: Pruning::Irep,
            random: RipperRandom::ChaCha8,
        }
    }

    /// Weka 3.6.14's JRip as the thesis ran it: the options of
    /// [`Self::weka_defaults`] drawing from [`RipperRandom::Weka`], so that
    /// the rules are those of `weka.classifiers.rules.JRip -F 3 -N 2.0 -O 2
    /// -S 1`, and [`stratified_cross_validation`](super::stratified_cross_validation)
    /// with `folds = 10, seed = 1` is Weka's `-x 10 -s 1`.
    pub fn weka_3_6() -> Self {
        Self::weka_defaults().with_random(RipperRandom::Weka)
    }

    /// The same parameters with another seed.
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The same parameters drawing from another generator.
    pub fn with_random(mut self, random: RipperRandom) -> Self {
        self.random = random;
        self
    }

    /// Refuses values outside each field's domain (see the fields' docs).
    pub fn check(&self) -> Result<(), RipperError> {
        if self.folds < 2 {
            return Err(RipperError::InvalidParameter {
                name: "folds",
                reason: format!("must be at least 2, got {}", self.folds),
            });
        }
        if !(self.min_no.is_finite() && self.min_no >= 0.0) {
            return Err(RipperError::InvalidParameter {
                name: "min_no",
                reason: format!("must be finite and non-negative, got {}", self.min_no),
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weka_defaults_are_jrips() {
        let p = RipperParams::weka_defaults();
        assert_eq!(p.folds, 3);
        assert_eq!(p.min_no, 2.0);
        assert_eq!(p.optimizations, 2);
        assert_eq!(p.seed, 1);
        assert_eq!(p.error_rate_check, ErrorRateCheck::StopAtHalf);
        assert_eq!(p.pruning, Pruning::Irep);
        assert_eq!(p.random, RipperRandom::ChaCha8);
        assert_eq!(p.check(), Ok(()));
    }

    #[test]
    fn weka_3_6_is_weka_defaults_with_javas_generator() {
        let p = RipperParams::weka_3_6();
        assert_eq!(p.random, RipperRandom::Weka);
        assert_eq!(p.with_random(RipperRandom::ChaCha8), RipperParams::weka_defaults());
    }

    #[test]
    fn check_refuses_out_of_domain_values() {
        let mut p = RipperParams::weka_defaults();
        p.folds = 1;
        assert!(matches!(p.check(), Err(RipperError::InvalidParameter { name: "folds", .. })));
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            let mut p = RipperParams::weka_defaults();
            p.min_no = bad;
            assert!(matches!(p.check(), Err(RipperError::InvalidParameter { name: "min_no", .. })));
        }
    }
}
