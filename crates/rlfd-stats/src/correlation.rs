//! Pearson's product-moment correlation with its two-sided t-test (MATLAB `corr`, `scipy.stats.pearsonr`).
//!
//! `r = Σ(x−x̄)(y−ȳ) / √(Σ(x−x̄)² Σ(y−ȳ)²)`, `ν = n − 2`,
//! `t = r √(ν / (1 − r²))`, `p = P(|T_ν| ≥ |t|) = I_{1−r²}(ν/2, 1/2)`.
//! The p-value is evaluated from `1 − r² = (1 − r)(1 + r)` directly (no
//! detour through `t`), tail-accurate as in [`crate::tdist`]. `|r| = 1` gives
//! `t = ±∞` and `p = 0`.
//!
//! Conditioning: when `|r|` is close to 1 the p-value is sensitive to the
//! last bits of `r` (relative error ≈ `(ν/2)·ε/(1 − r²)`); that is a property
//! of the data, not of the algorithm, and scipy shares it.

use crate::error::{Result, StatsError, check_sample};
use crate::summary::{compensated_sum, mean_unchecked};
use crate::tdist::two_sided_p_from_beta_args;

/// Outcome of a Pearson correlation test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Correlation {
    /// Pearson's r, in `[-1, 1]`.
    pub r: f64,
    /// Number of pairs.
    pub n: usize,
    /// Degrees of freedom of the test, `n − 2`.
    pub df: f64,
    /// t statistic `r √((n−2)/(1−r²))`; infinite when `|r| = 1`.
    pub t: f64,
    /// Two-sided p-value for the null hypothesis `ρ = 0`.
    pub p: f64,
}

impl Correlation {
    /// The two-sided `level` confidence interval for ρ by Fisher's z
    /// transformation, as `scipy.stats.pearsonr(x, y).confidence_interval(level)`:
    /// `tanh(atanh r ± z_{1−α/2} / √(n − 3))`. Needs `n ≥ 4` and `level` in (0, 1);
    /// `|r| = 1` gives the point `[r, r]`.
    pub fn confidence_interval(&self, level: f64) -> Result<(f64, f64)> {
        if !(level > 0.0 && level < 1.0) {
            return Err(StatsError::InvalidParameter("confidence level must lie strictly between 0 and 1"));
        }
        if self.n < 4 {
            return Err(StatsError::TooFewSamples { input: "x", needed: 4, got: self.n });
        }
        let normal = statrs::distribution::Normal::standard();
        let z = statrs::distribution::ContinuousCDF::inverse_cdf(&normal, 1.0 - (1.0 - level) / 2.0);
        let centre = libm::atanh(self.r);
        let half = z / ((self.n - 3) as f64).sqrt();
        Ok((libm::tanh(centre - half), libm::tanh(centre + half)))
    }
}

/// Pearson correlation of paired samples and its two-sided p-value.
///
/// Needs at least three finite pairs of equal length; a constant input
/// has no correlation ([`StatsError::ZeroVariance`]).
pub fn pearson(x: &[f64], y: &[f64]) -> Result<Correlation> {
    if x.len() != y.len() {
        return Err(StatsError::LengthMismatch { left: x.len(), right: y.len() });
    }
    check_sample("x", x, 3)?;
    check_sample("y", y, 3)?;
    let mx = mean_unchecked(x);
    let my = mean_unchecked(y);
    if !(mx.is_finite() && my.is_finite()) {
        return Err(StatsError::Overflow);
    }
    let sxx = compensated_sum(x.iter().map(|&a| (a - mx) * (a - mx)));
    let syy = compensated_sum(y.iter().map(|&b| (b - my) * (b - my)));
    let sxy = compensated_sum(x.iter().zip(y).map(|(&a, &b)| (a - mx) * (b - my)));
    if !(sxx.is_finite() && syy.is_finite() && sxy.is_finite()) {
        return Err(StatsError::Overflow);
    }
    if sxx == 0.0 || syy == 0.0 {
        return Err(StatsError::ZeroVariance);
    }
    // One rounding in the product when it is representable (exact r = ±1 for
    // exactly linear data such as [1, 2, 3, 4] vs [3, 5, 7, 9]).
    let product = sxx * syy;
    let norm = if product.is_normal() { product.sqrt() } else { sxx.sqrt() * syy.sqrt() };
    let r = (sxy / norm).clamp(-1.0, 1.0);
    let n = x.len();
    let df = (n - 2) as f64;
    let one_minus_r2 = (1.0 - r) * (1.0 + r);
    let (t, p) = if one_minus_r2 == 0.0 {
        (r * f64::INFINITY, 0.0)
    } else {
        let t = r * (df / one_minus_r2).sqrt();
        (t, two_sided_p_from_beta_args(df, one_minus_r2, r * r)?)
    };
    Ok(Correlation { r, n, df, t, p })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;

    /// Pasted reference, scipy 1.17.1:
    /// `r = scipy.stats.pearsonr([1, 2, 3.5, 4, 5.5, 6, 7.2, 8.1], [2.1, 1.9, 3.9, 3.7, 6.2, 5.1, 7.9, 7.0])`,
    /// `r.statistic = 0.9487857037458457`,
    /// `r.confidence_interval(0.95) = (0.7365742176404384, 0.990935444809548)`.
    #[test]
    fn fisher_interval_matches_scipy() {
        let x = [1.0, 2.0, 3.5, 4.0, 5.5, 6.0, 7.2, 8.1];
        let y = [2.1, 1.9, 3.9, 3.7, 6.2, 5.1, 7.9, 7.0];
        let c = pearson(&x, &y).unwrap();
        assert_close(c.r, 0.9487857037458457, 1e-14);
        let (lo, hi) = c.confidence_interval(0.95).unwrap();
        assert_close(lo, 0.7365742176404384, 1e-12);
        assert_close(hi, 0.990935444809548, 1e-12);
        assert!(pearson(&[1.0, 2.0, 3.0], &[1.0, 3.0, 2.0]).unwrap().confidence_interval(0.95).is_err());
        assert!(c.confidence_interval(1.0).is_err());
    }
    use proptest::prelude::*;

    /// Pasted reference: `res = scipy.stats.pearsonr(x, y)`, `r = float(res.statistic)`,
    /// `p = float(res.pvalue)`, `t = r*np.sqrt((n-2)/(1-r*r))`; scipy 1.17.1.
    fn check(x: &[f64], y: &[f64], r: f64, t: f64, p: f64, rel: f64) {
        let c = pearson(x, y).unwrap();
        assert_eq!(c.n, x.len());
        assert_eq!(c.df, (x.len() - 2) as f64);
        assert_close(c.r, r, rel);
        assert_close(c.t, t, rel);
        assert_close(c.p, p, rel);
        // Symmetric in its arguments.
        let d = pearson(y, x).unwrap();
        assert_close(d.r, c.r, 1e-15);
    }

    // Section 10 of spec/algorithms.md: r = 0.8, df = 3, p = 0.1040880.
    #[test]
    fn spec_vector() {
        check(
            &[1.0, 2.0, 3.0, 4.0, 5.0],
            &[2.0, 1.0, 4.0, 3.0, 5.0],
            0.8,
            2.3094010767585034,
            0.10408803866182782,
            1e-12,
        );
    }

    #[test]
    fn negative_r() {
        check(
            &[1.2, 2.3, 3.1, 4.8, 5.5, 6.1, 7.4, 8.0, 9.3, 10.7],
            &[9.8, 8.1, 8.4, 6.0, 5.9, 4.2, 4.5, 2.6, 1.8, 1.1],
            -0.9836643772779238,
            -15.455746750441827,
            3.054793687830506e-07,
            1e-12,
        );
    }

    // n = 60, r ≈ 0.984, p ≈ 6.6e-45. Data generated identically in both
    // languages: x_i = i, y_i = 0.5 i + 0.5 ((7 i) % 11 − 5), i = 0..59
    // (every value is exact in binary). mpmath (80 digits) on the same data
    // gives p = 6.576383821369335e-45, 1.2e-13 from scipy.
    #[test]
    fn near_one_tiny_p() {
        let x: Vec<f64> = (0..60).map(f64::from).collect();
        let y: Vec<f64> = (0..60).map(|i| 0.5 * f64::from(i) + 0.5 * f64::from((7 * i) % 11 - 5)).collect();
        let c = pearson(&x, &y).unwrap();
        assert_close(c.r, 0.9836836985305158, 1e-14);
        assert_close(c.p, 6.576383821370153e-45, 1e-11);
    }

    // r ≈ −0.99993 (1 − |r| ≈ 7e-5), n = 20, p ≈ 3.5e-36. Data:
    // x_i = 0.5 i, y_i = 100 − 3 i + 0.1 ((3 i) % 7 − 3), pasted as printed by Python.
    // Here p is ill-conditioned in r: scipy's r and the exact r of these
    // inputs differ in the last bits and their p-values by 5e-11 relative, so
    // the tolerance against scipy is 1e-9. Exact reference (mpmath, 80
    // digits, sums over the f64 inputs): `r = Sxy/sqrt(Sxx*Syy)`,
    // `p = mpmath.betainc(9, 0.5, 0, 1 - r*r, regularized=True)` = 3.465984203701698e-36.
    #[test]
    fn near_minus_one_tiny_p() {
        check(
            &[0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5, 7.0, 7.5, 8.0, 8.5, 9.0, 9.5],
            &[
                99.7, 97.0, 94.3, 90.9, 88.2, 84.8, 82.1, 78.7, 76.0, 73.3, 69.9, 67.2, 63.8, 61.1, 57.7, 55.0, 52.3,
                48.9, 46.2, 42.8,
            ],
            -0.9999307745901987,
            -360.55036368380524,
            3.46598420386154e-36,
            1e-9,
        );
        // Against the exact value we are much closer than scipy is.
        let c = pearson(
            &(0..20).map(|i| 0.5 * f64::from(i)).collect::<Vec<_>>(),
            &[
                99.7, 97.0, 94.3, 90.9, 88.2, 84.8, 82.1, 78.7, 76.0, 73.3, 69.9, 67.2, 63.8, 61.1, 57.7, 55.0, 52.3,
                48.9, 46.2, 42.8,
            ],
        )
        .unwrap();
        assert_close(c.p, 3.465984203701698e-36, 1e-11);
    }

    // n = 3, the smallest sample the test accepts: r = 0.5, p = 2/3.
    #[test]
    fn three_pairs() {
        check(&[1.0, 2.0, 3.0], &[1.0, 3.0, 2.0], 0.4999999999999999, 0.5773502691896256, 0.6666666666666666, 1e-14);
    }

    #[test]
    fn weak_correlation_p_near_one() {
        check(
            &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0],
            &[3.0, 1.0, 4.0, 1.5, 5.0, 2.0, 2.5, 3.2],
            0.14174424754011983,
            0.3507424169915978,
            0.7377678854693022,
            1e-12,
        );
    }

    // Exactly linear data: scipy gives r = 1.0, p = 0.0.
    #[test]
    fn perfect_correlation() {
        let c = pearson(&[1.0, 2.0, 3.0, 4.0], &[3.0, 5.0, 7.0, 9.0]).unwrap();
        assert_eq!((c.r, c.t, c.p), (1.0, f64::INFINITY, 0.0));
        let c = pearson(&[1.0, 2.0, 3.0, 4.0], &[-3.0, -5.0, -7.0, -9.0]).unwrap();
        assert_eq!((c.r, c.t, c.p), (-1.0, f64::NEG_INFINITY, 0.0));
    }

    #[test]
    fn errors() {
        assert_eq!(pearson(&[1.0, 2.0, 3.0], &[1.0, 2.0]), Err(StatsError::LengthMismatch { left: 3, right: 2 }));
        assert_eq!(pearson(&[1.0, 2.0], &[1.0, 2.0]), Err(StatsError::TooFewSamples { input: "x", needed: 3, got: 2 }));
        assert_eq!(
            pearson(&[1.0, 2.0, 3.0], &[1.0, f64::INFINITY, 2.0]),
            Err(StatsError::NonFinite { input: "y", index: 1 })
        );
        assert_eq!(pearson(&[4.0, 4.0, 4.0], &[1.0, 2.0, 3.0]), Err(StatsError::ZeroVariance));
        assert_eq!(pearson(&[1.0, 2.0, 3.0], &[0.5, 0.5, 0.5]), Err(StatsError::ZeroVariance));
    }

    proptest! {
        #[test]
        fn r_is_bounded_symmetric_and_affine_invariant(
            pairs in proptest::collection::vec((-1e3..1e3_f64, -1e3..1e3_f64), 3..40),
            scale in 0.1..10.0_f64,
            shift in -100.0..100.0_f64,
        ) {
            let (x, y): (Vec<f64>, Vec<f64>) = pairs.into_iter().unzip();
            let c = pearson(&x, &y).unwrap();
            prop_assert!((-1.0..=1.0).contains(&c.r));
            prop_assert!((0.0..=1.0).contains(&c.p));
            prop_assert_eq!(c.r, pearson(&y, &x).unwrap().r);
            let xs: Vec<f64> = x.iter().map(|v| scale * v + shift).collect();
            prop_assert!((pearson(&xs, &y).unwrap().r - c.r).abs() <= 1e-9);
            let neg: Vec<f64> = y.iter().map(|v| -v).collect();
            prop_assert_eq!(pearson(&x, &neg).unwrap().r, -c.r);
        }
    }
}
