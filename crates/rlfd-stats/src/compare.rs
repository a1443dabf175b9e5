//! What a skeptical reader needs beside a two-sample p-value: t, df, two- and one-sided p, the mean difference with its confidence interval, and Hedges' g.
//!
//! For samples `x` (size `n`) and `y` (size `m`), with the statistic of
//! [`crate::ttest`] (pooled or Welch: standard error `se`, degrees of
//! freedom `ν`, `t = (x̄ − ȳ)/se`):
//!
//! - **p-values**: two-sided `P(|T_ν| ≥ |t|)`; one-sided `P(T_ν ≥ t)` for
//!   the alternative `μ_x > μ_y` ("greater") and `P(T_ν ≤ t)` for
//!   `μ_x < μ_y` ("less"), as `scipy.stats.ttest_ind(..., alternative=...)`;
//! - **interval** for `μ_x − μ_y` at confidence `level`:
//!   `(x̄ − ȳ) ± t*·se` with `t* = t_{ν, 1−(1−level)/2}` the Student-t
//!   quantile ([`crate::tdist::students_t_quantile`]), as
//!   `ttest_ind(...).confidence_interval(level)` (two-sided alternative);
//! - **effect size**: Cohen's `d = (x̄ − ȳ)/s_p` with the pooled standard
//!   deviation `s_p = √(((n−1)s_x² + (m−1)s_y²)/(n+m−2))`, whichever
//!   variance model the test uses, and Hedges' `g = J·d` with the
//!   small-sample correction in its usual approximate form
//!   `J = 1 − 3/(4(n+m) − 9)`, that is `1 − 3/(4ν − 1)` with `ν = n + m − 2`
//!   (Hedges 1981, "Distribution theory for Glass's estimator of effect size
//!   and related estimators", J. Educ. Statist. 6(2); the formula of
//!   pingouin's `compute_effsize(..., eftype='hedges')`).
//!   The exact `J = Γ(ν/2)/(√(ν/2) Γ((ν−1)/2))` is 1.3 % smaller at `ν = 2`,
//!   0.04 % at `ν = 10` and under 1e-4 relative from `ν = 20`; it is not used.
//!
//! The t, df and two-sided p are bit-for-bit those of [`crate::student_t_test`]
//! and [`crate::welch_t_test`]. This module reports; it does not decide
//! (see [`crate::format::stars`] and, for "no difference" claims, [`crate::tost`](mod@crate::tost)).

use crate::error::{Result, StatsError};
use crate::tdist::{students_t_cdf, students_t_sf, students_t_two_sided_p, upper_quantile};
use crate::ttest::{Statistic, pooled_statistic, pooled_variance, welch_statistic};

/// How the two samples' variances enter the t statistic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variance {
    /// Student's test with the pooled variance, `ν = n + m − 2` (MATLAB
    /// `ttest2`'s default and what the thesis used).
    Pooled,
    /// Welch's unequal-variance test, Welch–Satterthwaite `ν`.
    Welch,
}

/// The alternative hypothesis of a test of `μ_x − μ_y = 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Alternative {
    /// `μ_x ≠ μ_y`.
    TwoSided,
    /// `μ_x > μ_y`.
    Greater,
    /// `μ_x < μ_y`.
    Less,
}

/// One t-test of `μ_x − μ_y = 0` with everything a report prints beside its p-value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Comparison {
    /// Pooled or Welch.
    pub variance: Variance,
    /// `x̄ − ȳ`.
    pub difference: f64,
    /// Standard error of the difference.
    pub se: f64,
    /// The t statistic `difference / se`; positive when `x̄ > ȳ`.
    pub t: f64,
    /// Degrees of freedom (fractional for Welch).
    pub df: f64,
    /// Two-sided p-value (the same bits as [`crate::student_t_test`] / [`crate::welch_t_test`]).
    pub p: f64,
    /// One-sided p-value for the alternative `μ_x > μ_y`, `P(T ≥ t)`.
    pub p_greater: f64,
    /// One-sided p-value for the alternative `μ_x < μ_y`, `P(T ≤ t)`.
    pub p_less: f64,
    /// Confidence level of the interval, e.g. 0.95.
    pub level: f64,
    /// Lower bound of the two-sided `level` interval for `μ_x − μ_y`.
    pub lower: f64,
    /// Upper bound of the two-sided `level` interval for `μ_x − μ_y`.
    pub upper: f64,
}

impl Comparison {
    /// The t-test of `x` against `y` with the given variance model and an
    /// interval at confidence `level` (strictly between 0 and 1).
    ///
    /// Each sample needs at least two finite values and the two must not
    /// both be constant (the errors of [`crate::student_t_test`]).
    pub fn of(x: &[f64], y: &[f64], variance: Variance, level: f64) -> Result<Self> {
        check_level(level)?;
        let s = statistic(x, y, variance)?;
        from_statistic(&s, variance, level)
    }

    /// The p-value for `alternative`.
    pub fn p_value(&self, alternative: Alternative) -> f64 {
        match alternative {
            Alternative::TwoSided => self.p,
            Alternative::Greater => self.p_greater,
            Alternative::Less => self.p_less,
        }
    }
}

/// Both t-tests of two samples, their descriptive statistics and the effect size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoSample {
    /// Size of `x`.
    pub n_x: usize,
    /// Size of `y`.
    pub n_y: usize,
    /// Mean of `x`.
    pub mean_x: f64,
    /// Mean of `y`.
    pub mean_y: f64,
    /// Sample standard deviation of `x` (`n − 1`).
    pub sd_x: f64,
    /// Sample standard deviation of `y` (`n − 1`).
    pub sd_y: f64,
    /// `x̄ − ȳ`.
    pub difference: f64,
    /// Student's pooled-variance test.
    pub pooled: Comparison,
    /// Welch's test.
    pub welch: Comparison,
    /// Cohen's d with the pooled standard deviation, `(x̄ − ȳ)/s_p`.
    pub cohens_d: f64,
    /// Hedges' g, `d · (1 − 3/(4(n+m) − 9))`.
    pub hedges_g: f64,
}

impl TwoSample {
    /// Compares `x` with `y`: both tests with intervals at `level`, and the effect size.
    ///
    /// Each sample needs at least two finite values and the two must not
    /// both be constant; `level` must lie strictly between 0 and 1.
    pub fn of(x: &[f64], y: &[f64], level: f64) -> Result<Self> {
        check_level(level)?;
        let ps = pooled_statistic(x, y)?;
        let ws = welch_statistic(x, y)?;
        let (cohens_d, hedges_g) = effect_sizes(&ps)?;
        let mo = &ps.moments;
        Ok(Self {
            n_x: x.len(),
            n_y: y.len(),
            mean_x: mo.mean_x,
            mean_y: mo.mean_y,
            sd_x: mo.var_x.sqrt(),
            sd_y: mo.var_y.sqrt(),
            difference: ps.difference,
            pooled: from_statistic(&ps, Variance::Pooled, level)?,
            welch: from_statistic(&ws, Variance::Welch, level)?,
            cohens_d,
            hedges_g,
        })
    }

    /// The comparison under `variance`.
    pub fn comparison(&self, variance: Variance) -> &Comparison {
        match variance {
            Variance::Pooled => &self.pooled,
            Variance::Welch => &self.welch,
        }
    }
}

/// Hedges' g of `x` against `y`: Cohen's d with the pooled standard deviation
/// times `J = 1 − 3/(4(n+m) − 9)` (see the module docs); positive when `x̄ > ȳ`.
///
/// Same requirements as [`crate::student_t_test`].
pub fn hedges_g(x: &[f64], y: &[f64]) -> Result<f64> {
    Ok(effect_sizes(&pooled_statistic(x, y)?)?.1)
}

/// Fails unless `level` lies strictly between 0 and 1.
pub(crate) fn check_level(level: f64) -> Result<()> {
    if level > 0.0 && level < 1.0 {
        Ok(())
    } else {
        Err(StatsError::InvalidParameter("confidence level must lie strictly between 0 and 1"))
    }
}

pub(crate) fn statistic(x: &[f64], y: &[f64], variance: Variance) -> Result<Statistic> {
    match variance {
        Variance::Pooled => pooled_statistic(x, y),
        Variance::Welch => welch_statistic(x, y),
    }
}

fn from_statistic(s: &Statistic, variance: Variance, level: f64) -> Result<Comparison> {
    let p = students_t_two_sided_p(s.t, s.df)?;
    let p_greater = students_t_sf(s.t, s.df)?;
    let p_less = students_t_cdf(s.t, s.df)?;
    let critical = upper_quantile(0.5 * (1.0 - level), s.df)?;
    let half_width = critical * s.se;
    let (lower, upper) = (s.difference - half_width, s.difference + half_width);
    if !(lower.is_finite() && upper.is_finite()) {
        return Err(StatsError::Overflow);
    }
    Ok(Comparison {
        variance,
        difference: s.difference,
        se: s.se,
        t: s.t,
        df: s.df,
        p,
        p_greater,
        p_less,
        level,
        lower,
        upper,
    })
}

/// `(d, g)` from the pooled statistic.
fn effect_sizes(pooled: &Statistic) -> Result<(f64, f64)> {
    let mo = &pooled.moments;
    let sd = pooled_variance(mo)?.sqrt();
    // Not zero: the pooled statistic has already rejected a zero standard error.
    let d = pooled.difference / sd;
    let j = 1.0 - 3.0 / (4.0 * (mo.n + mo.m) - 9.0);
    Ok((d, j * d))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;
    use crate::ttest::{student_t_test, welch_t_test};
    use proptest::prelude::*;

    /// One pair of samples with its pasted reference values.
    struct Case {
        x: &'static [f64],
        y: &'static [f64],
        level: f64,
        /// `(t, df, p two-sided, p greater, p less, lower, upper)`, pooled then Welch.
        tests: [(f64, f64, f64, f64, f64, f64, f64); 2],
        /// `(d, g)`.
        effect: (f64, f64),
    }

    /// Every number below comes from (Python 3.11.7, scipy 1.17.1, numpy 2.4.6, pingouin 0.7.0):
    ///
    /// ```python
    /// import numpy as np, scipy.stats as st, pingouin as pg
    /// for ev in (True, False):                       # pooled, then Welch
    ///     r = st.ttest_ind(x, y, equal_var=ev)
    ///     ci = r.confidence_interval(level)
    ///     gt = st.ttest_ind(x, y, equal_var=ev, alternative='greater').pvalue
    ///     lt = st.ttest_ind(x, y, equal_var=ev, alternative='less').pvalue
    ///     print(r.statistic, r.df, r.pvalue, gt, lt, ci.low, ci.high)
    /// nx, ny = len(x), len(y)
    /// sp = np.sqrt(((nx-1)*np.var(x, ddof=1) + (ny-1)*np.var(y, ddof=1)) / (nx+ny-2))
    /// d = (np.mean(x) - np.mean(y)) / sp
    /// g = d * (1 - 3 / (4*(nx+ny) - 9))
    /// assert abs(g - pg.compute_effsize(x, y, eftype='hedges')) <= 1e-14 * abs(g)
    /// print(d, g)
    /// ```
    const CASES: &[Case] = &[
        // The spec vector of `ttest`. Level 0.95.
        Case {
            x: &[1.0, 2.0, 3.0, 4.0, 5.0],
            y: &[2.0, 4.0, 6.0, 8.0, 10.0],
            level: 0.95,
            tests: [
                (
                    -1.8973665961010275,
                    8.0,
                    0.09434977284243762,
                    0.9528251135787812,
                    0.04717488642121881,
                    -6.646112680506018,
                    0.6461126805060187,
                ),
                (
                    -1.8973665961010275,
                    5.882352941176471,
                    0.10753119493062728,
                    0.9462344025346864,
                    0.05376559746531364,
                    -6.887741643736975,
                    0.887741643736975,
                ),
            ],
            effect: (-1.2, -1.0838709677419354),
        },
        // 7 vs 11, x̄ > ȳ. Level 0.95.
        Case {
            x: &[12.1, 14.3, 11.8, 15.2, 13.7, 12.9, 14.8],
            y: &[10.2, 11.9, 9.8, 12.5, 10.7, 11.1, 13.0, 10.4, 9.9, 11.6, 12.2],
            level: 0.95,
            tests: [
                (
                    4.062604487745059,
                    16.0,
                    0.000904838116956441,
                    0.0004524190584782205,
                    0.9995475809415217,
                    1.1159850244389409,
                    3.55154744309353,
                ),
                (
                    3.89370062809368,
                    11.175996764106895,
                    0.002431198590031008,
                    0.001215599295015504,
                    0.9987844007049845,
                    1.0170925802904296,
                    3.650439887242041,
                ),
            ],
            effect: (1.9642439939865215, 1.8707085657014488),
        },
        // Very unequal variances: the Welch interval excludes 0, the pooled one does not. Level 0.95.
        Case {
            x: &[3.1, 2.7, 3.4, 2.9, 3.0],
            y: &[4.8, 1.2, 6.9, 3.3, 7.5, 2.1, 5.6, 8.2, 4.4, 6.1, 0.9, 5.0],
            level: 0.95,
            tests: [
                (
                    -1.502895436063276,
                    15.0,
                    0.1536254123976564,
                    0.9231872938011718,
                    0.0768127061988282,
                    -3.982016707750511,
                    0.6886833744171796,
                ),
                (
                    -2.345582763283749,
                    11.598555452954338,
                    0.03768397009074925,
                    0.9811580149546254,
                    0.018841985045374626,
                    -3.1821484247579126,
                    -0.11118490857541863,
                ),
            ],
            effect: (-0.7999771846702569, -0.7593003786700744),
        },
        // The smallest samples (2 and 2): t* = 4.30 (pooled, ν = 2). Level 0.95.
        Case {
            x: &[1.0, 2.0],
            y: &[3.0, 5.0],
            level: 0.95,
            tests: [
                (
                    -2.23606797749979,
                    2.0,
                    0.1548457452714834,
                    0.9225771273642583,
                    0.0774228726357417,
                    -7.310511993647414,
                    2.310511993647414,
                ),
                (
                    -2.23606797749979,
                    1.4705882352941178,
                    0.19872738893452602,
                    0.900636305532737,
                    0.09936369446726301,
                    -9.418522830071064,
                    4.418522830071064,
                ),
            ],
            effect: (-2.23606797749979, -1.2777531299998799),
        },
        // One constant sample: Welch ν = m − 1 = 4. Level 0.95.
        Case {
            x: &[2.0, 2.0, 2.0, 2.0],
            y: &[1.0, 3.0, 2.5, 4.0, 0.5],
            level: 0.95,
            tests: [
                (
                    -0.27380016946280045,
                    7.0,
                    0.792141311638947,
                    0.6039293441805265,
                    0.3960706558194735,
                    -1.9272628108537773,
                    1.527262810853777,
                ),
                (
                    -0.3104602102825334,
                    4.0,
                    0.7717151268489589,
                    0.6141424365755206,
                    0.38585756342447947,
                    -1.9885996422350551,
                    1.5885996422350548,
                ),
            ],
            effect: (-0.18367073735093514, -0.16326287764527567),
        },
        // The spec vector of `ttest`. Level 0.99.
        Case {
            x: &[1.0, 2.0, 3.0, 4.0, 5.0],
            y: &[2.0, 4.0, 6.0, 8.0, 10.0],
            level: 0.99,
            tests: [
                (
                    -1.8973665961010275,
                    8.0,
                    0.09434977284243762,
                    0.9528251135787812,
                    0.04717488642121881,
                    -8.305333199543796,
                    2.305333199543796,
                ),
                (
                    -1.8973665961010275,
                    5.882352941176471,
                    0.10753119493062728,
                    0.9462344025346864,
                    0.05376559746531364,
                    -8.910410719273102,
                    2.9104107192731012,
                ),
            ],
            effect: (-1.2, -1.0838709677419354),
        },
        // Very unequal variances: the Welch interval excludes 0, the pooled one does not. Level 0.99.
        Case {
            x: &[3.1, 2.7, 3.4, 2.9, 3.0],
            y: &[4.8, 1.2, 6.9, 3.3, 7.5, 2.1, 5.6, 8.2, 4.4, 6.1, 0.9, 5.0],
            level: 0.99,
            tests: [
                (
                    -1.502895436063276,
                    15.0,
                    0.1536254123976564,
                    0.9231872938011718,
                    0.0768127061988282,
                    -4.8752704437637675,
                    1.5819371104304363,
                ),
                (
                    -2.345582763283749,
                    11.598555452954338,
                    0.03768397009074925,
                    0.9811580149546254,
                    0.018841985045374626,
                    -3.8046244239226827,
                    0.5112910905893515,
                ),
            ],
            effect: (-0.7999771846702569, -0.7593003786700744),
        },
        // 7 vs 11, x̄ > ȳ. Level 0.5.
        Case {
            x: &[12.1, 14.3, 11.8, 15.2, 13.7, 12.9, 14.8],
            y: &[10.2, 11.9, 9.8, 12.5, 10.7, 11.1, 13.0, 10.4, 9.9, 11.6, 12.2],
            level: 0.5,
            tests: [
                (
                    4.062604487745059,
                    16.0,
                    0.000904838116956441,
                    0.0004524190584782205,
                    0.9995475809415217,
                    1.9373192363697351,
                    2.730213231162736,
                ),
                (
                    3.89370062809368,
                    11.175996764106895,
                    0.002431198590031008,
                    0.001215599295015504,
                    0.9987844007049845,
                    1.9159613147569936,
                    2.7515711527754774,
                ),
            ],
            effect: (1.9642439939865215, 1.8707085657014488),
        },
    ];

    fn check(case: &Case, rel: f64) {
        let two = TwoSample::of(case.x, case.y, case.level).unwrap();
        assert_eq!((two.n_x, two.n_y), (case.x.len(), case.y.len()));
        for (c, (t, df, p, gt, lt, lo, hi)) in [two.pooled, two.welch].into_iter().zip(case.tests) {
            assert_close(c.t, t, rel);
            assert_close(c.df, df, rel);
            assert_close(c.p, p, rel);
            assert_close(c.p_greater, gt, rel);
            assert_close(c.p_less, lt, rel);
            assert_close(c.lower, lo, rel);
            assert_close(c.upper, hi, rel);
            assert_eq!(c.level, case.level);
            assert_eq!(c.difference, two.difference);
            assert_eq!(Comparison::of(case.x, case.y, c.variance, case.level), Ok(c));
        }
        assert_close(two.cohens_d, case.effect.0, rel);
        assert_close(two.hedges_g, case.effect.1, rel);
        assert_eq!(hedges_g(case.x, case.y), Ok(two.hedges_g));
    }

    #[test]
    fn matches_scipy() {
        for case in CASES {
            check(case, 1e-12);
        }
    }

    // The large samples of `ttest::tests::large_df` (ν ≈ 1100), generated
    // identically in Python: x_i = 0.01 * ((37 i) % 101), y_i = 0.01 * ((53 i) % 103) + 0.05;
    // reference as for `CASES`, level 0.95.
    #[test]
    fn large_df() {
        let x: Vec<f64> = (0..600).map(|i| 0.01 * ((37 * i) % 101) as f64).collect();
        let y: Vec<f64> = (0..500).map(|i| 0.01 * ((53 * i) % 103) as f64 + 0.05).collect();
        let two = TwoSample::of(&x, &y, 0.95).unwrap();
        let expected = [
            (0.9992544607551528, 0.0007455392448472135, -0.09180855971521037, -0.02180477361812297),
            (0.9992390717034834, 0.000760928296516692, -0.09187230821925481, -0.021741025114078535),
        ];
        for (c, (gt, lt, lo, hi)) in [two.pooled, two.welch].into_iter().zip(expected) {
            assert_close(c.p_greater, gt, 1e-12);
            assert_close(c.p_less, lt, 1e-12);
            assert_close(c.lower, lo, 1e-12);
            assert_close(c.upper, hi, 1e-12);
        }
        assert_close(two.cohens_d, -0.19282821114226562, 1e-12);
        assert_close(two.hedges_g, -0.19269646788710124, 1e-12);
    }

    // The t, df and two-sided p are those of the plain t-tests, bit for bit.
    #[test]
    fn agrees_bitwise_with_the_t_tests() {
        for case in CASES {
            let two = TwoSample::of(case.x, case.y, case.level).unwrap();
            let (s, w) = (student_t_test(case.x, case.y).unwrap(), welch_t_test(case.x, case.y).unwrap());
            assert_eq!((two.pooled.t, two.pooled.df, two.pooled.p), (s.t, s.df, s.p));
            assert_eq!((two.welch.t, two.welch.df, two.welch.p), (w.t, w.df, w.p));
            assert_eq!(two.comparison(Variance::Pooled), &two.pooled);
            assert_eq!(two.comparison(Variance::Welch), &two.welch);
            for c in [two.pooled, two.welch] {
                assert_eq!(c.p_value(Alternative::TwoSided), c.p);
                assert_eq!(c.p_value(Alternative::Greater), c.p_greater);
                assert_eq!(c.p_value(Alternative::Less), c.p_less);
            }
        }
    }

    #[test]
    fn errors() {
        let ok = [1.0, 2.0, 3.0];
        for level in [0.0, 1.0, -0.1, 1.5, f64::NAN] {
            assert!(matches!(TwoSample::of(&ok, &ok, level), Err(StatsError::InvalidParameter(_))));
            assert!(matches!(Comparison::of(&ok, &ok, Variance::Welch, level), Err(StatsError::InvalidParameter(_))));
        }
        assert_eq!(TwoSample::of(&[1.0], &ok, 0.95), Err(StatsError::TooFewSamples { input: "x", needed: 2, got: 1 }));
        assert_eq!(TwoSample::of(&ok, &[1.0, f64::NAN], 0.95), Err(StatsError::NonFinite { input: "y", index: 1 }));
        assert_eq!(TwoSample::of(&[1.0, 1.0], &[2.0, 2.0], 0.95), Err(StatsError::ZeroVariance));
        assert_eq!(hedges_g(&[3.0, 3.0], &[3.0, 3.0, 3.0]), Err(StatsError::ZeroVariance));
        assert_eq!(
            Comparison::of(&[1e308, 1.7e308], &[-1.7e308, -1e308], Variance::Pooled, 0.95),
            Err(StatsError::Overflow)
        );
    }

    fn sample() -> impl Strategy<Value = Vec<f64>> {
        proptest::collection::vec(-1e3..1e3_f64, 2..30)
    }

    proptest! {
        #[test]
        fn interval_and_p_values_are_consistent(x in sample(), y in sample(), level in 0.5..0.999_f64) {
            let two = TwoSample::of(&x, &y, level).unwrap();
            for c in [two.pooled, two.welch] {
                // The interval is centred on the difference and excludes 0
                // exactly when the two-sided p is below 1 − level.
                prop_assert!(c.lower <= c.difference && c.difference <= c.upper);
                prop_assert!((c.upper - c.difference - (c.difference - c.lower)).abs() <= 1e-9 * (c.upper - c.lower));
                let excludes_zero = c.lower > 0.0 || c.upper < 0.0;
                let alpha = 1.0 - level;
                if (c.p - alpha).abs() > 1e-9 {
                    prop_assert_eq!(excludes_zero, c.p < alpha);
                }
                // One-sided p-values add to one; the smaller is half the two-sided one.
                prop_assert!((c.p_greater + c.p_less - 1.0).abs() <= 1e-12);
                prop_assert!((c.p_greater.min(c.p_less) - 0.5 * c.p).abs() <= 1e-15);
            }
            // Swapping the samples negates d, g and the interval.
            let back = TwoSample::of(&y, &x, level).unwrap();
            prop_assert_eq!(back.hedges_g, -two.hedges_g);
            prop_assert_eq!(back.pooled.lower, -two.pooled.upper);
            prop_assert_eq!(back.welch.p_greater, two.welch.p_less);
            prop_assert!(two.hedges_g.abs() < two.cohens_d.abs() || two.cohens_d == 0.0);
        }

        #[test]
        fn wider_level_wider_interval(x in sample(), y in sample(), level in 0.5..0.98_f64) {
            let narrow = Comparison::of(&x, &y, Variance::Welch, level).unwrap();
            let wide = Comparison::of(&x, &y, Variance::Welch, level + 0.01).unwrap();
            prop_assert!(wide.lower <= narrow.lower && narrow.upper <= wide.upper);
        }
    }
}
