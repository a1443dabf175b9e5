//! The analysis plan's verdict on all replications together
//! (`rlfd_report::plan`): each component of a claim has one estimate per
//! replication; the K estimates are tested with a one-sample t-test
//! (replication means, the replication as the unit), the claim is decided by
//! intersection–union over its components, and the power at the thesis's
//! effect limits what a negative result may say.
//!
//! A directional component is *reproduced* when its 95 % interval lies above
//! 0; *not reproduced* when the interval lies entirely below 0, or below the
//! smallest effect of interest (d33 of the thesis's design, in the
//! component's within-replication SD) while the power at the thesis's effect
//! reaches the plan's threshold; otherwise *inconclusive*. An equivalence
//! component is reproduced when its 90 % interval lies inside ±margin, not
//! reproduced when its 95 % interval lies entirely outside, else
//! inconclusive. A yes/no component (an order, a first-to-cross) is pooled
//! by the exact binomial rule: reproduced when the Clopper–Pearson 95 %
//! interval of the rate at which it holds lies above one half, not
//! reproduced when below, else inconclusive. A component defined in fewer
//! than half the replications (or in fewer than two) is not evaluable.

use rlfd_report::claims::{Claim, Direction, Verdict};
use rlfd_report::plan::{AnalysisPlan, ClaimPlan};
use rlfd_report::robustness::{Pooled, PooledComponent};
use rlfd_stats::{OneSample, clopper_pearson, one_sample_power};

/// The pooled verdict of a claim from its instances, one per replication
/// (`None` when the claim has no estimates).
pub fn pool(plan: &AnalysisPlan, replications: &[Option<&Claim>]) -> Option<Pooled> {
    let first = replications.iter().flatten().next()?;
    if first.estimates.is_empty() {
        return None;
    }
    let claim_plan = plan.claim(&first.id);
    let components: Vec<PooledComponent> = first
        .estimates
        .iter()
        .enumerate()
        .map(|(k, e)| {
            let same: Vec<_> = replications
                .iter()
                .flatten()
                .filter_map(|c| c.estimates.get(k).filter(|x| x.label == e.label))
                .collect();
            let values: Vec<f64> = same.iter().filter_map(|x| x.value).collect();
            let sds: Vec<f64> = same.iter().filter_map(|x| x.sd).collect();
            let sd_within = if sds.is_empty() { None } else { Some(sds.iter().sum::<f64>() / sds.len() as f64) };
            component(plan, claim_plan, &e.label, e.direction, e.thesis, &values, sd_within, replications.len())
        })
        .collect();
    Some(Pooled { verdict: conjunction(components.iter().map(|c| c.verdict)), components })
}

/// Intersection–union: reproduced when every component is; not reproduced
/// when one is (even beside a component that is not evaluable);
/// otherwise not evaluable when one is, else inconclusive.
pub fn conjunction(verdicts: impl IntoIterator<Item = Verdict>) -> Verdict {
    let all: Vec<Verdict> = verdicts.into_iter().collect();
    if all.is_empty() {
        Verdict::NotEvaluable
    } else if all.contains(&Verdict::NotReproduced) {
        Verdict::NotReproduced
    } else if all.contains(&Verdict::NotEvaluable) {
        Verdict::NotEvaluable
    } else if all.iter().all(|v| *v == Verdict::Reproduced) {
        Verdict::Reproduced
    } else {
        Verdict::Inconclusive
    }
}

#[allow(clippy::too_many_arguments)]
fn component(
    plan: &AnalysisPlan,
    claim_plan: Option<&ClaimPlan>,
    label: &str,
    direction: Direction,
    thesis: Option<f64>,
    values: &[f64],
    sd_within: Option<f64>,
    planned: usize,
) -> PooledComponent {
    let n = values.len();
    let mean = if n == 0 { f64::NAN } else { values.iter().sum::<f64>() / n as f64 };
    let done = |lower, upper, power, verdict| PooledComponent {
        label: label.into(),
        replications: n,
        mean,
        lower,
        upper,
        power,
        verdict,
        sd_within,
        thesis,
        direction,
    };
    let undecided = |verdict| done(f64::NAN, f64::NAN, None, verdict);
    if n < 2 || 2 * n < planned {
        return undecided(Verdict::NotEvaluable);
    }
    let alpha = plan.conventions.alpha;
    if direction == Direction::Holds {
        // The exact binomial rule: the rate at which the property holds,
        // with its Clopper–Pearson interval against one half.
        let k = values.iter().filter(|v| **v > 0.5).count();
        let (lower, upper) = clopper_pearson(k, n, 1.0 - alpha).unwrap_or((f64::NAN, f64::NAN));
        let verdict = if lower > 0.5 {
            Verdict::Reproduced
        } else if upper < 0.5 {
            Verdict::NotReproduced
        } else {
            Verdict::Inconclusive
        };
        return done(lower, upper, None, verdict);
    }
    let level = match direction {
        Direction::Above | Direction::Holds => 1.0 - alpha,
        Direction::Equivalent { .. } => 1.0 - 2.0 * alpha,
    };
    let (lower, upper, sd_between) = match OneSample::of(values, 0.0, level) {
        Ok(t) => (t.lower, t.upper, t.sd),
        // Every replication gave the same estimate: the interval is that point.
        Err(_) => (mean, mean, 0.0),
    };
    let power = thesis.filter(|_| sd_between > 0.0).and_then(|e| one_sample_power(e, sd_between, n, alpha).ok());
    let verdict = match direction {
        Direction::Holds => unreachable!("decided above"),
        Direction::Above => {
            let sesoi = claim_plan.and_then(|c| c.d33(&plan.conventions)).zip(sd_within).map_or(0.0, |(d, s)| d * s);
            let powered = power.is_some_and(|p| p >= plan.conventions.power_threshold);
            if lower > 0.0 {
                Verdict::Reproduced
            } else if upper < 0.0 || (powered && upper < sesoi) {
                Verdict::NotReproduced
            } else {
                Verdict::Inconclusive
            }
        }
        Direction::Equivalent { margin } => {
            let wide = OneSample::of(values, 0.0, 1.0 - alpha).map_or((mean, mean), |t| (t.lower, t.upper));
            if lower > -margin && upper < margin {
                Verdict::Reproduced
            } else if wide.0 > margin || wide.1 < -margin {
                Verdict::NotReproduced
            } else {
                Verdict::Inconclusive
            }
        }
    };
    done(lower, upper, power, verdict)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_report::claims::Estimate;
    use rlfd_report::plan::analysis_plan;

    fn claim(id: &str, estimates: Vec<Estimate>) -> Claim {
        Claim::from_spec(id, "", "", Verdict::Reproduced, "").unwrap().with_estimates(estimates)
    }

    fn pooled(values: &[f64], sd: f64, thesis: Option<f64>) -> Pooled {
        let claims: Vec<Claim> =
            values.iter().map(|&v| claim("C5.1", vec![Estimate::above("VB vs NP", v, sd, thesis)])).collect();
        let refs: Vec<Option<&Claim>> = claims.iter().map(Some).collect();
        pool(analysis_plan(), &refs).unwrap()
    }

    /// The interval is SciPy's: `ttest_1samp([1.2, 0.4, 2.2, 1.9, 0.7, 1.1,
    /// 3.0, -0.2], 0).confidence_interval(0.95)` = (0.4204791052408815,
    /// 2.154520894759118), above 0: reproduced.
    #[test]
    fn an_interval_above_zero_reproduces() {
        let p = pooled(&[1.2, 0.4, 2.2, 1.9, 0.7, 1.1, 3.0, -0.2], 1.0, None);
        let c = &p.components[0];
        assert!((c.lower - 0.4204791052408815).abs() < 1e-8 && (c.upper - 2.154520894759118).abs() < 1e-8);
        assert_eq!((c.verdict, p.verdict), (Verdict::Reproduced, Verdict::Reproduced));
    }

    #[test]
    fn only_a_powered_test_may_exclude_the_thesis_s_effect() {
        // Small positive estimates, interval straddling 0 but below the
        // smallest effect of interest (d33 = 0.722 for n = 10 × sd 10 = 7.2).
        let values = [0.5, -0.3, 0.2, 0.1, -0.1, 0.4, 0.0, 0.3, -0.2, 0.1];
        // No thesis effect, no power: inconclusive.
        assert_eq!(pooled(&values, 10.0, None).verdict, Verdict::Inconclusive);
        // A large thesis effect gives power ≈ 1: the data exclude it.
        let p = pooled(&values, 10.0, Some(5.0));
        assert!(p.components[0].power.unwrap() > 0.99);
        assert_eq!(p.verdict, Verdict::NotReproduced);
        // A tiny thesis effect gives little power: inconclusive.
        assert_eq!(pooled(&values, 10.0, Some(0.01)).verdict, Verdict::Inconclusive);
        // Significantly opposite: not reproduced whatever the power.
        assert_eq!(pooled(&[-1.0, -1.2, -0.8, -1.1, -0.9], 1.0, None).verdict, Verdict::NotReproduced);
    }

    #[test]
    fn equivalence_needs_the_90_percent_interval_inside_the_margin() {
        let one = |values: &[f64], margin: f64| {
            let claims: Vec<Claim> = values
                .iter()
                .map(|&v| claim("C6.3", vec![Estimate::equivalent("SAR vs SIS", v, 1.0, margin)]))
                .collect();
            let refs: Vec<Option<&Claim>> = claims.iter().map(Some).collect();
            pool(analysis_plan(), &refs).unwrap().verdict
        };
        let values = [0.5, -0.3, 0.2, 0.1, -0.1, 0.4, 0.0, 0.3, -0.2, 0.1];
        assert_eq!(one(&values, 1.0), Verdict::Reproduced);
        assert_eq!(one(&values, 0.1), Verdict::Inconclusive);
        assert_eq!(one(&[5.0, 5.2, 4.9, 5.1], 1.0), Verdict::NotReproduced);
    }

    #[test]
    fn a_yes_no_property_is_pooled_by_the_binomial_rule() {
        let one = |held: usize, of: usize| {
            let claims: Vec<Claim> =
                (0..of).map(|k| claim("C6.4", vec![Estimate::holds("SIS first", k < held)])).collect();
            let refs: Vec<Option<&Claim>> = claims.iter().map(Some).collect();
            pool(analysis_plan(), &refs).unwrap()
        };
        // SciPy: binomtest(9, 10).proportion_ci(0.95) = (0.555, 0.997); (8, 10) = (0.444, 0.975).
        assert_eq!(one(9, 10).verdict, Verdict::Reproduced);
        assert_eq!(one(8, 10).verdict, Verdict::Inconclusive);
        assert_eq!(one(1, 10).verdict, Verdict::NotReproduced);
        assert_eq!(one(2, 10).verdict, Verdict::Inconclusive);
        assert!((one(9, 10).components[0].mean - 0.9).abs() < 1e-12);
    }

    #[test]
    fn undefined_estimates_make_a_component_not_evaluable_and_not_reproduced_wins() {
        let claims: Vec<Claim> = (0..10)
            .map(|k| {
                claim(
                    "C6.7",
                    vec![
                        Estimate::above("SIS vs HAT", -1.0 - 0.1 * f64::from(k), 1.0, None),
                        Estimate::above("DIS vs HAT", if k < 3 { 1.0 } else { f64::NAN }, 1.0, None),
                    ],
                )
            })
            .collect();
        let refs: Vec<Option<&Claim>> = claims.iter().map(Some).collect();
        let p = pool(analysis_plan(), &refs).unwrap();
        assert_eq!(p.components[1].verdict, Verdict::NotEvaluable);
        assert_eq!(p.verdict, Verdict::NotReproduced);
        assert_eq!(conjunction([Verdict::Reproduced, Verdict::Inconclusive]), Verdict::Inconclusive);
        assert_eq!(conjunction([Verdict::Reproduced, Verdict::NotEvaluable]), Verdict::NotEvaluable);
    }
}
