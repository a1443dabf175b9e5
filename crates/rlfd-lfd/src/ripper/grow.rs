//! Growing one rule by FOIL information gain and pruning it by incremental
//! reduced-error pruning: JRip's `RipperRule.grow`, `NumericAntd.splitData`,
//! `NominalAntd.splitData` and `RipperRule.prune` (JRip.java, Weka commit
//! 0b4f0571).
//!
//! Grow, on the grow data for class y, starting from the rule's conditions:
//! with p/t the positive/total weight still covered and defAcRt = (p+1)/(t+1),
//! add the condition of largest gain p_c [log₂((p_c+1)/(t_c+1)) − log₂ defAcRt]
//! (strictly largest, so the lower attribute index wins ties; the gain must
//! be positive and the condition cover at least minNo positive weight),
//! restrict the data to what it covers, and repeat while data remain and
//! defAcRt < 1. Numeric candidates sit at each boundary between distinct
//! values v < v′: `x <= v` (the prefix) and `x >= v` (the suffix from v's
//! first occurrence), the prefix only if its gain is strictly larger. A
//! nominal attribute is used once.
//!
//! Prune, on the prune data: the prefix of j + 1 conditions is worth
//! (p_j + 1)/(c_j + 2), or (TP_j + TN_j)/N with the whole-data metric of the
//! optimisation stage; the empty rule is worth (P + 1)/(N + 2) in both cases
//! (as JRip computes it). The first prefix of strictly largest worth that
//! beats the empty rule is kept; if none does, every condition goes.
//!
//! What it is not: the rule-set loop (`learner.rs`). Performance: numeric
//! attributes are pre-sorted once per fit (`Table::sorted`); a grow call
//! filters those lists (O(n) per attribute) and each new condition filters
//! them again, so nothing is sorted inside the loop and the buffers live in
//! [`Grower`] across calls.

use super::mdl::{gr, log2, sm};
use super::table::{Kind, LearnedRule, Table};
use super::{Condition, Operator};

/// Which worth the pruning compares (JRip's `useWhole` flag).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PruneMetric {
    /// (p + 1)/(c + 2) on what the prefix covers: the build stage.
    CoveredAccuracy,
    /// (TP + TN)/N on all the prune data: the optimisation stage.
    WholeAccuracy,
}

/// The best condition on one attribute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Split {
    pub condition: Condition,
    pub gain: f64,
    /// Positive weight covered.
    pub accu: f64,
    /// Total weight covered.
    pub cover: f64,
    /// (accu + 1)/(cover + 1): the next defAcRt.
    pub rate: f64,
}

/// Reusable buffers for growing and pruning.
#[derive(Debug, Default)]
pub(crate) struct Grower {
    /// Per numeric attribute, the current grow data sorted by value.
    sorted: Vec<Vec<usize>>,
    /// Membership of the grow data, indexed by instance.
    member: Vec<bool>,
    current: Vec<usize>,
    next: Vec<usize>,
    nominal_cover: Vec<f64>,
    nominal_accu: Vec<f64>,
}

impl Grower {
    pub fn new(table: &Table) -> Self {
        Self { sorted: vec![Vec::new(); table.kinds.len()], member: vec![false; table.labels.len()], ..Self::default() }
    }

    /// Extends `rule` on `data` (see the module docs).
    pub fn grow(&mut self, table: &Table, rule: &mut LearnedRule, data: &[usize], min_no: f64) {
        let class = rule.class;
        let (mut total, mut positive) = (0.0, 0.0);
        for &i in data {
            total += table.weights[i];
            if table.labels[i] == class {
                positive += table.weights[i];
            }
        }
        if !gr(total, 0.0) {
            return;
        }
        let mut def_ac_rt = (positive + 1.0) / (total + 1.0);

        let mut used = vec![false; table.kinds.len()];
        for c in &rule.conditions {
            if matches!(table.kinds[c.attribute], Kind::Nominal { .. }) {
                used[c.attribute] = true;
            }
        }

        self.current.clear();
        self.current.extend_from_slice(data);
        for &i in data {
            self.member[i] = true;
        }
        for (a, kind) in table.kinds.iter().enumerate() {
            self.sorted[a].clear();
            if *kind == Kind::Numeric {
                let member = &self.member;
                self.sorted[a].extend(table.sorted[a].iter().copied().filter(|&i| member[i]));
            }
        }
        for &i in data {
            self.member[i] = false;
        }

        // JRip also requires an unused attribute, but it counts the class
        // attribute, which is never used: the test is always true.
        while !self.current.is_empty() && sm(def_ac_rt, 1.0) {
            let mut best: Option<Split> = None;
            for (a, kind) in table.kinds.iter().enumerate() {
                if used[a] {
                    continue;
                }
                let split = match *kind {
                    Kind::Numeric => numeric_split(table, a, &self.sorted[a], class, def_ac_rt),
                    Kind::Nominal { values } => self.nominal_split(table, a, values, class, def_ac_rt),
                };
                if let Some(split) = split
                    && split.gain > best.map_or(0.0, |b| b.gain)
                {
                    best = Some(split);
                }
            }
            let Some(best) = best else { break };
            if sm(best.accu, min_no) {
                break;
            }
            let condition = best.condition;
            if matches!(table.kinds[condition.attribute], Kind::Nominal { .. }) {
                used[condition.attribute] = true;
            }
            rule.conditions.push(condition);
            let column = &table.columns[condition.attribute];
            self.current.retain(|&i| condition.holds(column[i]));
            for (a, kind) in table.kinds.iter().enumerate() {
                if *kind == Kind::Numeric {
                    self.sorted[a].retain(|&i| condition.holds(column[i]));
                }
            }
            def_ac_rt = best.rate;
        }
    }

    fn nominal_split(
        &mut self,
        table: &Table,
        attribute: usize,
        values: usize,
        class: usize,
        def_ac_rt: f64,
    ) -> Option<Split> {
        self.nominal_cover.clear();
        self.nominal_cover.resize(values, 0.0);
        self.nominal_accu.clear();
        self.nominal_accu.resize(values, 0.0);
        let column = &table.columns[attribute];
        for &i in &self.current {
            let x = column[i];
            if x.is_nan() {
                continue;
            }
            let v = x as usize;
            self.nominal_cover[v] += table.weights[i];
            if table.labels[i] == class {
                self.nominal_accu[v] += table.weights[i];
            }
        }
        let log_def = log2(def_ac_rt);
        let mut best: Option<Split> = None;
        for v in 0..values {
            let (cover, accu) = (self.nominal_cover[v], self.nominal_accu[v]);
            let rate = (accu + 1.0) / (cover + 1.0);
            let gain = accu * (log2(rate) - log_def);
            if gain > best.map_or(0.0, |b| b.gain) {
                best = Some(Split {
                    condition: Condition { attribute, op: Operator::Equal, value: v as f64 },
                    gain,
                    accu,
                    cover,
                    rate,
                });
            }
        }
        best
    }

    /// Truncates `rule` to its best prefix on `data` (see the module docs).
    pub fn prune(&mut self, table: &Table, rule: &mut LearnedRule, data: &[usize], metric: PruneMetric) {
        let class = rule.class;
        let (mut total, mut positive) = (0.0, 0.0);
        for &i in data {
            total += table.weights[i];
            if table.labels[i] == class {
                positive += table.weights[i];
            }
        }
        if !gr(total, 0.0) || rule.conditions.is_empty() {
            return;
        }
        let mut best_worth = (positive + 1.0) / (total + 2.0);
        let mut keep = 0;
        let mut true_negatives = 0.0;
        self.current.clear();
        self.current.extend_from_slice(data);
        for (j, condition) in rule.conditions.iter().enumerate() {
            let column = &table.columns[condition.attribute];
            let (mut covered, mut covered_positive) = (0.0, 0.0);
            self.next.clear();
            for &i in &self.current {
                let w = table.weights[i];
                let is_positive = table.labels[i] == class;
                if condition.holds(column[i]) {
                    covered += w;
                    self.next.push(i);
                    if is_positive {
                        covered_positive += w;
                    }
                } else if metric == PruneMetric::WholeAccuracy && !is_positive {
                    true_negatives += w;
                }
            }
            std::mem::swap(&mut self.current, &mut self.next);
            let worth = match metric {
                PruneMetric::CoveredAccuracy => (covered_positive + 1.0) / (covered + 2.0),
                PruneMetric::WholeAccuracy => (covered_positive + true_negatives) / total,
            };
            // strictly better only: a longer prefix must earn its conditions
            if worth > best_worth {
                best_worth = worth;
                keep = j + 1;
            }
        }
        rule.conditions.truncate(keep);
    }
}

/// JRip's `NumericAntd.splitData` on `sorted` (the grow data with a value
/// for `attribute`, ascending): the best `<=`/`>=` split, if any has gain > 0.
pub(crate) fn numeric_split(
    table: &Table,
    attribute: usize,
    sorted: &[usize],
    class: usize,
    def_ac_rt: f64,
) -> Option<Split> {
    let column = &table.columns[attribute];
    let (mut snd_cover, mut snd_accu) = (0.0, 0.0);
    for &i in sorted {
        snd_cover += table.weights[i];
        if table.labels[i] == class {
            snd_accu += table.weights[i];
        }
    }
    let (mut fst_cover, mut fst_accu) = (0.0, 0.0);
    let log_def = log2(def_ac_rt);
    let mut best: Option<Split> = None;
    let mut prev = 0;
    for split in 1..=sorted.len() {
        if split < sorted.len() && column[sorted[split]] <= column[sorted[prev]] {
            continue;
        }
        // sorted[prev..split] holds one value v: add it to the prefix `<= v`;
        // the suffix `>= v` still holds it
        for &i in &sorted[prev..split] {
            fst_cover += table.weights[i];
            if table.labels[i] == class {
                fst_accu += table.weights[i];
            }
        }
        let fst_rate = (fst_accu + 1.0) / (fst_cover + 1.0);
        let snd_rate = (snd_accu + 1.0) / (snd_cover + 1.0);
        let fst_gain = fst_accu * (log2(fst_rate) - log_def);
        let snd_gain = snd_accu * (log2(snd_rate) - log_def);
        let (op, gain, rate, accu, cover) = if fst_gain > snd_gain {
            (Operator::LessEq, fst_gain, fst_rate, fst_accu, fst_cover)
        } else {
            (Operator::GreaterEq, snd_gain, snd_rate, snd_accu, snd_cover)
        };
        if gain > best.map_or(0.0, |b| b.gain) {
            best = Some(Split {
                condition: Condition { attribute, op, value: column[sorted[prev]] },
                gain,
                accu,
                cover,
                rate,
            });
        }
        for &i in &sorted[prev..split] {
            snd_cover -= table.weights[i];
            if table.labels[i] == class {
                snd_accu -= table.weights[i];
            }
        }
        prev = split;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-attribute numeric table (or nominal with `values`), labels in
    /// learning order.
    fn table(xs: &[f64], labels: &[usize], kind: Kind) -> Table {
        let n = xs.len();
        let mut sorted: Vec<usize> = (0..n).filter(|&i| !xs[i].is_nan()).collect();
        sorted.sort_by(|&i, &j| xs[i].total_cmp(&xs[j]));
        Table {
            columns: vec![xs.to_vec()],
            kinds: vec![kind],
            labels: labels.to_vec(),
            weights: vec![1.0; n],
            n_classes: 2,
            sorted: vec![if kind == Kind::Numeric { sorted } else { Vec::new() }],
        }
    }

    fn rate(p: f64, t: f64) -> f64 {
        (p + 1.0) / (t + 1.0)
    }

    fn gain(p: f64, t: f64, def: f64) -> f64 {
        p * (log2(rate(p, t)) - log2(def))
    }

    #[test]
    fn numeric_split_picks_the_boundary_of_largest_gain() {
        // x:     1  2  2  3  4  5
        // class: 1  1  1  0  0  0   (class 1 positive)
        let t = table(&[1.0, 2.0, 2.0, 3.0, 4.0, 5.0], &[1, 1, 1, 0, 0, 0], Kind::Numeric);
        let def = rate(3.0, 6.0);
        let split = numeric_split(&t, 0, &t.sorted[0], 1, def).unwrap();
        assert_eq!(split.condition.op, Operator::LessEq);
        assert_eq!(split.condition.value, 2.0);
        assert_eq!((split.accu, split.cover), (3.0, 3.0));
        assert!((split.gain - gain(3.0, 3.0, def)).abs() < 1e-12);
        assert_eq!(split.rate, 1.0);
    }

    #[test]
    fn numeric_suffix_starts_at_the_first_occurrence_of_its_value() {
        // positives at the top: the suffix `>= 4` covers both 4s
        let t = table(&[1.0, 2.0, 3.0, 4.0, 4.0, 6.0], &[0, 0, 0, 1, 1, 1], Kind::Numeric);
        let split = numeric_split(&t, 0, &t.sorted[0], 1, rate(3.0, 6.0)).unwrap();
        assert_eq!(split.condition.op, Operator::GreaterEq);
        assert_eq!(split.condition.value, 4.0);
        assert_eq!((split.accu, split.cover), (3.0, 3.0));
    }

    #[test]
    fn numeric_split_prefers_the_suffix_on_equal_gain() {
        // at the boundary after v = 2 the prefix `<= 2` and the suffix `>= 2`
        // both cover one positive of two: JRip keeps the suffix
        let t = table(&[1.0, 2.0, 3.0], &[0, 1, 0], Kind::Numeric);
        let def = rate(1.0, 3.0);
        let split = numeric_split(&t, 0, &t.sorted[0], 1, def).unwrap();
        assert_eq!(split.condition.op, Operator::GreaterEq);
        assert_eq!(split.condition.value, 2.0);
        assert!((split.gain - gain(1.0, 2.0, def)).abs() < 1e-12);
    }

    #[test]
    fn numeric_split_needs_positive_gain_and_values() {
        let pure = table(&[1.0, 2.0], &[1, 1], Kind::Numeric);
        assert_eq!(numeric_split(&pure, 0, &pure.sorted[0], 1, rate(2.0, 2.0)), None);
        let missing = table(&[f64::NAN, f64::NAN], &[1, 0], Kind::Numeric);
        assert_eq!(numeric_split(&missing, 0, &missing.sorted[0], 1, 0.5), None);
    }

    #[test]
    fn grow_stops_when_the_rule_is_pure() {
        let t = table(&[1.0, 2.0, 2.0, 3.0, 4.0, 5.0], &[1, 1, 1, 0, 0, 0], Kind::Numeric);
        let mut rule = LearnedRule::empty(1);
        Grower::new(&t).grow(&t, &mut rule, &[0, 1, 2, 3, 4, 5], 2.0);
        assert_eq!(rule.conditions, vec![Condition { attribute: 0, op: Operator::LessEq, value: 2.0 }]);
    }

    #[test]
    fn grow_respects_min_no() {
        // the only useful split covers one positive, below minNo = 2
        let t = table(&[1.0, 2.0, 3.0, 4.0], &[1, 0, 0, 0], Kind::Numeric);
        let mut rule = LearnedRule::empty(1);
        Grower::new(&t).grow(&t, &mut rule, &[0, 1, 2, 3], 2.0);
        assert!(rule.conditions.is_empty());
        Grower::new(&t).grow(&t, &mut rule, &[0, 1, 2, 3], 1.0);
        assert_eq!(rule.conditions.len(), 1);
    }

    #[test]
    fn grow_uses_a_nominal_attribute_once() {
        // value 1 is mostly positive; after `= 1` nothing else can be added
        let t = table(&[1.0, 1.0, 1.0, 0.0, 0.0, 2.0], &[1, 1, 0, 0, 0, 0], Kind::Nominal { values: 3 });
        let mut rule = LearnedRule::empty(1);
        Grower::new(&t).grow(&t, &mut rule, &[0, 1, 2, 3, 4, 5], 1.0);
        assert_eq!(rule.conditions, vec![Condition { attribute: 0, op: Operator::Equal, value: 1.0 }]);
    }

    fn rule_with(values: &[f64]) -> LearnedRule {
        LearnedRule {
            conditions: values.iter().map(|&v| Condition { attribute: 0, op: Operator::LessEq, value: v }).collect(),
            class: 1,
        }
    }

    #[test]
    fn prune_keeps_the_shortest_of_equally_good_prefixes() {
        // x <= 4 and x <= 3 cover the same prune instances: equal worth, the
        // shorter prefix stays
        let t = table(&[1.0, 2.0, 5.0, 6.0], &[1, 1, 0, 0], Kind::Numeric);
        let mut rule = rule_with(&[4.0, 3.0]);
        Grower::new(&t).prune(&t, &mut rule, &[0, 1, 2, 3], PruneMetric::CoveredAccuracy);
        assert_eq!(rule, rule_with(&[4.0]));
    }

    #[test]
    fn prune_cuts_a_condition_that_lowers_the_worth() {
        // x <= 4 covers both positives (worth 3/4); x <= 1 only one (2/3)
        let t = table(&[1.0, 2.0, 5.0, 6.0], &[1, 1, 0, 0], Kind::Numeric);
        let mut rule = rule_with(&[4.0, 1.0]);
        Grower::new(&t).prune(&t, &mut rule, &[0, 1, 2, 3], PruneMetric::CoveredAccuracy);
        assert_eq!(rule, rule_with(&[4.0]));
    }

    #[test]
    fn prune_drops_everything_when_no_prefix_beats_the_empty_rule() {
        // x <= 2 covers 1 positive and 1 negative: (1+1)/(2+2) = 0.5, the
        // empty rule (2+1)/(4+2) = 0.5 too; not strictly better
        let t = table(&[1.0, 2.0, 5.0, 6.0], &[1, 0, 1, 0], Kind::Numeric);
        let mut rule = rule_with(&[2.0]);
        Grower::new(&t).prune(&t, &mut rule, &[0, 1, 2, 3], PruneMetric::CoveredAccuracy);
        assert!(rule.conditions.is_empty());
    }

    #[test]
    fn prune_with_the_whole_data_metric_counts_true_negatives() {
        // x: 1 2 3 4 5 6, positives at 1, 2, 4; rule x <= 4 and x <= 2
        let t = table(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0], &[1, 1, 0, 1, 0, 0], Kind::Numeric);
        let data = [0, 1, 2, 3, 4, 5];
        // (p+1)/(c+2): x <= 4 → 4/6, x <= 2 → 3/4; both conditions stay
        let mut covered = rule_with(&[4.0, 2.0]);
        Grower::new(&t).prune(&t, &mut covered, &data, PruneMetric::CoveredAccuracy);
        assert_eq!(covered, rule_with(&[4.0, 2.0]));
        // (TP+TN)/N: x <= 4 → (3+2)/6, x <= 2 → (2+3)/6; a tie, the shorter
        // prefix stays
        let mut whole = rule_with(&[4.0, 2.0]);
        Grower::new(&t).prune(&t, &mut whole, &data, PruneMetric::WholeAccuracy);
        assert_eq!(whole, rule_with(&[4.0]));
    }
}
