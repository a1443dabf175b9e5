//! The numbers each Maze claim turns on, for the scorecard: the thesis's
//! Table 6.1 means beside ours, the episodes to surpass the demonstrator
//! and its return, attached to the claims the verdict code built (the tests
//! behind each verdict come with the claim, from its family). Rendering
//! only: no verdict is computed here.

use rlfd_report::claims::{Claim, KeyNumber};
use rlfd_report::published::published;
use rlfd_report::table::NumFormat;

use super::claims::Crossings;
use super::metrics::{Metric, MetricTable};
use crate::agents::MazeAgent;
use crate::maze::demonstrator::thesis as maze_thesis;

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

/// The Maze claims with their key numbers.
pub fn maze_numbers(claims: Vec<Claim>, table: &MetricTable, crossings: &Crossings, hmn: f64) -> Vec<Claim> {
    use MazeAgent::*;
    claims
        .into_iter()
        .map(|c| match c.id.as_str() {
            "C6.1" => c.with_number(means(table, &[Sis, Dis, Sarsa, Hat, Sbs], Metric::Cumulative)),
            "C6.2" => c.with_number(means(table, &[Hat, Sbs, Sarsa], Metric::Initial)),
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
                // The verdict's reading: the episode from which the mean curve stays above.
                let ours: Vec<f64> = MazeAgent::ALL
                    .iter()
                    .map(|a| crossings.iter().find(|c| c.0 == *a).and_then(|c| c.1).map_or(f64::NAN, |e| e as f64))
                    .collect();
                let names: Vec<&str> = MazeAgent::ALL.iter().map(|a| a.label()).collect();
                c.with_number(KeyNumber::new(
                    format!("episodes until the mean curve stays above the demonstrator: {}", names.join(" vs ")),
                    &theirs,
                    &ours,
                    NumFormat::Integer,
                ))
            }
            "C6.5" => c.with_number(means(table, &MazeAgent::ALL, Metric::Asymptotic)).with_number(KeyNumber::new(
                "the demonstrator's return",
                &[maze_thesis::HMN],
                &[hmn],
                REWARD,
            )),
            _ => c,
        })
        .collect()
}
