//! Time-to-event data with right censoring: the Kaplan–Meier estimate and
//! the log-rank test.
//!
//! A claim such as "with guidance the teacher's involvement falls below 50 %
//! earlier" is about the time of an event that some sessions never reach:
//! a session that ends before its involvement falls below one half is
//! *censored* at its end (all we know is that the event had not happened by
//! then). Counting it as an event at its end, or dropping it, biases the
//! comparison; the standard tools for such data are these two.
//!
//! - [`kaplan_meier`]: `S(t) = ∏_{t_j ≤ t} (1 − d_j / n_j)` over the distinct
//!   event times `t_j`, with `d_j` events and `n_j` subjects at risk (those
//!   whose time is `≥ t_j`; a subject censored at `t_j` is still at risk
//!   there). The median is the first `t_j` with `S(t_j) ≤ 0.5`, or none when
//!   the curve never gets there.
//! - [`log_rank`] (Mantel 1966; Peto & Peto 1972): at every distinct event
//!   time of the pooled sample, the events expected in group `x` under the
//!   null hypothesis of equal hazards, `E = Σ d_j n_xj / n_j`, with the
//!   hypergeometric variance `V = Σ d_j (n_xj/n_j)(1 − n_xj/n_j)(n_j − d_j)/(n_j − 1)`;
//!   `z = (O − E)/√V` is standard normal under the null (χ² = z², one
//!   degree of freedom). `z > 0` means group `x` has more events than its
//!   share, i.e. it reaches the event earlier.
//!
//! Both agree with Python's `lifelines` 0.30 (`KaplanMeierFitter`,
//! `statistics.logrank_test`); the values are pasted into the tests with
//! their source.

use crate::error::{Result, StatsError, finite};

/// One subject's time and whether the event was observed at it (`false`:
/// censored, the event had not happened by then).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeToEvent {
    /// The time of the event, or of censoring.
    pub time: f64,
    /// Whether the event happened at `time`.
    pub observed: bool,
}

impl TimeToEvent {
    /// An observed event at `time`.
    pub fn event(time: f64) -> Self {
        TimeToEvent { time, observed: true }
    }

    /// A subject censored at `time`.
    pub fn censored(time: f64) -> Self {
        TimeToEvent { time, observed: false }
    }
}

fn check(input: &'static str, sample: &[TimeToEvent]) -> Result<()> {
    if sample.is_empty() {
        return Err(StatsError::TooFewSamples { input, needed: 1, got: 0 });
    }
    for (index, s) in sample.iter().enumerate() {
        if finite(s.time).is_err() {
            return Err(StatsError::NonFinite { input, index });
        }
    }
    Ok(())
}

/// The distinct times of `samples` at which an event was observed, ascending.
fn event_times(samples: &[&[TimeToEvent]]) -> Vec<f64> {
    let mut times: Vec<f64> = samples.iter().flat_map(|s| s.iter().filter(|e| e.observed).map(|e| e.time)).collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
}

/// At risk at `t` (time ≥ t) and events at `t`, in one sample.
fn at(sample: &[TimeToEvent], t: f64) -> (f64, f64) {
    let at_risk = sample.iter().filter(|e| e.time >= t).count();
    let events = sample.iter().filter(|e| e.observed && e.time == t).count();
    (at_risk as f64, events as f64)
}

/// A Kaplan–Meier survival curve: `(t_j, S(t_j))` at each distinct event time.
#[derive(Debug, Clone, PartialEq)]
pub struct KaplanMeier {
    /// The steps of the curve, ascending in time.
    pub steps: Vec<(f64, f64)>,
    /// Subjects.
    pub subjects: usize,
    /// Subjects whose event was not observed.
    pub censored: usize,
}

impl KaplanMeier {
    /// The median time to the event: the first time at which `S(t) ≤ 0.5`;
    /// `None` when the curve stays above one half.
    pub fn median(&self) -> Option<f64> {
        self.steps.iter().find(|&&(_, s)| s <= 0.5).map(|&(t, _)| t)
    }
}

/// The Kaplan–Meier estimate of `sample`'s survival curve.
pub fn kaplan_meier(sample: &[TimeToEvent]) -> Result<KaplanMeier> {
    check("sample", sample)?;
    let mut s = 1.0;
    let steps = event_times(&[sample])
        .into_iter()
        .map(|t| {
            let (n, d) = at(sample, t);
            s *= 1.0 - d / n;
            (t, s)
        })
        .collect();
    Ok(KaplanMeier { steps, subjects: sample.len(), censored: sample.iter().filter(|e| !e.observed).count() })
}

/// The log-rank test of two samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogRank {
    /// Events observed in `x`.
    pub observed: f64,
    /// Events expected in `x` under equal hazards.
    pub expected: f64,
    /// The variance of `observed − expected` under the null.
    pub variance: f64,
    /// `(observed − expected)/√variance`: positive when `x` reaches the event earlier.
    pub z: f64,
    /// `z²`, the χ² statistic with one degree of freedom.
    pub chi_squared: f64,
    /// The two-sided p-value.
    pub p: f64,
    /// The one-sided p-value for "`x` reaches the event earlier" (`z > 0`).
    pub p_earlier: f64,
}

/// The log-rank test of `x` against `y` (see the module docs). Fails when
/// there is no observed event at all, or when the variance is zero (every
/// event at a time where only one group is at risk).
pub fn log_rank(x: &[TimeToEvent], y: &[TimeToEvent]) -> Result<LogRank> {
    check("x", x)?;
    check("y", y)?;
    let (mut observed, mut expected, mut variance) = (0.0, 0.0, 0.0);
    for t in event_times(&[x, y]) {
        let (nx, dx) = at(x, t);
        let (ny, dy) = at(y, t);
        let (n, d) = (nx + ny, dx + dy);
        observed += dx;
        expected += d * nx / n;
        if n > 1.0 {
            variance += d * (nx / n) * (1.0 - nx / n) * (n - d) / (n - 1.0);
        }
    }
    if variance <= 0.0 {
        return Err(StatsError::InvalidParameter("the log-rank test needs events while both groups are at risk"));
    }
    let z = (observed - expected) / variance.sqrt();
    Ok(LogRank {
        observed,
        expected,
        variance,
        z,
        chi_squared: z * z,
        p: libm::erfc(z.abs() / std::f64::consts::SQRT_2),
        p_earlier: 0.5 * libm::erfc(z / std::f64::consts::SQRT_2),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(times: &[f64], observed: &[u8]) -> Vec<TimeToEvent> {
        times.iter().zip(observed).map(|(&time, &o)| TimeToEvent { time, observed: o == 1 }).collect()
    }

    fn close(a: f64, b: f64) {
        assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
    }

    // Reference: lifelines 0.30.0 (Python 3.11), statistics.logrank_test and
    // KaplanMeierFitter.median_survival_time_ on the data below.
    const X_T: [f64; 10] = [3.0, 5.0, 5.0, 7.0, 8.0, 10.0, 12.0, 12.0, 15.0, 20.0];
    const X_E: [u8; 10] = [1, 1, 0, 1, 1, 0, 1, 1, 0, 0];
    const Y_T: [f64; 11] = [4.0, 6.0, 8.0, 9.0, 12.0, 14.0, 16.0, 18.0, 20.0, 20.0, 22.0];
    const Y_E: [u8; 11] = [1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 0];

    #[test]
    fn log_rank_with_ties_and_censoring_matches_lifelines() {
        let (x, y) = (sample(&X_T, &X_E), sample(&Y_T, &Y_E));
        let r = log_rank(&x, &y).unwrap();
        // logrank_test(X_T, Y_T, event_observed_A=X_E, event_observed_B=Y_E)
        close(r.chi_squared, 0.5096397511599201);
        close(r.p, 0.47529484663917454);
        assert!(r.z > 0.0, "x has its events earlier");
        close(r.p_earlier, r.p / 2.0);
        // Swapping the groups flips z and keeps χ².
        let s = log_rank(&y, &x).unwrap();
        close(s.z, -r.z);
        close(s.p_earlier, 1.0 - r.p_earlier);
    }

    #[test]
    fn kaplan_meier_medians_match_lifelines() {
        assert_eq!(kaplan_meier(&sample(&X_T, &X_E)).unwrap().median(), Some(12.0));
        assert_eq!(kaplan_meier(&sample(&Y_T, &Y_E)).unwrap().median(), Some(18.0));
        let km = kaplan_meier(&sample(&X_T, &X_E)).unwrap();
        assert_eq!((km.subjects, km.censored), (10, 4));
        // S after the first event: 1 − 1/10.
        close(km.steps[0].1, 0.9);
    }

    #[test]
    fn uncensored_integer_times_match_lifelines() {
        let a: Vec<TimeToEvent> = [2.0, 3.0, 3.0, 4.0, 4.0, 4.0, 5.0, 6.0].map(TimeToEvent::event).to_vec();
        let b: Vec<TimeToEvent> = [4.0, 5.0, 5.0, 6.0, 7.0, 7.0, 8.0, 9.0, 9.0].map(TimeToEvent::event).to_vec();
        let r = log_rank(&a, &b).unwrap();
        close(r.chi_squared, 9.45445678174409);
        close(r.p, 0.002106366652660015);
        assert_eq!(kaplan_meier(&a).unwrap().median(), Some(4.0));
        assert_eq!(kaplan_meier(&b).unwrap().median(), Some(7.0));
    }

    #[test]
    fn a_curve_that_stays_above_one_half_has_no_median() {
        let s = [TimeToEvent::event(1.0), TimeToEvent::censored(2.0), TimeToEvent::censored(3.0)];
        assert_eq!(kaplan_meier(&s).unwrap().median(), None);
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(log_rank(&[], &[TimeToEvent::event(1.0)]).is_err());
        assert!(log_rank(&[TimeToEvent::event(f64::NAN)], &[TimeToEvent::event(1.0)]).is_err());
        let censored = [TimeToEvent::censored(1.0)];
        assert!(log_rank(&censored, &censored).is_err(), "no event, no test");
    }
}
