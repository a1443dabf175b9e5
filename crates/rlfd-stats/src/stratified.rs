//! rliable's stratified-bootstrap interval for an aggregate over tasks, such as the IQM, with the Monte Carlo error of each bound.
//!
//! Agarwal, Schwarzer, Castro, Courville & Bellemare (2021), "Deep
//! reinforcement learning at the edge of the statistical precipice",
//! NeurIPS; rliable's `get_interval_estimates` with `StratifiedBootstrap`.
//! Scores come as strata, one per task, each holding that task's runs. For
//! `B` resamples, confidence `1 − α` and an aggregate `θ` of the pooled scores:
//!
//! 1. `rng = ChaCha8Rng::seed_from_u64(seed)`;
//! 2. for `b = 0..B`: for each stratum `k` in order, draw its `n_k` runs with
//!    replacement (`rng.random_range(0..n_k)`, the drawing code of
//!    [`Bootstrap`]) into that stratum's segment of one reused buffer, and
//!    record `θ*_b = θ(buffer)`;
//! 3. report the type-7 quantiles of the `θ*` at `α/2` and `1 − α/2`
//!    (rliable's default `method='percentile'`: arch's `conf_int`, which
//!    calls `np.percentile`).
//!
//! Runs never move between tasks, so every task keeps its weight. rliable
//! takes a `num_runs × num_tasks` matrix (the same number of runs per task);
//! here strata may differ in size and each is resampled to its own size.
//! With one stratum this is exactly [`Bootstrap::statistic_ci`]: same draws,
//! same bits.
//!
//! **IQM.** The aggregate of [`Bootstrap::stratified_iqm_ci`] is rliable's
//! `aggregate_iqm`, `scipy.stats.trim_mean(scores, 0.25, axis=None)` over all
//! runs of all tasks ([`aggregate_iqm`]): it drops `⌊N/4⌋` scores from each
//! end of the `N` pooled scores, as [`crate::trim_mean`] does, not
//! [`crate::iqm`]'s fractional weights (the two differ unless `N` is a
//! multiple of 4).
//!
//! **Monte Carlo error of a bound.** A bound is the `a`-quantile `Q̂(a)` of
//! `B` independent resampled statistics (`a = α/2` or `1 − α/2`). Its Monte
//! Carlo standard error is estimated from the order statistics around it:
//! `MCSE = (Q̂(a + h) − Q̂(a − h)) / 2` with `h = √(a(1 − a)/B)`, the levels
//! clamped to `[0, 1]`. This is the binomial argument of ArviZ's
//! `mcse(..., method='quantile')` (Vehtari, Gelman, Simpson, Carpenter &
//! Bürkner 2021, "Rank-normalization, folding, and localization", Bayesian
//! Analysis 16(2)) for independent draws (effective sample size `B`), with
//! the normal approximation to its beta quantiles: half the width of a ±1 sd
//! band of the bound's order statistic. Asymptotically it is the textbook
//! `√(a(1 − a)/B) / f(Q(a))` with the density `f` estimated by a difference
//! quotient (Siddiqui 1960). It is distribution-free, costs nothing beyond
//! the sort the interval needs, and shrinks as `1/√B`. Batch means were the
//! alternative and were rejected: with 2 000 resamples in 20 batches the
//! 2.5 % quantile of a batch rests on 2.5 values, which biases it. Rounded
//! to a unit of at least `4·MCSE`, a bound rarely changes with the stream
//! (it still can when it lies near a rounding boundary).
//!
//! Determinism: as [`crate::bootstrap`]. No global generator, no clock.

use crate::bootstrap::{Bootstrap, BootstrapCi, resample_into};
use crate::error::{Result, StatsError};
use crate::robust::{quantile_sorted, trim_mean_sorted};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A stratified percentile-bootstrap interval with the Monte Carlo standard error of each bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StratifiedCi {
    /// The aggregate on the original scores, the interval and its parameters.
    pub ci: BootstrapCi,
    /// Monte Carlo standard error of `ci.lower` (see the module docs).
    pub lower_mcse: f64,
    /// Monte Carlo standard error of `ci.upper`.
    pub upper_mcse: f64,
}

/// rliable's `aggregate_iqm`: the 25 % trimmed mean (`scipy.stats.trim_mean(x, 0.25)`)
/// of all scores of all strata pooled.
///
/// Needs at least one stratum, each non-empty and finite.
pub fn aggregate_iqm<S: AsRef<[f64]>>(strata: &[S]) -> Result<f64> {
    let mut pooled = Vec::with_capacity(check_strata(strata)?);
    for stratum in strata {
        pooled.extend_from_slice(stratum.as_ref());
    }
    pooled.sort_by(f64::total_cmp);
    let v = trim_mean_sorted(&pooled, IQM_TRIM);
    if v.is_finite() { Ok(v) } else { Err(StatsError::Overflow) }
}

/// rliable trims a quarter of the scores from each end.
const IQM_TRIM: f64 = 0.25;

/// Resamples of [`headline_iqm`]: five times rliable's 2 000, so that a
/// bound's Monte Carlo error is a small fraction of a table's last digit
/// (the tables print it; see [`StratifiedCi`]).
pub const HEADLINE_RESAMPLES: usize = 10_000;

/// The seed of [`headline_iqm`]'s generator: the thesis's master seed, fixed
/// before any run, the same for every row (each row resamples its own runs).
pub const HEADLINE_SEED: u64 = 20_160_501;

/// What the chapters print beside the thesis's means: rliable's IQM of one
/// condition's runs (one task, so one stratum) with its 95 % stratified
/// percentile-bootstrap interval, [`HEADLINE_RESAMPLES`] resamples drawn by
/// ChaCha8 seeded with [`HEADLINE_SEED`], and the Monte Carlo error of each bound.
///
/// Needs at least one finite run.
pub fn headline_iqm(runs: &[f64]) -> Result<StratifiedCi> {
    Bootstrap::new(0.95, HEADLINE_RESAMPLES, HEADLINE_SEED)?.stratified_iqm_ci(&[runs])
}

impl Bootstrap {
    /// Stratified percentile CI of rliable's IQM ([`aggregate_iqm`]) over `strata`
    /// (one slice of run scores per task), with the Monte Carlo error of its bounds.
    ///
    /// Needs at least one stratum, each non-empty and finite.
    pub fn stratified_iqm_ci<S: AsRef<[f64]>>(&self, strata: &[S]) -> Result<StratifiedCi> {
        // The statistic sorts a scratch copy, so no resample allocates.
        let mut scratch = Vec::new();
        self.stratified(strata, |pooled| {
            scratch.clear();
            scratch.extend_from_slice(pooled);
            scratch.sort_by(f64::total_cmp);
            trim_mean_sorted(&scratch, IQM_TRIM)
        })
    }

    /// Stratified percentile CI of an arbitrary aggregate of the pooled scores
    /// (strata concatenated in order), with the Monte Carlo error of its bounds.
    ///
    /// `statistic` sees resamples in a buffer it may not keep; if it returns
    /// NaN or an infinity the result is [`StatsError::NonFiniteStatistic`].
    /// With a single stratum the interval is bit for bit that of
    /// [`Bootstrap::statistic_ci`], so this also gives a plain bootstrap its
    /// Monte Carlo error.
    pub fn stratified_ci<S: AsRef<[f64]>>(
        &self,
        strata: &[S],
        statistic: impl Fn(&[f64]) -> f64,
    ) -> Result<StratifiedCi> {
        self.stratified(strata, statistic)
    }

    fn stratified<S: AsRef<[f64]>>(
        &self,
        strata: &[S],
        mut statistic: impl FnMut(&[f64]) -> f64,
    ) -> Result<StratifiedCi> {
        let total = check_strata(strata)?;
        let mut buffer = Vec::with_capacity(total);
        for stratum in strata {
            buffer.extend_from_slice(stratum.as_ref());
        }
        let estimate = statistic(&buffer);
        if !estimate.is_finite() {
            return Err(StatsError::NonFiniteStatistic { resample: None });
        }
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed());
        let mut stats = Vec::with_capacity(self.resamples());
        for b in 0..self.resamples() {
            let mut rest = buffer.as_mut_slice();
            for stratum in strata {
                let stratum = stratum.as_ref();
                let (segment, tail) = rest.split_at_mut(stratum.len());
                resample_into(&mut rng, stratum, segment);
                rest = tail;
            }
            let v = statistic(&buffer);
            if !v.is_finite() {
                return Err(StatsError::NonFiniteStatistic { resample: Some(b) });
            }
            stats.push(v);
        }
        stats.sort_by(f64::total_cmp);
        let ci = self.interval_sorted(estimate, &stats);
        let (lower, upper) = self.bound_probabilities();
        Ok(StratifiedCi { ci, lower_mcse: quantile_mcse(&stats, lower), upper_mcse: quantile_mcse(&stats, upper) })
    }
}

/// Monte Carlo standard error of the type-7 `a`-quantile of the ascending,
/// non-empty `sorted` (independent draws): `(Q(a + h) − Q(a − h))/2`,
/// `h = √(a(1 − a)/B)`.
fn quantile_mcse(sorted: &[f64], a: f64) -> f64 {
    let h = libm::sqrt(a * (1.0 - a) / sorted.len() as f64);
    let above = quantile_sorted(sorted, (a + h).min(1.0));
    let below = quantile_sorted(sorted, (a - h).max(0.0));
    0.5 * (above - below)
}

/// Checks the strata (at least one, each non-empty and finite) and returns their total size.
fn check_strata<S: AsRef<[f64]>>(strata: &[S]) -> Result<usize> {
    if strata.is_empty() {
        return Err(StatsError::TooFewSamples { input: "strata", needed: 1, got: 0 });
    }
    let mut total = 0;
    for (stratum, values) in strata.iter().enumerate() {
        let values = values.as_ref();
        if values.is_empty() {
            return Err(StatsError::EmptyStratum { stratum });
        }
        if let Some(index) = values.iter().position(|v| !v.is_finite()) {
            return Err(StatsError::NonFiniteInStratum { stratum, index });
        }
        total += values.len();
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robust::trim_mean;
    use crate::summary::{Summary, assert_close};

    // Source: rliable 1.2.0 (numpy 2.4.6, scipy 1.17.1, arch 7.2.0):
    //   x = np.array([8.21, 7.95, 8.60, 8.02, 8.33, 7.71, 8.48, 8.19, 8.90, 7.88])
    //   scipy.stats.trim_mean(x, 0.25)                 -> 8.196666666666667
    //   rly.get_interval_estimates({"a": x.reshape(-1, 1)},
    //       lambda s: np.array([metrics.aggregate_iqm(s)]), reps=50000)
    //                                                  -> [7.973333333333334, 8.466666666666667]
    // rliable draws from numpy's generator, so the bounds agree within their
    // Monte Carlo errors, not bit for bit.
    #[test]
    fn headline_iqm_is_rliables_interval() {
        let x = [8.21, 7.95, 8.60, 8.02, 8.33, 7.71, 8.48, 8.19, 8.90, 7.88];
        let r = headline_iqm(&x).unwrap();
        assert_close(r.ci.estimate, 8.196666666666667, 1e-15);
        assert_eq!((r.ci.resamples, r.ci.seed, r.ci.level), (HEADLINE_RESAMPLES, HEADLINE_SEED, 0.95));
        // rliable's own error at 50 000 resamples is under half ours at 10 000.
        assert!((r.ci.lower - 7.973333333333334).abs() <= 4.0 * r.lower_mcse, "{r:?}");
        assert!((r.ci.upper - 8.466666666666667).abs() <= 4.0 * r.upper_mcse, "{r:?}");
        assert!(r.lower_mcse > 0.0 && r.lower_mcse < 0.01 && r.upper_mcse < 0.01, "{r:?}");
        assert_eq!(headline_iqm(&[]), Err(StatsError::EmptyStratum { stratum: 0 }));
        assert_eq!(headline_iqm(&[1.0, f64::NAN]), Err(StatsError::NonFiniteInStratum { stratum: 0, index: 1 }));
    }
    use proptest::prelude::*;

    /// Three tasks with 5, 5 and 7 runs (17 scores: not a multiple of 4, so
    /// rliable's IQM and [`crate::iqm`] differ).
    const TASKS: [&[f64]; 3] =
        [&[0.12, 0.35, 0.08, 0.41, 0.27], &[1.10, 0.95, 1.32, 0.88, 1.05], &[0.55, 0.61, 0.47, 0.72, 0.50, 0.66, 0.58]];

    // Source: scipy 1.17.1, numpy 2.4.6, rliable's definition (rliable/metrics.py):
    //   import numpy as np, scipy.stats
    //   float(scipy.stats.trim_mean(np.concatenate(tasks), proportiontocut=0.25, axis=None))
    // and, for the rectangular 3 × 4 case, the matrix form rliable's aggregate_iqm takes:
    //   float(scipy.stats.trim_mean(np.array(m).T, proportiontocut=0.25, axis=None))
    #[test]
    fn aggregate_iqm_matches_scipy_trim_mean() {
        // 17 scores: ⌊17/4⌋ = 4 dropped from each end, the mean of the middle 9
        // (also exactly 0.5977… in rational arithmetic on the f64 inputs).
        assert_close(aggregate_iqm(&TASKS).unwrap(), 0.5977777777777777, 1e-15);
        let matrix = [[1.0, 2.0, 3.0, 10.0], [0.5, 0.25, 4.0, 2.5], [7.0, 0.0, 1.5, 3.5]];
        assert_eq!(aggregate_iqm(&matrix).unwrap(), 2.25);
        // Not the fractional-weight IQM of `crate::iqm` when 17 ∤ 4.
        let pooled: Vec<f64> = TASKS.concat();
        assert_eq!(aggregate_iqm(&TASKS).unwrap(), trim_mean(&pooled, 0.25).unwrap());
        assert_ne!(aggregate_iqm(&TASKS).unwrap(), crate::robust::iqm(&pooled).unwrap());
    }

    // One stratum is a plain bootstrap of rliable's IQM: same bits.
    #[test]
    fn one_stratum_is_the_plain_bootstrap() {
        let pooled: Vec<f64> = TASKS.concat();
        for seed in [0, 1, 20110101] {
            let b = Bootstrap::new(0.95, 1000, seed).unwrap();
            let plain = b.statistic_ci(&pooled, |s| trim_mean(s, 0.25).unwrap_or(f64::NAN)).unwrap();
            let stratified = b.stratified_iqm_ci(&[&pooled]).unwrap();
            assert_eq!(stratified.ci, plain);
            let generic = b.stratified_ci(&[&pooled], |s| trim_mean(s, 0.25).unwrap_or(f64::NAN)).unwrap();
            assert_eq!(generic, stratified);
        }
    }

    // Fixed seed → fixed bits. Self-generated regression values (rand 0.10.3,
    // rand_chacha 0.10.0): no independent implementation of this ChaCha8
    // stream exists to compare with; a change moves every golden interval.
    #[test]
    fn value_stability() {
        let b = Bootstrap::new(0.95, 2000, 20110101).unwrap();
        let ci = b.stratified_iqm_ci(&TASKS).unwrap();
        assert_eq!(ci.ci.estimate, aggregate_iqm(&TASKS).unwrap());
        assert_eq!((ci.ci.lower, ci.ci.upper, ci.lower_mcse, ci.upper_mcse), STABLE);
        assert_eq!((ci.ci.level, ci.ci.resamples, ci.ci.seed), (0.95, 2000, 20110101));
        let again = b.stratified_iqm_ci(&TASKS).unwrap();
        assert_eq!(again, ci);
    }
    const STABLE: (f64, f64, f64, f64) = (0.5544444444444444, 0.65, 0.0011111111111111183, 0.002777777777777768);

    #[test]
    fn interval_contains_the_estimate_and_mcse_is_positive() {
        for seed in 0..20 {
            let ci = Bootstrap::new(0.95, 500, seed).unwrap().stratified_iqm_ci(&TASKS).unwrap();
            assert!(ci.ci.lower <= ci.ci.estimate && ci.ci.estimate <= ci.ci.upper, "{ci:?}");
            assert!(ci.lower_mcse > 0.0 && ci.upper_mcse > 0.0);
            assert!(ci.lower_mcse < ci.ci.upper - ci.ci.lower);
        }
    }

    // Stratification removes the between-task variance: the stratified
    // interval is narrower than the plain bootstrap of the pooled scores,
    // whose resamples can move runs between tasks.
    #[test]
    fn stratification_narrows_the_interval() {
        let pooled: Vec<f64> = TASKS.concat();
        let b = Bootstrap::new(0.95, 4000, 5).unwrap();
        let strat = b.stratified_iqm_ci(&TASKS).unwrap().ci;
        let plain = b.stratified_iqm_ci(&[&pooled]).unwrap().ci;
        assert!(strat.upper - strat.lower < plain.upper - plain.lower, "{strat:?} vs {plain:?}");
    }

    // The MCSE predicts how far a bound moves between streams: over 200
    // seeds, the standard deviation of each bound agrees with the mean
    // reported MCSE within 15 % (measured: within 5 % at B = 500 and 2 000;
    // the sd of 200 draws is itself uncertain by about 5 %).
    #[test]
    fn mcse_predicts_the_spread_across_streams() {
        for resamples in [500, 2000] {
            let mut lowers = Vec::new();
            let mut uppers = Vec::new();
            let mut mcse = (0.0, 0.0);
            for seed in 0..200 {
                let ci = Bootstrap::new(0.95, resamples, seed).unwrap().stratified_iqm_ci(&TASKS).unwrap();
                lowers.push(ci.ci.lower);
                uppers.push(ci.ci.upper);
                mcse.0 += ci.lower_mcse / 200.0;
                mcse.1 += ci.upper_mcse / 200.0;
            }
            let (sd_lower, sd_upper) = (Summary::of(&lowers).unwrap().sd, Summary::of(&uppers).unwrap().sd);
            assert_close(mcse.0, sd_lower, 0.15);
            assert_close(mcse.1, sd_upper, 0.15);
        }
    }

    #[test]
    fn more_resamples_shrink_the_mcse() {
        let mean_mcse = |resamples| {
            let mut total = 0.0;
            for seed in 0..20 {
                let ci = Bootstrap::new(0.95, resamples, seed).unwrap().stratified_iqm_ci(&TASKS).unwrap();
                total += ci.lower_mcse + ci.upper_mcse;
            }
            total / 40.0
        };
        let (small, large) = (mean_mcse(500), mean_mcse(8000));
        // √(8000/500) = 4; allow for the estimate's own noise.
        assert!(large < small / 3.0 && large > small / 5.5, "{small} vs {large}");
    }

    #[test]
    fn constant_scores_give_a_point() {
        let strata = [vec![2.5; 4], vec![2.5; 6]];
        let ci = Bootstrap::new(0.95, 300, 9).unwrap().stratified_iqm_ci(&strata).unwrap();
        assert_eq!((ci.ci.estimate, ci.ci.lower, ci.ci.upper), (2.5, 2.5, 2.5));
        assert_eq!((ci.lower_mcse, ci.upper_mcse), (0.0, 0.0));
    }

    #[test]
    fn errors() {
        let b = Bootstrap::new(0.95, 10, 0).unwrap();
        let none: [&[f64]; 0] = [];
        assert_eq!(b.stratified_iqm_ci(&none), Err(StatsError::TooFewSamples { input: "strata", needed: 1, got: 0 }));
        assert_eq!(aggregate_iqm(&none), Err(StatsError::TooFewSamples { input: "strata", needed: 1, got: 0 }));
        let empty: [&[f64]; 2] = [&[1.0], &[]];
        assert_eq!(b.stratified_iqm_ci(&empty), Err(StatsError::EmptyStratum { stratum: 1 }));
        let nan: [&[f64]; 2] = [&[1.0], &[2.0, f64::NAN]];
        assert_eq!(b.stratified_iqm_ci(&nan), Err(StatsError::NonFiniteInStratum { stratum: 1, index: 1 }));
        assert_eq!(aggregate_iqm(&nan), Err(StatsError::NonFiniteInStratum { stratum: 1, index: 1 }));
        assert_eq!(
            b.stratified_ci(&[[1.0, 2.0]], |_| f64::NAN),
            Err(StatsError::NonFiniteStatistic { resample: None })
        );
        assert_eq!(
            b.stratified_ci(&[[1.0, 2.0]], |s| if s == [1.0, 2.0] { 0.0 } else { f64::INFINITY }),
            Err(StatsError::NonFiniteStatistic { resample: Some(0) })
        );
        assert_eq!(aggregate_iqm(&[[1.7e308, 1.7e308]]), Err(StatsError::Overflow));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn reproducible_and_ordered(
            strata in proptest::collection::vec(proptest::collection::vec(-1e3..1e3_f64, 1..12), 1..6),
            seed in any::<u64>(),
        ) {
            let b = Bootstrap::new(0.9, 200, seed).unwrap();
            let ci = b.stratified_iqm_ci(&strata).unwrap();
            prop_assert!(ci.ci.lower <= ci.ci.upper);
            prop_assert!(ci.lower_mcse >= 0.0 && ci.upper_mcse >= 0.0);
            let again = b.stratified_iqm_ci(&strata).unwrap();
            prop_assert_eq!(ci.ci.lower.to_bits(), again.ci.lower.to_bits());
            prop_assert_eq!(ci.upper_mcse.to_bits(), again.upper_mcse.to_bits());
        }
    }
}
