//! The learner's working copy of a dataset and the random reorderings JRip
//! applies to it: class order by ascending frequency (Weka's `ClassOrder`
//! filter), shuffling (`Instances.randomize`) and the class-stratified
//! grow/prune split (`RuleStats.stratify` and `RuleStats.partition`).
//!
//! What it is: a column-major table whose class labels are renumbered so that
//! class 0 is the least frequent; instance sets are `Vec<usize>` of row
//! indices whose order is kept exactly where Weka's order matters (the
//! shuffles depend on it).
//!
//! What it is not: a generator. The learner draws through [`JripRandom`],
//! which `java.util.Random`'s clone (`JavaRandom`, Weka's stream) and a
//! `ChaCha8Rng` implement with the same draws in the same places
//! (`random_range(0..j + 1)` where Java calls `nextInt(j + 1)`); which one
//! is the caller's choice (`RipperRandom`).
//!
//! Sources: JRip.java (Weka commit 0b4f0571), RuleStats.java (19e3b5a2),
//! weka/filters/supervised/attribute/ClassOrder.java, weka/core/Instances.java
//! and `Utils.sort(double[])` in weka/core/Utils.java.

use rand::{Rng as _, RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::{AttributeKind, Condition, Dataset};

/// The random draws JRip makes.
pub(crate) trait JripRandom: Sized {
    /// A uniform index in `0..bound` (Java's `nextInt(bound)`), `bound > 0`.
    fn below(&mut self, bound: usize) -> usize;
    /// A new generator seeded from this one: JRip seeds the `ClassOrder`
    /// filter's own `Random` with `m_Random.nextInt()`.
    fn fork(&mut self) -> Self;
}

impl JripRandom for ChaCha8Rng {
    fn below(&mut self, bound: usize) -> usize {
        self.random_range(0..bound)
    }

    fn fork(&mut self) -> Self {
        ChaCha8Rng::seed_from_u64(self.next_u64())
    }
}

/// Numeric or nominal, without the names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    Numeric,
    Nominal { values: usize },
}

/// A rule while it is learned: conditions and the class it predicts, in
/// learning order (class 0 = least frequent).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LearnedRule {
    pub conditions: Vec<Condition>,
    pub class: usize,
}

impl LearnedRule {
    pub fn empty(class: usize) -> Self {
        Self { conditions: Vec::new(), class }
    }
}

/// The dataset seen by the learner: see the module docs.
#[derive(Debug, Clone)]
pub(crate) struct Table {
    pub columns: Vec<Vec<f64>>,
    pub kinds: Vec<Kind>,
    /// Class in learning order.
    pub labels: Vec<usize>,
    pub weights: Vec<f64>,
    pub n_classes: usize,
    /// Per numeric attribute, the instances with a value, sorted by value;
    /// empty for nominal attributes. Growing filters these instead of sorting.
    pub sorted: Vec<Vec<usize>>,
}

impl Table {
    pub fn new(data: &Dataset, order: &ClassOrder) -> Self {
        let n = data.len();
        let kinds: Vec<Kind> = data
            .attributes()
            .iter()
            .map(|a| match &a.kind {
                AttributeKind::Numeric => Kind::Numeric,
                AttributeKind::Nominal { values } => Kind::Nominal { values: values.len() },
            })
            .collect();
        let columns: Vec<Vec<f64>> = (0..kinds.len()).map(|a| (0..n).map(|i| data.row(i)[a]).collect()).collect();
        let sorted = columns
            .iter()
            .zip(&kinds)
            .map(|(column, kind)| match kind {
                Kind::Numeric => {
                    let mut present: Vec<usize> = (0..n).filter(|&i| !column[i].is_nan()).collect();
                    present.sort_by(|&i, &j| column[i].total_cmp(&column[j]));
                    present
                }
                Kind::Nominal { .. } => Vec::new(),
            })
            .collect();
        Self {
            columns,
            kinds,
            labels: data.labels().iter().map(|&c| order.to_learning[c]).collect(),
            weights: data.weights().to_vec(),
            n_classes: order.to_original.len(),
            sorted,
        }
    }

    pub fn covers(&self, conditions: &[Condition], i: usize) -> bool {
        conditions.iter().all(|c| c.holds(self.columns[c.attribute][i]))
    }
}

/// Classes renumbered by ascending total weight (Weka's `ClassOrder` with
/// `FREQ_ASCEND`).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ClassOrder {
    /// learning index → original class index
    pub to_original: Vec<usize>,
    /// original class index → learning index
    pub to_learning: Vec<usize>,
    /// total weight per class, in learning order
    pub counts: Vec<f64>,
}

impl ClassOrder {
    /// As `ClassOrder.batchFinished`: shuffle the class indices
    /// (Fisher–Yates, one draw per position from the last down), then sort
    /// the shuffled list by weight with Weka's `Utils.sort`, which is not
    /// stable ([`weka_sort`]). A tie is thus broken by the seed, as in Weka,
    /// not by the class index.
    pub fn frequency_ascending(class_weights: &[f64], rng: &mut impl JripRandom) -> Self {
        let mut shuffled: Vec<usize> = (0..class_weights.len()).collect();
        randomize(&mut shuffled, rng);
        let shuffled_weights: Vec<f64> = shuffled.iter().map(|&c| class_weights[c]).collect();
        let to_original: Vec<usize> =
            weka_sort(&shuffled_weights).into_iter().map(|position| shuffled[position]).collect();
        let mut to_learning = vec![0; to_original.len()];
        for (learning, &original) in to_original.iter().enumerate() {
            to_learning[original] = learning;
        }
        let counts = to_original.iter().map(|&c| class_weights[c]).collect();
        Self { to_original, to_learning, counts }
    }
}

/// Weka's `Utils.sort(double[])`: the positions of `values` in ascending
/// order, by an index quicksort with a median-of-three pivot and explicit
/// compare-and-swap networks for 2 and 3 elements. It is not stable (three
/// equal weights come out reversed, for instance), and JRip's class order
/// depends on exactly how it permutes ties, so it is reproduced here rather
/// than replaced by a library sort. `values` must not hold NaN.
pub(crate) fn weka_sort(values: &[f64]) -> Vec<usize> {
    let mut index: Vec<usize> = (0..values.len()).collect();
    if values.len() > 1 {
        quick_sort(values, &mut index, 0, values.len() - 1);
    }
    index
}

fn quick_sort(values: &[f64], index: &mut [usize], left: usize, right: usize) {
    let order = |index: &mut [usize], l: usize, r: usize| {
        if values[index[l]] > values[index[r]] {
            index.swap(l, r);
        }
    };
    match right - left {
        0 => {}
        1 => order(index, left, right),
        2 => {
            order(index, left, left + 1);
            order(index, left, right);
            order(index, left + 1, right);
        }
        _ => {
            let center = (left + right) / 2;
            order(index, left, center);
            order(index, left, right);
            order(index, center, right);
            // the median waits beside the right end while the rest is split
            index.swap(center, right - 1);
            let pivot = values[index[right - 1]];
            let (mut l, mut r) = (left, right - 1);
            let split = loop {
                l += 1;
                while values[index[l]] < pivot {
                    l += 1;
                }
                r -= 1;
                while values[index[r]] > pivot {
                    r -= 1;
                }
                if l >= r {
                    break l;
                }
                index.swap(l, r);
            };
            index.swap(split, right - 1);
            quick_sort(values, index, left, split - 1);
            quick_sort(values, index, split + 1, right);
        }
    }
}

/// `Instances.randomize`: Fisher–Yates from the last position down.
pub(crate) fn randomize<T>(items: &mut [T], rng: &mut impl JripRandom) {
    for j in (1..items.len()).rev() {
        let k = rng.below(j + 1);
        items.swap(j, k);
    }
}

/// `RuleStats.stratify`: bag the instances by class (class 0 first, input
/// order kept), shuffle each bag, then deal fold k the instances k, k + F,
/// k + 2F, … of the bags laid end to end, folds one after another.
pub(crate) fn stratify(
    data: &[usize],
    labels: &[usize],
    n_classes: usize,
    folds: usize,
    rng: &mut impl JripRandom,
) -> Vec<usize> {
    let mut bags: Vec<Vec<usize>> = vec![Vec::new(); n_classes];
    for &i in data {
        bags[labels[i]].push(i);
    }
    for bag in &mut bags {
        randomize(bag, rng);
    }
    let mut dealt = Vec::with_capacity(data.len());
    for fold in 0..folds {
        let (mut offset, mut bag) = (fold, 0);
        'fold: loop {
            while offset >= bags[bag].len() {
                offset -= bags[bag].len();
                bag += 1;
                if bag >= bags.len() {
                    break 'fold;
                }
            }
            dealt.push(bags[bag][offset]);
            offset += folds;
        }
    }
    dealt
}

/// `RuleStats.partition`: the first ⌊n (F − 1) / F⌋ instances grow, the rest
/// prune. Returns the split index.
pub(crate) fn grow_prune_split(n: usize, folds: usize) -> usize {
    n * (folds - 1) / folds
}

/// `RuleStats.numAllConditions`: the number of conditions a rule could hold,
/// C in the theory DL. A nominal attribute offers one per declared value, a
/// numeric one `<=` and `>=` per distinct present value (distinct as Java's
/// `HashSet<Double>` sees them: by bit pattern).
pub(crate) fn possible_conditions(data: &Dataset) -> f64 {
    let mut total = 0.0;
    let mut bits: Vec<u64> = Vec::with_capacity(data.len());
    for (a, attribute) in data.attributes().iter().enumerate() {
        match &attribute.kind {
            AttributeKind::Nominal { values } => total += values.len() as f64,
            AttributeKind::Numeric => {
                bits.clear();
                bits.extend((0..data.len()).map(|i| data.row(i)[a]).filter(|v| !v.is_nan()).map(f64::to_bits));
                bits.sort_unstable();
                bits.dedup();
                total += 2.0 * bits.len() as f64;
            }
        }
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ripper::Attribute;

    #[test]
    fn class_order_is_ascending_by_weight() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let order = ClassOrder::frequency_ascending(&[5.0, 2.0, 9.0], &mut rng);
        assert_eq!(order.to_original, vec![1, 0, 2]);
        assert_eq!(order.to_learning, vec![1, 0, 2]);
        assert_eq!(order.counts, vec![2.0, 5.0, 9.0]);
    }

    #[test]
    fn class_order_ties_follow_the_shuffle_and_wekas_sort() {
        // replay the shuffle, then Weka's sort: for three tied classes its
        // compare-and-swap network moves nothing; with a smaller class last,
        // the (first, last) swap reverses the tied pair
        for seed in 0..20 {
            let mut shuffled = vec![0, 1, 2];
            randomize(&mut shuffled, &mut ChaCha8Rng::seed_from_u64(seed));
            let tied = ClassOrder::frequency_ascending(&[3.0; 3], &mut ChaCha8Rng::seed_from_u64(seed));
            assert_eq!(tied.to_original, shuffled, "seed {seed}");

            let weights = [3.0, 3.0, 1.0];
            let order = ClassOrder::frequency_ascending(&weights, &mut ChaCha8Rng::seed_from_u64(seed));
            assert_eq!(order.to_original[0], 2, "seed {seed}");
            let tied_pair: Vec<usize> = shuffled.iter().copied().filter(|&c| c != 2).collect();
            let expected = if shuffled[2] == 2 { vec![tied_pair[1], tied_pair[0]] } else { tied_pair };
            assert_eq!(order.to_original[1..], expected[..], "seed {seed}");
        }
        let orders: std::collections::BTreeSet<Vec<usize>> = (0..20)
            .map(|seed| ClassOrder::frequency_ascending(&[1.0; 3], &mut ChaCha8Rng::seed_from_u64(seed)).to_original)
            .collect();
        assert!(orders.len() > 1, "ties are broken by the seed, not the index");
    }

    /// Expected orders printed by `weka.core.Utils.sort(double[])` (Weka
    /// 3.6.14, the same quicksort as the reference commit's), OpenJDK 17.
    #[test]
    fn weka_sort_permutes_ties_like_weka() {
        let cases: [(&[f64], &[usize]); 9] = [
            (&[5.0, 5.0, 1.0], &[2, 1, 0]),
            (&[2.0, 2.0], &[0, 1]),
            (&[7.0, 7.0, 7.0, 7.0], &[0, 1, 2, 3]),
            (&[3.0, 3.0, 3.0], &[0, 1, 2]),
            (&[1.0, 3.0, 3.0], &[0, 1, 2]),
            (&[3.0, 1.0, 3.0], &[1, 0, 2]),
            (&[4.0, 4.0, 4.0, 4.0, 4.0], &[0, 3, 2, 1, 4]),
            (&[2.0, 1.0, 2.0, 1.0, 2.0, 1.0], &[5, 1, 3, 2, 4, 0]),
            (&[5.0, 1.0, 4.0, 1.0, 9.0, 2.0, 6.0, 5.0, 3.0], &[1, 3, 5, 8, 2, 0, 7, 6, 4]),
        ];
        for (values, expected) in cases {
            assert_eq!(weka_sort(values), expected, "{values:?}");
        }
    }

    #[test]
    fn stratify_deals_folds_from_class_bags() {
        // two classes: 0 holds 0..4, 1 holds 4..10; three folds
        let labels = [0, 0, 0, 0, 1, 1, 1, 1, 1, 1];
        let data: Vec<usize> = (0..10).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let dealt = stratify(&data, &labels, 2, 3, &mut rng);
        // replay the shuffles to know the bags
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut bag0 = vec![0, 1, 2, 3];
        let mut bag1 = vec![4, 5, 6, 7, 8, 9];
        randomize(&mut bag0, &mut rng);
        randomize(&mut bag1, &mut rng);
        let line: Vec<usize> = bag0.iter().chain(&bag1).copied().collect();
        let expected: Vec<usize> =
            (0..3).flat_map(|k| line.iter().skip(k).step_by(3).copied().collect::<Vec<_>>()).collect();
        assert_eq!(dealt, expected);
        assert_eq!(grow_prune_split(10, 3), 6);
        // the grow part (folds 0 and 1) holds 2/3 of each class, up to rounding
        let grow_class0 = dealt[..6].iter().filter(|&&i| labels[i] == 0).count();
        assert!((2..=3).contains(&grow_class0));
    }

    #[test]
    fn possible_conditions_counts_values() {
        let data = Dataset::new(
            vec![Attribute::numeric("x"), Attribute::nominal("c", vec!["a".into(), "b".into(), "c".into()])],
            vec![vec![1.0, 0.0], vec![2.0, 1.0], vec![2.0, f64::NAN], vec![f64::NAN, 0.0]],
            "y",
            vec!["n".into(), "p".into()],
            vec![0, 1, 0, 1],
        )
        .unwrap();
        // x: 2 distinct values → 4 conditions; c: 3 values
        assert_eq!(possible_conditions(&data), 7.0);
    }
}
