//! The Maze's per-trial metrics and their comparisons (Tables 6.1, 6.2).

use std::collections::BTreeMap;

use rlfd_stats::{Summary, TTest, curve, student_t_test, welch_t_test};

use crate::agents::{MazeAgent, MazeTrial};

/// The thesis's three metrics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Metric {
    /// Return of the first episode.
    Initial,
    /// Return of the last episode (the thesis's Maze: "asymptotic (last episode)").
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

    /// Column header.
    pub fn header(self) -> &'static str {
        match self {
            Metric::Initial => "Initial",
            Metric::Asymptotic => "Asymptotic",
            Metric::Cumulative => "Cumulative",
        }
    }

    /// The metric of one trial.
    pub fn of(self, trial: &MazeTrial) -> f64 {
        let r = &trial.returns;
        match self {
            Metric::Initial => curve::initial(r).unwrap_or(f64::NAN),
            Metric::Asymptotic => curve::asymptotic_last(r).unwrap_or(f64::NAN),
            Metric::Cumulative => curve::cumulative(r).unwrap_or(f64::NAN),
        }
    }
}

/// Per agent and metric, the values over trials.
#[derive(Clone, Debug, Default)]
pub struct MetricTable {
    values: BTreeMap<(MazeAgent, Metric), Vec<f64>>,
}

impl MetricTable {
    /// Computes every agent's metrics, trial by trial in order.
    pub fn new(trials: &BTreeMap<MazeAgent, Vec<MazeTrial>>) -> Self {
        let mut values = BTreeMap::new();
        for (&agent, ts) in trials {
            for m in Metric::ALL {
                values.insert((agent, m), ts.iter().map(|t| m.of(t)).collect());
            }
        }
        MetricTable { values }
    }

    /// The values of `agent` on `metric`, one per trial.
    pub fn values(&self, agent: MazeAgent, metric: Metric) -> &[f64] {
        self.values.get(&(agent, metric)).map_or(&[], Vec::as_slice)
    }

    /// Mean and spread, if there are at least two trials.
    pub fn summary(&self, agent: MazeAgent, metric: Metric) -> Option<Summary> {
        Summary::of(self.values(agent, metric)).ok()
    }

    /// The pooled (Student) and Welch tests of two agents on a metric.
    pub fn tests(&self, a: MazeAgent, b: MazeAgent, metric: Metric) -> (Option<TTest>, Option<TTest>) {
        let (x, y) = (self.values(a, metric), self.values(b, metric));
        (student_t_test(x, y).ok(), welch_t_test(x, y).ok())
    }
}

/// The ten pairs of Table 6.2, in the thesis's order, from their labels.
pub fn thesis_pairs() -> [(MazeAgent, MazeAgent); 10] {
    use MazeAgent::*;
    [
        (Sarsa, Sis),
        (Sarsa, Dis),
        (Sarsa, Hat),
        (Sarsa, Sbs),
        (Dis, Hat),
        (Dis, Sis),
        (Dis, Sbs),
        (Sis, Hat),
        (Sis, Sbs),
        (Sbs, Hat),
    ]
}

/// "SAR vs SIS": the row label of a pair in `thesis-numbers.toml`.
pub fn pair_label(a: MazeAgent, b: MazeAgent) -> String {
    format!("{} vs {}", a.label(), b.label())
}

/// The trial-mean learning curve and its standard error, per episode.
pub fn mean_curve(trials: &[MazeTrial]) -> (Vec<f64>, Vec<f64>) {
    let curves: Vec<&[f64]> = trials.iter().map(|t| t.returns.as_slice()).collect();
    let mean = curve::mean_curve(&curves).unwrap_or_default();
    let se = curve::se_curve(&curves).unwrap_or_else(|_| vec![0.0; mean.len()]);
    (mean, se)
}
