//! Verdicts on the thesis's Maze claims (C6.1–C6.5) and on C6.11, computed
//! from the data with the tests `claims.md` names. Nothing here knows what the
//! thesis's answer was; the verdicts follow from our numbers alone.

use rlfd_harness::Scale;
use rlfd_report::claims::{Check, Claim, TestFloor, Verdict};
use rlfd_report::published::published;
use rlfd_rl::mdp::check_potential_shaping;
use rlfd_rl::random::seeded;
use rlfd_stats::format::p_value;

use super::metrics::{Metric, MetricTable};
use crate::agents::MazeAgent;

/// Trials below which a significance test is not taken as evidence: 10, as
/// the thesis tested ([`TestFloor::ThesisTested`]); shared by both halves.
pub(crate) const MIN_TRIALS_FOR_TESTS: usize = TestFloor::ThesisTested.trials();

struct Evidence {
    text: Vec<String>,
    holds: bool,
}

fn mean(table: &MetricTable, a: MazeAgent, m: Metric) -> f64 {
    table.summary(a, m).map_or(f64::NAN, |s| s.mean)
}

/// `a` above `b` on `m` with a pooled t-test p below `alpha`.
fn above(table: &MetricTable, a: MazeAgent, b: MazeAgent, m: Metric, alpha: f64, ev: &mut Evidence) {
    let (ma, mb) = (mean(table, a, m), mean(table, b, m));
    let p = table.tests(a, b, m).0.map_or(f64::NAN, |t| t.p);
    ev.text.push(format!("{} {:.1} vs {} {:.1} (p = {})", a.label(), ma, b.label(), mb, p_value(p)));
    ev.holds &= ma > mb && p < alpha;
}

/// Decidable when `ok`, else: too few trials for the thesis's tests.
fn check(ok: bool, trials: usize) -> Check {
    Check::when(ok, || {
        format!(
            "{trials} trials per agent are too few for the thesis's tests (it used {}); the evidence is shown for the record",
            published().number("ch6.maze.trials").unwrap_or(f64::NAN)
        )
    })
}

/// The Maze claims C6.1–C6.5.
pub fn maze_claims(
    table: &MetricTable,
    surpass: &[(MazeAgent, Option<usize>)],
    hmn: f64,
    trials: usize,
    scale: Scale,
    diverged: Option<String>,
) -> rlfd_report::Result<Vec<Claim>> {
    use MazeAgent::*;
    // Every Maze claim compares several of the five agents: a diverged
    // learner makes them all not evaluable.
    let (tests, paper) = match diverged {
        Some(why) => (Check::Undecidable(why.clone()), Check::Undecidable(why)),
        None => (
            check(trials >= MIN_TRIALS_FOR_TESTS && scale == Scale::Paper, trials),
            check(scale == Scale::Paper, trials),
        ),
    };
    let mut out = Vec::new();

    let mut ev = Evidence { text: vec![], holds: true };
    for a in [Sis, Dis] {
        for b in [Sarsa, Hat, Sbs] {
            above(table, a, b, Metric::Cumulative, 1e-4, &mut ev);
        }
    }
    let (v, why) = tests.verdict(
        ev.holds,
        "SIS and DIS each collect significantly more cumulative reward than SARSA, HAT and SBS (p < 1e-4).",
        "At least one of the six comparisons is not in the thesis's direction or not significant at p < 1e-4.",
    );
    out.push(Claim::from_spec(
        "C6.1",
        "SIS −93,592 and DIS −113,689 against SAR −151,526, HAT −150,141, SBS −159,635; all six p ≤ 1.0e-17.",
        ev.text.join("; "),
        v,
        why,
    )?);

    let mut ev = Evidence { text: vec![], holds: true };
    above(table, Hat, Sarsa, Metric::Initial, 1e-4, &mut ev);
    above(table, Sbs, Sarsa, Metric::Initial, 1e-4, &mut ev);
    let (v, why) = tests.verdict(
        ev.holds,
        "HAT and SBS start significantly better than SARSA (p < 1e-4).",
        "HAT or SBS does not start significantly better than SARSA at p < 1e-4.",
    );
    out.push(Claim::from_spec(
        "C6.2",
        "Initial: HAT −164.68, SBS −324.04 against SAR −3,730.36; p = 1.6e-13 and 1.7e-12.",
        ev.text.join("; "),
        v,
        why,
    )?);

    let mut significant = Vec::new();
    let mut smallest = f64::INFINITY;
    for (a, b) in super::metrics::thesis_pairs() {
        let p = table.tests(a, b, Metric::Asymptotic).0.map_or(f64::NAN, |t| t.p);
        smallest = smallest.min(p);
        if p < 0.05 {
            significant.push(format!("{} vs {} (p = {})", a.label(), b.label(), p_value(p)));
        }
    }
    let text = if significant.is_empty() {
        format!("No pair differs at p < 0.05 on the last episode; smallest p = {}.", p_value(smallest))
    } else {
        format!("Significant at p < 0.05: {}.", significant.join(", "))
    };
    let (v, why) = tests.verdict(
        significant.is_empty(),
        "No pair of agents differs significantly in the last episode's reward.",
        "Some pairs differ significantly in the last episode's reward.",
    );
    out.push(Claim::from_spec("C6.3", "All ten asymptotic p-values ≥ 0.0516.", text, v, why)?);

    let described: Vec<String> =
        surpass.iter().map(|(a, e)| format!("{} {}", a.label(), e.map_or("never".into(), |e| e.to_string()))).collect();
    let first = surpass.iter().filter_map(|(a, e)| e.map(|e| (e, *a))).min();
    let sis = surpass.iter().find(|(a, _)| *a == Sis).and_then(|(_, e)| *e);
    let holds = matches!((sis, first), (Some(s), Some((f, _))) if s == f && surpass.iter().filter(|(_, e)| *e == Some(s)).count() == 1);
    let (v, why) = paper.verdict(
        holds,
        "SIS is the first agent whose mean curve stays above the demonstrator.",
        "Another agent's mean curve stays above the demonstrator before SIS's does (or SIS's never does).",
    );
    out.push(Claim::from_spec(
        "C6.4",
        "Episodes to surpass the demonstrator: SAR 110, SIS 90, DIS 115, HAT 135, SBS 136.",
        format!("Episode from which the mean curve stays above HMN = {hmn:.1}: {}.", described.join(", ")),
        v,
        why,
    )?);

    let mut below = Vec::new();
    let mut text = Vec::new();
    for a in MazeAgent::ALL {
        let m = mean(table, a, Metric::Asymptotic);
        text.push(format!("{} {m:.1}", a.label()));
        if m.partial_cmp(&hmn) != Some(std::cmp::Ordering::Greater) {
            below.push(a.label());
        }
    }
    let (v, why) = paper.verdict(
        below.is_empty(),
        "Every agent's mean last-episode reward is above the demonstrator's mean.",
        &format!("{} end below the demonstrator's mean.", below.join(", ")),
    );
    out.push(Claim::from_spec(
        "C6.5",
        "Asymptotic rewards −165.88 to −267.88, all above HMN = −327.5.",
        format!("Last-episode means {} against our HMN = {hmn:.1}.", text.join(", ")),
        v,
        why,
    )?);
    Ok(out)
}

/// Claim C6.11 from the shaping theorem checked on random MDPs (the same
/// check the property tests of `rlfd-rl` run, here on a fixed sample).
pub fn shaping_invariance_claim(mdps: usize) -> rlfd_report::Result<Claim> {
    let report = check_potential_shaping(&mut seeded(0x6e67_3939), mdps);
    let holds = report.greedy_mismatches == 0 && report.max_shift_error < 1e-9;
    let evidence = format!(
        "Value iteration on {} random MDPs (half with cycles and γ < 1, half episodic with γ = 1), with and without potential-based shaping (Φ = 0 on terminal states): greedy action sets differ in {} of {} states; largest |Q′ − (Q* − Φ)| = {:.1e}. The property tests of `rlfd-rl` check the same on fresh MDPs at every test run, plus the look-ahead form, Φ ≡ 0 and a non-zero terminal potential that does change the policy.",
        report.mdps, report.greedy_mismatches, report.states_compared, report.max_shift_error
    );
    let (verdict, reason) = if holds {
        (
            Verdict::Reproduced,
            "Potential-based shaping left every optimal policy unchanged and shifted every value by exactly −Φ.",
        )
    } else {
        (Verdict::NotReproduced, "Shaping changed an optimal policy or the value shift.")
    };
    Claim::from_spec(
        "C6.11",
        "Cited from Ng et al. (1999), Wiewiora et al. (2003) and Devlin & Kudenko (2012); not tested in the thesis.",
        evidence,
        verdict,
        reason,
    )
}
