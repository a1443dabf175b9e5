//! The learner's output: conditions, rules and the ordered decision list,
//! with prediction and the two text forms (the thesis's `if … elseif … else`
//! and Weka's `JRIP rules:` listing).
//!
//! What it is: plain data (serialisable) plus `predict`. Classes and
//! attributes are the dataset's original indices, whatever order the learner
//! visited the classes in.
//!
//! What it is not: the learner. The one piece of learning logic here is
//! [`clean_up`], JRip's final removal of redundant numeric tests
//! (`RipperRule.cleanUp` in JRip.java, Weka commit 0b4f0571).

use std::fmt::{self, Write as _};

use serde::{Deserialize, Serialize};

use super::{Attribute, AttributeKind};

/// The test a condition applies to its attribute.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Operator {
    /// Numeric `x <= value` (JRip's first bag).
    LessEq,
    /// Numeric `x >= value` (JRip's second bag).
    GreaterEq,
    /// Nominal `x = value`, the value's index.
    Equal,
}

/// One antecedent of a rule. A missing value (NaN) never satisfies it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Condition {
    /// Index of the tested attribute.
    pub attribute: usize,
    /// The test.
    pub op: Operator,
    /// The split point (numeric) or the value's index (nominal).
    pub value: f64,
}

impl Condition {
    /// Whether the attribute value `x` satisfies the condition; NaN never does.
    pub fn holds(&self, x: f64) -> bool {
        match self.op {
            Operator::LessEq => x <= self.value,
            Operator::GreaterEq => x >= self.value,
            Operator::Equal => x == self.value,
        }
    }
}

/// What a rule covered on the training data, rules taken in order (an
/// instance counts for the first rule that covers it only).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Coverage {
    /// Total weight covered (Weka prints it first in `(covered/errors)`).
    pub covered: f64,
    /// Weight covered of another class than the rule's.
    pub false_positives: f64,
    /// Weight covered per class, indexed like the dataset's class names.
    /// Normalised, this is the class distribution Weka predicts.
    pub class_weights: Vec<f64>,
}

/// A conjunction of conditions that predicts a class.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Rule {
    /// The antecedents, in the order they were grown.
    pub conditions: Vec<Condition>,
    /// The predicted class (index into the dataset's class names).
    pub class: usize,
    /// Training coverage.
    pub coverage: Coverage,
}

impl Rule {
    /// Whether every condition holds for `x`. Attributes beyond `x`'s length
    /// count as missing.
    pub fn covers(&self, x: &[f64]) -> bool {
        self.conditions.iter().all(|c| x.get(c.attribute).is_some_and(|&v| c.holds(v)))
    }
}

/// An ordered rule list: the first rule that covers an instance predicts its
/// class, and the default class catches the rest.
///
/// `Display` prints the thesis's form, numbers with 2 decimals unless a
/// precision is given (`format!("{list:.4}")`):
///
/// ```text
/// if (state_11 >= 74.84 and state_3 <= 5.99) -> Action = 1
/// elseif (state_3 <= 4.84) -> Action = 2
/// else -> Action = 0
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DecisionList {
    /// The rules, in the order they are tried.
    pub rules: Vec<Rule>,
    /// The class predicted when no rule covers (the most frequent class).
    pub default_class: usize,
    /// Training coverage of the default rule (what no rule covered).
    pub default_coverage: Coverage,
    attributes: Vec<Attribute>,
    class_attribute: String,
    class_names: Vec<String>,
}

impl DecisionList {
    pub(crate) fn new(
        rules: Vec<Rule>,
        default_class: usize,
        default_coverage: Coverage,
        attributes: Vec<Attribute>,
        class_attribute: String,
        class_names: Vec<String>,
    ) -> Self {
        Self { rules, default_class, default_coverage, attributes, class_attribute, class_names }
    }

    /// The class of the first rule that covers `x`, else the default class.
    /// This is the decision list as printed, and as a demonstration-following
    /// agent uses it.
    pub fn predict(&self, x: &[f64]) -> usize {
        self.rules.iter().find(|r| r.covers(x)).map_or(self.default_class, |r| r.class)
    }

    /// Weka's `classifyInstance`: the most frequent training class (lowest
    /// index on ties) among what the first covering rule covered, else the
    /// default rule's. It differs from [`Self::predict`] only for a rule (or
    /// the default) whose covered training data are not mostly its own class.
    /// Where the rule covered nothing (Weka would throw when normalising), it
    /// falls back to the rule's class.
    pub fn predict_by_distribution(&self, x: &[f64]) -> usize {
        let (class, coverage) = self
            .rules
            .iter()
            .find(|r| r.covers(x))
            .map_or((self.default_class, &self.default_coverage), |r| (r.class, &r.coverage));
        let mut best: Option<(usize, f64)> = None;
        for (c, &w) in coverage.class_weights.iter().enumerate() {
            if best.is_none_or(|(_, bw)| w > bw) {
                best = Some((c, w));
            }
        }
        match best {
            Some((c, w)) if w > 0.0 => c,
            _ => class,
        }
    }

    /// The attributes the conditions index.
    pub fn attributes(&self) -> &[Attribute] {
        &self.attributes
    }

    /// The class variable's name.
    pub fn class_attribute(&self) -> &str {
        &self.class_attribute
    }

    /// The class names the rules' classes index.
    pub fn class_names(&self) -> &[String] {
        &self.class_names
    }

    /// Weka's `JRip.toString()` listing: one line per rule with
    /// `(covered/false positives)`, numbers with up to 6 decimals, the
    /// default rule last, then the number of rules (default included).
    pub fn to_weka_string(&self) -> String {
        let mut out = String::from("JRIP rules:\n===========\n\n");
        let class_text = |class: usize| {
            format!("{}={}", self.class_attribute, self.class_names.get(class).map_or("?", String::as_str))
        };
        for rule in &self.rules {
            let antecedents: Vec<String> =
                rule.conditions.iter().map(|c| format!("({})", self.condition_text(c, weka_number))).collect();
            let _ = writeln!(
                out,
                "{} => {} ({}/{})",
                antecedents.join(" and "),
                class_text(rule.class),
                java_double(rule.coverage.covered),
                java_double(rule.coverage.false_positives)
            );
        }
        let _ = writeln!(
            out,
            " => {} ({}/{})",
            class_text(self.default_class),
            java_double(self.default_coverage.covered),
            java_double(self.default_coverage.false_positives)
        );
        let _ = write!(out, "\nNumber of Rules : {}\n", self.rules.len() + 1);
        out
    }

    fn condition_text(&self, c: &Condition, number: impl Fn(f64) -> String) -> String {
        let attribute = self.attributes.get(c.attribute);
        let name = attribute.map_or("?", |a| a.name.as_str());
        match c.op {
            Operator::LessEq => format!("{name} <= {}", number(c.value)),
            Operator::GreaterEq => format!("{name} >= {}", number(c.value)),
            Operator::Equal => {
                let value = match attribute.map(|a| &a.kind) {
                    Some(AttributeKind::Nominal { values }) => {
                        values.get(c.value as usize).cloned().unwrap_or_else(|| c.value.to_string())
                    }
                    _ => c.value.to_string(),
                };
                format!("{name} = {value}")
            }
        }
    }
}

impl fmt::Display for DecisionList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let precision = f.precision().unwrap_or(2);
        let number = |v: f64| format!("{v:.precision$}");
        let class_text = |class: usize| {
            format!("{} = {}", self.class_attribute, self.class_names.get(class).map_or("?", String::as_str))
        };
        for (i, rule) in self.rules.iter().enumerate() {
            let keyword = if i == 0 { "if" } else { "elseif" };
            let antecedents = if rule.conditions.is_empty() {
                "true".to_string()
            } else {
                rule.conditions.iter().map(|c| self.condition_text(c, number)).collect::<Vec<_>>().join(" and ")
            };
            writeln!(f, "{keyword} ({antecedents}) -> {}", class_text(rule.class))?;
        }
        if self.rules.is_empty() {
            write!(f, "-> {}", class_text(self.default_class))
        } else {
            write!(f, "else -> {}", class_text(self.default_class))
        }
    }
}

/// JRip's `cleanUp`: scanning the conditions from last to first, keep a
/// numeric `<=` only if its split point is strictly below every later `<=` on
/// the same attribute, and a `>=` only if strictly above every later `>=`.
/// Nominal conditions stay. Coverage never changes: a removed test is implied
/// by a kept one.
pub(crate) fn clean_up(conditions: &mut Vec<Condition>, n_attributes: usize) {
    let mut upper = vec![f64::MAX; n_attributes];
    let mut lower = vec![-f64::MAX; n_attributes];
    let mut keep = vec![true; conditions.len()];
    for (i, c) in conditions.iter().enumerate().rev() {
        match c.op {
            Operator::LessEq if c.value < upper[c.attribute] => upper[c.attribute] = c.value,
            Operator::GreaterEq if c.value > lower[c.attribute] => lower[c.attribute] = c.value,
            Operator::LessEq | Operator::GreaterEq => keep[i] = false,
            Operator::Equal => {}
        }
    }
    let mut flags = keep.into_iter();
    conditions.retain(|_| flags.next().unwrap_or(true));
}

/// Weka's `Utils.doubleToString(v, 6)`: at most 6 decimals, no trailing zeros.
fn weka_number(v: f64) -> String {
    let text = format!("{v:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" { "0".to_string() } else { text.to_string() }
}

/// Java's `Double.toString` for the weights Weka prints: integral values
/// keep one decimal (`12.0`).
fn java_double(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e7 { format!("{v:.1}") } else { format!("{v}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn le(attribute: usize, value: f64) -> Condition {
        Condition { attribute, op: Operator::LessEq, value }
    }

    fn ge(attribute: usize, value: f64) -> Condition {
        Condition { attribute, op: Operator::GreaterEq, value }
    }

    fn coverage(covered: f64, false_positives: f64, class_weights: Vec<f64>) -> Coverage {
        Coverage { covered, false_positives, class_weights }
    }

    /// The thesis's chapter-5 list (state_11, state_3, … ; Action 0/1/2),
    /// abridged to two rules.
    fn thesis_like() -> DecisionList {
        let attributes = (0..13).map(|k| Attribute::numeric(format!("state_{k}"))).collect();
        let rules = vec![
            Rule {
                conditions: vec![ge(11, 74.84), le(3, 5.99), le(11, 76.26)],
                class: 1,
                coverage: coverage(12.0, 1.0, vec![1.0, 11.0, 0.0]),
            },
            Rule {
                conditions: vec![le(3, 4.84), ge(0, 7.33)],
                class: 2,
                coverage: coverage(5.0, 3.0, vec![3.0, 0.0, 2.0]),
            },
        ];
        DecisionList::new(
            rules,
            0,
            coverage(40.0, 4.5, vec![35.5, 2.0, 2.5]),
            attributes,
            "Action".into(),
            vec!["0".into(), "1".into(), "2".into()],
        )
    }

    #[test]
    fn display_follows_the_thesis() {
        let expected = "\
if (state_11 >= 74.84 and state_3 <= 5.99 and state_11 <= 76.26) -> Action = 1
elseif (state_3 <= 4.84 and state_0 >= 7.33) -> Action = 2
else -> Action = 0";
        assert_eq!(thesis_like().to_string(), expected);
        assert!(format!("{:.3}", thesis_like()).starts_with("if (state_11 >= 74.840 and"));
    }

    #[test]
    fn weka_text_lists_rules_with_coverage() {
        let expected = "\
JRIP rules:
===========

(state_11 >= 74.84) and (state_3 <= 5.99) and (state_11 <= 76.26) => Action=1 (12.0/1.0)
(state_3 <= 4.84) and (state_0 >= 7.33) => Action=2 (5.0/3.0)
 => Action=0 (40.0/4.5)

Number of Rules : 3
";
        assert_eq!(thesis_like().to_weka_string(), expected);
    }

    #[test]
    fn predict_takes_the_first_covering_rule() {
        let list = thesis_like();
        let mut x = vec![0.0; 13];
        x[11] = 75.0;
        x[3] = 4.0;
        x[0] = 8.0;
        assert_eq!(list.predict(&x), 1, "both rules cover; the first wins");
        x[11] = 80.0;
        assert_eq!(list.predict(&x), 2);
        x[0] = f64::NAN;
        assert_eq!(list.predict(&x), 0, "a missing value fails its condition");
        assert_eq!(list.predict(&[]), 0, "absent attributes count as missing");
    }

    #[test]
    fn predict_by_distribution_follows_the_covered_classes() {
        let list = thesis_like();
        let mut x = vec![0.0; 13];
        x[3] = 4.0;
        x[0] = 8.0;
        // the second rule covered 3 of class 0 and 2 of its own class 2
        assert_eq!(list.predict(&x), 2);
        assert_eq!(list.predict_by_distribution(&x), 0);
        x[3] = 9.0;
        assert_eq!(list.predict_by_distribution(&x), 0);
    }

    #[test]
    fn clean_up_keeps_the_tightest_later_tests() {
        let mut conditions = vec![le(0, 7.0), le(0, 5.0), ge(0, 1.0), ge(0, 3.0), le(1, 2.0)];
        clean_up(&mut conditions, 2);
        assert_eq!(conditions, vec![le(0, 5.0), ge(0, 3.0), le(1, 2.0)]);
    }

    #[test]
    fn clean_up_drops_an_equal_earlier_test_and_keeps_a_tighter_earlier_one() {
        // JRip compares strictly and scans from the end: an equal earlier
        // test goes, a strictly tighter earlier test stays with the later one
        let mut equal = vec![ge(0, 2.0), ge(0, 2.0)];
        clean_up(&mut equal, 1);
        assert_eq!(equal, vec![ge(0, 2.0)]);
        let mut tighter_first = vec![le(0, 5.0), le(0, 7.0)];
        clean_up(&mut tighter_first, 1);
        assert_eq!(tighter_first, vec![le(0, 5.0), le(0, 7.0)]);
    }

    #[test]
    fn clean_up_leaves_nominal_tests() {
        let eq = Condition { attribute: 0, op: Operator::Equal, value: 1.0 };
        let mut conditions = vec![eq, eq];
        clean_up(&mut conditions, 1);
        assert_eq!(conditions.len(), 2);
    }

    #[test]
    fn number_formats_follow_weka() {
        assert_eq!(weka_number(74.84), "74.84");
        assert_eq!(weka_number(5.0), "5");
        assert_eq!(weka_number(1.0 / 3.0), "0.333333");
        assert_eq!(java_double(12.0), "12.0");
        assert_eq!(java_double(4.5), "4.5");
    }
}
