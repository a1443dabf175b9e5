//! The per-trial metrics both halves tabulate and test (Tables 6.1–6.4),
//! the thesis's ten pairs, and when each agent's curve surpasses the
//! demonstrator. Each half computes its metrics its own way
//! ([`Scored`]: the Maze's asymptote is the last episode, Mario's the mean
//! of the last 100); everything built on them is shared.

use std::collections::BTreeMap;

use rlfd_stats::{Summary, TTest, student_t_test, welch_t_test};

use crate::shaping::{Agent, Baseline};

/// The thesis's three metrics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Metric {
    /// Return of the first episode.
    Initial,
    /// Return at the end of the run (each half says how it reads it).
    Asymptotic,
    /// Sum of all episodes' returns.
    Cumulative,
}

impl Metric {
    /// In the thesis's column order.
    pub const ALL: [Metric; 3] = [Metric::Initial, Metric::Asymptotic, Metric::Cumulative];

    /// The key in `thesis-numbers.toml`.
    pub fn key(self) -> &'static str {
        match self {
            Metric::Initial => "initial",
            Metric::Asymptotic => "asymptotic",
            Metric::Cumulative => "cumulative",
        }
    }

    /// Column header in `T`'s half.
    pub fn header<T: Scored>(self) -> &'static str {
        match self {
            Metric::Initial => "Initial",
            Metric::Asymptotic => T::ASYMPTOTIC_HEADER,
            Metric::Cumulative => "Cumulative",
        }
    }
}

/// A trial the metrics are computed of.
pub trait Scored {
    /// The asymptotic column's header.
    const ASYMPTOTIC_HEADER: &'static str;
    /// The metric of this trial.
    fn metric(&self, m: Metric) -> f64;
}

/// `m` of each trial, in order.
pub fn values<T: Scored>(trials: &[T], m: Metric) -> Vec<f64> {
    trials.iter().map(|t| t.metric(m)).collect()
}

/// Per agent and metric, the values over trials.
#[derive(Clone, Debug, Default)]
pub struct MetricTable {
    values: BTreeMap<(Agent, Metric), Vec<f64>>,
}

impl MetricTable {
    /// Computes every agent's metrics, trial by trial in order.
    pub fn new<T: Scored>(trials: &BTreeMap<Agent, Vec<T>>) -> Self {
        let mut values = BTreeMap::new();
        for (&agent, ts) in trials {
            for m in Metric::ALL {
                values.insert((agent, m), self::values(ts, m));
            }
        }
        MetricTable { values }
    }

    /// The values of `agent` on `metric`, one per trial (none for an absent agent).
    pub fn values(&self, agent: Agent, metric: Metric) -> &[f64] {
        self.values.get(&(agent, metric)).map_or(&[], Vec::as_slice)
    }

    /// Mean and spread, if there are at least two trials.
    pub fn summary(&self, agent: Agent, metric: Metric) -> Option<Summary> {
        Summary::of(self.values(agent, metric)).ok()
    }

    /// The mean, NaN when there is no summary.
    pub fn mean(&self, agent: Agent, metric: Metric) -> f64 {
        self.summary(agent, metric).map_or(f64::NAN, |s| s.mean)
    }

    /// The pooled (Student) and Welch tests of two agents on a metric.
    pub fn tests(&self, a: Agent, b: Agent, metric: Metric) -> (Option<TTest>, Option<TTest>) {
        let (x, y) = (self.values(a, metric), self.values(b, metric));
        (student_t_test(x, y).ok(), welch_t_test(x, y).ok())
    }
}

/// The ten pairs of Tables 6.2 and 6.4, in the thesis's order.
pub fn thesis_pairs() -> [(Agent, Agent); 10] {
    use Agent::*;
    [
        (Baseline, Sis),
        (Baseline, Dis),
        (Baseline, Hat),
        (Baseline, Sbs),
        (Dis, Hat),
        (Dis, Sis),
        (Dis, Sbs),
        (Sis, Hat),
        (Sis, Sbs),
        (Sbs, Hat),
    ]
}

/// "SAR vs SIS": the row label of a pair in `thesis-numbers.toml`.
pub fn pair_label(a: Agent, b: Agent, baseline: Baseline) -> String {
    format!("{} vs {}", a.label(baseline), b.label(baseline))
}

/// When each agent's curve rises above the demonstrator: the episode from
/// which it stays above (the verdicts' reading of "surpass") and the first
/// episode above it.
pub type Crossings = [(Agent, Option<usize>, Option<usize>)];

/// Whether `agent` is the only one with the smallest episode of `pick`.
pub fn alone_first(
    crossings: &Crossings,
    agent: Agent,
    pick: impl Fn(&(Agent, Option<usize>, Option<usize>)) -> Option<usize>,
) -> bool {
    let mine = crossings.iter().find(|c| c.0 == agent).and_then(&pick);
    let first = crossings.iter().filter_map(&pick).min();
    matches!((mine, first), (Some(m), Some(f)) if m == f && crossings.iter().filter(|c| pick(c) == Some(m)).count() == 1)
}
