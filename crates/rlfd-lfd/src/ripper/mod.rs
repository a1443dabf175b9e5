//! RIPPER (Cohen, "Fast Effective Rule Induction", ICML 1995) as Weka's JRip
//! implements it: the propositional rule learner the thesis uses to summarise
//! a human demonstration as a decision list (chapter 5's Keepaway rules,
//! chapter 6's HAT baseline).
//!
//! ```
//! use rlfd_lfd::ripper::{Attribute, Dataset, Ripper, RipperParams};
//!
//! let rows: Vec<Vec<f64>> = (0..30).map(|i| vec![f64::from(i % 10)]).collect();
//! let labels = rows.iter().map(|x| usize::from(x[0] >= 7.0)).collect();
//! let data = Dataset::new(
//!     vec![Attribute::numeric("state_0")],
//!     rows,
//!     "Action",
//!     vec!["0".into(), "1".into()],
//!     labels,
//! )?;
//! let list = Ripper::fit(&RipperParams::weka_defaults(), &data)?;
//! assert_eq!(list.to_string(), "if (state_0 >= 7.00) -> Action = 1\nelse -> Action = 0");
//! // Weka 3.6's own random stream: on separable data, the same rule
//! let weka = Ripper::fit(&RipperParams::weka_3_6(), &data)?;
//! assert_eq!(weka.to_string(), list.to_string());
//! # Ok::<(), rlfd_lfd::ripper::RipperError>(())
//! ```
//!
//! # What it is
//!
//! - [`Dataset`]: checked numeric/nominal instances with a nominal class
//!   (NaN = missing) and optional weights.
//! - [`RipperParams`]: JRip's options, [`RipperParams::weka_defaults`] being
//!   `-F 3 -N 2.0 -O 2 -S 1` with the error check and pruning on, and the
//!   random generator, [`RipperRandom`]: `ChaCha8` (what `weka_defaults`
//!   uses) or `Weka`, Weka 3.6's own `java.util.Random` stream
//!   ([`RipperParams::weka_3_6`]).
//! - [`Ripper::fit`]: classes ordered by ascending frequency, rules learned
//!   for each but the most frequent (the default rule, last); each rule grown
//!   by FOIL gain and pruned by IREP, the rule set stopped by MDL (64-bit
//!   surplus), optimised twice (replacement and revision, chosen by relative
//!   description length), reduced by DL, and cleaned of redundant numeric
//!   tests. The algorithm is spelled out in `learner.rs`, `grow.rs`,
//!   `stats.rs` and [`mdl`].
//! - [`DecisionList`]: the ordered rules, [`DecisionList::predict`], the
//!   thesis's `if … elseif … else` text (`Display`) and Weka's listing
//!   ([`DecisionList::to_weka_string`]).
//! - [`stratified_cross_validation`]: Weka's stratified k-fold procedure.
//! - [`JavaRandom`]: a clone of `java.util.Random`, with
//!   [`JavaRandom::for_instances`], JRip's seeding from the seed and the text
//!   of one instance ([`Dataset::weka_instance_text`]).
//!
//! # Randomness: ChaCha8 or Weka's
//!
//! A fit draws from one generator, at the points and in the order JRip
//! draws: a generator forked from it (as JRip seeds its `ClassOrder` filter
//! from `m_Random.nextInt()`) shuffles the classes, then the main one
//! shuffles each class bag at every grow/prune stratification.
//! [`RipperParams::random`] says which:
//!
//! - [`RipperRandom::Weka`] ([`RipperParams::weka_3_6`]): `java.util.Random`
//!   seeded exactly as Weka 3.6.14's JRip seeds itself (`-S seed`: the seed
//!   plus the Java hash of the text of an instance drawn with it), and
//!   cross-validation folds drawn from `new Random(seed)` as
//!   `Evaluation.crossValidateModel` draws them. The rules, coverage counts,
//!   training accuracy and cross-validation counts are Weka's (checked in
//!   `tests/ripper_weka.rs` against Weka's printed output, and below).
//!   The text is that of the instance with the class written last, as Weka
//!   holds an ARFF file whose last attribute is the class.
//! - [`RipperRandom::ChaCha8`] ([`RipperParams::weka_defaults`]): one
//!   `rand_chacha::ChaCha8Rng` seeded with [`RipperParams::seed`] (the fork
//!   seeded with its first `u64`). Reproducible for a seed, but on noisy
//!   data the rules need not equal Weka's for the same seed; on separable
//!   data they do not depend on the split. The chapters' stored rules and
//!   cross-validation results were made this way and stay as they are.
//!
//! # What it is not
//!
//! Weka with ChaCha8: [`RipperParams::weka_defaults`] runs Weka's algorithm
//! on another random stream, so its rules are not the ones Weka prints (use
//! [`RipperParams::weka_3_6`] for those). Nor a reader of ARFF or CSV files:
//! a caller builds the [`Dataset`]. Everything else is deterministic: no
//! hash-map iteration, no clock, no global generator.
//!
//! Classes of equal frequency are ordered as Weka orders them: the class
//! indices are shuffled (Fisher–Yates), then sorted by weight with a copy of
//! Weka's `Utils.sort`, an unstable quicksort, so the seed decides ties.
//!
//! # Checked against Weka
//!
//! The tests drive the learner with [`RipperRandom::Weka`] and compare with
//! Weka 3.6.14 (whose JRip is the reference commit's without `cleanUp`):
//! the rule lists, coverage counts, the effective seeds JRip derives, and
//! 10-fold cross-validation counts are identical on the data sets of
//! `weka_check.rs` and `tests/ripper_weka.rs`, the latter run through the
//! Weka command line. In a bulk run over 6,000 generated data sets (numeric and
//! nominal attributes, missing values, three noisy classes, 30 to 505
//! instances) 5,999 listings were identical, `cleanUp` included; the one
//! difference is an exact tie of two gains (4·log₂ 1.8 = 2·log₂ 3.24) that
//! Java's `Math.log` rounds to equal values and the portable fdlibm `log`
//! used here ([`mdl::log2`], Java's `StrictMath.log`) does not. Mathematically
//! tied gains can thus be ordered differently from Weka's in rare cases.
//!
//! # Sources and deviations
//!
//! Followed: bnjmn/weka, weka/src/main/java/weka/classifiers/rules/JRip.java
//! at commit 0b4f0571 and RuleStats.java at commit 19e3b5a2, with
//! `weka.filters.supervised.attribute.ClassOrder` (class order),
//! `weka.core.Instances` (`randomize`, `stratify`, `trainCV`, `testCV`,
//! `numDistinctValues`) and `weka.core.Utils` (`log2`, `sort`, the 10⁻⁶
//! tolerant comparisons). Tie-breaking is JRip's throughout: the first
//! attribute of strictly largest gain; the suffix test on an equal
//! prefix/suffix gain; the shortest prefix of strictly largest pruning
//! worth; old rule, then revision, then replacement on equal relative DL;
//! equally frequent classes as above. JRip quirks kept on purpose: the empty
//! rule's pruning worth is (P+1)/(N+2) even under the whole-data metric;
//! potential judges each rule as if it were last; when the optimisation pass
//! runs out of positives early, the next old rule is skipped
//! (`position + 1`; such a rule covers no positive, and `reduceDL` would
//! delete it anyway in every case the bulk comparison met).
//!
//! Deviations, each where Weka's behaviour is a Java artefact:
//! - 0 · log₂ 0 is 0 in the subset DL (Java: NaN);
//! - a description length that would still be NaN (an expected error rate
//!   above 1) counts as +∞ bits, so that candidate is rejected, where Weka
//!   throws "Should never happen";
//! - a rule (or default) that covered no training weight predicts its own
//!   class in [`DecisionList::predict_by_distribution`], where Weka throws
//!   when normalising its distribution;
//! - weighted sums over equal attribute values may add in another order than
//!   Weka's (its sort order among ties), which can move the last bits when
//!   weights are not integers;
//! - [`DecisionList::predict`] returns the first covering rule's class (the
//!   list as printed); Weka's `classifyInstance` returns the covering rule's
//!   majority training class, available as
//!   [`DecisionList::predict_by_distribution`] and used by the
//!   cross-validation. The two differ only for rules whose training coverage
//!   is not mostly their own class.

mod cv;
mod dataset;
mod error;
mod grow;
mod java_random;
mod learner;
pub mod mdl;
mod params;
mod rule;
mod stats;
mod table;
#[cfg(test)]
mod weka_check;
mod weka_seed;

pub use cv::{CrossValidation, FoldOutcome, stratified_cross_validation};
pub use dataset::{Attribute, AttributeKind, Dataset};
pub use error::RipperError;
pub use java_random::JavaRandom;
pub use params::{ErrorRateCheck, Pruning, RipperParams, RipperRandom};
pub use rule::{Condition, Coverage, DecisionList, Operator, Rule};

/// The RIPPER learner (Weka's JRip). See the module docs.
#[derive(Debug, Clone, Copy)]
pub struct Ripper;

impl Ripper {
    /// Learns a decision list from `data`, drawing from the generator
    /// `params.random` names (see the module docs).
    ///
    /// Fails only on invalid parameters ([`RipperParams::check`]) or when
    /// `data` has fewer instances than `params.folds` (JRip's minimum).
    pub fn fit(params: &RipperParams, data: &Dataset) -> Result<DecisionList, RipperError> {
        learner::fit(params, data)
    }
}
