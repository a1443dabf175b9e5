//! Two-sample t-tests: pooled-variance Student (MATLAB `ttest2`'s default, what the thesis used) and Welch.
//!
//! With sample sizes `n`, `m`, means `x̄`, `ȳ` and `n − 1` variances `s_x²`, `s_y²`:
//!
//! - **Student (pooled)**: `s_p² = ((n−1)s_x² + (m−1)s_y²)/(n+m−2)`,
//!   `t = (x̄ − ȳ)/(s_p √(1/n + 1/m))`, `ν = n + m − 2`.
//! - **Welch**: `t = (x̄ − ȳ)/√(s_x²/n + s_y²/m)`,
//!   `ν = (s_x²/n + s_y²/m)² / [(s_x²/n)²/(n−1) + (s_y²/m)²/(m−1)]`
//!   (Welch–Satterthwaite; MATLAB `'Vartype','unequal'`).
//!
//! Both are two-sided: `p = P(|T_ν| ≥ |t|)`, computed in the tail-accurate way
//! described in [`crate::tdist`]. `t > 0` means `x̄ > ȳ`. This module tests;
//! it does not decide: significance stars live in [`crate::format::stars`].

use crate::error::{Result, StatsError, check_sample, finite};
use crate::summary::mean_var_unchecked;
use crate::tdist::students_t_two_sided_p;

/// Outcome of a two-sample t-test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TTest {
    /// The t statistic; positive when the first sample's mean is larger.
    pub t: f64,
    /// Degrees of freedom (fractional for Welch).
    pub df: f64,
    /// Two-sided p-value.
    pub p: f64,
}

/// Sizes, means and variances of both samples after the shared checks.
pub(crate) struct Moments {
    pub(crate) n: f64,
    pub(crate) m: f64,
    pub(crate) mean_x: f64,
    pub(crate) mean_y: f64,
    pub(crate) var_x: f64,
    pub(crate) var_y: f64,
}

fn moments(x: &[f64], y: &[f64]) -> Result<Moments> {
    check_sample("x", x, 2)?;
    check_sample("y", y, 2)?;
    let (mean_x, var_x) = mean_var_unchecked(x)?;
    let (mean_y, var_y) = mean_var_unchecked(y)?;
    Ok(Moments { n: x.len() as f64, m: y.len() as f64, mean_x, mean_y, var_x, var_y })
}

/// Everything a two-sample t-test computes before its p-value: the shared
/// arithmetic of the tests here and of [`crate::compare`] and [`crate::tost`](mod@crate::tost),
/// so all of them print the same bits for the same data.
pub(crate) struct Statistic {
    pub(crate) moments: Moments,
    /// `x̄ − ȳ`.
    pub(crate) difference: f64,
    /// Standard error of the difference.
    pub(crate) se: f64,
    /// `difference / se`.
    pub(crate) t: f64,
    /// Degrees of freedom.
    pub(crate) df: f64,
}

/// `(x̄ − ȳ, (x̄ − ȳ)/se)`, rejecting a zero (or underflowed) standard error.
fn t_statistic(mo: &Moments, se: f64) -> Result<(f64, f64)> {
    if se.is_nan() || se <= 0.0 {
        return Err(StatsError::ZeroVariance);
    }
    let diff = finite(mo.mean_x - mo.mean_y)?;
    Ok((diff, diff / se))
}

/// The pooled variance `s_p² = ((n−1)s_x² + (m−1)s_y²)/(n+m−2)`.
pub(crate) fn pooled_variance(mo: &Moments) -> Result<f64> {
    finite(((mo.n - 1.0) * mo.var_x + (mo.m - 1.0) * mo.var_y) / (mo.n + mo.m - 2.0))
}

/// The pooled (Student) statistic: `se = s_p √(1/n + 1/m)`, `ν = n + m − 2`.
pub(crate) fn pooled_statistic(x: &[f64], y: &[f64]) -> Result<Statistic> {
    let mo = moments(x, y)?;
    let df = mo.n + mo.m - 2.0;
    let pooled = pooled_variance(&mo)?;
    let se = (pooled * (1.0 / mo.n + 1.0 / mo.m)).sqrt();
    let (difference, t) = t_statistic(&mo, se)?;
    Ok(Statistic { moments: mo, difference, se, t, df })
}

/// The Welch statistic: `se = √(s_x²/n + s_y²/m)`, Welch–Satterthwaite `ν`.
pub(crate) fn welch_statistic(x: &[f64], y: &[f64]) -> Result<Statistic> {
    let mo = moments(x, y)?;
    let a = mo.var_x / mo.n;
    let b = mo.var_y / mo.m;
    let se = finite(a + b)?.sqrt();
    let (difference, t) = t_statistic(&mo, se)?;
    // Scale by the larger term so the squares neither overflow nor underflow.
    let s = a.max(b);
    let (a, b) = (a / s, b / s);
    let df = (a + b) * (a + b) / (a * a / (mo.n - 1.0) + b * b / (mo.m - 1.0));
    Ok(Statistic { moments: mo, difference, se, t, df })
}

/// Two-sample Student's t-test with pooled variance, two-sided (MATLAB `ttest2(x, y)`,
/// `scipy.stats.ttest_ind(x, y)`).
///
/// Each sample needs at least two finite values; if both samples are
/// constant the test is undefined ([`StatsError::ZeroVariance`]).
pub fn student_t_test(x: &[f64], y: &[f64]) -> Result<TTest> {
    let s = pooled_statistic(x, y)?;
    let p = students_t_two_sided_p(s.t, s.df)?;
    Ok(TTest { t: s.t, df: s.df, p })
}

/// Welch's unequal-variance t-test, two-sided (MATLAB `ttest2(x, y, 'Vartype', 'unequal')`,
/// `scipy.stats.ttest_ind(x, y, equal_var=False)`).
///
/// Each sample needs at least two finite values; if both samples are
/// constant the test is undefined ([`StatsError::ZeroVariance`]). One
/// constant sample is fine: `ν` is then the other sample's `n − 1`.
pub fn welch_t_test(x: &[f64], y: &[f64]) -> Result<TTest> {
    let s = welch_statistic(x, y)?;
    let p = students_t_two_sided_p(s.t, s.df)?;
    Ok(TTest { t: s.t, df: s.df, p })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;
    use proptest::prelude::*;

    /// Pasted reference: `r = scipy.stats.ttest_ind(x, y, equal_var=...)`,
    /// `(float(r.statistic), float(r.df), float(r.pvalue))`, scipy 1.17.1.
    /// Every p was also confirmed with mpmath (60 digits) to ≤ 4e-15 relative:
    /// `mpmath.betainc(df/2, 0.5, 0, df/(df+t*t), regularized=True)`.
    struct Case {
        x: &'static [f64],
        y: &'static [f64],
        pooled: (f64, f64, f64),
        welch: (f64, f64, f64),
    }

    fn check(case: &Case, rel: f64) {
        for (test, (t, df, p)) in [
            (student_t_test(case.x, case.y).unwrap(), case.pooled),
            (welch_t_test(case.x, case.y).unwrap(), case.welch),
        ] {
            assert_close(test.t, t, rel);
            assert_close(test.df, df, rel);
            assert_close(test.p, p, rel);
        }
    }

    // Section 10 of spec/algorithms.md.
    #[test]
    fn spec_vector() {
        check(
            &Case {
                x: &[1.0, 2.0, 3.0, 4.0, 5.0],
                y: &[2.0, 4.0, 6.0, 8.0, 10.0],
                pooled: (-1.8973665961010275, 8.0, 0.09434977284243762),
                welch: (-1.8973665961010275, 5.882352941176471, 0.10753119493062728),
            },
            1e-12,
        );
    }

    // Unequal sizes (7 vs 11), positive t, p around 1e-3.
    #[test]
    fn unequal_sizes() {
        check(
            &Case {
                x: &[12.1, 14.3, 11.8, 15.2, 13.7, 12.9, 14.8],
                y: &[10.2, 11.9, 9.8, 12.5, 10.7, 11.1, 13.0, 10.4, 9.9, 11.6, 12.2],
                pooled: (4.062604487745059, 16.0, 0.000904838116956441),
                welch: (3.89370062809368, 11.175996764106895, 0.002431198590031008),
            },
            1e-12,
        );
    }

    // Negative t; very unequal variances, so pooled and Welch disagree
    // (p = 0.15 vs 0.038).
    #[test]
    fn negative_t_unequal_variances() {
        check(
            &Case {
                x: &[3.1, 2.7, 3.4, 2.9, 3.0],
                y: &[4.8, 1.2, 6.9, 3.3, 7.5, 2.1, 5.6, 8.2, 4.4, 6.1, 0.9, 5.0],
                pooled: (-1.502895436063276, 15.0, 0.1536254123976564),
                welch: (-2.345582763283749, 11.598555452954338, 0.03768397009074925),
            },
            1e-12,
        );
    }

    // Huge |t| (≈ 561): p ≈ 2.9e-93 (pooled), the regime of the thesis's
    // 3.0772e-94. Data: x_i = round(25 + 0.02·((7i) mod 11), 2),
    // y_i = round(10 + 0.03·((5i) mod 13), 2), i = 0..24.
    #[test]
    fn far_tail() {
        check(
            &Case {
                x: &[
                    25.0, 25.14, 25.06, 25.2, 25.12, 25.04, 25.18, 25.1, 25.02, 25.16, 25.08, 25.0, 25.14, 25.06, 25.2,
                    25.12, 25.04, 25.18, 25.1, 25.02, 25.16, 25.08, 25.0, 25.14, 25.06,
                ],
                y: &[
                    10.0, 10.15, 10.3, 10.06, 10.21, 10.36, 10.12, 10.27, 10.03, 10.18, 10.33, 10.09, 10.24, 10.0,
                    10.15, 10.3, 10.06, 10.21, 10.36, 10.12, 10.27, 10.03, 10.18, 10.33, 10.09,
                ],
                pooled: (560.7628578160302, 48.0, 2.923376319893952e-93),
                welch: (560.7628578160302, 37.62047339212814, 2.158323388043778e-75),
            },
            1e-12,
        );
    }

    // p ≈ 3e-40, the regime of the thesis's 1.4592e-44. Data:
    // x_i = round(14.5 + 0.1·((7i) mod 11), 2), y_i = round(10 + 0.1·((5i) mod 13), 2).
    #[test]
    fn deep_tail() {
        check(
            &Case {
                x: &[
                    14.5, 15.2, 14.8, 15.5, 15.1, 14.7, 15.4, 15.0, 14.6, 15.3, 14.9, 14.5, 15.2, 14.8, 15.5, 15.1,
                    14.7, 15.4, 15.0, 14.6, 15.3, 14.9, 14.5, 15.2, 14.8,
                ],
                y: &[
                    10.0, 10.5, 11.0, 10.2, 10.7, 11.2, 10.4, 10.9, 10.1, 10.6, 11.1, 10.3, 10.8, 10.0, 10.5, 11.0,
                    10.2, 10.7, 11.2, 10.4, 10.9, 10.1, 10.6, 11.1, 10.3,
                ],
                pooled: (43.453354734207856, 48.0, 3.3674787297374016e-40),
                welch: (43.45335473420786, 46.55376510255318, 2.4723968872984042e-39),
            },
            1e-12,
        );
    }

    // Nearly equal means: p near 1.
    #[test]
    fn p_near_one() {
        check(
            &Case {
                x: &[5.1, 4.9, 5.3, 4.7, 5.0, 5.2, 4.8],
                y: &[5.0, 5.2, 4.8, 5.1, 4.9, 5.001],
                pooled: (-0.0016117800900666119, 11.0, 0.9987428451422887),
                welch: (-0.0016666643518587116, 10.38463313594011, 0.998701778637392),
            },
            1e-9,
        );
        check(
            &Case {
                x: &[5.1, 4.9, 5.3, 4.7, 5.0, 5.2, 4.8],
                y: &[5.0, 5.2, 4.8, 5.1, 4.9, 5.02],
                pooled: (-0.03222150800478851, 11.0, 0.974872627048786),
                welch: (-0.03331483023263482, 10.391691265511353, 0.974054774938689),
            },
            1e-10,
        );
    }

    // Equal means exactly: t = 0, p = 1 (scipy gives t = 0.0, p = 1.0).
    #[test]
    fn equal_means() {
        let x = [5.1, 4.9, 5.3, 4.7, 5.0, 5.2, 4.8];
        let y = [5.0, 5.2, 4.8, 5.1, 4.9, 5.0];
        let s = student_t_test(&x, &y).unwrap();
        assert_eq!((s.t, s.df, s.p), (0.0, 11.0, 1.0));
        let w = welch_t_test(&x, &y).unwrap();
        assert_eq!((w.t, w.p), (0.0, 1.0));
        assert_close(w.df, 10.384615384615387, 1e-12);
    }

    // Smallest samples (2 and 2), and one constant sample (Welch df = m − 1).
    #[test]
    fn minimal_and_one_constant_sample() {
        check(
            &Case {
                x: &[1.0, 2.0],
                y: &[3.0, 5.0],
                pooled: (-2.23606797749979, 2.0, 0.1548457452714834),
                welch: (-2.23606797749979, 1.4705882352941178, 0.19872738893452602),
            },
            1e-12,
        );
        check(
            &Case {
                x: &[2.0, 2.0, 2.0, 2.0],
                y: &[1.0, 3.0, 2.5, 4.0, 0.5],
                pooled: (-0.27380016946280045, 7.0, 0.792141311638947),
                welch: (-0.3104602102825334, 4.0, 0.7717151268489589),
            },
            1e-12,
        );
    }

    // Large samples (600 vs 500, df ≈ 1100), generated identically in both
    // languages: x_i = 0.01 * ((37 i) % 101), y_i = 0.01 * ((53 i) % 103) + 0.05.
    #[test]
    fn large_df() {
        let x: Vec<f64> = (0..600).map(|i| 0.01 * ((37 * i) % 101) as f64).collect();
        let y: Vec<f64> = (0..500).map(|i| 0.01 * ((53 * i) % 103) as f64 + 0.05).collect();
        let s = student_t_test(&x, &y).unwrap();
        assert_close(s.t, -3.184453100426544, 1e-12);
        assert_eq!(s.df, 1098.0);
        assert_close(s.p, 0.001491078489694427, 1e-12);
        let w = welch_t_test(&x, &y).unwrap();
        assert_close(w.t, -3.178807159395463, 1e-12);
        assert_close(w.df, 1054.9001846816361, 1e-12);
        assert_close(w.p, 0.001521856593033384, 1e-12);
    }

    #[test]
    fn errors() {
        let ok = [1.0, 2.0, 3.0];
        for f in [student_t_test, welch_t_test] {
            assert_eq!(f(&[1.0], &ok), Err(StatsError::TooFewSamples { input: "x", needed: 2, got: 1 }));
            assert_eq!(f(&ok, &[]), Err(StatsError::TooFewSamples { input: "y", needed: 2, got: 0 }));
            assert_eq!(f(&ok, &[1.0, f64::NAN]), Err(StatsError::NonFinite { input: "y", index: 1 }));
            assert_eq!(f(&[1.0, 1.0], &[2.0, 2.0]), Err(StatsError::ZeroVariance));
            assert_eq!(f(&[3.0, 3.0], &[3.0, 3.0, 3.0]), Err(StatsError::ZeroVariance));
            assert_eq!(f(&[1e308, 1.7e308], &[-1.7e308, -1e308]), Err(StatsError::Overflow));
        }
    }

    fn sample() -> impl Strategy<Value = Vec<f64>> {
        proptest::collection::vec(-1e3..1e3_f64, 2..30)
    }

    proptest! {
        #[test]
        fn antisymmetric(x in sample(), y in sample()) {
            for f in [student_t_test, welch_t_test] {
                let (a, b) = (f(&x, &y).unwrap(), f(&y, &x).unwrap());
                prop_assert_eq!(a.t, -b.t);
                prop_assert_eq!(a.df, b.df);
                prop_assert_eq!(a.p, b.p);
                prop_assert!((0.0..=1.0).contains(&a.p));
            }
        }

        #[test]
        fn pooled_equals_welch_for_equal_sizes_and_variances(x in sample(), shift in -10.0..10.0_f64) {
            // y = shift − x has exactly the variance of x (same deviations, negated).
            let y: Vec<f64> = x.iter().map(|v| shift - v).collect();
            let (s, w) = (student_t_test(&x, &y).unwrap(), welch_t_test(&x, &y).unwrap());
            prop_assert!((s.t - w.t).abs() <= 1e-12 * s.t.abs().max(1.0));
            prop_assert!((s.df - w.df).abs() <= 1e-9 * s.df);
            prop_assert!((s.p - w.p).abs() <= 1e-9);
        }

        #[test]
        fn shifting_both_samples_changes_nothing_much(x in sample(), y in sample(), c in -100.0..100.0_f64) {
            let xs: Vec<f64> = x.iter().map(|v| v + c).collect();
            let ys: Vec<f64> = y.iter().map(|v| v + c).collect();
            let (a, b) = (student_t_test(&x, &y).unwrap(), student_t_test(&xs, &ys).unwrap());
            prop_assert!((a.t - b.t).abs() <= 1e-6 * a.t.abs().max(1.0));
        }
    }
}
