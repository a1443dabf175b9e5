//! Learning-curve metrics on per-episode returns (`curve[0]` is episode 1), and episode-wise means over trials.
//!
//! The thesis compares learners by their initial performance (first
//! episode), asymptotic performance (last episode, Table 6.2) and cumulative
//! reward (the sum over the trial); those three and a few helpers for the
//! figures live here. Episode numbers in results are one-based, like the
//! thesis's axes; slice indices are zero-based.

use std::cmp::Ordering;

use crate::error::{Result, StatsError, check_finite, check_sample, finite};
use crate::summary::{compensated_sum, mean_unchecked, mean_var_unchecked};

/// `curve[index]`, or why it cannot be used.
fn episode(curve: &[f64], index: Option<usize>) -> Result<f64> {
    match index.and_then(|i| curve.get(i).map(|&v| (i, v))) {
        None => Err(StatsError::TooFewSamples { input: "curve", needed: 1, got: curve.len() }),
        Some((index, v)) if !v.is_finite() => Err(StatsError::NonFinite { input: "curve", index }),
        Some((_, v)) => Ok(v),
    }
}

/// Performance in the first episode, `curve[0]`.
pub fn initial(curve: &[f64]) -> Result<f64> {
    episode(curve, Some(0))
}

/// Performance in the last episode (what the thesis's Maze table calls asymptotic).
pub fn asymptotic_last(curve: &[f64]) -> Result<f64> {
    episode(curve, curve.len().checked_sub(1))
}

/// Mean of the last `k` episodes, a less noisy asymptotic measure; `1 ≤ k ≤ curve.len()`.
///
/// The whole curve must be finite, not only its last `k` episodes.
pub fn asymptotic_mean_last(curve: &[f64], k: usize) -> Result<f64> {
    if k == 0 {
        return Err(StatsError::InvalidParameter("asymptotic window k must be at least 1"));
    }
    check_sample("curve", curve, k)?;
    finite(mean_unchecked(&curve[curve.len() - k..]))
}

/// Total reward over the trial, `Σ curve` (compensated, in episode order).
pub fn cumulative(curve: &[f64]) -> Result<f64> {
    check_sample("curve", curve, 1)?;
    finite(compensated_sum(curve.iter().copied()))
}

/// Trailing moving average: `out[i]` is the mean of `curve[i+1−w ..= i]`, the
/// current episode and up to `w − 1` before it.
///
/// The window is shorter at the start (`out[0] = curve[0]`,
/// `out[1] = mean(curve[0..=1])`, …), so the output has the input's length
/// and no value is invented before episode 1. Each window is averaged
/// afresh (no running sum), so no rounding drifts along long curves.
pub fn moving_average(curve: &[f64], window: usize) -> Result<Vec<f64>> {
    if window == 0 {
        return Err(StatsError::InvalidParameter("moving-average window must be at least 1"));
    }
    check_finite("curve", curve)?;
    (0..curve.len()).map(|i| finite(mean_unchecked(&curve[(i + 1).saturating_sub(window)..=i]))).collect()
}

/// Checks a set of trials: at least `needed` of them, equal lengths, finite values.
fn check_trials<T: AsRef<[f64]>>(trials: &[T], needed: usize) -> Result<usize> {
    if trials.len() < needed {
        return Err(StatsError::TooFewSamples { input: "trials", needed, got: trials.len() });
    }
    let expected = trials[0].as_ref().len();
    for (trial, curve) in trials.iter().enumerate() {
        let curve = curve.as_ref();
        if curve.len() != expected {
            return Err(StatsError::RaggedTrials { trial, expected, got: curve.len() });
        }
        if let Some(episode) = curve.iter().position(|v| !v.is_finite()) {
            return Err(StatsError::NonFiniteInTrial { trial, episode });
        }
    }
    Ok(expected)
}

/// Applies `f` to each episode's column of values across trials.
fn per_episode<T: AsRef<[f64]>>(trials: &[T], needed: usize, f: impl Fn(&[f64]) -> Result<f64>) -> Result<Vec<f64>> {
    let episodes = check_trials(trials, needed)?;
    let mut column = vec![0.0; trials.len()];
    (0..episodes)
        .map(|e| {
            for (slot, trial) in column.iter_mut().zip(trials) {
                *slot = trial.as_ref()[e];
            }
            f(&column)
        })
        .collect()
}

/// Episode-wise mean over trials (at least one trial, all of one length).
pub fn mean_curve<T: AsRef<[f64]>>(trials: &[T]) -> Result<Vec<f64>> {
    per_episode(trials, 1, |c| finite(mean_unchecked(c)))
}

/// Episode-wise sample standard deviation (`n − 1`) over trials (at least two trials).
pub fn sd_curve<T: AsRef<[f64]>>(trials: &[T]) -> Result<Vec<f64>> {
    per_episode(trials, 2, |c| Ok(mean_var_unchecked(c)?.1.sqrt()))
}

/// Episode-wise standard error of the mean over trials, `sd/√trials` (at least two trials).
pub fn se_curve<T: AsRef<[f64]>>(trials: &[T]) -> Result<Vec<f64>> {
    let root_n = (trials.len() as f64).sqrt();
    per_episode(trials, 2, |c| Ok(mean_var_unchecked(c)?.1.sqrt() / root_n))
}

/// The one-based episode from which `curve` stays strictly above `reference`
/// through the last episode; `None` if the last episode is not above it.
///
/// A curve that starts above, dips to or below `reference` and recovers
/// counts from the recovery: `[5, 1, 6, 7]` against `3` gives `Some(3)`.
/// NaN never counts as above (nor does anything when `reference` is NaN).
pub fn episodes_to_surpass(curve: &[f64], reference: f64) -> Option<usize> {
    let above_from =
        curve.iter().rposition(|&v| v.partial_cmp(&reference) != Some(Ordering::Greater)).map_or(0, |i| i + 1);
    (above_from < curve.len()).then_some(above_from + 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;
    use proptest::prelude::*;

    // Hand-computed expectations.
    const CURVE: [f64; 6] = [-10.0, -4.0, 2.0, 5.0, 4.0, 7.0];

    #[test]
    fn point_metrics() {
        assert_eq!(initial(&CURVE), Ok(-10.0));
        assert_eq!(asymptotic_last(&CURVE), Ok(7.0));
        assert_eq!(asymptotic_mean_last(&CURVE, 1), Ok(7.0));
        assert_eq!(asymptotic_mean_last(&CURVE, 3), Ok(16.0 / 3.0));
        assert_eq!(asymptotic_mean_last(&CURVE, 6), Ok(4.0 / 6.0));
        assert_eq!(cumulative(&CURVE), Ok(4.0));
    }

    #[test]
    fn moving_average_is_trailing_and_short_at_the_start() {
        let ma = moving_average(&CURVE, 3).unwrap();
        let expected = [-10.0, -7.0, -4.0, 1.0, 11.0 / 3.0, 16.0 / 3.0];
        assert_eq!(ma.len(), CURVE.len());
        for (a, e) in ma.iter().zip(expected) {
            assert_close(*a, e, 1e-15);
        }
        assert_eq!(moving_average(&CURVE, 1).unwrap(), CURVE.to_vec());
        // A window longer than the curve is the running mean.
        let long = moving_average(&CURVE, 100).unwrap();
        assert_close(long[5], 4.0 / 6.0, 1e-15);
        assert_eq!(moving_average(&[], 3), Ok(vec![]));
    }

    #[test]
    fn across_trials() {
        let trials = vec![vec![1.0, 2.0, 3.0], vec![3.0, 2.0, 7.0], vec![2.0, 2.0, 8.0]];
        assert_eq!(mean_curve(&trials), Ok(vec![2.0, 2.0, 6.0]));
        // Column 3 is [3, 7, 8]: variance ((−3)² + 1² + 2²)/2 = 7.
        let sd = sd_curve(&trials).unwrap();
        assert_eq!(&sd[..2], &[1.0, 0.0]);
        assert_close(sd[2], 7.0_f64.sqrt(), 1e-15);
        let se = se_curve(&trials).unwrap();
        assert_close(se[0], 1.0 / 3.0_f64.sqrt(), 1e-15);
        assert_close(se[2], (7.0_f64 / 3.0).sqrt(), 1e-15);
        // Slices work as well as vectors.
        let slices: [&[f64]; 2] = [&[1.0, 2.0], &[3.0, 4.0]];
        assert_eq!(mean_curve(&slices), Ok(vec![2.0, 3.0]));
    }

    #[test]
    fn surpass() {
        // Starts above, dips below, recovers at episode 3.
        assert_eq!(episodes_to_surpass(&[5.0, 1.0, 6.0, 7.0], 3.0), Some(3));
        // Equal is not above.
        assert_eq!(episodes_to_surpass(&[5.0, 3.0, 6.0, 7.0], 3.0), Some(3));
        // Above throughout.
        assert_eq!(episodes_to_surpass(&[4.0, 5.0], 3.0), Some(1));
        // Ends below, or at the reference.
        assert_eq!(episodes_to_surpass(&[4.0, 5.0, 2.0], 3.0), None);
        assert_eq!(episodes_to_surpass(&[4.0, 3.0], 3.0), None);
        // Only the last episode.
        assert_eq!(episodes_to_surpass(&CURVE, 5.0), Some(6));
        assert_eq!(episodes_to_surpass(&CURVE, 3.0), Some(4));
        assert_eq!(episodes_to_surpass(&[], 0.0), None);
        assert_eq!(episodes_to_surpass(&[1.0, f64::NAN, 2.0], 0.0), Some(3));
        assert_eq!(episodes_to_surpass(&[1.0, 2.0], f64::NAN), None);
    }

    #[test]
    fn errors() {
        let empty: [f64; 0] = [];
        let too_few = |needed| StatsError::TooFewSamples { input: "curve", needed, got: 0 };
        assert_eq!(initial(&empty), Err(too_few(1)));
        assert_eq!(asymptotic_last(&empty), Err(too_few(1)));
        assert_eq!(cumulative(&empty), Err(too_few(1)));
        assert_eq!(initial(&[f64::NAN]), Err(StatsError::NonFinite { input: "curve", index: 0 }));
        assert_eq!(asymptotic_last(&[1.0, 2.0, f64::NAN]), Err(StatsError::NonFinite { input: "curve", index: 2 }));
        assert!(matches!(asymptotic_mean_last(&CURVE, 0), Err(StatsError::InvalidParameter(_))));
        assert_eq!(
            asymptotic_mean_last(&CURVE, 7),
            Err(StatsError::TooFewSamples { input: "curve", needed: 7, got: 6 })
        );
        assert!(matches!(moving_average(&CURVE, 0), Err(StatsError::InvalidParameter(_))));
        assert_eq!(cumulative(&[1.0, f64::INFINITY]), Err(StatsError::NonFinite { input: "curve", index: 1 }));
        assert_eq!(cumulative(&[1e308, 1e308]), Err(StatsError::Overflow));
        let ragged = vec![vec![1.0, 2.0], vec![1.0, 2.0], vec![1.0]];
        assert_eq!(mean_curve(&ragged), Err(StatsError::RaggedTrials { trial: 2, expected: 2, got: 1 }));
        let nan = vec![vec![1.0, 2.0], vec![1.0, f64::NAN]];
        assert_eq!(mean_curve(&nan), Err(StatsError::NonFiniteInTrial { trial: 1, episode: 1 }));
        let none: Vec<Vec<f64>> = vec![];
        assert!(matches!(mean_curve(&none), Err(StatsError::TooFewSamples { needed: 1, .. })));
        assert!(matches!(se_curve(&[vec![1.0]]), Err(StatsError::TooFewSamples { needed: 2, .. })));
    }

    proptest! {
        #[test]
        fn surpass_point_is_the_start_of_the_final_run_above(
            curve in proptest::collection::vec(-10.0..10.0_f64, 0..30),
            reference in -10.0..10.0_f64,
        ) {
            match episodes_to_surpass(&curve, reference) {
                Some(k) => {
                    prop_assert!(k >= 1 && k <= curve.len());
                    prop_assert!(curve[k - 1..].iter().all(|&v| v > reference));
                    prop_assert!(k == 1 || curve[k - 2] <= reference);
                }
                None => prop_assert!(curve.last().is_none_or(|&v| v <= reference)),
            }
        }

        #[test]
        fn moving_average_of_constant_is_constant(c in -1e6..1e6_f64, n in 0usize..50, w in 1usize..10) {
            let ma = moving_average(&vec![c; n], w).unwrap();
            prop_assert!(ma.iter().all(|&v| v == c));
        }

        #[test]
        fn mean_curve_of_identical_trials_is_the_trial(
            curve in proptest::collection::vec(-1e6..1e6_f64, 0..20),
            trials in 1usize..6,
        ) {
            let set = vec![curve.clone(); trials];
            prop_assert_eq!(mean_curve(&set).unwrap(), curve);
        }
    }
}
