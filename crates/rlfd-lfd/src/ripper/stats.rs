//! The statistics of a rule set for one class and the MDL decisions built on
//! them: Weka's `RuleStats` (RuleStats.java, Weka commit 19e3b5a2).
//!
//! What it is: the rules of one class in order, with each rule's
//! coverage/error counts on what the rules before it left uncovered, and
//! - `potential`: the bits saved by deleting a rule, judged as if it were
//!   the last rule (Cohen's original shortcut, kept by Weka): the data DL with
//!   it plus its theory DL minus the data DL without it;
//! - `relative_dl(i)`: the DL of the rule set with rule i minus the DL without
//!   it, each minimised by first deleting later rules with potential ≥ 0 (or
//!   error ≥ 1/2 when the error check is on);
//! - `reduce_dl`: delete, from the last rule to the first, every rule with
//!   potential ≥ 0 (or error ≥ 1/2), then recount.
//!
//! What it is not: the formulas (`mdl.rs`) or the build/optimise loop
//! (`learner.rs`).

use super::mdl::{data_dl, gr_or_eq, theory_dl};
use super::table::{LearnedRule, Table};

/// JRip's six "simple stats" of a rule on the data it is applied to.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct SimpleStats {
    pub covered: f64,
    pub uncovered: f64,
    pub true_pos: f64,
    pub true_neg: f64,
    pub false_pos: f64,
    pub false_neg: f64,
}

/// What every DL computation for one class shares.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DlContext {
    /// Expected FP/(FP + FN): the class's share of the remaining classes.
    pub exp_fp_rate: f64,
    /// JRip's `checkErr`.
    pub check_err: bool,
    /// C, the number of possible conditions.
    pub possible_conditions: f64,
}

/// Applies `rule` to `data`: its stats, and optionally what it leaves
/// uncovered (in order) and the weight it covers per class.
pub(crate) fn simple_stats(
    table: &Table,
    rule: &LearnedRule,
    data: &[usize],
    mut uncovered: Option<&mut Vec<usize>>,
    mut class_weights: Option<&mut [f64]>,
) -> SimpleStats {
    let mut s = SimpleStats::default();
    for &i in data {
        let w = table.weights[i];
        let positive = table.labels[i] == rule.class;
        if table.covers(&rule.conditions, i) {
            s.covered += w;
            if positive {
                s.true_pos += w;
            } else {
                s.false_pos += w;
            }
            if let Some(weights) = class_weights.as_deref_mut() {
                weights[table.labels[i]] += w;
            }
        } else {
            s.uncovered += w;
            if positive {
                s.false_neg += w;
            } else {
                s.true_neg += w;
            }
            if let Some(list) = uncovered.as_deref_mut() {
                list.push(i);
            }
        }
    }
    s
}

/// A rule set's stats as JRip's `RuleStats` keeps them (see the module docs).
#[derive(Debug, Clone)]
pub(crate) struct RuleStats {
    /// The data the first rule is applied to.
    data: Vec<usize>,
    pub rules: Vec<LearnedRule>,
    pub stats: Vec<SimpleStats>,
    /// What rules 0..=i leave uncovered, in data order.
    uncovered: Vec<Vec<usize>>,
    /// Weight covered per (learning-order) class.
    pub class_weights: Vec<Vec<f64>>,
}

impl RuleStats {
    pub fn new(data: Vec<usize>) -> Self {
        Self { data, rules: Vec::new(), stats: Vec::new(), uncovered: Vec::new(), class_weights: Vec::new() }
    }

    pub fn len(&self) -> usize {
        self.rules.len()
    }

    /// The data rule `index` is applied to.
    fn data_before(&self, index: usize) -> &[usize] {
        if index == 0 { &self.data } else { &self.uncovered[index - 1] }
    }

    /// What the whole rule set leaves uncovered.
    pub fn uncovered_by_last(&self) -> &[usize] {
        self.data_before(self.len())
    }

    /// `addAndUpdate`: appends a rule and counts it on what the others leave.
    pub fn add_and_update(&mut self, rule: LearnedRule, table: &Table) {
        let mut left = Vec::new();
        let mut weights = vec![0.0; table.n_classes];
        let stats = simple_stats(table, &rule, self.data_before(self.len()), Some(&mut left), Some(&mut weights));
        self.rules.push(rule);
        self.stats.push(stats);
        self.uncovered.push(left);
        self.class_weights.push(weights);
    }

    pub fn remove_last(&mut self) {
        self.rules.pop();
        self.stats.pop();
        self.uncovered.pop();
        self.class_weights.pop();
    }

    /// `countData()`: recounts every rule from the data.
    fn count_data(&mut self, table: &Table) {
        let rules = std::mem::take(&mut self.rules);
        self.stats.clear();
        self.uncovered.clear();
        self.class_weights.clear();
        for rule in rules {
            self.add_and_update(rule, table);
        }
    }

    pub fn relative_dl(&self, index: usize, ctx: &DlContext, table: &Table) -> f64 {
        relative_dl(index, &self.rules, &self.stats, self.data_before(index), ctx, table)
    }

    /// `reduceDL`: see the module docs.
    pub fn reduce_dl(&mut self, ctx: &DlContext, table: &Table) {
        let mut total = cumulative(&self.stats);
        let mut recount = false;
        for k in (0..self.stats.len()).rev() {
            let rule_stats = self.stats[k];
            let saved = potential(
                theory_dl(self.rules[k].conditions.len(), ctx.possible_conditions),
                ctx,
                &mut total,
                &rule_stats,
            );
            if saved.is_nan() {
                continue;
            }
            // The stats stay indexed by the original positions during the
            // scan; only a deleted tail is removed with its stats.
            if k + 1 == self.stats.len() {
                self.remove_last();
            } else {
                self.rules.remove(k);
                recount = true;
            }
        }
        if recount {
            self.count_data(table);
        }
    }
}

/// The rule set's totals: covered counts summed, uncovered counts of the last
/// rule.
fn cumulative(stats: &[SimpleStats]) -> SimpleStats {
    let mut total = SimpleStats::default();
    for s in stats {
        total.covered += s.covered;
        total.true_pos += s.true_pos;
        total.false_pos += s.false_pos;
    }
    if let Some(last) = stats.last() {
        total.uncovered = last.uncovered;
        total.true_neg = last.true_neg;
        total.false_neg = last.false_neg;
    }
    total
}

/// `RuleStats.potential`: the bits saved by deleting a rule with stats
/// `rule` and theory DL `theory` from a rule set with totals `total`, or NaN
/// if it should stay. A deleted rule's coverage moves to the uncovered part
/// of `total`.
fn potential(theory: f64, ctx: &DlContext, total: &mut SimpleStats, rule: &SimpleStats) -> f64 {
    let without = SimpleStats {
        covered: total.covered - rule.covered,
        uncovered: total.uncovered + rule.covered,
        false_pos: total.false_pos - rule.false_pos,
        false_neg: total.false_neg + rule.true_pos,
        ..*total
    };
    let e = ctx.exp_fp_rate;
    let dl_with = data_dl(e, total.covered, total.uncovered, total.false_pos, total.false_neg);
    let dl_without = data_dl(e, without.covered, without.uncovered, without.false_pos, without.false_neg);
    let saved = dl_with + theory - dl_without;
    // 0/0 for a rule that covers nothing: NaN, never "over"
    let over_error = ctx.check_err && gr_or_eq(rule.false_pos / rule.covered, 0.5);
    if gr_or_eq(saved, 0.0) || over_error {
        total.covered = without.covered;
        total.uncovered = without.uncovered;
        total.false_pos = without.false_pos;
        total.false_neg = without.false_neg;
        saved
    } else {
        f64::NAN
    }
}

/// `minDataDLIfExists`: the data DL with every rule, after deleting the rules
/// after `index` that have potential.
fn min_data_dl_if_exists(index: usize, rules: &[LearnedRule], stats: &[SimpleStats], ctx: &DlContext) -> f64 {
    let mut total = cumulative(stats);
    let mut saved_total = 0.0;
    for k in index + 1..stats.len() {
        let theory = theory_dl(rules[k].conditions.len(), ctx.possible_conditions);
        let saved = potential(theory, ctx, &mut total, &stats[k]);
        if !saved.is_nan() {
            saved_total += saved;
        }
    }
    data_dl(ctx.exp_fp_rate, total.covered, total.uncovered, total.false_pos, total.false_neg) - saved_total
}

/// `minDataDLIfDeleted`: the data DL without rule `index` (the later rules
/// recounted on `before`, the data rule `index` was applied to), after
/// deleting the later rules that have potential.
fn min_data_dl_if_deleted(
    index: usize,
    rules: &[LearnedRule],
    stats: &[SimpleStats],
    before: &[usize],
    ctx: &DlContext,
    table: &Table,
) -> f64 {
    let mut total = SimpleStats::default();
    for s in &stats[..index] {
        total.covered += s.covered;
        total.true_pos += s.true_pos;
        total.false_pos += s.false_pos;
    }
    let mut later = Vec::with_capacity(rules.len().saturating_sub(index + 1));
    let mut data = before.to_vec();
    let mut left = Vec::with_capacity(data.len());
    for rule in &rules[index + 1..] {
        left.clear();
        let s = simple_stats(table, rule, &data, Some(&mut left), None);
        total.covered += s.covered;
        total.true_pos += s.true_pos;
        total.false_pos += s.false_pos;
        later.push(s);
        std::mem::swap(&mut data, &mut left);
    }
    if let Some(last) = later.last() {
        total.uncovered = last.uncovered;
        total.true_neg = last.true_neg;
        total.false_neg = last.false_neg;
    } else if index > 0 {
        let last = &stats[index - 1];
        total.uncovered = last.uncovered;
        total.true_neg = last.true_neg;
        total.false_neg = last.false_neg;
    } else {
        // no rule left at all: everything is uncovered
        let only = &stats[0];
        total.uncovered = only.covered + only.uncovered;
        total.true_neg = only.true_neg + only.false_pos;
        total.false_neg = only.true_pos + only.false_neg;
    }
    let mut saved_total = 0.0;
    for (k, s) in (index + 1..rules.len()).zip(&later) {
        let theory = theory_dl(rules[k].conditions.len(), ctx.possible_conditions);
        let saved = potential(theory, ctx, &mut total, s);
        if !saved.is_nan() {
            saved_total += saved;
        }
    }
    data_dl(ctx.exp_fp_rate, total.covered, total.uncovered, total.false_pos, total.false_neg) - saved_total
}

/// `RuleStats.relativeDL`: min DL with rule `index` + its theory DL − min DL
/// without it. `stats` must hold every rule's stats (rules after `index`
/// counted after it), `before` the data rule `index` was applied to.
///
/// Where Java would produce NaN and Weka throw "Should never happen" (an
/// expected error rate above 1 in a data DL), the rule is worth +∞ bits, so
/// the caller rejects it.
pub(crate) fn relative_dl(
    index: usize,
    rules: &[LearnedRule],
    stats: &[SimpleStats],
    before: &[usize],
    ctx: &DlContext,
    table: &Table,
) -> f64 {
    let dl = min_data_dl_if_exists(index, rules, stats, ctx)
        + theory_dl(rules[index].conditions.len(), ctx.possible_conditions)
        - min_data_dl_if_deleted(index, rules, stats, before, ctx, table);
    if dl.is_nan() { f64::INFINITY } else { dl }
}

/// `countData(index, uncovered, prevRuleStats)` followed by `relativeDL`:
/// the relative DL of `rules[index]` when rules 0..index have the stats
/// `previous` and left `uncovered`; `first_data` is what rule 0 was applied
/// to (used when `index` is 0).
pub(crate) fn relative_dl_after(
    index: usize,
    rules: &[LearnedRule],
    previous: &[SimpleStats],
    uncovered: &[usize],
    first_data: &[usize],
    ctx: &DlContext,
    table: &Table,
) -> f64 {
    let mut stats = previous.to_vec();
    let mut data = uncovered.to_vec();
    let mut left = Vec::with_capacity(data.len());
    for rule in &rules[index..] {
        left.clear();
        stats.push(simple_stats(table, rule, &data, Some(&mut left), None));
        std::mem::swap(&mut data, &mut left);
    }
    let before = if index == 0 { first_data } else { uncovered };
    relative_dl(index, rules, &stats, before, ctx, table)
}

#[cfg(test)]
mod tests {
    use super::super::table::Kind;
    use super::super::{Condition, Operator};
    use super::*;

    /// x = 0..10, class 1 (positive) for x >= 7 and at x = 2.
    fn table() -> Table {
        weighted_table(1.0)
    }

    fn weighted_table(weight: f64) -> Table {
        let xs: Vec<f64> = (0..10).map(f64::from).collect();
        let labels = vec![0, 0, 1, 0, 0, 0, 0, 1, 1, 1];
        let mut sorted: Vec<usize> = (0..10).collect();
        sorted.sort_by(|&i, &j| xs[i].total_cmp(&xs[j]));
        Table {
            columns: vec![xs],
            kinds: vec![Kind::Numeric],
            labels,
            weights: vec![weight; 10],
            n_classes: 2,
            sorted: vec![sorted],
        }
    }

    fn rule(op: Operator, value: f64) -> LearnedRule {
        LearnedRule { conditions: vec![Condition { attribute: 0, op, value }], class: 1 }
    }

    fn ctx() -> DlContext {
        DlContext { exp_fp_rate: 0.4, check_err: true, possible_conditions: 20.0 }
    }

    #[test]
    fn add_and_update_counts_on_what_is_left() {
        let t = table();
        let mut rs = RuleStats::new((0..10).collect());
        rs.add_and_update(rule(Operator::GreaterEq, 7.0), &t);
        rs.add_and_update(rule(Operator::GreaterEq, 2.0), &t);
        assert_eq!(
            rs.stats[0],
            SimpleStats { covered: 3.0, uncovered: 7.0, true_pos: 3.0, true_neg: 6.0, false_pos: 0.0, false_neg: 1.0 }
        );
        // x >= 2 on 0..7: covers 2..=6, one positive
        assert_eq!(rs.stats[1].covered, 5.0);
        assert_eq!(rs.stats[1].true_pos, 1.0);
        assert_eq!(rs.uncovered_by_last(), &[0, 1]);
        assert_eq!(rs.class_weights[1], vec![4.0, 1.0]);
        rs.remove_last();
        assert_eq!(rs.uncovered_by_last(), &[0, 1, 2, 3, 4, 5, 6]);
    }

    #[test]
    fn relative_dl_of_a_single_rule_is_its_dl_minus_the_default_dl() {
        // with one rule there is nothing later to delete: relative DL is
        // dataDL(with) + theoryDL − dataDL(nothing covered)
        let t = table();
        let mut rs = RuleStats::new((0..10).collect());
        rs.add_and_update(rule(Operator::GreaterEq, 7.0), &t);
        let c = ctx();
        let expected = data_dl(0.4, 3.0, 7.0, 0.0, 1.0) + theory_dl(1, 20.0) - data_dl(0.4, 0.0, 10.0, 0.0, 4.0);
        assert!((rs.relative_dl(0, &c, &t) - expected).abs() < 1e-12);
        assert!(expected < 0.0, "a good rule shortens the description");
    }

    #[test]
    fn relative_dl_after_matches_a_full_recount() {
        let t = table();
        let mut rs = RuleStats::new((0..10).collect());
        rs.add_and_update(rule(Operator::GreaterEq, 7.0), &t);
        rs.add_and_update(rule(Operator::LessEq, 2.0), &t);
        let c = ctx();
        let full = rs.relative_dl(1, &c, &t);
        let data: Vec<usize> = (0..10).collect();
        let after = relative_dl_after(1, &rs.rules, &rs.stats[..1], rs.data_before(1), &data, &c, &t);
        assert_eq!(full, after);
    }

    #[test]
    fn reduce_dl_deletes_a_rule_that_only_adds_errors() {
        let t = table();
        let mut rs = RuleStats::new((0..10).collect());
        rs.add_and_update(rule(Operator::GreaterEq, 7.0), &t);
        // x <= 1 covers two negatives only: error 1 ≥ 1/2
        rs.add_and_update(rule(Operator::LessEq, 1.0), &t);
        rs.reduce_dl(&ctx(), &t);
        assert_eq!(rs.rules, vec![rule(Operator::GreaterEq, 7.0)]);
        assert_eq!(rs.stats.len(), 1);
    }

    #[test]
    fn reduce_dl_recounts_after_deleting_a_middle_rule() {
        // with unit weights the data are too few to pay for x >= 7 (its
        // potential is +0.78 bits, python3 on the formulas); weight 5 makes it
        // save 7.58 bits
        let t = weighted_table(5.0);
        let mut rs = RuleStats::new((0..10).collect());
        // a useless first rule, then the good one
        rs.add_and_update(rule(Operator::LessEq, 0.0), &t);
        rs.add_and_update(rule(Operator::GreaterEq, 7.0), &t);
        rs.reduce_dl(&ctx(), &t);
        assert_eq!(rs.rules, vec![rule(Operator::GreaterEq, 7.0)]);
        assert_eq!(rs.stats[0].covered, 15.0);
        assert_eq!(rs.stats[0].true_pos, 15.0);
        assert_eq!(rs.uncovered_by_last(), &[0, 1, 2, 3, 4, 5, 6]);
    }

    #[test]
    fn potential_of_a_rule_covering_nothing_is_its_theory_dl() {
        let mut total =
            SimpleStats { covered: 3.0, uncovered: 7.0, true_pos: 3.0, true_neg: 6.0, false_pos: 0.0, false_neg: 1.0 };
        let before = total;
        let saved = potential(2.5, &ctx(), &mut total, &SimpleStats::default());
        assert_eq!(saved, 2.5);
        assert_eq!(total, before);
    }
}
