//! The numbers each Mario claim (C6.6–C6.10) turns on, for the scorecard,
//! beyond the shared ones ([`crate::report::scorecard`]: Table 6.3's means,
//! the episodes to surpass the demonstrator): the demonstrator's mean and
//! HAT's best stretch (C6.8), who surpasses first (C6.9) and the
//! demonstration-length study's means (C6.10, which the thesis shows only
//! as bar plots, so its side is empty). Rendering only: no verdict reads
//! them. An agent none of whose trials ran to the end (a diverged learner)
//! has NaN for ours, shown as a dash; a value the thesis does not give is
//! NaN too, never filled in.

use rlfd_report::claims::{KeyNumber, TestOutcome};
use rlfd_report::table::NumFormat;
use rlfd_stats::Summary;
use rlfd_stats::format::thousands;

use crate::mario::demonstrator::thesis as demo_thesis;
use crate::mario::experiment::DemoLengthResults;
use crate::mario::params::{BASELINE, MarioTrial};
use crate::report::metrics::{Crossings, Metric, MetricTable, values};
use crate::report::scorecard::{Half, means};
use crate::shaping::Agent;

/// Points as Table 6.3 shows them.
const POINTS: NumFormat = NumFormat::grouped(1);

fn words(m: Metric) -> &'static str {
    match m {
        Metric::Initial => "initial points",
        Metric::Asymptotic => "asymptotic points (last 100)",
        Metric::Cumulative => "cumulative points",
    }
}

/// Mario's key numbers: Table 6.3's points and the episodes to surpass.
pub const HALF: Half = Half {
    baseline: BASELINE,
    means_key: "ch6.mario.table_6_3",
    surpass_key: "ch6.mario.episodes_to_surpass_demonstrator",
    format: POINTS,
    words,
    curve: "smoothed mean curve",
};

/// C6.9's decision: which agent's curve stays above the demonstrator first.
pub(super) fn first_to_surpass(surpassed: &Crossings) -> TestOutcome {
    let first = surpassed.iter().filter_map(|c| c.1).min();
    let note = match first {
        Some(e) => {
            let who: Vec<&str> = surpassed.iter().filter(|c| c.1 == Some(e)).map(|c| c.0.label(BASELINE)).collect();
            format!("first: {} at episode {}", who.join(" and "), thousands(e as f64, 0))
        }
        None => "no agent's curve stays above".into(),
    };
    TestOutcome::note("DIS first alone", "the first smoothed mean curve to stay above the demonstrator", note)
}

/// C6.8's numbers: the demonstrator's mean score, HAT's asymptote and its
/// highest `bin`-episode mean (which the thesis does not give).
pub(super) fn hat_against_demonstrator(table: &MetricTable, hat_max: f64, hmn: f64, bin: usize) -> [KeyNumber; 3] {
    [
        KeyNumber::new("the demonstrator's mean score (HMN)", &[demo_thesis::MEAN_SCORE], &[hmn], POINTS),
        means(&HALF, table, &[Agent::Hat], Metric::Asymptotic),
        KeyNumber::new(
            format!("HAT's highest {bin}-episode mean"),
            &[],
            &[if hat_max.is_finite() { hat_max } else { f64::NAN }],
            POINTS,
        ),
    ]
}

/// C6.8's decision: whether HAT's smoothed mean curve ever rises above HMN.
pub(super) fn hat_stays_below(hat: Option<&(Agent, Option<usize>, Option<usize>)>, bin: usize) -> TestOutcome {
    let note = match hat {
        Some((_, _, Some(f))) => format!("above from episode {}", thousands(*f as f64, 0)),
        Some(_) => "never above".into(),
        None => "no HAT trial ran to the end".into(),
    };
    TestOutcome::note("HAT", format!("every {bin}-episode mean at or below the demonstrator's"), note)
}

/// The demonstration-length study's means of `m` (C6.10), per length; the
/// thesis shows them only as bars (Figures 6.6 and 6.7), so its side is empty.
pub(super) fn study_means(s: &DemoLengthResults, m: Metric) -> KeyNumber {
    let runs: Vec<(usize, &[MarioTrial])> = s.runs.iter().map(|(l, _, ts)| (*l, ts.as_slice())).collect();
    length_means(&runs, m)
}

/// [`study_means`] of `(observations per demonstration, trials)`, in order.
fn length_means(runs: &[(usize, &[MarioTrial])], m: Metric) -> KeyNumber {
    let ours: Vec<f64> = runs.iter().map(|(_, ts)| Summary::of(&values(ts, m)).map_or(f64::NAN, |s| s.mean)).collect();
    let names: Vec<String> = runs.iter().map(|(l, _)| l.to_string()).collect();
    KeyNumber::new(format!("DIS {}: {} observations", words(m), names.join(" vs ")), &[], &ours, POINTS)
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;
    use crate::mario::params::MarioEnds;
    use crate::report::scorecard::surpass;

    fn trial(returns: &[i32]) -> MarioTrial {
        MarioTrial {
            returns: returns.to_vec(),
            steps: vec![1; returns.len()],
            ends: MarioEnds::default(),
            diverged_at: None,
        }
    }

    fn values_of(k: &KeyNumber) -> (Vec<f64>, Vec<f64>) {
        (k.thesis.iter().map(|n| n.value).collect(), k.ours.iter().map(|n| n.value).collect())
    }

    #[test]
    fn table_6_3_means_beside_ours_a_diverged_agent_a_dash() {
        use Agent::*;
        // DIS: two trials of three episodes; HAT diverged in every trial (absent).
        let trials = MetricTable::new(&BTreeMap::from([(Dis, vec![trial(&[1, 2, 3]), trial(&[3, 4, 5])])]));
        let k = means(&HALF, &trials, &[Dis, Hat], Metric::Cumulative);
        assert_eq!(k.label, "cumulative points: DIS vs HAT");
        let (theirs, ours) = values_of(&k);
        assert_eq!(theirs, [25_725_731.6, 13_250_664.4]);
        assert_eq!(ours[0], 9.0);
        assert!(ours[1].is_nan());
        // Asymptotic: the mean of the last 100 episodes (all three here), then over trials.
        let (theirs, ours) = values_of(&means(&HALF, &trials, &[Dis], Metric::Asymptotic));
        assert_eq!((theirs, ours), (vec![1398.7714], vec![3.0]));
    }

    #[test]
    fn episodes_to_surpass_and_who_was_first() {
        use Agent::*;
        let surpassed =
            [(Baseline, Some(11_000), Some(9_000)), (Dis, Some(6_000), Some(4_000)), (Sbs, None, Some(100))];
        let (theirs, ours) = values_of(&surpass(&HALF, &surpassed));
        // QLR, SIS, DIS, HAT, SBS; the thesis's HAT never surpasses.
        assert_eq!(theirs[..3], [11_000.0, 10_000.0, 4_000.0]);
        assert!(theirs[3].is_nan() && theirs[4] == 12_000.0);
        assert_eq!(ours[0], 11_000.0);
        assert!(ours[1].is_nan() && ours[2] == 6_000.0 && ours[3].is_nan() && ours[4].is_nan());
        assert_eq!(first_to_surpass(&surpassed).note.as_deref(), Some("first: DIS at episode 6,000"));
        assert_eq!(first_to_surpass(&[(Sbs, None, None)]).note.as_deref(), Some("no agent's curve stays above"));
    }

    #[test]
    fn hat_against_the_demonstrator() {
        let trials = MetricTable::new(&BTreeMap::from([(Agent::Hat, vec![trial(&[800, 900]), trial(&[1000, 1100])])]));
        let [hmn, asymptote, peak] = hat_against_demonstrator(&trials, 1_050.0, 1_300.5, 100);
        assert_eq!(values_of(&hmn), (vec![1224.0], vec![1300.5]));
        assert_eq!(values_of(&asymptote), (vec![867.2241], vec![950.0]));
        assert_eq!(peak.label, "HAT's highest 100-episode mean");
        assert_eq!(values_of(&peak), (vec![], vec![1050.0]));
        // No HAT trial: no peak, a dash.
        let [_, _, peak] = hat_against_demonstrator(&MetricTable::default(), f64::NEG_INFINITY, 1_300.5, 100);
        assert!(peak.ours[0].value.is_nan());
        let hat = (Agent::Hat, None, Some(12_000));
        assert_eq!(hat_stays_below(Some(&hat), 100).note.as_deref(), Some("above from episode 12,000"));
        assert_eq!(hat_stays_below(Some(&(Agent::Hat, None, None)), 100).note.as_deref(), Some("never above"));
        assert_eq!(hat_stays_below(None, 100).test, "every 100-episode mean at or below the demonstrator's");
    }

    #[test]
    fn the_length_study_has_no_thesis_numbers() {
        let (a, b) = ([trial(&[10, 20]), trial(&[30, 40])], [trial(&[50]), trial(&[60, -20])]);
        let k = length_means(&[(100, &a[..]), (500, &b[..])], Metric::Cumulative);
        assert_eq!(k.label, "DIS cumulative points: 100 vs 500 observations");
        assert_eq!(values_of(&k), (vec![], vec![50.0, 45.0]));
        // One trial has no summary (as in the claim's own means): a dash.
        assert!(length_means(&[(953, &b[..1])], Metric::Cumulative).ours[0].value.is_nan());
    }
}
