//! The numbers each chapter-5 claim turns on, for the scorecard: the
//! thesis's Tables 5.1–5.4 means (jumpstart, final and total reward), its
//! hours to the threshold and its teachers' mean demonstrations, beside ours.
//! Rendering only: no verdict reads them. A value the thesis does not give
//! is NaN (shown as a dash), never filled in.

use rlfd_report::claims::KeyNumber;
use rlfd_report::table::NumFormat;

use super::metrics::Metric;
use super::tables::{Analysis, thesis, thesis_demo_mean, thesis_hours};
use crate::experiment::Condition;
use crate::inputs::DemoSetId;
use crate::learners::Method;

/// Seconds as Tables 5.1–5.4 show ours (two decimals).
const SECONDS: NumFormat = NumFormat::fixed(2);

/// The format of a metric, as the chapter's tables write it.
fn format(m: Metric) -> NumFormat {
    if m == Metric::Total { NumFormat::fixed(1) } else { SECONDS }
}

/// A metric in words, with its unit.
fn words(m: Metric) -> &'static str {
    match m {
        Metric::Jumpstart => "jumpstart (s)",
        Metric::Final => "final reward (s)",
        Metric::Total => "total reward",
    }
}

/// A condition as the scorecard names it: `No Prior`, `Value Bonus (A)`,
/// `PPR, Subject B`.
pub fn condition_name(c: &Condition) -> String {
    let set = c.set.map_or("", DemoSetId::label);
    match c.method {
        Method::NoPrior => "No Prior".into(),
        Method::ValueBonus { .. } | Method::ExtraAction { .. } if c.set == Some(DemoSetId::A20) => {
            format!("{} (A)", c.method.label())
        }
        Method::ValueBonus { .. } | Method::ExtraAction { .. } => format!("{}, {set}", c.method.label()),
        Method::PolicyReuse { .. } => format!("PPR, {set}"),
    }
}

/// The thesis's mean of `m` for a condition: Table 5.1 for No Prior and the
/// methods on Subject A's rules, Table 5.3 for PPR on Subject A's and C's
/// sets, Table 5.4 for PPR on Subject B's (the tables agree where they
/// repeat a condition); NaN where the thesis has no such condition.
pub fn thesis_value(c: &Condition, m: Metric) -> f64 {
    match (c.method, c.set) {
        (Method::NoPrior, _) => thesis("ch5.table_5_1", m.key(), "No Prior"),
        (Method::ValueBonus { .. } | Method::ExtraAction { .. }, Some(DemoSetId::A20)) => {
            thesis("ch5.table_5_1", m.key(), c.method.label())
        }
        (Method::PolicyReuse { .. }, Some(set)) => {
            let table = match set {
                DemoSetId::B | DemoSetId::BLimited | DemoSetId::BFast => "ch5.table_5_4",
                _ => "ch5.table_5_3",
            };
            thesis(table, m.key(), set.label())
        }
        _ => f64::NAN,
    }
}

/// `m`'s means of the `compared` conditions, in order, the thesis's beside
/// ours; labelled `total reward: No Prior vs Value Bonus vs …`.
pub fn means(a: &Analysis, m: Metric, compared: &[(&str, &Condition)]) -> KeyNumber {
    let names: Vec<&str> = compared.iter().map(|(l, _)| *l).collect();
    let theirs: Vec<f64> = compared.iter().map(|(_, c)| thesis_value(c, m)).collect();
    let ours: Vec<f64> = compared.iter().map(|(_, c)| a.summary(c, m).map_or(f64::NAN, |s| s.0)).collect();
    KeyNumber::new(format!("{}: {}", words(m), names.join(" vs ")), &theirs, &ours, format(m))
}

/// Hours until the trial-mean training curve reaches `threshold` s (NaN:
/// never), the thesis's beside ours.
pub fn hours(a: &Analysis, threshold: f64, compared: &[(&str, &Condition)]) -> KeyNumber {
    let names: Vec<&str> = compared.iter().map(|(l, _)| *l).collect();
    let theirs: Vec<f64> = compared.iter().map(|(_, c)| thesis_hours(c)).collect();
    let ours: Vec<f64> = compared.iter().map(|(_, c)| a.hours(c).unwrap_or(f64::NAN)).collect();
    KeyNumber::new(format!("hours to {threshold} s: {}", names.join(" vs ")), &theirs, &ours, NumFormat::fixed(2))
}

/// The thesis's mean demonstration (s) of the teacher C5.9 compares a
/// condition with: Subject A's 20 for No Prior and A (10), the set's own
/// otherwise; NaN for the A + C sets, whose teacher is A's and C's 40
/// episodes together, a mean the thesis does not give.
fn thesis_teacher_mean(c: &Condition) -> f64 {
    match c.set {
        None | Some(DemoSetId::A20) | Some(DemoSetId::A10) => thesis_demo_mean(DemoSetId::A20),
        Some(DemoSetId::AcBest) | Some(DemoSetId::AcWorst) => f64::NAN,
        Some(id) => thesis_demo_mean(id),
    }
}

/// A condition's final reward beside its teacher's mean demonstration (C5.9).
pub fn final_against_teacher(a: &Analysis, c: &Condition, teacher_mean: f64) -> KeyNumber {
    let ours = a.summary(c, Metric::Final).map_or(f64::NAN, |s| s.0);
    KeyNumber::new(
        format!("{}: final vs teacher (s)", condition_name(c)),
        &[thesis_value(c, Metric::Final), thesis_teacher_mean(c)],
        &[ours, teacher_mean],
        SECONDS,
    )
}

/// Subject A's rules played with the learners' exploration beside No
/// Prior's final reward (C5.10); the thesis gives no number for the rules.
pub fn rules_against_final(epsilon: f64, rules: f64, no_prior_final: f64) -> KeyNumber {
    KeyNumber::new(
        format!("Subject A's rules at ε = {epsilon} vs No Prior's final reward (s)"),
        &[f64::NAN, thesis_value(&Condition::NO_PRIOR, Metric::Final)],
        &[rules, no_prior_final],
        SECONDS,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conditions_are_named_and_read_from_the_thesis_s_tables() {
        let a20 = |method| Condition { method, set: Some(DemoSetId::A20) };
        assert_eq!(condition_name(&Condition::NO_PRIOR), "No Prior");
        assert_eq!(condition_name(&a20(Method::VALUE_BONUS)), "Value Bonus (A)");
        assert_eq!(condition_name(&Condition::ppr(DemoSetId::BLimited)), "PPR, Limited Actions");
        // Table 5.1 for the methods, 5.3 and 5.4 for the sets.
        assert_eq!(thesis_value(&a20(Method::EXTRA_ACTION), Metric::Final), 16.0);
        assert_eq!(thesis_value(&Condition::ppr(DemoSetId::A20), Metric::Total), 411.0);
        assert_eq!(thesis_value(&Condition::ppr(DemoSetId::AcBest), Metric::Total), 431.0);
        assert_eq!(thesis_value(&Condition::ppr(DemoSetId::A10), Metric::Jumpstart), -2.23);
        assert_eq!(thesis_value(&Condition::ppr(DemoSetId::B), Metric::Jumpstart), 3.35);
        assert_eq!(thesis_value(&Condition::ppr(DemoSetId::BFast), Metric::Total), 401.0);
        // The thesis gives No Prior no jumpstart and no Value Bonus on B's rules.
        assert!(thesis_value(&Condition::NO_PRIOR, Metric::Jumpstart).is_nan());
        assert!(
            thesis_value(&Condition { method: Method::VALUE_BONUS, set: Some(DemoSetId::B) }, Metric::Final).is_nan()
        );
    }

    #[test]
    fn teachers_and_rules_carry_only_the_thesis_s_numbers() {
        let value = |k: &KeyNumber| -> (Vec<f64>, Vec<f64>) {
            (k.thesis.iter().map(|n| n.value).collect(), k.ours.iter().map(|n| n.value).collect())
        };
        let a = Analysis {
            metrics: Default::default(),
            hours_to: Default::default(),
            no_prior_initial: f64::NAN,
            threshold: 14.0,
            trials: 0,
        };
        let k = final_against_teacher(&a, &Condition::ppr(DemoSetId::BLimited), 5.5);
        assert_eq!(k.label, "PPR, Limited Actions: final vs teacher (s)");
        let (theirs, ours) = value(&k);
        assert_eq!(theirs, [16.0, 5.2]);
        assert!(ours[0].is_nan() && ours[1] == 5.5);
        let (theirs, _) = value(&final_against_teacher(&a, &Condition::ppr(DemoSetId::AcWorst), 9.0));
        assert_eq!(theirs[0], 16.1);
        assert!(theirs[1].is_nan(), "the thesis gives no pooled A + C mean");
        assert_eq!(value(&final_against_teacher(&a, &Condition::NO_PRIOR, 9.0)).0, [14.3, 10.4]);
        let k = rules_against_final(0.1, 8.25, 14.75);
        assert_eq!(k.label, "Subject A's rules at ε = 0.1 vs No Prior's final reward (s)");
        let (theirs, ours) = value(&k);
        assert!(theirs[0].is_nan() && theirs[1] == 14.3);
        assert_eq!(ours, [8.25, 14.75]);
    }
}
