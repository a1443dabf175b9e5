//! Equivalence of two means by Schuirmann's two one-sided tests (TOST): evidence *for* "no difference", which a non-significant t-test is not.
//!
//! Schuirmann (1987), "A comparison of the two one-sided tests procedure and
//! the power approach for assessing the equivalence of average
//! bioavailability", J. Pharmacokinet. Biopharm. 15(6). For a margin
//! `[low, high]` (`low < high`; symmetric `[−δ, δ]` is the usual case) the
//! null hypothesis is non-equivalence, `μ_x − μ_y ≤ low` or
//! `μ_x − μ_y ≥ high`, and the alternative is `low < μ_x − μ_y < high`.
//! With `d = x̄ − ȳ` and the standard error `se` and degrees of freedom `ν`
//! of the pooled or Welch t-test ([`crate::ttest`]):
//!
//! - lower test: `t_L = (d − low)/se`, `p_L = P(T_ν ≥ t_L)`;
//! - upper test: `t_U = (d − high)/se`, `p_U = P(T_ν ≤ t_U)`;
//! - `p = max(p_L, p_U)`: equivalence is shown at level `α` when `p < α`,
//!   which happens exactly when the two-sided `1 − 2α` interval of
//!   [`crate::compare::Comparison`] lies inside `(low, high)`.
//!
//! This is `statsmodels.stats.weightstats.ttost_ind(x, y, low, high,
//! usevar='pooled' | 'unequal')`. The margin is a scientific choice that
//! must be stated beside the result; this module only tests it.

use crate::compare::{Variance, statistic};
use crate::error::{Result, StatsError, finite};
use crate::tdist::{students_t_cdf, students_t_sf};

/// A checked equivalence margin `[low, high]` for `μ_x − μ_y`: finite, `low < high`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Margin {
    low: f64,
    high: f64,
}

impl Margin {
    /// The margin `[low, high]`; both finite and `low < high` (it need not contain 0).
    pub fn new(low: f64, high: f64) -> Result<Self> {
        if !(low.is_finite() && high.is_finite()) {
            return Err(StatsError::InvalidParameter("equivalence margin bounds must be finite"));
        }
        if low >= high {
            return Err(StatsError::InvalidParameter("equivalence margin needs low < high"));
        }
        Ok(Self { low, high })
    }

    /// The symmetric margin `[−delta, delta]`, `delta` finite and positive.
    pub fn symmetric(delta: f64) -> Result<Self> {
        if !(delta.is_finite() && delta > 0.0) {
            return Err(StatsError::InvalidParameter("equivalence margin delta must be finite and positive"));
        }
        Self::new(-delta, delta)
    }

    /// The lower bound.
    pub fn low(&self) -> f64 {
        self.low
    }

    /// The upper bound.
    pub fn high(&self) -> f64 {
        self.high
    }
}

/// One of the two one-sided tests.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneSidedTest {
    /// The margin bound tested against (`low` or `high`).
    pub bound: f64,
    /// `(x̄ − ȳ − bound)/se`.
    pub t: f64,
    /// One-sided p-value: `P(T ≥ t)` for the lower test, `P(T ≤ t)` for the upper one.
    pub p: f64,
}

/// Outcome of a TOST equivalence test of two means.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tost {
    /// Pooled or Welch standard error and degrees of freedom.
    pub variance: Variance,
    /// The margin tested.
    pub margin: Margin,
    /// `x̄ − ȳ`.
    pub difference: f64,
    /// Standard error of the difference.
    pub se: f64,
    /// Degrees of freedom.
    pub df: f64,
    /// The test of `μ_x − μ_y ≤ low` against `> low`.
    pub lower: OneSidedTest,
    /// The test of `μ_x − μ_y ≥ high` against `< high`.
    pub upper: OneSidedTest,
    /// The TOST p-value, `max(lower.p, upper.p)`: small means equivalent within the margin.
    pub p: f64,
}

/// Schuirmann's TOST for `low < μ_x − μ_y < high` (see the module docs).
///
/// Each sample needs at least two finite values and the two must not both
/// be constant (the errors of [`crate::student_t_test`]).
pub fn tost(x: &[f64], y: &[f64], margin: Margin, variance: Variance) -> Result<Tost> {
    let s = statistic(x, y, variance)?;
    let t_low = finite(s.difference - margin.low)? / s.se;
    let t_high = finite(s.difference - margin.high)? / s.se;
    let lower = OneSidedTest { bound: margin.low, t: t_low, p: students_t_sf(t_low, s.df)? };
    let upper = OneSidedTest { bound: margin.high, t: t_high, p: students_t_cdf(t_high, s.df)? };
    Ok(Tost { variance, margin, difference: s.difference, se: s.se, df: s.df, lower, upper, p: lower.p.max(upper.p) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::Comparison;
    use crate::summary::assert_close;
    use proptest::prelude::*;

    /// A TOST reference: `(variance, low, high, p, (t_L, p_L), (t_U, p_U), df)`.
    type Expected = (Variance, f64, f64, f64, (f64, f64), (f64, f64), f64);

    fn check(x: &[f64], y: &[f64], expected: &[Expected], rel: f64) {
        for &(variance, low, high, p, (t1, p1), (t2, p2), df) in expected {
            let r = tost(x, y, Margin::new(low, high).unwrap(), variance).unwrap();
            assert_close(r.p, p, rel);
            assert_close(r.lower.t, t1, rel);
            assert_close(r.lower.p, p1, rel);
            assert_close(r.upper.t, t2, rel);
            assert_close(r.upper.p, p2, rel);
            assert_close(r.df, df, rel);
            assert_eq!((r.lower.bound, r.upper.bound), (low, high));
        }
    }

    // Source: statsmodels 0.15.0 (scipy 1.17.1, Python 3.11.7):
    //   from statsmodels.stats.weightstats import ttost_ind
    //   p, (t1, p1, df1), (t2, p2, df2) = ttost_ind(x, y, low, high, usevar=usevar)
    // with usevar 'pooled' (Variance::Pooled) or 'unequal' (Variance::Welch).
    // Nearly equal means, margin ±0.3: equivalent (p ≈ 0.008 pooled); the
    // asymmetric margin [−0.1, 0.4] is not (p ≈ 0.19).
    #[test]
    fn matches_statsmodels_equivalent_case() {
        let x = [5.1, 4.9, 5.3, 4.7, 5.0, 5.2, 4.8];
        let y = [5.0, 5.2, 4.8, 5.1, 4.9, 5.02];
        check(&x, &y, EQUIVALENT, 1e-12);
    }

    // Very unequal variances (the `ttest` case where pooled and Welch
    // disagree), d ≈ −1.65; margins ±1 and ±3 and the asymmetric [−2.5, 0.5].
    #[test]
    fn matches_statsmodels_unequal_variances() {
        let x = [3.1, 2.7, 3.4, 2.9, 3.0];
        let y = [4.8, 1.2, 6.9, 3.3, 7.5, 2.1, 5.6, 8.2, 4.4, 6.1, 0.9, 5.0];
        check(&x, &y, UNEQUAL, 1e-12);
    }

    // TOST at α rejects exactly when the 1 − 2α interval lies inside the margin.
    #[test]
    fn agrees_with_the_interval() {
        let x = [5.1, 4.9, 5.3, 4.7, 5.0, 5.2, 4.8];
        let y = [5.0, 5.2, 4.8, 5.1, 4.9, 5.02];
        for variance in [Variance::Pooled, Variance::Welch] {
            let ci = Comparison::of(&x, &y, variance, 0.90).unwrap();
            // A margin just wider than the 90 % interval: p just below 0.05; just narrower: above.
            let wide = tost(&x, &y, Margin::new(ci.lower - 1e-9, ci.upper + 1e-9).unwrap(), variance).unwrap();
            let narrow = tost(&x, &y, Margin::new(ci.lower + 1e-9, ci.upper - 1e-9).unwrap(), variance).unwrap();
            assert!(wide.p < 0.05 && narrow.p > 0.05, "{} {}", wide.p, narrow.p);
            assert_close(wide.p, 0.05, 1e-6);
        }
    }

    #[test]
    fn errors() {
        let ok = [1.0, 2.0, 3.0];
        let m = Margin::symmetric(1.0).unwrap();
        assert_eq!((m.low(), m.high()), (-1.0, 1.0));
        for delta in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(Margin::symmetric(delta), Err(StatsError::InvalidParameter(_))));
        }
        assert!(matches!(Margin::new(1.0, 1.0), Err(StatsError::InvalidParameter(_))));
        assert!(matches!(Margin::new(2.0, 1.0), Err(StatsError::InvalidParameter(_))));
        assert!(matches!(Margin::new(f64::NEG_INFINITY, 1.0), Err(StatsError::InvalidParameter(_))));
        assert_eq!(
            tost(&[1.0], &ok, m, Variance::Pooled),
            Err(StatsError::TooFewSamples { input: "x", needed: 2, got: 1 })
        );
        assert_eq!(tost(&[2.0, 2.0], &[2.0, 2.0], m, Variance::Welch), Err(StatsError::ZeroVariance));
        // d = 1e308 is fine; d − low = 2e308 is not.
        let huge = Margin::new(-1e308, 1.0).unwrap();
        assert_eq!(tost(&[1e308, 1e308], &[0.0, 1.0], huge, Variance::Welch), Err(StatsError::Overflow));
    }

    fn sample() -> impl Strategy<Value = Vec<f64>> {
        proptest::collection::vec(-1e3..1e3_f64, 2..30)
    }

    proptest! {
        #[test]
        fn wider_margins_are_easier(x in sample(), y in sample(), delta in 0.1..100.0_f64) {
            for variance in [Variance::Pooled, Variance::Welch] {
                let narrow = tost(&x, &y, Margin::symmetric(delta).unwrap(), variance).unwrap();
                let wide = tost(&x, &y, Margin::symmetric(2.0 * delta).unwrap(), variance).unwrap();
                prop_assert!(wide.p <= narrow.p);
                prop_assert!((0.0..=1.0).contains(&narrow.p));
                prop_assert_eq!(narrow.p, narrow.lower.p.max(narrow.upper.p));
                // Swapping the samples mirrors the margin.
                let back = tost(&y, &x, Margin::symmetric(delta).unwrap(), variance).unwrap();
                prop_assert_eq!(back.p, narrow.p);
            }
        }
    }

    const EQUIVALENT: &[Expected] = &[
        (
            Variance::Pooled,
            -0.3,
            0.3,
            0.007651988111880741,
            (2.8677142124264976, 0.007651988111880741),
            (-2.9321572284360746, 0.006818849364948177),
            11.0,
        ),
        (
            Variance::Welch,
            -0.3,
            0.3,
            0.006809037004442982,
            (2.965019890704829, 0.006809037004442982),
            (-3.0316495511700983, 0.006063457862452082),
            10.391691265511357,
        ),
        (
            Variance::Pooled,
            -0.1,
            0.4,
            0.18507219455226592,
            (0.9344237321389736, 0.18507219455226592),
            (-3.898802468579837, 0.0012408440642532603),
            11.0,
        ),
        (
            Variance::Welch,
            -0.1,
            0.4,
            0.17796260341011386,
            (0.9661300767465197, 0.17796260341011386),
            (-4.031094458149253, 0.0011083909475788083),
            10.391691265511357,
        ),
    ];
    const UNEQUAL: &[Expected] = &[
        (
            Variance::Pooled,
            -1.0,
            1.0,
            0.7180804394487292,
            (-0.5902058999924601, 0.7180804394487292),
            (-2.415584972134092, 0.014464706389970215),
            15.0,
        ),
        (
            Variance::Welch,
            -1.0,
            1.0,
            0.8121301465972901,
            (-0.9211397896296495, 0.8121301465972901),
            (-3.7700257369378485, 0.0014153271493615829),
            11.598555452954338,
        ),
        (
            Variance::Pooled,
            -3.0,
            3.0,
            0.11788191557172906,
            (1.2351731721491719, 0.11788191557172906),
            (-4.240964044275724, 0.0003557876828164762),
            15.0,
        ),
        (
            Variance::Welch,
            -3.0,
            3.0,
            0.03936293092740695,
            (1.9277461576785495, 0.03936293092740695),
            (-6.618911684246047, 1.4571977906256221e-05),
            11.598555452954338,
        ),
        (
            Variance::Pooled,
            -2.5,
            0.5,
            0.22409693768796185,
            (0.778828404113764, 0.22409693768796185),
            (-1.959240204098684, 0.03447021543934261),
            15.0,
        ),
        (
            Variance::Welch,
            -2.5,
            0.5,
            0.12416433042712036,
            (1.2155246708514997, 0.12416433042712036),
            (-3.0578042501107987, 0.00514933829374447),
            11.598555452954338,
        ),
    ];
}
