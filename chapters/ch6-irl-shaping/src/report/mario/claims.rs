//! Verdicts on the thesis's Mario claims C6.6–C6.9 (the five agents),
//! computed from the data with the tests `claims.md` names, decided as
//! [`crate::report::family`] says; C6.10 is decided with the
//! demonstration-length study's section. Nothing here knows what the
//! thesis's answer was.

use rlfd_harness::Scale;
use rlfd_report::claims::{Check, Claim, TestOutcome, Verdict};
use rlfd_report::published::published;
use rlfd_stats::format::thousands;

use super::scorecard::{self, HALF};
use super::{bin_size, mean_binned};
use crate::mario::demonstrator::thesis as demo_thesis;
use crate::mario::experiment::MarioResults;
use crate::mario::params::BASELINE;
use crate::report::claims::{MIN_TRIALS_FOR_TESTS, holds_unless_diverged};
use crate::report::family::Family;
use crate::report::metrics::{Crossings, Metric, MetricTable, alone_first};
use crate::shaping::Agent;

/// Decidable when `ok`, else: too few trials for the thesis's tests.
pub(super) fn check(ok: bool, trials: usize) -> Check {
    Check::when(ok, || {
        let p = published();
        format!(
            "{trials} trials per agent at the quick scale are too few for the thesis's tests (it used {} trials of {} episodes); the evidence is shown for the record",
            p.number("ch6.mario.trials").unwrap_or(f64::NAN),
            thousands(p.number("ch6.mario.episodes").unwrap_or(f64::NAN), 0)
        )
    })
}

/// A mean for the evidence, or what stands in for it when every trial diverged.
fn mean_text(x: f64, decimals: usize) -> String {
    if x.is_nan() { "(every trial diverged)".into() } else { thousands(x, decimals) }
}

/// [`check`], unless a learner the claim rests on diverged.
fn check_agents(ok: bool, trials: usize, r: &MarioResults, agents: &[Agent]) -> Check {
    match crate::report::diverged_agents(&r.diverged, agents, BASELINE, r.params.trials) {
        Some(why) => Check::Undecidable(why),
        None => check(ok, trials),
    }
}

/// What the claims C6.6–C6.9 and C6.12 read: the agents' trials, their
/// metrics and whether the thesis's tests apply (paper scale, enough trials).
struct Context<'a> {
    r: &'a MarioResults,
    table: MetricTable,
    trials: usize,
    ok: bool,
}

impl Context<'_> {
    fn label(&self, a: Agent, b: Agent) -> String {
        crate::report::metrics::pair_label(a, b, BASELINE)
    }

    fn check(&self, ok: bool, agents: &[Agent]) -> Check {
        check_agents(ok, self.trials, self.r, agents)
    }

    /// The family "each of `agents` significantly above each of `others` in `metric`" at `alpha`.
    fn above_family(&self, agents: &[Agent], others: &[Agent], metric: Metric, key: &str, alpha: f64) -> Family {
        crate::report::family::above_each(&self.table, (agents, others), metric, (HALF.means_key, key), BASELINE, alpha)
    }
}

pub(super) fn main_claims(r: &MarioResults, surpassed: &Crossings, hmn: f64) -> rlfd_report::Result<Vec<Claim>> {
    let trials = r.params.trials as usize;
    let c = Context {
        r,
        table: MetricTable::new(&r.trials),
        trials,
        ok: trials >= MIN_TRIALS_FOR_TESTS && r.scale == Scale::Paper,
    };
    Ok(vec![claim_6_6(&c)?, claim_6_7(&c)?, claim_6_8(&c, surpassed, hmn)?, claim_6_9(&c, surpassed)?, claim_6_12(&c)?])
}

/// C6.6: DIS collects the most cumulative points.
fn claim_6_6(c: &Context) -> rlfd_report::Result<Claim> {
    use Agent::*;
    let family = c.above_family(&[Dis], &[Baseline, Hat, Sbs], Metric::Cumulative, "cumulative", 0.05);
    let mean = |a: Agent| c.table.mean(a, Metric::Cumulative);
    let largest = Agent::ALL.iter().all(|&a| a == Dis || mean(Dis) > mean(a));
    let (v, why) = c.check(c.ok, &Agent::ALL).verdict(
        family.holds() && largest,
        "DIS collects the most cumulative points, significantly more than Q(λ), HAT and SBS (Holm-adjusted p < 0.05).",
        "DIS is not the largest, or not significantly above Q(λ), HAT and SBS at Holm-adjusted p < 0.05.",
    );
    let largest_test = TestOutcome::note(
        "DIS vs the other four",
        "the largest mean cumulative points",
        if largest { "yes" } else { "no" },
    );
    Ok(Claim::from_spec(
        "C6.6",
        crate::report::evidence("C6.6")?,
        format!(
            "Cumulative points, {}: {}. DIS's mean is {}the largest of the five.",
            family.rule(),
            family.texts(1).join("; "),
            if largest { "" } else { "not " }
        ),
        v,
        why,
    )?
    .with_number(crate::report::scorecard::means(&HALF, &c.table, &[Dis, Baseline, Sis, Hat, Sbs], Metric::Cumulative))
    .with_tests(family.outcomes())
    .with_estimates(family.estimates())
    .with_test(largest_test))
}

/// C6.7: SIS, DIS and Q(λ) end above HAT.
fn claim_6_7(c: &Context) -> rlfd_report::Result<Claim> {
    use Agent::*;
    let family = c.above_family(&[Sis, Dis, Baseline], &[Hat], Metric::Asymptotic, "asymptotic", 0.05);
    let (mut v, mut why) = c.check(c.ok, &[Sis, Dis, Baseline, Hat]).verdict(
        family.holds(),
        "SIS, DIS and Q(λ) end significantly above HAT (Holm-adjusted p < 0.05).",
        "At least one of SIS, DIS, Q(λ) does not end significantly above HAT (Holm-adjusted p < 0.05).",
    );
    // A conjunction that already fails on the comparisons whose learners did
    // not diverge is not reproduced, whatever the diverged one would show.
    let diverged = &c.r.diverged;
    if v == Verdict::NotEvaluable && c.ok {
        let mut evaluable = Family::new();
        for a in [Sis, Dis, Baseline].into_iter().filter(|a| !diverged.contains_key(a)) {
            evaluable.above(
                c.label(a, Hat),
                c.table.values(a, Metric::Asymptotic),
                c.table.values(Hat, Metric::Asymptotic),
                0.05,
            );
        }
        if !diverged.contains_key(&Hat) && !evaluable.is_empty() && !evaluable.holds() {
            why = format!(
                "Not reproduced on the comparisons whose learners did not diverge ({}), whatever the diverged learner would show. {why}",
                evaluable.texts(1).join("; ")
            );
            v = Verdict::NotReproduced;
        }
    }
    Ok(Claim::from_spec(
        "C6.7",
        crate::report::evidence("C6.7")?,
        format!("Mean of the last 100 episodes, {}: {}.", family.rule(), family.texts(1).join("; ")),
        v,
        why,
    )?
    .with_number(crate::report::scorecard::means(&HALF, &c.table, &[Sis, Dis, Baseline, Hat], Metric::Asymptotic))
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}

/// C6.8: HAT never rises above the demonstrator (HMN).
fn claim_6_8(c: &Context, surpassed: &Crossings, hmn: f64) -> rlfd_report::Result<Claim> {
    let r = c.r;
    let hat = surpassed.iter().find(|x| x.0 == Agent::Hat);
    let bin = bin_size(r.params.episodes);
    let hat_trials = r.trials.get(&Agent::Hat).map_or(&[][..], |t| &t[..]);
    let hat_max = mean_binned(hat_trials, bin).into_iter().fold(f64::NEG_INFINITY, f64::max);
    let (v, why) = c.check(r.scale == Scale::Paper, &[Agent::Hat]).verdict(
        hat_max <= hmn,
        "HAT's smoothed mean curve never rises above the demonstrator's mean.",
        "HAT's smoothed mean curve rises above the demonstrator's mean.",
    );
    let [hmn_number, hat_asymptote, hat_peak] = scorecard::hat_against_demonstrator(&c.table, hat_max, hmn, bin);
    Ok(Claim::from_spec(
        "C6.8",
        crate::report::evidence("C6.8")?,
        format!(
            "HAT's highest {bin}-episode mean is {} against HMN = {}; {}.{}",
            mean_text(hat_max, 1),
            thousands(hmn, 1),
            match hat {
                Some((_, Some(e), Some(f))) => format!("it first rises above it at episode {f} and stays above from episode {e}"),
                Some((_, None, Some(f))) => format!("it first rises above it at episode {f} but does not stay above"),
                _ => "it never rises above it".into(),
            },
            if hat_max <= hmn && hat_max > demo_thesis::MEAN_SCORE {
                format!(
                    " HAT does pass the thesis's demonstrator mean of {}: the verdict rests on our demonstrator scoring more than the thesis's.",
                    thousands(demo_thesis::MEAN_SCORE, 0)
                )
            } else {
                String::new()
            }
        ),
        v,
        why,
    )?
    .with_estimates([holds_unless_diverged("HAT never above HMN", hat_max <= hmn, r.diverged.contains_key(&Agent::Hat))])
    .with_number(hmn_number)
    .with_number(hat_asymptote)
    .with_number(hat_peak)
    .with_test(scorecard::hat_stays_below(hat, bin)))
}

/// C6.9: DIS is the first agent to stay above the demonstrator.
fn claim_6_9(c: &Context, surpassed: &Crossings) -> rlfd_report::Result<Claim> {
    let described: Vec<String> = surpassed
        .iter()
        .map(|(a, e, f)| {
            format!(
                "{} {} (first above at {})",
                a.label(BASELINE),
                e.map_or("never".into(), |e| e.to_string()),
                f.map_or("never".into(), |f| f.to_string())
            )
        })
        .collect();
    let holds = alone_first(surpassed, Agent::Dis, |x| x.1);
    let first_too = alone_first(surpassed, Agent::Dis, |x| x.2);
    let (v, why) = c.check(c.r.scale == Scale::Paper, &Agent::ALL).verdict(
        holds,
        "DIS is the first agent whose smoothed mean curve stays above the demonstrator.",
        "Another agent's smoothed mean curve stays above the demonstrator before DIS's (or DIS's never does).",
    );
    Ok(Claim::from_spec(
        "C6.9",
        crate::report::evidence("C6.9")?,
        format!(
            "Stays above from episode: {}. Read as the first bin above it, DIS is {} the first alone.",
            described.join(", "),
            if first_too { "also" } else { "not" }
        ),
        v,
        why,
    )?
    .with_estimates([holds_unless_diverged("DIS stays above HMN first", holds, c.r.diverged.contains_key(&Agent::Dis))])
    .with_number(crate::report::scorecard::surpass(&HALF, surpassed))
    .with_test(scorecard::first_to_surpass(surpassed)))
}

/// C6.12: SIS and DIS each collect more cumulative points than Q(λ), HAT and SBS.
fn claim_6_12(c: &Context) -> rlfd_report::Result<Claim> {
    use Agent::*;
    let family = c.above_family(&[Sis, Dis], &[Baseline, Hat, Sbs], Metric::Cumulative, "cumulative", 1e-4);
    let (v, why) = c.check(c.ok, &Agent::ALL).verdict(
        family.holds(),
        "SIS and DIS each collect significantly more cumulative points than Q(λ), HAT and SBS (Holm-adjusted p < 1e-4).",
        "At least one of the six comparisons is not in the thesis's direction or not significant at Holm-adjusted p < 1e-4.",
    );
    Ok(Claim::from_spec(
        "C6.12",
        crate::report::evidence("C6.12")?,
        format!("Cumulative points, {}: {}.", family.rule(), family.texts(1).join("; ")),
        v,
        why,
    )?
    .with_number(crate::report::scorecard::means(&HALF, &c.table, &[Sis, Dis, Baseline, Hat, Sbs], Metric::Cumulative))
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}
