//! Descriptive statistics of one sample: mean, sample standard deviation, standard error, [`Summary`].
//!
//! Algorithm (documented because reports depend on the last bits):
//! - sums are Neumaier-compensated (Kahan–Babuška) and run sequentially in
//!   index order, never reordered, so results do not depend on threads or
//!   platform vectorisation;
//! - the mean is two-pass: `m0 = Σx/n`, then `m = m0 + Σ(x − m0)/n`, which
//!   removes the rounding of the first pass (a constant sample gives its
//!   value exactly);
//! - the variance is two-pass on the refined mean with an `n − 1`
//!   denominator (MATLAB `std`, `numpy.std(ddof=1)`): `Σ(x − m)² / (n − 1)`.
//!
//! Inputs must be finite; a running sum that exceeds `f64::MAX` (values near
//! ±1e308) returns [`crate::StatsError::Overflow`] rather than an infinity.

use crate::error::{Result, check_sample, finite};

/// Neumaier-compensated sum of `values`, accumulated in iteration order.
///
/// The result is the correctly rounded sum in all but pathological cases
/// (error bound `2ε|Σx|` plus `O(nε²)Σ|x|`). Returns a non-finite value if a
/// partial sum overflows; callers check.
pub(crate) fn compensated_sum(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut sum = 0.0_f64;
    let mut compensation = 0.0_f64;
    for v in values {
        let t = sum + v;
        if sum.abs() >= v.abs() {
            compensation += (sum - t) + v;
        } else {
            compensation += (v - t) + sum;
        }
        sum = t;
    }
    if sum.is_finite() { sum + compensation } else { sum }
}

/// Two-pass mean of a non-empty, finite sample; non-finite only on overflow.
pub(crate) fn mean_unchecked(x: &[f64]) -> f64 {
    let n = x.len() as f64;
    let m0 = compensated_sum(x.iter().copied()) / n;
    if !m0.is_finite() {
        return m0;
    }
    m0 + compensated_sum(x.iter().map(|&v| v - m0)) / n
}

/// Mean and `n − 1` variance of a finite sample with at least two values.
pub(crate) fn mean_var_unchecked(x: &[f64]) -> Result<(f64, f64)> {
    let m = finite(mean_unchecked(x))?;
    let ss = compensated_sum(x.iter().map(|&v| (v - m) * (v - m)));
    let var = finite(ss / (x.len() - 1) as f64)?;
    Ok((m, var))
}

/// Arithmetic mean `Σx / n`.
///
/// Errors: empty input ([`crate::StatsError::TooFewSamples`]), a NaN or infinity
/// ([`crate::StatsError::NonFinite`]), overflow of the sum ([`crate::StatsError::Overflow`]).
pub fn mean(x: &[f64]) -> Result<f64> {
    check_sample("x", x, 1)?;
    finite(mean_unchecked(x))
}

/// Sample variance with the `n − 1` denominator: `Σ(x − x̄)² / (n − 1)`.
///
/// Needs at least two values.
pub fn sample_variance(x: &[f64]) -> Result<f64> {
    check_sample("x", x, 2)?;
    Ok(mean_var_unchecked(x)?.1)
}

/// Sample standard deviation `√(Σ(x − x̄)² / (n − 1))` (MATLAB `std`).
///
/// Needs at least two values.
pub fn sample_sd(x: &[f64]) -> Result<f64> {
    Ok(sample_variance(x)?.sqrt())
}

/// Standard error of the mean, `s / √n` with `s` the `n − 1` standard deviation
/// (`scipy.stats.sem`).
///
/// Needs at least two values.
pub fn standard_error(x: &[f64]) -> Result<f64> {
    Ok(sample_sd(x)? / (x.len() as f64).sqrt())
}

/// The usual one-line description of a sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// Number of values.
    pub n: usize,
    /// Arithmetic mean.
    pub mean: f64,
    /// Sample standard deviation (`n − 1` denominator).
    pub sd: f64,
    /// Standard error of the mean, `sd / √n`.
    pub se: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
}

impl Summary {
    /// Summarises a finite sample of at least two values.
    ///
    /// Two values are required because the standard deviation is undefined
    /// for one; a single trial is reported by its value, not by a `Summary`.
    pub fn of(x: &[f64]) -> Result<Self> {
        check_sample("x", x, 2)?;
        let (mean, var) = mean_var_unchecked(x)?;
        let sd = var.sqrt();
        let n = x.len();
        let min = x.iter().copied().fold(f64::INFINITY, f64::min);
        let max = x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Ok(Self { n, mean, sd, se: sd / (n as f64).sqrt(), min, max })
    }
}

/// Asserts `actual` is within `rel` relative error of `expected` (absolute near zero).
#[cfg(test)]
pub(crate) fn assert_close(actual: f64, expected: f64, rel: f64) {
    let scale = expected.abs().max(f64::MIN_POSITIVE);
    let err = (actual - expected).abs() / scale;
    assert!(
        err <= rel || actual == expected,
        "actual {actual:e} vs expected {expected:e}: relative error {err:e} > {rel:e}"
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::StatsError;
    use proptest::prelude::*;

    /// One reference case: data and the values SciPy/numpy (or exact
    /// rational arithmetic) give for them.
    struct Case {
        x: &'static [f64],
        mean: f64,
        sd: f64,
        se: f64,
    }

    fn check(case: &Case, rel: f64) {
        let s = Summary::of(case.x).unwrap();
        assert_eq!(s.n, case.x.len());
        assert_close(s.mean, case.mean, rel);
        assert_close(s.sd, case.sd, rel);
        assert_close(s.se, case.se, rel);
        assert_close(mean(case.x).unwrap(), case.mean, rel);
        assert_close(sample_sd(case.x).unwrap(), case.sd, rel);
        assert_close(standard_error(case.x).unwrap(), case.se, rel);
    }

    // Source: scipy 1.17.1 / numpy 2.4.6.
    //   mean: float(np.mean(x)); sd: float(np.std(x, ddof=1)); se: float(scipy.stats.sem(x))
    #[test]
    fn matches_numpy() {
        check(
            &Case {
                x: &[12.1, 14.3, 11.8, 15.2, 13.7, 12.9, 14.8],
                mean: 13.542857142857144,
                sd: 1.3201731488169053,
                se: 0.4989785484735137,
            },
            1e-14,
        );
        check(
            &Case {
                x: &[-151525.96, -120000.5, -98000.25, -175000.0, -160250.75],
                mean: -140955.492,
                sd: 31334.225716404257,
                se: 14013.091744840392,
            },
            1e-14,
        );
    }

    // A large common offset: numpy's pairwise sum is one ulp off here
    // (np.mean gives 1000000000.2500001, np.std(ddof=1) 0.1290994140939514),
    // so the reference is exact rational arithmetic on the f64 inputs:
    //   from fractions import Fraction as F; fx = [F(v) for v in x]
    //   m = sum(fx)/n; var = sum((v-m)**2 for v in fx)/(n-1); sd = mpmath.sqrt(var) (60 digits)
    #[test]
    fn large_offset_is_exact() {
        let x = [1e9 + 0.1, 1e9 + 0.2, 1e9 + 0.3, 1e9 + 0.4];
        let s = Summary::of(&x).unwrap();
        assert_eq!(s.mean, 1000000000.25);
        assert_close(s.sd, 0.12909941409387804, 1e-15);
        assert_eq!(s.min, x[0]);
        assert_eq!(s.max, x[3]);
    }

    #[test]
    fn constant_sample_is_exact() {
        let x = [0.1; 7];
        assert_eq!(mean(&x).unwrap(), 0.1);
        assert_eq!(sample_sd(&x).unwrap(), 0.0);
    }

    #[test]
    fn errors() {
        assert_eq!(mean(&[]), Err(StatsError::TooFewSamples { input: "x", needed: 1, got: 0 }));
        assert_eq!(Summary::of(&[1.0]), Err(StatsError::TooFewSamples { input: "x", needed: 2, got: 1 }));
        assert_eq!(sample_sd(&[1.0, f64::NAN]), Err(StatsError::NonFinite { input: "x", index: 1 }));
        assert_eq!(mean(&[f64::NEG_INFINITY]), Err(StatsError::NonFinite { input: "x", index: 0 }));
        assert_eq!(mean(&[1.7e308, 1.7e308]), Err(StatsError::Overflow));
        assert_eq!(sample_sd(&[1e200, -1e200]), Err(StatsError::Overflow));
    }

    #[test]
    fn compensation_recovers_lost_digits() {
        // Naive left-to-right summation returns 0 here; the exact sum is 2.
        let v = [1.0, 1e100, 1.0, -1e100];
        assert_eq!(compensated_sum(v), 2.0);
    }

    proptest! {
        #[test]
        fn mean_of_constant_is_the_constant(c in -1e12..1e12_f64, n in 1usize..200) {
            let x = vec![c; n];
            prop_assert_eq!(mean(&x).unwrap(), c);
            if n >= 2 {
                prop_assert_eq!(sample_sd(&x).unwrap(), 0.0);
            }
        }

        #[test]
        fn summary_is_ordered(x in proptest::collection::vec(-1e6..1e6_f64, 2..60)) {
            let s = Summary::of(&x).unwrap();
            prop_assert!(s.min <= s.mean && s.mean <= s.max);
            prop_assert!(s.sd >= 0.0 && s.se >= 0.0);
            prop_assert!(s.se <= s.sd);
        }

        #[test]
        fn shift_moves_mean_not_sd(x in proptest::collection::vec(-1e3..1e3_f64, 2..40), c in -1e3..1e3_f64) {
            let shifted: Vec<f64> = x.iter().map(|v| v + c).collect();
            let a = Summary::of(&x).unwrap();
            let b = Summary::of(&shifted).unwrap();
            prop_assert!((b.mean - a.mean - c).abs() <= 1e-9);
            prop_assert!((b.sd - a.sd).abs() <= 1e-9 * (1.0 + a.sd));
        }
    }
}
