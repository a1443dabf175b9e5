//! The numbers a claim turns on, for the scorecard, in either half: an
//! agent table's means beside the thesis's, and the episodes from which
//! each agent's curve stays above the demonstrator beside the thesis's.
//! Rendering only: no verdict reads them. An agent none of whose trials ran
//! to the end (a diverged learner) has NaN for ours, shown as a dash; a
//! value the thesis does not give is NaN too, never filled in.

use rlfd_report::claims::KeyNumber;
use rlfd_report::published::published;
use rlfd_report::table::NumFormat;

use super::metrics::{Crossings, Metric, MetricTable};
use crate::shaping::{Agent, Baseline};

/// What a half's key numbers say and where the thesis's stand.
#[derive(Clone, Copy, Debug)]
pub struct Half {
    /// What the half calls its baseline.
    pub baseline: Baseline,
    /// The means table's key in `thesis-numbers.toml` (e.g. `ch6.maze.table_6_1`).
    pub means_key: &'static str,
    /// The episodes to surpass the demonstrator (`<key>.<label>`).
    pub surpass_key: &'static str,
    /// How a mean is shown.
    pub format: NumFormat,
    /// A metric in words (`initial reward`, `asymptotic points (last 100)`).
    pub words: fn(Metric) -> &'static str,
    /// The curve that surpasses (`mean curve`, `smoothed mean curve`).
    pub curve: &'static str,
}

/// `m`'s means of `agents`, in order, the thesis's table beside ours.
pub fn means(half: &Half, table: &MetricTable, agents: &[Agent], m: Metric) -> KeyNumber {
    let names: Vec<&str> = agents.iter().map(|a| a.label(half.baseline)).collect();
    let theirs: Vec<f64> = agents
        .iter()
        .map(|a| published().table_value(half.means_key, m.key(), a.label(half.baseline)).unwrap_or(f64::NAN))
        .collect();
    let ours: Vec<f64> = agents.iter().map(|&a| table.mean(a, m)).collect();
    KeyNumber::new(format!("{}: {}", (half.words)(m), names.join(" vs ")), &theirs, &ours, half.format)
}

/// The episode from which each agent's curve stays above the demonstrator
/// (the verdict's reading), every agent in the thesis's order; the thesis's
/// beside ours (absent from the thesis: never).
pub fn surpass(half: &Half, crossings: &Crossings) -> KeyNumber {
    let label = |a: &Agent| a.label(half.baseline);
    let theirs: Vec<f64> = Agent::ALL
        .iter()
        .map(|a| published().number(&format!("{}.{}", half.surpass_key, label(a))).unwrap_or(f64::NAN))
        .collect();
    let ours: Vec<f64> = Agent::ALL
        .iter()
        .map(|a| crossings.iter().find(|c| c.0 == *a).and_then(|c| c.1).map_or(f64::NAN, |e| e as f64))
        .collect();
    let names: Vec<&str> = Agent::ALL.iter().map(label).collect();
    KeyNumber::new(
        format!("episodes until the {} stays above the demonstrator: {}", half.curve, names.join(" vs ")),
        &theirs,
        &ours,
        NumFormat::Integer,
    )
}
