//! The one-sample t-test of a mean against a reference value, with its
//! interval: `t = (x̄ − μ₀)/(s/√n)`, `ν = n − 1` (`scipy.stats.ttest_1samp`).
//!
//! Two uses: a sample against a fixed reference (the learners' asymptote
//! against the demonstrator's mean), and the replication as the unit of
//! analysis (one effect per replication, tested across replications).

use crate::compare::check_level;
use crate::error::{Result, StatsError, check_sample, finite};
use crate::summary::mean_var_unchecked;
use crate::tdist::{students_t_cdf, students_t_sf, students_t_two_sided_p, upper_quantile};

/// The t-test of `μ = μ₀` on one sample, with everything a report prints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneSample {
    /// The sample's size.
    pub n: usize,
    /// Its mean `x̄`.
    pub mean: f64,
    /// Its standard deviation (`n − 1`).
    pub sd: f64,
    /// `x̄ − μ₀`.
    pub difference: f64,
    /// Standard error of the mean, `s/√n`.
    pub se: f64,
    /// `difference / se`; positive when `x̄ > μ₀`.
    pub t: f64,
    /// `n − 1`.
    pub df: f64,
    /// Two-sided p-value.
    pub p: f64,
    /// One-sided p for `μ > μ₀`.
    pub p_greater: f64,
    /// One-sided p for `μ < μ₀`.
    pub p_less: f64,
    /// Confidence level of the interval.
    pub level: f64,
    /// Lower bound of the two-sided `level` interval for `μ − μ₀`.
    pub lower: f64,
    /// Upper bound of that interval.
    pub upper: f64,
}

impl OneSample {
    /// Tests `x`'s mean against `reference`, with an interval at `level`.
    ///
    /// The sample needs at least two finite values and must not be constant
    /// ([`StatsError::ZeroVariance`]); `level` lies strictly between 0 and 1.
    pub fn of(x: &[f64], reference: f64, level: f64) -> Result<Self> {
        check_level(level)?;
        check_sample("x", x, 2)?;
        let reference = finite(reference)?;
        let (mean, var) = mean_var_unchecked(x)?;
        let n = x.len();
        let df = (n - 1) as f64;
        let se = (var / n as f64).sqrt();
        if se.is_nan() || se <= 0.0 {
            return Err(StatsError::ZeroVariance);
        }
        let difference = finite(mean - reference)?;
        let t = difference / se;
        let half_width = upper_quantile(0.5 * (1.0 - level), df)? * se;
        let (lower, upper) = (difference - half_width, difference + half_width);
        if !(lower.is_finite() && upper.is_finite()) {
            return Err(StatsError::Overflow);
        }
        Ok(OneSample {
            n,
            mean,
            sd: var.sqrt(),
            difference,
            se,
            t,
            df,
            p: students_t_two_sided_p(t, df)?,
            p_greater: students_t_sf(t, df)?,
            p_less: students_t_cdf(t, df)?,
            level,
            lower,
            upper,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;

    /// Pasted reference, SciPy 1.10.1:
    /// `r = scipy.stats.ttest_1samp(x, 0.5)`: statistic 2.147747083059588,
    /// pvalue 0.06884226294059796, df 7; `r.confidence_interval(0.95)` for
    /// the mean: (0.4204791052408815, 2.154520894759118);
    /// `alternative="greater"`: 0.03442113147029898.
    #[test]
    fn matches_scipy() {
        let x = [1.2, 0.4, 2.2, 1.9, 0.7, 1.1, 3.0, -0.2];
        let r = OneSample::of(&x, 0.5, 0.95).unwrap();
        assert_close(r.t, 2.147747083059588, 1e-12);
        assert_close(r.p, 0.06884226294059796, 1e-10);
        assert_close(r.p_greater, 0.03442113147029898, 1e-10);
        assert_close(r.p_less, 1.0 - 0.03442113147029898, 1e-10);
        assert_eq!(r.df, 7.0);
        // The interval goes through the t quantile, accurate to about 1e-9.
        assert_close(r.lower + 0.5, 0.4204791052408815, 1e-8);
        assert_close(r.upper + 0.5, 2.154520894759118, 1e-8);
    }

    /// SciPy 1.10.1: `ttest_1samp([10.5, 9.8, 11.2], 12.0)`: statistic
    /// −3.7115374447904554, pvalue 0.065536937037425; 90 % interval of the
    /// mean (9.319901877406343, 11.680098122593657).
    #[test]
    fn matches_scipy_below_the_reference() {
        let r = OneSample::of(&[10.5, 9.8, 11.2], 12.0, 0.90).unwrap();
        assert_close(r.t, -3.7115374447904554, 1e-12);
        assert_close(r.p, 0.065536937037425, 1e-10);
        assert_close(r.lower + 12.0, 9.319901877406343, 1e-8);
        assert_close(r.upper + 12.0, 11.680098122593657, 1e-8);
    }

    #[test]
    fn refuses_what_it_cannot_test() {
        assert!(matches!(OneSample::of(&[1.0, 1.0, 1.0], 0.0, 0.95), Err(StatsError::ZeroVariance)));
        assert!(OneSample::of(&[1.0], 0.0, 0.95).is_err());
        assert!(OneSample::of(&[1.0, 2.0], f64::NAN, 0.95).is_err());
        assert!(OneSample::of(&[1.0, 2.0], 0.0, 1.0).is_err());
    }
}
