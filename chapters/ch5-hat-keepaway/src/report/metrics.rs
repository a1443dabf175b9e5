//! The thesis's metrics (section 5.3.2), computed from each trial's stored
//! episode durations, and their comparisons.
//!
//! How the thesis's definitions are read (each a documented decision):
//!
//! - **Learning curve**: at simulated time τ, the mean duration (s) of the
//!   last `window` (1,000) training episodes that ended by τ (all of them
//!   while fewer have ended); at τ = 0, before any training, the jumpstart
//!   evaluation's mean.
//! - **Jumpstart**: the mean duration of the evaluation episodes played with
//!   learning off before training (the agents as they start: ψ = 1, forced
//!   periods in force), minus No Prior's; tested on the per-trial means.
//! - **Final reward**: the mean of the last `window` training episodes.
//! - **Total reward**: the curve's values at the integral hours
//!   0, 1, …, 30 summed ("the sum of the average episode durations at every
//!   integral hour of training", each "a sliding window over the past
//!   1,000 episodes"), in seconds.
//! - **Hours to 14 s**: on the trial-mean training curve sampled every
//!   0.1 h (from 0.1 h: the jumpstart evaluation is not training), the
//!   first time it reaches 14 s, interpolated linearly between samples.

use rlfd_stats::{Summary, TTest, student_t_test, welch_t_test};

use crate::keepaway::{CYCLES_PER_HOUR, CYCLES_PER_SECOND};
use crate::learners::LearningTrial;

/// One trial's metrics.
#[derive(Clone, Debug, PartialEq)]
pub struct TrialMetrics {
    /// The jumpstart evaluation's mean duration (s).
    pub initial: f64,
    /// Mean of the last `window` episodes (s).
    pub final_reward: f64,
    /// Sum of the curve at the integral hours 0..=H (s).
    pub total: f64,
    /// The curve at the integral hours 0..=H (s).
    pub hourly: Vec<f64>,
}

/// A trial's episode end times and prefix sums, for window means at any time.
#[derive(Clone, Debug)]
pub struct Curve {
    ends: Vec<u64>,
    prefix: Vec<u64>,
    window: usize,
    initial: f64,
}

impl Curve {
    /// The curve of a trial with a sliding window of `window` episodes.
    pub fn new(trial: &LearningTrial, window: usize) -> Curve {
        let mut ends = Vec::with_capacity(trial.durations.len());
        let mut prefix = Vec::with_capacity(trial.durations.len() + 1);
        prefix.push(0);
        let mut t = 0u64;
        for &d in &trial.durations {
            t += u64::from(d);
            ends.push(t);
            prefix.push(t);
        }
        Curve { ends, prefix, window: window.max(1), initial: trial.jumpstart_cycles / CYCLES_PER_SECOND }
    }

    /// The mean duration (s) of the last `window` episodes ended by `hours`
    /// (the jumpstart mean at 0 and before the first episode ends).
    pub fn at(&self, hours: f64) -> f64 {
        let tau = (hours * CYCLES_PER_HOUR as f64).round() as u64;
        let n = self.ends.partition_point(|&e| e <= tau);
        if hours <= 0.0 || n == 0 {
            return self.initial;
        }
        let from = n.saturating_sub(self.window);
        (self.prefix[n] - self.prefix[from]) as f64 / (n - from) as f64 / CYCLES_PER_SECOND
    }

    /// The mean of the last `window` episodes of the trial (s).
    pub fn final_reward(&self) -> f64 {
        let n = self.ends.len();
        if n == 0 {
            return self.initial;
        }
        let from = n.saturating_sub(self.window);
        (self.prefix[n] - self.prefix[from]) as f64 / (n - from) as f64 / CYCLES_PER_SECOND
    }
}

/// The metrics of a trial over `hours` simulated hours.
pub fn trial_metrics(trial: &LearningTrial, window: usize, hours: f64) -> TrialMetrics {
    let curve = Curve::new(trial, window);
    let whole = hours.floor() as usize;
    let hourly: Vec<f64> = (0..=whole).map(|h| curve.at(h as f64)).collect();
    TrialMetrics { initial: curve.initial, final_reward: curve.final_reward(), total: hourly.iter().sum(), hourly }
}

/// The trial-mean curve sampled at `times` (hours), with its standard error over trials.
pub fn mean_curve(trials: &[LearningTrial], window: usize, times: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let curves: Vec<Curve> = trials.iter().map(|t| Curve::new(t, window)).collect();
    let mut mean = Vec::with_capacity(times.len());
    let mut se = Vec::with_capacity(times.len());
    for &h in times {
        let v: Vec<f64> = curves.iter().map(|c| c.at(h)).collect();
        match Summary::of(&v) {
            Ok(s) => {
                mean.push(s.mean);
                se.push(s.se);
            }
            Err(_) => {
                mean.push(v.first().copied().unwrap_or(f64::NAN));
                se.push(0.0);
            }
        }
    }
    (mean, se)
}

/// The first time (hours) the trial-mean training curve reaches `threshold`
/// seconds, sampled every 0.1 h from 0.1 h to `hours` and interpolated
/// between samples (the first sample's time if it is already there); `None`
/// if never. The jumpstart evaluation (hour 0) is not part of it.
pub fn hours_to_threshold(trials: &[LearningTrial], window: usize, hours: f64, threshold: f64) -> Option<f64> {
    let steps = (hours * 10.0).round() as usize;
    let times: Vec<f64> = (1..=steps).map(|k| k as f64 / 10.0).collect();
    let (mean, _) = mean_curve(trials, window, &times);
    if mean.first().is_some_and(|&v| v >= threshold) {
        return times.first().copied();
    }
    for k in 1..times.len() {
        if mean[k] >= threshold {
            let (t0, t1, v0, v1) = (times[k - 1], times[k], mean[k - 1], mean[k]);
            return Some(if v1 > v0 { t0 + (threshold - v0) / (v1 - v0) * (t1 - t0) } else { t1 });
        }
    }
    None
}

/// Per-trial values of one metric for a condition.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConditionMetrics {
    /// Jumpstart evaluation means (s).
    pub initial: Vec<f64>,
    /// Final rewards (s).
    pub final_reward: Vec<f64>,
    /// Total rewards.
    pub total: Vec<f64>,
    /// Hourly curves.
    pub hourly: Vec<Vec<f64>>,
}

impl ConditionMetrics {
    /// The metrics of a condition's trials.
    pub fn of(trials: &[LearningTrial], window: usize, hours: f64) -> ConditionMetrics {
        let mut m = ConditionMetrics::default();
        for t in trials {
            let x = trial_metrics(t, window, hours);
            m.initial.push(x.initial);
            m.final_reward.push(x.final_reward);
            m.total.push(x.total);
            m.hourly.push(x.hourly);
        }
        m
    }

    /// One metric's values.
    pub fn values(&self, metric: Metric) -> &[f64] {
        match metric {
            Metric::Jumpstart => &self.initial,
            Metric::Final => &self.final_reward,
            Metric::Total => &self.total,
        }
    }
}

/// The thesis's three metrics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Metric {
    /// Initial performance (reported relative to No Prior).
    Jumpstart,
    /// Final reward.
    Final,
    /// Total reward.
    Total,
}

impl Metric {
    /// In the thesis's column order.
    pub const ALL: [Metric; 3] = [Metric::Jumpstart, Metric::Final, Metric::Total];

    /// The key in `thesis-numbers.toml`.
    pub fn key(self) -> &'static str {
        match self {
            Metric::Jumpstart => "jumpstart",
            Metric::Final => "final",
            Metric::Total => "total",
        }
    }

    /// Column header.
    pub fn header(self) -> &'static str {
        match self {
            Metric::Jumpstart => "Jumpstart",
            Metric::Final => "Final",
            Metric::Total => "Total",
        }
    }
}

/// Mean and sd (sd 0 for a single trial).
pub fn mean_sd(x: &[f64]) -> (f64, f64) {
    match Summary::of(x) {
        Ok(s) => (s.mean, s.sd),
        Err(_) => (x.first().copied().unwrap_or(f64::NAN), 0.0),
    }
}

/// The pooled (Student) and Welch tests of `x` against `y`.
pub fn tests(x: &[f64], y: &[f64]) -> (Option<TTest>, Option<TTest>) {
    (student_t_test(x, y).ok(), welch_t_test(x, y).ok())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trial(durations: Vec<u32>, jump: f64) -> LearningTrial {
        LearningTrial { jumpstart_cycles: jump, jumpstart_episodes: 10, durations, greedy_cycles: Vec::new() }
    }

    #[test]
    fn the_curve_is_a_sliding_window_at_simulated_times() {
        // 36,000 cycles per hour: 360 episodes of 100 cycles, then 180 of 200.
        let mut d = vec![100u32; 360];
        d.extend(vec![200u32; 180]);
        let t = trial(d, 50.0);
        let c = Curve::new(&t, 100);
        assert_eq!(c.at(0.0), 5.0);
        assert_eq!(c.at(1.0), 10.0);
        assert_eq!(c.at(2.0), 20.0);
        // Half an hour into the second hour: 90 episodes of 200 and 10 of 100.
        assert!((c.at(1.5) - (90.0 * 20.0 + 10.0 * 10.0) / 100.0).abs() < 1e-12);
        let m = trial_metrics(&t, 100, 2.0);
        assert_eq!(m.hourly, vec![5.0, 10.0, 20.0]);
        assert_eq!(m.total, 35.0);
        assert_eq!(m.final_reward, 20.0);
    }

    #[test]
    fn the_threshold_is_interpolated_on_the_mean_curve() {
        let mut d = vec![100u32; 360];
        d.extend(vec![200u32; 180]);
        let trials = [trial(d.clone(), 50.0), trial(d, 50.0)];
        // Every 0.1 h adds 18 episodes of 20 s to the window: 13.6 s at 1.2 h, 15.4 s at 1.3 h.
        let h = hours_to_threshold(&trials, 100, 2.0, 14.0).unwrap();
        let (m, _) = mean_curve(&trials, 100, &[h]);
        assert!((m[0] - 14.0).abs() < 0.6, "{h} {m:?}");
        assert!(h > 1.0 && h < 1.5);
        assert_eq!(hours_to_threshold(&trials, 100, 2.0, 25.0), None);
    }
}
