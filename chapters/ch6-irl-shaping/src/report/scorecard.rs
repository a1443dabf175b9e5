//! The numbers each Maze claim turns on, for the scorecard: the thesis's
//! Table 6.1 means beside ours, and the pooled t-tests (or the surpass
//! episodes) behind the verdict, attached to the claims the verdict code
//! built. Rendering only: no verdict is computed here.

use rlfd_report::claims::{Claim, KeyNumber, TestOutcome};
use rlfd_report::published::published;
use rlfd_report::table::NumFormat;

use super::metrics::{Metric, MetricTable};
use crate::agents::MazeAgent;

const REWARD: NumFormat = NumFormat::Fixed { decimals: 0, thousands: true };

fn thesis(a: MazeAgent, m: Metric) -> f64 {
    published().table_value("ch6.maze.table_6_1", m.key(), a.label()).unwrap_or(f64::NAN)
}

fn means(table: &MetricTable, agents: &[MazeAgent], m: Metric) -> KeyNumber {
    let names: Vec<&str> = agents.iter().map(|a| a.label()).collect();
    let ours: Vec<f64> = agents.iter().map(|&a| table.summary(a, m).map_or(f64::NAN, |s| s.mean)).collect();
    let theirs: Vec<f64> = agents.iter().map(|&a| thesis(a, m)).collect();
    KeyNumber::new(format!("{} reward: {}", m.header().to_lowercase(), names.join(" vs ")), &theirs, &ours, REWARD)
}

fn test(table: &MetricTable, a: MazeAgent, b: MazeAgent, m: Metric) -> TestOutcome {
    let p = table.tests(a, b, m).0.map_or(f64::NAN, |t| t.p);
    TestOutcome::p(format!("{} vs {}", a.label(), b.label()), "pooled t-test", p)
}

/// The Maze claims with their key numbers and tests.
pub fn maze_numbers(
    claims: Vec<Claim>,
    table: &MetricTable,
    surpass: &[(MazeAgent, Option<usize>)],
    hmn: f64,
) -> Vec<Claim> {
    use MazeAgent::*;
    claims
        .into_iter()
        .map(|c| match c.id.as_str() {
            "C6.1" => {
                let mut c = c.with_number(means(table, &[Sis, Dis, Sarsa, Hat, Sbs], Metric::Cumulative));
                for a in [Sis, Dis] {
                    for b in [Sarsa, Hat, Sbs] {
                        c = c.with_test(test(table, a, b, Metric::Cumulative));
                    }
                }
                c
            }
            "C6.2" => c
                .with_number(means(table, &[Hat, Sbs, Sarsa], Metric::Initial))
                .with_test(test(table, Hat, Sarsa, Metric::Initial))
                .with_test(test(table, Sbs, Sarsa, Metric::Initial)),
            "C6.3" => c.with_number(means(table, &MazeAgent::ALL, Metric::Asymptotic)),
            "C6.4" => {
                let theirs: Vec<f64> = MazeAgent::ALL
                    .iter()
                    .map(|a| {
                        published()
                            .number(&format!("ch6.maze.episodes_to_surpass_demonstrator.{}", a.label()))
                            .unwrap_or(f64::NAN)
                    })
                    .collect();
                let ours: Vec<f64> = MazeAgent::ALL
                    .iter()
                    .map(|a| surpass.iter().find(|(b, _)| b == a).and_then(|(_, e)| *e).map_or(f64::NAN, |e| e as f64))
                    .collect();
                let names: Vec<&str> = MazeAgent::ALL.iter().map(|a| a.label()).collect();
                c.with_number(KeyNumber::new(
                    format!("episodes to surpass the demonstrator: {}", names.join(" vs ")),
                    &theirs,
                    &ours,
                    NumFormat::Integer,
                ))
            }
            "C6.5" => c.with_number(means(table, &MazeAgent::ALL, Metric::Asymptotic)).with_number(KeyNumber::new(
                "the demonstrator's return",
                &[-327.5],
                &[hmn],
                REWARD,
            )),
            _ => c,
        })
        .collect()
}
