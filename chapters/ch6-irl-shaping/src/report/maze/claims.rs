//! Verdicts on the thesis's Maze claims (C6.1–C6.5), computed from the data
//! with the tests `claims.md` names, decided as [`crate::report::family`]
//! says (two-sided tests with the direction, Holm within a
//! claim's family); C6.3's "do not differ" is an equivalence test (TOST)
//! against a margin fixed before the run, not the absence of a significant
//! difference. Nothing here knows what the thesis's answer was; the
//! verdicts follow from our numbers alone.

use rlfd_harness::Scale;
use rlfd_report::claims::{Check, Claim};
use rlfd_report::published::published;
use rlfd_stats::format::p_value;

use crate::maze::params::BASELINE;
use crate::report::claims::{MIN_TRIALS_FOR_TESTS, holds_unless_diverged};
use crate::report::family::{self, Family, MAZE_MARGIN};
use crate::report::metrics::{Crossings, Metric, MetricTable, alone_first, thesis_pairs};
use crate::shaping::Agent;

/// The thesis's table of Maze means (Table 6.1).
const THESIS_MEANS: &str = "ch6.maze.table_6_1";

/// Decidable when `ok`, else: too few trials for the thesis's tests.
fn check(ok: bool, trials: usize) -> Check {
    Check::when(ok, || {
        format!(
            "{trials} trials per agent are too few for the thesis's tests (it used {}); the evidence is shown for the record",
            published().number("ch6.maze.trials").unwrap_or(f64::NAN)
        )
    })
}

fn crossing_text(e: Option<usize>) -> String {
    e.map_or("never".into(), |e| e.to_string())
}

/// What the Maze claims read: the agents' metrics, the demonstrator's mean
/// (HMN), the crossings of it, and the checks of the thesis's tests
/// (`tests`: enough trials at paper scale) and of its curves (`paper`).
struct Context<'a> {
    table: &'a MetricTable,
    crossings: &'a Crossings,
    hmn: f64,
    tests: Check,
    paper: Check,
    /// Whether a learner diverged (every Maze claim compares all five agents).
    diverged: bool,
}

impl Context<'_> {
    fn values(&self, a: Agent, m: Metric) -> &[f64] {
        self.table.values(a, m)
    }

    /// The family "each of `agents` significantly above each of `others` in `metric`" at `alpha`.
    fn above_family(&self, agents: &[Agent], others: &[Agent], metric: Metric, key: &str, alpha: f64) -> Family {
        family::above_each(self.table, (agents, others), metric, (THESIS_MEANS, key), BASELINE, alpha)
    }
}

/// The Maze claims C6.1–C6.5.
pub fn maze_claims(
    table: &MetricTable,
    crossings: &Crossings,
    hmn: f64,
    trials: usize,
    scale: Scale,
    diverged: Option<String>,
) -> rlfd_report::Result<Vec<Claim>> {
    // Every Maze claim compares several of the five agents: a diverged
    // learner makes them all not evaluable.
    let any_diverged = diverged.is_some();
    let (tests, paper) = match diverged {
        Some(why) => (Check::Undecidable(why.clone()), Check::Undecidable(why)),
        None => (
            check(trials >= MIN_TRIALS_FOR_TESTS && scale == Scale::Paper, trials),
            check(scale == Scale::Paper, trials),
        ),
    };
    let c = Context { table, crossings, hmn, tests, paper, diverged: any_diverged };
    Ok(vec![claim_6_1(&c)?, claim_6_2(&c)?, claim_6_3(&c)?, claim_6_4(&c)?, claim_6_5(&c)?])
}

/// C6.1: SIS and DIS collect more cumulative reward than SARSA, HAT and SBS.
fn claim_6_1(c: &Context) -> rlfd_report::Result<Claim> {
    use Agent::*;
    let family = c.above_family(&[Sis, Dis], &[Baseline, Hat, Sbs], Metric::Cumulative, "cumulative", 1e-4);
    let (v, why) = c.tests.verdict(
        family.holds(),
        "SIS and DIS each collect significantly more cumulative reward than SARSA, HAT and SBS (Holm-adjusted p < 1e-4).",
        "At least one of the six comparisons is not in the thesis's direction or not significant at Holm-adjusted p < 1e-4.",
    );
    Ok(Claim::from_spec(
        "C6.1",
        crate::report::evidence("C6.1")?,
        format!("Cumulative reward, {}: {}.", family.rule(), family.texts(1).join("; ")),
        v,
        why,
    )?
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}

/// C6.2: HAT and SBS start better than SARSA.
fn claim_6_2(c: &Context) -> rlfd_report::Result<Claim> {
    use Agent::*;
    let family = c.above_family(&[Hat, Sbs], &[Baseline], Metric::Initial, "initial", 1e-4);
    let (v, why) = c.tests.verdict(
        family.holds(),
        "HAT and SBS start significantly better than SARSA (Holm-adjusted p < 1e-4).",
        "HAT or SBS does not start significantly better than SARSA at Holm-adjusted p < 1e-4.",
    );
    Ok(Claim::from_spec(
        "C6.2",
        crate::report::evidence("C6.2")?,
        format!("First-episode reward, {}: {}.", family.rule(), family.texts(1).join("; ")),
        v,
        why,
    )?
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}

/// C6.3: every agent ends at the same reward (equivalence within the margin).
fn claim_6_3(c: &Context) -> rlfd_report::Result<Claim> {
    let mut family = Family::new();
    let mut significant = Vec::new();
    for (a, b) in thesis_pairs() {
        let (x, y) = (c.values(a, Metric::Asymptotic), c.values(b, Metric::Asymptotic));
        family.equivalent(format!("{} vs {}", a.label(BASELINE), b.label(BASELINE)), x, y, MAZE_MARGIN);
        let p = c.table.tests(a, b, Metric::Asymptotic).0.map_or(f64::NAN, |t| t.p);
        if p < 0.05 {
            significant.push(format!("{} vs {} (p = {})", a.label(BASELINE), b.label(BASELINE), p_value(p)));
        }
    }
    let old_reading = if significant.is_empty() {
        "No pair differs at p < 0.05 in a two-sided t-test (the thesis's reading, which cannot show that nothing differs).".to_string()
    } else {
        format!("Two-sided t-tests at p < 0.05 (the thesis's reading): {} differ.", significant.join(", "))
    };
    let (v, why) = c.tests.verdict(
        family.holds(),
        "Every pair of agents ends equivalent within the margin (TOST, Holm-adjusted p < 0.05).",
        "Some pairs cannot be shown equivalent within the margin (TOST, Holm-adjusted p ≥ 0.05): their last-episode rewards may differ by more than it.",
    );
    Ok(Claim::from_spec(
        "C6.3",
        crate::report::evidence("C6.3")?,
        format!(
            "Last-episode reward, equivalence within ±{} (a tenth of the thesis's |HMN|, fixed before the run) by two one-sided tests, {}: {}. {old_reading}",
            family::num(MAZE_MARGIN, 2),
            family.rule(),
            family.texts(1).join("; ")
        ),
        v,
        why,
    )?
    .with_tests(family.outcomes())
    .with_estimates(family.estimates()))
}

/// C6.4: SIS is the first agent to stay above the demonstrator.
fn claim_6_4(c: &Context) -> rlfd_report::Result<Claim> {
    let described: Vec<String> = c
        .crossings
        .iter()
        .map(|(a, e, f)| format!("{} {} (first above at {})", a.label(BASELINE), crossing_text(*e), crossing_text(*f)))
        .collect();
    let holds = alone_first(c.crossings, Agent::Sis, |x| x.1);
    let first_too = alone_first(c.crossings, Agent::Sis, |x| x.2);
    let (v, why) = c.paper.verdict(
        holds,
        "SIS is the first agent whose mean curve stays above the demonstrator.",
        "Another agent's mean curve stays above the demonstrator before SIS's does (or SIS's never does).",
    );
    Ok(Claim::from_spec(
        "C6.4",
        crate::report::evidence("C6.4")?,
        format!(
            "Episode from which the mean curve stays above HMN = {}: {}. Read as the first episode above it, SIS is {} the first alone.",
            family::num(c.hmn, 1),
            described.join(", "),
            if first_too { "also" } else { "not" }
        ),
        v,
        why,
    )?
    .with_estimates([holds_unless_diverged("SIS stays above HMN first", holds, c.diverged)]))
}

/// C6.5: every agent ends above the demonstrator.
fn claim_6_5(c: &Context) -> rlfd_report::Result<Claim> {
    let hmn = c.hmn;
    let mut below = Vec::new();
    let mut text = Vec::new();
    let mut above = Family::new();
    for a in Agent::ALL {
        above.above_value(format!("{} vs HMN", a.label(BASELINE)), c.values(a, Metric::Asymptotic), hmn, 0.05);
        above.thesis_effect(family::thesis_difference(THESIS_MEANS, "asymptotic", a.label(BASELINE), "HMN"));
        let m = c.table.mean(a, Metric::Asymptotic);
        let crossing = c.crossings.iter().find(|x| x.0 == a);
        text.push(format!(
            "{} {} (stays above from {}, first above at {})",
            a.label(BASELINE),
            family::num(m, 1),
            crossing_text(crossing.and_then(|x| x.1)),
            crossing_text(crossing.and_then(|x| x.2))
        ));
        if m.partial_cmp(&hmn) != Some(std::cmp::Ordering::Greater) {
            below.push(a.label(BASELINE));
        }
    }
    let (v, why) = c.paper.verdict(
        below.is_empty(),
        "Every agent's mean last-episode reward is above the demonstrator's mean.",
        &format!(
            "{} end at or below the demonstrator's mean (point means, not a test: the pooled verdict over replications says whether the data exclude the thesis's finding).",
            below.join(", ")
        ),
    );
    Ok(Claim::from_spec(
        "C6.5",
        crate::report::evidence("C6.5")?,
        format!("Last-episode means {} against our HMN = {}.", text.join(", "), family::num(hmn, 1)),
        v,
        why,
    )?
    .with_estimates(above.estimates()))
}
