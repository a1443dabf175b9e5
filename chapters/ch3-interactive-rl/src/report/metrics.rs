//! What the report computes from stored sessions: Table 3.2's five numbers
//! per session, the teacher's involvement over time (Figure 3.4), the
//! reductions with guidance, and the tests behind the claims.
//!
//! Reductions are `1 − mean(guided) / mean(unguided)`, in percent, as the
//! thesis's "guidance remarkably reduces the learning time (small state
//! space: 28%, large state space: 44%)". Involvement per minute pools the
//! trials still training in that minute: the share of their actions (by
//! start time) the teacher rewarded, guided, or either.

use rand::Rng;
use rlfd_rl::random::{below, seeded};
use rlfd_stats::{Summary, TTest, TimeToEvent, quantile, student_t_test, welch_t_test};

use crate::experiment::Condition;
use crate::nao::{Action, Durations};
use crate::session::{SessionRecord, flag};

/// A row of Table 3.2.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Metric {
    States,
    Actions,
    CumulativeReward,
    Guidance,
    Minutes,
}

impl Metric {
    /// Table 3.2's rows, in order.
    pub const ALL: [Metric; 5] =
        [Metric::States, Metric::Actions, Metric::CumulativeReward, Metric::Guidance, Metric::Minutes];

    /// The column key of `thesis-numbers.toml`.
    pub fn key(self) -> &'static str {
        match self {
            Metric::States => "states",
            Metric::Actions => "actions",
            Metric::CumulativeReward => "cumulative_reward",
            Metric::Guidance => "total_guidance",
            Metric::Minutes => "training_time_min",
        }
    }

    /// Table 3.2's row label.
    pub fn label(self) -> &'static str {
        match self {
            Metric::States => "#States",
            Metric::Actions => "#Actions",
            Metric::CumulativeReward => "Cumul. Rew.",
            Metric::Guidance => "Total #G.",
            Metric::Minutes => "Training Time [min.]",
        }
    }

    /// The session's value.
    pub fn of(self, r: &SessionRecord) -> f64 {
        match self {
            Metric::States => f64::from(r.states_discovered),
            Metric::Actions => f64::from(r.actions),
            Metric::CumulativeReward => r.cumulative_reward,
            Metric::Guidance => f64::from(r.guidance_given),
            Metric::Minutes => r.training_minutes(),
        }
    }
}

/// The metric's values over sessions, in trial order.
pub fn values(trials: &[SessionRecord], m: Metric) -> Vec<f64> {
    trials.iter().map(|t| m.of(t)).collect()
}

/// Mean over sessions (NaN for none).
pub fn mean(trials: &[SessionRecord], m: Metric) -> f64 {
    let v = values(trials, m);
    if v.is_empty() { f64::NAN } else { rlfd_stats::mean(&v).unwrap_or(f64::NAN) }
}

/// Mean and sd (sd NaN for fewer than two sessions).
pub fn summary(trials: &[SessionRecord], m: Metric) -> (f64, f64) {
    match Summary::of(&values(trials, m)) {
        Ok(s) => (s.mean, s.sd),
        Err(_) => (mean(trials, m), f64::NAN),
    }
}

/// `1 − guided / unguided` in percent.
pub fn reduction_pct(guided: f64, unguided: f64) -> f64 {
    100.0 * (1.0 - guided / unguided)
}

/// Pooled (the thesis's MATLAB default) and Welch t-tests, guided vs unguided.
pub fn tests(guided: &[SessionRecord], unguided: &[SessionRecord], m: Metric) -> (Option<TTest>, Option<TTest>) {
    let (g, u) = (values(guided, m), values(unguided, m));
    (student_t_test(&g, &u).ok(), welch_t_test(&g, &u).ok())
}

/// The guided and unguided conditions of a state space.
pub fn pair(small: bool) -> (Condition, Condition) {
    if small {
        (Condition::SmallGuidance, Condition::SmallNoGuidance)
    } else {
        (Condition::LargeGuidance, Condition::LargeNoGuidance)
    }
}

/// The teacher's involvement per time bin, pooled over sessions.
#[derive(Clone, Debug, PartialEq)]
pub struct Involvement {
    /// Bin width in minutes.
    pub bin_minutes: f64,
    /// Sessions pooled.
    pub sessions: usize,
    /// Actions starting in each bin.
    pub actions: Vec<u32>,
    /// Of those, rewarded.
    pub rewarded: Vec<u32>,
    /// Of those, guided.
    pub guided: Vec<u32>,
    /// Of those, rewarded or guided.
    pub attended: Vec<u32>,
    /// Sessions still training at the bin's start.
    pub running: Vec<u32>,
}

impl Involvement {
    /// Share of the bin's actions with the given count, in percent (NaN for an empty bin).
    pub fn share(&self, counts: &[u32], bin: usize) -> f64 {
        if self.actions[bin] == 0 { f64::NAN } else { 100.0 * f64::from(counts[bin]) / f64::from(self.actions[bin]) }
    }

    /// The end (in minutes) of the first bin whose share of attended actions is below 50 %.
    pub fn first_below_half(&self) -> Option<f64> {
        (0..self.actions.len())
            .find(|&b| self.actions[b] > 0 && 2 * self.attended[b] < self.actions[b])
            .map(|b| (b + 1) as f64 * self.bin_minutes)
    }
}

/// Start times (seconds) of a session's actions.
fn start_times(r: &SessionRecord, seconds: &[f64; Action::COUNT]) -> Vec<f64> {
    let mut t = 0.0;
    r.action_log
        .iter()
        .map(|&a| {
            let start = t;
            t += seconds[a as usize];
            start
        })
        .collect()
}

/// Involvement of `sessions` in bins of `bin_minutes`.
pub fn involvement(sessions: &[SessionRecord], durations: &Durations, bin_minutes: f64) -> Involvement {
    let seconds = durations.table();
    let width = bin_minutes * 60.0;
    let longest = sessions.iter().map(|s| s.training_seconds).fold(0.0, f64::max);
    let bins = ((longest / width).ceil() as usize).max(1);
    let mut inv = Involvement {
        bin_minutes,
        sessions: sessions.len(),
        actions: vec![0; bins],
        rewarded: vec![0; bins],
        guided: vec![0; bins],
        attended: vec![0; bins],
        running: vec![0; bins],
    };
    for s in sessions {
        for (b, running) in inv.running.iter_mut().enumerate() {
            if s.training_seconds > b as f64 * width {
                *running += 1;
            }
        }
        for (start, &f) in start_times(s, &seconds).into_iter().zip(&s.flags) {
            let b = ((start / width) as usize).min(bins - 1);
            inv.actions[b] += 1;
            inv.rewarded[b] += u32::from(f & flag::REWARDED != 0);
            inv.guided[b] += u32::from(f & flag::GUIDED != 0);
            inv.attended[b] += u32::from(f & (flag::REWARDED | flag::GUIDED) != 0);
        }
    }
    inv
}

/// Per session: the end (minutes) of the first bin in which fewer than half
/// of its actions drew reward or guidance, as a time to an event; a session
/// that never gets there is *censored* at its end (its crossing, if any, lies
/// after the session stopped: counting it as a crossing at the end would
/// bias the comparison toward whichever condition ends sooner).
pub fn first_below_half_per_session(
    sessions: &[SessionRecord],
    durations: &Durations,
    bin_minutes: f64,
) -> Vec<TimeToEvent> {
    sessions
        .iter()
        .map(|s| match involvement(std::slice::from_ref(s), durations, bin_minutes).first_below_half() {
            Some(t) => TimeToEvent::event(t),
            None => TimeToEvent::censored(s.training_minutes()),
        })
        .collect()
}

/// A percentile-bootstrap interval for `statistic` of four independent
/// samples, each resampled within itself (`resamples` times, seeded): the
/// difference between the large and the small space's reductions needs all
/// four conditions at once. Returns `(estimate, lower, upper)` at `level`.
pub fn bootstrap_four(
    samples: [&[f64]; 4],
    statistic: impl Fn([&[f64]; 4]) -> f64,
    resamples: usize,
    level: f64,
    seed: u64,
) -> Option<(f64, f64, f64)> {
    if samples.iter().any(|s| s.is_empty()) {
        return None;
    }
    let estimate = statistic(samples);
    let mut rng = seeded(seed);
    let mut buffers: [Vec<f64>; 4] = std::array::from_fn(|i| vec![0.0; samples[i].len()]);
    let mut stats = Vec::with_capacity(resamples);
    for _ in 0..resamples {
        for (buffer, sample) in buffers.iter_mut().zip(samples) {
            resample(&mut rng, sample, buffer);
        }
        stats.push(statistic([&buffers[0], &buffers[1], &buffers[2], &buffers[3]]));
    }
    let alpha = 1.0 - level;
    Some((estimate, quantile(&stats, alpha / 2.0).ok()?, quantile(&stats, 1.0 - alpha / 2.0).ok()?))
}

fn resample<R: Rng + ?Sized>(rng: &mut R, from: &[f64], into: &mut [f64]) {
    for v in into.iter_mut() {
        *v = from[below(rng, from.len())];
    }
}

/// `x` with `decimals` digits and a typographic minus, for prose.
pub fn num(x: f64, decimals: usize) -> String {
    format!("{x:.decimals$}").replace('-', "\u{2212}")
}

/// Plain mean of a sample (sequential).
pub fn sample_mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(actions: &[(Action, u8)]) -> SessionRecord {
        let d = Durations::thesis();
        SessionRecord {
            states_discovered: 3,
            actions: actions.len() as u32,
            cumulative_reward: 0.0,
            guidance_given: 0,
            rewards_given: 0,
            mistakes: 0,
            training_seconds: actions.iter().map(|(a, _)| d.seconds(*a)).sum(),
            finished: true,
            objects_sorted: 0,
            objects_missorted: 0,
            descriptors_read: 0,
            action_log: actions.iter().map(|(a, _)| a.index() as u8).collect(),
            flags: actions.iter().map(|(_, f)| *f).collect(),
        }
    }

    #[test]
    fn involvement_bins_actions_by_start_time() {
        // TakePicture lasts 2 units = 9.33 s: 7 pictures span 65.3 s.
        let attended = flag::REWARDED | flag::GUIDED;
        let mut acts = vec![(Action::TakePicture, attended); 4];
        acts.extend(vec![(Action::TakePicture, 0); 3]);
        let r = record(&acts);
        let inv = involvement(std::slice::from_ref(&r), &Durations::thesis(), 0.5);
        // Starts at 0, 9.3, 18.7, 28.0 (bin 0); 37.3, 46.7, 56.0 (bin 1); total 65.3 s → 3 bins.
        assert_eq!(inv.actions, vec![4, 3, 0]);
        assert_eq!(inv.attended, vec![4, 0, 0]);
        assert_eq!(inv.running, vec![1, 1, 1]);
        assert_eq!(inv.first_below_half(), Some(1.0));
        assert_eq!(inv.share(&inv.rewarded, 0), 100.0);
        assert!(inv.share(&inv.rewarded, 2).is_nan());
        assert_eq!(first_below_half_per_session(&[r], &Durations::thesis(), 0.5), vec![TimeToEvent::event(1.0)]);
    }

    #[test]
    fn reductions_and_the_thesis_s_arithmetic() {
        // From the thesis's own Table 3.2: 14 vs 18 minutes is a 22.2 % cut, not 28 %.
        assert!((reduction_pct(14.0, 18.0) - 22.22).abs() < 0.01);
        assert!((reduction_pct(11.33, 22.0) - 48.5).abs() < 0.01);
    }

    #[test]
    fn the_four_sample_bootstrap_brackets_its_estimate_and_is_seeded() {
        let a = [1.0, 2.0, 3.0, 4.0];
        let b = [2.0, 3.0, 4.0, 5.0];
        let stat = |s: [&[f64]; 4]| sample_mean(s[0]) - sample_mean(s[1]) + sample_mean(s[2]) - sample_mean(s[3]);
        let (e, lo, hi) = bootstrap_four([&a, &b, &b, &a], stat, 2000, 0.95, 7).unwrap();
        assert_eq!(e, 0.0);
        assert!(lo < 0.0 && hi > 0.0);
        assert_eq!(bootstrap_four([&a, &b, &b, &a], stat, 2000, 0.95, 7), Some((e, lo, hi)));
        assert_eq!(bootstrap_four([&a, &[], &b, &a], stat, 10, 0.95, 7), None);
    }
}
