//! The RIPPER driver: JRip's `buildClassifier`, `rulesetForOneClass` and
//! `checkStop` (JRip.java, Weka commit 0b4f0571).
//!
//! For each class y but the most frequent, least frequent first, on the data
//! the earlier classes' rules left uncovered:
//! 1. Build: repeat { stratify and split the data (F − 1 folds grow, one
//!    prunes), grow a rule, prune it, dl += relativeDL, minDL = min(minDL, dl) }
//!    until dl > minDL + 64 bits, or the rule covers no positive weight, or
//!    its error on what it covers reaches 1/2 (that rule is discarded);
//!    otherwise accept it, drop what it covers, and go on while positives
//!    remain.
//! 2. Optimise, `optimizations` times: for each rule i on a fresh
//!    stratification of what rules 0..i−1 leave, grow a replacement from
//!    nothing and a revision from rule i (on the grow instances rule i
//!    covers), prune both with the whole-data metric on the prune data minus
//!    what rules i+1.. cover, and keep whichever of old, revision and
//!    replacement has the smallest relative DL (ties: old, then revision).
//!    Positives left over get new rules as in the build stage. Then delete
//!    rules by `reduceDL`.
//!
//! Then every rule is cleaned of redundant numeric tests and the most frequent
//! class becomes the default rule.
//!
//! Kept from Weka on purpose: when the optimisation pass runs out of
//! positives before reaching the last old rule, JRip re-adds the old rules
//! after the next one but not the next one itself (`position + 1` in
//! JRip.java); this module does the same. Deviation: where Weka would throw
//! on a NaN description length, the candidate costs +∞ bits (see
//! `stats::relative_dl`).

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::grow::{Grower, PruneMetric};
use super::mdl::{MAX_DL_SURPLUS, data_dl, eq, gr};
use super::rule::clean_up;
use super::stats::{DlContext, RuleStats, SimpleStats, relative_dl_after, simple_stats};
use super::table::{ClassOrder, JripRandom, LearnedRule, Table, grow_prune_split, possible_conditions, stratify};
use super::{
    Coverage, Dataset, DecisionList, ErrorRateCheck, JavaRandom, Pruning, RipperError, RipperParams, RipperRandom, Rule,
};

/// [`Ripper::fit`](super::Ripper::fit): see the module docs.
pub(crate) fn fit(params: &RipperParams, data: &Dataset) -> Result<DecisionList, RipperError> {
    // --- seeding: the fit's only random generator. A generator forked from
    // it shuffles the classes (ties in frequency), as JRip seeds its
    // ClassOrder filter; then it shuffles every grow/prune stratification,
    // in the order JRip draws them.
    match params.random {
        RipperRandom::ChaCha8 => fit_with(params, data, ChaCha8Rng::seed_from_u64(params.seed)),
        // JRip: m_Random = instances.getRandomNumberGenerator(m_Seed)
        RipperRandom::Weka => fit_with(params, data, JavaRandom::for_instances(data, params.seed as i64)),
    }
}

/// [`fit`] drawing from `rng`.
pub(crate) fn fit_with<R: JripRandom>(
    params: &RipperParams,
    data: &Dataset,
    mut rng: R,
) -> Result<DecisionList, RipperError> {
    params.check()?;
    if data.len() < params.folds {
        return Err(RipperError::TooFewInstances { required: params.folds, provided: data.len() });
    }

    let order = ClassOrder::frequency_ascending(&data.class_weights(), &mut rng.fork());

    let table = Table::new(data, &order);
    let mut learner = Learner {
        grower: Grower::new(&table),
        table: &table,
        params,
        rng,
        possible_conditions: possible_conditions(data),
    };

    let n_classes = order.counts.len();
    let mut remaining: Vec<usize> = (0..data.len()).collect();
    let mut per_class: Vec<RuleStats> = Vec::new();
    for class in 0..n_classes.saturating_sub(1) {
        if eq(order.counts[class], 0.0) {
            continue;
        }
        let others: f64 = order.counts[class..].iter().sum();
        let exp_fp_rate = order.counts[class] / others;
        let (mut class_weight, mut total_weight) = (0.0, 0.0);
        for &i in &remaining {
            total_weight += table.weights[i];
            if table.labels[i] == class {
                class_weight += table.weights[i];
            }
        }
        if class_weight <= 0.0 {
            // every instance of the class is covered by earlier classes' rules
            continue;
        }
        let default_dl = data_dl(exp_fp_rate, 0.0, total_weight, 0.0, class_weight);
        let ctx = DlContext {
            exp_fp_rate,
            check_err: params.error_rate_check == ErrorRateCheck::StopAtHalf,
            possible_conditions: learner.possible_conditions,
        };
        let stats = learner.ruleset_for_one_class(class, &ctx, &remaining, default_dl);
        if stats.len() > 0 {
            remaining = stats.uncovered_by_last().to_vec();
        }
        per_class.push(stats);
    }

    let to_original = |weights: &[f64]| {
        let mut out = vec![0.0; n_classes];
        for (learning, &w) in weights.iter().enumerate() {
            out[order.to_original[learning]] = w;
        }
        out
    };
    let mut rules = Vec::new();
    for stats in &per_class {
        for ((rule, s), weights) in stats.rules.iter().zip(&stats.stats).zip(&stats.class_weights) {
            let mut conditions = rule.conditions.clone();
            clean_up(&mut conditions, table.kinds.len());
            rules.push(Rule {
                conditions,
                class: order.to_original[rule.class],
                coverage: Coverage {
                    covered: s.covered,
                    false_positives: s.false_pos,
                    class_weights: to_original(weights),
                },
            });
        }
    }

    let default_learning = n_classes - 1;
    let mut default_weights = vec![0.0; n_classes];
    let default_stats =
        simple_stats(&table, &LearnedRule::empty(default_learning), &remaining, None, Some(&mut default_weights));
    Ok(DecisionList::new(
        rules,
        order.to_original[default_learning],
        Coverage {
            covered: default_stats.covered,
            false_positives: default_stats.false_pos,
            class_weights: to_original(&default_weights),
        },
        data.attributes().to_vec(),
        data.class_attribute().to_string(),
        data.class_names().to_vec(),
    ))
}

struct Learner<'a, R> {
    table: &'a Table,
    params: &'a RipperParams,
    rng: R,
    grower: Grower,
    possible_conditions: f64,
}

impl<R: JripRandom> Learner<'_, R> {
    /// JRip's `rulesetForOneClass`: the final rule set of `class` and its
    /// stats on `data`.
    fn ruleset_for_one_class(&mut self, class: usize, ctx: &DlContext, data: &[usize], default_dl: f64) -> RuleStats {
        let mut ruleset = Vec::new();
        let mut stats = self.build(class, ctx, data, default_dl, &mut ruleset);
        if self.params.pruning == Pruning::Irep {
            for _ in 0..self.params.optimizations {
                stats = self.optimise(class, ctx, data, default_dl, &mut ruleset);
            }
        }
        stats
    }

    fn stratified(&mut self, data: &[usize]) -> Vec<usize> {
        let t = self.table;
        stratify(data, &t.labels, t.n_classes, self.params.folds, &mut self.rng)
    }

    /// A new rule grown on `grow` and pruned on `prune` by (p+1)/(c+2).
    fn grow_and_prune(&mut self, class: usize, grow: &[usize], prune: &[usize]) -> LearnedRule {
        let mut rule = LearnedRule::empty(class);
        self.grower.grow(self.table, &mut rule, grow, self.params.min_no);
        self.grower.prune(self.table, &mut rule, prune, PruneMetric::CoveredAccuracy);
        rule
    }

    /// The building stage; accepted rules are appended to `ruleset`.
    fn build(
        &mut self,
        class: usize,
        ctx: &DlContext,
        data: &[usize],
        default_dl: f64,
        ruleset: &mut Vec<LearnedRule>,
    ) -> RuleStats {
        let table = self.table;
        let mut left = data.to_vec();
        let mut stats: Option<RuleStats> = None;
        let (mut dl, mut min_dl) = (default_dl, default_dl);
        loop {
            let rule = match self.params.pruning {
                Pruning::Irep => {
                    left = self.stratified(&left);
                    let (grow, prune) = left.split_at(grow_prune_split(left.len(), self.params.folds));
                    self.grow_and_prune(class, grow, prune)
                }
                Pruning::Off => {
                    let mut rule = LearnedRule::empty(class);
                    self.grower.grow(table, &mut rule, &left, self.params.min_no);
                    rule
                }
            };
            // JRip's stats start from the data as the first split left it
            let rs = stats.get_or_insert_with(|| RuleStats::new(left.clone()));
            rs.add_and_update(rule.clone(), table);
            let last = rs.len() - 1;
            dl += rs.relative_dl(last, ctx, table);
            if dl < min_dl {
                min_dl = dl;
            }
            let rule_stats = rs.stats[last];
            if should_stop(&rule_stats, min_dl, dl, ctx.check_err) {
                rs.remove_last();
                break;
            }
            ruleset.push(rule);
            left = rs.uncovered_by_last().to_vec();
            if !gr(rule_stats.false_neg, 0.0) {
                break;
            }
        }
        stats.unwrap_or_else(|| RuleStats::new(left))
    }

    /// One optimisation run over `ruleset`, which it rewrites; returns the
    /// final stats.
    fn optimise(
        &mut self,
        class: usize,
        ctx: &DlContext,
        data: &[usize],
        default_dl: f64,
        ruleset: &mut Vec<LearnedRule>,
    ) -> RuleStats {
        let table = self.table;
        let folds = self.params.folds;
        let mut left = data.to_vec();
        let mut fin = RuleStats::new(data.to_vec());
        let mut position = 0;
        let (mut dl, mut min_dl) = (default_dl, default_dl);
        let mut stop = false;
        let mut has_positive = true;
        while !stop && has_positive {
            let is_residual = position >= ruleset.len();
            left = self.stratified(&left);
            let (grow, prune) = left.split_at(grow_prune_split(left.len(), folds));
            let final_rule = if is_residual {
                self.grow_and_prune(class, grow, prune)
            } else {
                let old = &ruleset[position];
                if !left.iter().any(|&i| table.covers(&old.conditions, i)) {
                    // nothing to learn a variant from
                    fin.add_and_update(old.clone(), table);
                    position += 1;
                    continue;
                }
                let prune: Vec<usize> = prune
                    .iter()
                    .copied()
                    .filter(|&i| !ruleset[position + 1..].iter().any(|r| table.covers(&r.conditions, i)))
                    .collect();

                let mut replacement = LearnedRule::empty(class);
                self.grower.grow(table, &mut replacement, grow, self.params.min_no);
                self.grower.prune(table, &mut replacement, &prune, PruneMetric::WholeAccuracy);

                let mut revision = old.clone();
                let covered: Vec<usize> =
                    grow.iter().copied().filter(|&i| table.covers(&revision.conditions, i)).collect();
                self.grower.grow(table, &mut revision, &covered, self.params.min_no);
                self.grower.prune(table, &mut revision, &prune, PruneMetric::WholeAccuracy);

                let previous: &[SimpleStats] = &fin.stats[..position];
                let variant_dl =
                    |rules: &[LearnedRule]| relative_dl_after(position, rules, previous, &left, data, ctx, table);
                let mut trial = ruleset.clone();
                trial[position] = replacement.clone();
                let replacement_dl = variant_dl(&trial);
                trial[position] = revision.clone();
                let revision_dl = variant_dl(&trial);
                let old_dl = variant_dl(ruleset);

                if old_dl <= revision_dl && old_dl <= replacement_dl {
                    ruleset[position].clone()
                } else if revision_dl <= replacement_dl {
                    revision
                } else {
                    replacement
                }
            };

            fin.add_and_update(final_rule.clone(), table);
            let last = fin.len() - 1;
            let rule_stats = fin.stats[last];
            if is_residual {
                dl += fin.relative_dl(last, ctx, table);
                if dl < min_dl {
                    min_dl = dl;
                }
                stop = should_stop(&rule_stats, min_dl, dl, ctx.check_err);
                if stop {
                    fin.remove_last();
                } else {
                    ruleset.push(final_rule);
                }
            } else {
                ruleset[position] = final_rule;
            }
            if fin.len() > 0 {
                left = fin.uncovered_by_last().to_vec();
            }
            has_positive = gr(rule_stats.false_neg, 0.0);
            if !stop {
                position += 1;
            }
        }
        // Weka's `position + 1`: see the module docs
        if ruleset.len() > position + 1 {
            for rule in &ruleset[position + 1..] {
                fin.add_and_update(rule.clone(), table);
            }
        }
        fin.reduce_dl(ctx, table);
        ruleset.clone_from(&fin.rules);
        fin
    }
}

/// JRip's `checkStop`.
fn should_stop(rule: &SimpleStats, min_dl: f64, dl: f64, check_err: bool) -> bool {
    if dl > min_dl + MAX_DL_SURPLUS || !gr(rule.true_pos, 0.0) {
        true
    } else if rule.false_pos / rule.covered >= 0.5 {
        check_err
    } else {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stats(covered: f64, true_pos: f64) -> SimpleStats {
        SimpleStats { covered, true_pos, false_pos: covered - true_pos, ..SimpleStats::default() }
    }

    #[test]
    fn stop_on_dl_surplus_no_positive_or_high_error() {
        assert!(!should_stop(&stats(10.0, 9.0), 0.0, 64.0, true));
        assert!(should_stop(&stats(10.0, 9.0), 0.0, 64.5, true));
        assert!(should_stop(&stats(10.0, 0.0), 0.0, 0.0, true));
        assert!(should_stop(&stats(10.0, 5.0), 0.0, 0.0, true));
        assert!(!should_stop(&stats(10.0, 5.0), 0.0, 0.0, false));
        assert!(!should_stop(&stats(10.0, 6.0), 0.0, 0.0, true));
    }
}
