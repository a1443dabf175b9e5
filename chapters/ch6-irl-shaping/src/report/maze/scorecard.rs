//! The numbers each Maze claim turns on, for the scorecard: the thesis's
//! Table 6.1 means beside ours, the episodes to surpass the demonstrator
//! and its return, attached to the claims the verdict code built (the tests
//! behind each verdict come with the claim, from its family). Rendering
//! only: no verdict is computed here.

use rlfd_report::claims::{Claim, KeyNumber};
use rlfd_report::table::NumFormat;

use crate::maze::demonstrator::thesis as maze_thesis;
use crate::maze::params::BASELINE;
use crate::report::metrics::{Crossings, Metric, MetricTable};
use crate::report::scorecard::{Half, means, surpass};
use crate::shaping::Agent;

const REWARD: NumFormat = NumFormat::Fixed { decimals: 0, thousands: true };

fn words(m: Metric) -> &'static str {
    match m {
        Metric::Initial => "initial reward",
        Metric::Asymptotic => "asymptotic reward",
        Metric::Cumulative => "cumulative reward",
    }
}

/// The Maze's key numbers: Table 6.1's rewards and the episodes to surpass.
pub const HALF: Half = Half {
    baseline: BASELINE,
    means_key: "ch6.maze.table_6_1",
    surpass_key: "ch6.maze.episodes_to_surpass_demonstrator",
    format: REWARD,
    words,
    curve: "mean curve",
};

/// The Maze claims with their key numbers.
pub fn maze_numbers(claims: Vec<Claim>, table: &MetricTable, crossings: &Crossings, hmn: f64) -> Vec<Claim> {
    use Agent::*;
    claims
        .into_iter()
        .map(|c| match c.id.as_str() {
            "C6.1" => c.with_number(means(&HALF, table, &[Sis, Dis, Baseline, Hat, Sbs], Metric::Cumulative)),
            "C6.2" => c.with_number(means(&HALF, table, &[Hat, Sbs, Baseline], Metric::Initial)),
            "C6.3" => c.with_number(means(&HALF, table, &Agent::ALL, Metric::Asymptotic)),
            "C6.4" => c.with_number(surpass(&HALF, crossings)),
            "C6.5" => c.with_number(means(&HALF, table, &Agent::ALL, Metric::Asymptotic)).with_number(KeyNumber::new(
                "the demonstrator's return",
                &[maze_thesis::HMN],
                &[hmn],
                REWARD,
            )),
            _ => c,
        })
        .collect()
}
