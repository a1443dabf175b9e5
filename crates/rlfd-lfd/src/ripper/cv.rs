//! Stratified k-fold cross-validation of RIPPER, as Weka's
//! `Evaluation.crossValidateModel` runs it (the thesis reports 87 % for its
//! chapter-5 rules this way).
//!
//! Weka's procedure, followed step by step, drawing from the generator that
//! [`RipperParams::random`] names, seeded with the cross-validation's own
//! seed: [`RipperRandom::Weka`] is Weka's `new Random(seed)` (so `folds = 10,
//! seed = 1` is the command line's `-x 10 -s 1`), [`RipperRandom::ChaCha8`] a
//! `ChaCha8Rng` seeded with `seed_from_u64(seed)`:
//! 1. shuffle the instances (`Instances.randomize`);
//! 2. `Instances.stratify(k)`: group them by class, the classes in order of
//!    first appearance, then deal: take instances 0, k, 2k, …, then 1, k+1,
//!    …, and so on;
//! 3. fold i tests on the i-th contiguous block (`testCV`: the first n mod k
//!    blocks hold one more instance) and trains on the rest, shuffled again
//!    (`trainCV(k, i, random)`), with [`Ripper::fit`](super::Ripper::fit)
//!    and `params` (each fold's fit seeds its own generator from
//!    `params.seed`, with Weka as JRip does from the training part's text);
//! 4. count the weight classified correctly, with Weka's rule: the covering
//!    rule's majority training class
//!    ([`DecisionList::predict_by_distribution`]).
//!
//! What it is not: a general evaluation harness (no confusion matrix, no
//! kappa); the same RIPPER parameters, seed included, fit every fold.
//!
//! Source: `weka.classifiers.Evaluation.crossValidateModel` and
//! `weka.core.Instances` (`randomize`, `stratify`, `stratStep`, `trainCV`,
//! `testCV`) in bnjmn/weka, checked against Weka 3.6.14 (the tests in
//! `weka_check.rs` reproduce its per-fold counts, `tests/ripper_weka.rs` its
//! printed totals).

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::learner::fit_with;
use super::table::{JripRandom, randomize};
use super::{Dataset, DecisionList, JavaRandom, RipperError, RipperParams, RipperRandom};

/// One fold's outcome.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FoldOutcome {
    /// Weight of the fold's test instances classified correctly.
    pub correct: f64,
    /// Weight of the fold's test instances.
    pub total: f64,
    /// Rules in the fold's decision list, the default rule not counted.
    pub rules: usize,
}

/// The result of [`stratified_cross_validation`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CrossValidation {
    /// `correct / total`, a fraction (Weka prints it as a percentage).
    pub accuracy: f64,
    /// Weight classified correctly over all folds (a count for unit weights).
    pub correct: f64,
    /// Total test weight (the dataset's total weight).
    pub total: f64,
    /// Per fold, in fold order.
    pub per_fold: Vec<FoldOutcome>,
}

/// Stratified `folds`-fold cross-validation of [`Ripper::fit`](super::Ripper::fit) with
/// `params` on `data`; `seed` drives the fold assignment, drawn from the
/// generator [`RipperParams::random`] names (see the module docs). Needs
/// 2 ≤ `folds` ≤ `data.len()`, and every training part must be large enough
/// for `params` (at least `params.folds` instances).
///
/// With [`RipperParams::weka_3_6`], `folds = 10` and `seed = 1` this is the
/// 10-fold result Weka 3.6.14 prints for `JRip -t data.arff -x 10 -s 1`.
pub fn stratified_cross_validation(
    params: &RipperParams,
    data: &Dataset,
    folds: usize,
    seed: u64,
) -> Result<CrossValidation, RipperError> {
    // --- seeding: one generator for the shuffle and every training-set
    // shuffle, drawn in Weka's order; each fold's fit seeds its own from
    // `params.seed`
    match params.random {
        RipperRandom::ChaCha8 => cross_validate_with(params, data, folds, ChaCha8Rng::seed_from_u64(seed), |_, _| {
            ChaCha8Rng::seed_from_u64(params.seed)
        }),
        // Evaluation: new Random(seed); each fold's JRip seeds itself from
        // its training part
        RipperRandom::Weka => cross_validate_with(params, data, folds, JavaRandom::new(seed as i64), |_, train| {
            JavaRandom::for_instances(train, params.seed as i64)
        }),
    }
}

/// [`stratified_cross_validation`] drawing the folds from `rng` and fitting
/// fold `i` (training part `train`) with the generator `fit_rng(i, train)`.
pub(crate) fn cross_validate_with<R: JripRandom, F: JripRandom>(
    params: &RipperParams,
    data: &Dataset,
    folds: usize,
    mut rng: R,
    mut fit_rng: impl FnMut(usize, &Dataset) -> F,
) -> Result<CrossValidation, RipperError> {
    params.check()?;
    let n = data.len();
    if folds < 2 || folds > n {
        return Err(RipperError::CrossValidationFolds { folds, instances: n });
    }
    // fold 0 holds the largest test block, so the smallest training part
    let smallest_training = n - test_block(n, folds, 0).len();
    if smallest_training < params.folds {
        return Err(RipperError::TrainingPartTooSmall {
            folds,
            instances: n,
            training: smallest_training,
            required: params.folds,
        });
    }
    let mut order: Vec<usize> = (0..n).collect();
    randomize(&mut order, &mut rng);
    let order = stratify_instances(&order, data.labels(), folds);

    let mut per_fold = Vec::with_capacity(folds);
    let (mut correct, mut total) = (0.0, 0.0);
    for fold in 0..folds {
        let test = test_block(n, folds, fold);
        let mut train: Vec<usize> = order[..test.start].iter().chain(&order[test.end..]).copied().collect();
        randomize(&mut train, &mut rng);
        let train = data.select(&train);
        let model = fit_with(params, &train, fit_rng(fold, &train))?;
        let outcome = evaluate(&model, data, &order[test]);
        correct += outcome.correct;
        total += outcome.total;
        per_fold.push(outcome);
    }
    Ok(CrossValidation { accuracy: correct / total, correct, total, per_fold })
}

fn evaluate(model: &DecisionList, data: &Dataset, test: &[usize]) -> FoldOutcome {
    let (mut correct, mut total) = (0.0, 0.0);
    for &i in test {
        let w = data.weights()[i];
        total += w;
        if model.predict_by_distribution(data.row(i)) == data.labels()[i] {
            correct += w;
        }
    }
    FoldOutcome { correct, total, rules: model.rules.len() }
}

/// `Instances.stratify`: pull every instance of the class of the instance
/// before position `index` forward (swapping), skip one, repeat; then deal
/// (`stratStep`).
fn stratify_instances(order: &[usize], labels: &[usize], folds: usize) -> Vec<usize> {
    let mut grouped = order.to_vec();
    let n = grouped.len();
    let mut index = 1;
    while index < n {
        let class = labels[grouped[index - 1]];
        // Java fixes the scan's start once; `index` then advances inside it
        let start = index;
        for j in start..n {
            if labels[grouped[j]] == class {
                grouped.swap(index, j);
                index += 1;
            }
        }
        index += 1;
    }
    let mut dealt = Vec::with_capacity(n);
    for start in 0..folds.min(n) {
        dealt.extend(grouped.iter().skip(start).step_by(folds).copied());
    }
    dealt
}

/// `Instances.testCV(folds, fold)`: the fold's block of the dealt order.
fn test_block(n: usize, folds: usize, fold: usize) -> std::ops::Range<usize> {
    let base = n / folds;
    let extra = n % folds;
    let (size, offset) = if fold < extra { (base + 1, fold) } else { (base, extra) };
    let first = fold * base + offset;
    first..first + size
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_blocks_tile_the_data() {
        // 10 instances, 3 folds: blocks of 4, 3, 3
        assert_eq!(test_block(10, 3, 0), 0..4);
        assert_eq!(test_block(10, 3, 1), 4..7);
        assert_eq!(test_block(10, 3, 2), 7..10);
    }

    #[test]
    fn stratify_groups_by_first_appearance_then_deals() {
        // classes in order of appearance: 1, 0
        let labels = [1, 0, 1, 0, 1, 1];
        let order = [0, 1, 2, 3, 4, 5];
        // grouping (Weka's swap loop) gives 0 2 4 5 | 3 1 ... as computed by
        // hand: index 1: swap in 2 (→ 0 2 1 3 4 5), 4 (→ 0 2 4 3 1 5),
        // 5 (→ 0 2 4 5 1 3); then the zeros 1 3 stay
        let dealt = stratify_instances(&order, &labels, 2);
        // deal with step 2 from the grouped 0 2 4 5 1 3
        assert_eq!(dealt, vec![0, 4, 1, 2, 5, 3]);
        // each half holds the classes in proportion
        let first: Vec<usize> = dealt[..3].iter().map(|&i| labels[i]).collect();
        assert_eq!(first.iter().filter(|&&c| c == 1).count(), 2);
    }
}
