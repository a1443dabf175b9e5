//! Order statistics: quantiles, the interquartile mean (IQM) and the trimmed mean.
//!
//! Definitions (each sorts a copy of the finite input; ties and order do not matter):
//!
//! - [`quantile`]: linear interpolation between order statistics, Hyndman &
//!   Fan type 7 (numpy's default `np.quantile(x, q)`, R's default, MATLAB's
//!   `quantile` is type 5 and differs): `h = (n − 1) q`,
//!   `Q = x₍⌊h⌋₎ + (h − ⌊h⌋)(x₍⌊h⌋+1₎ − x₍⌊h⌋₎)` (zero-based order statistics).
//! - [`iqm`]: the interquartile mean as the mean of the empirical quantile
//!   function over `[0.25, 0.75]`: `IQM = 2 ∫_{1/4}^{3/4} Q(u) du` with `Q`
//!   the step quantile function. Each sorted value `x₍ᵢ₎` (one-based) owns
//!   the mass interval `[(i−1)/n, i/n]`, and gets weight
//!   `2·|[(i−1)/n, i/n] ∩ [1/4, 3/4]|`. So `n/4` observations are trimmed
//!   from each end, fractionally when `n` is not a multiple of 4. In units
//!   of `1/(4n)` the weights are the integers
//!   `Lᵢ = max(0, min(4i, 3n) − max(4(i−1), n))` and `IQM = Σ Lᵢ x₍ᵢ₎ / (2n)`.
//! - [`trim_mean`]: `scipy.stats.trim_mean(x, proportion)`: drop
//!   `⌊proportion·n⌋` values from each end, average the rest. rliable's
//!   "IQM" is exactly `trim_mean(x, 0.25)`; it equals [`iqm`] when `n` is a
//!   multiple of 4 and differs otherwise (e.g. `n = 7`: rliable drops one value
//!   at each end, [`iqm`] drops 1.75).

use crate::error::{Result, StatsError, check_sample};
use crate::summary::{compensated_sum, mean_unchecked};

/// Sorted copy of a sample already checked to be finite.
fn sorted(x: &[f64]) -> Vec<f64> {
    let mut s = x.to_vec();
    s.sort_by(f64::total_cmp);
    s
}

/// Type-7 quantile of an ascending, non-empty, finite slice; `q` in `[0, 1]`.
///
/// Interpolates like numpy's `_lerp`: from the lower neighbour when the
/// fraction is below one half and from the upper one otherwise, so the result
/// is exact at the order statistics and monotone in `q`.
pub(crate) fn quantile_sorted(sorted: &[f64], q: f64) -> f64 {
    let last = sorted.len() - 1;
    let h = last as f64 * q;
    let lo = (h.floor() as usize).min(last);
    let hi = (lo + 1).min(last);
    let frac = h - lo as f64;
    let (a, b) = (sorted[lo], sorted[hi]);
    let diff = b - a;
    if frac < 0.5 { a + diff * frac } else { b - diff * (1.0 - frac) }
}

/// The `q`-quantile of `x` (type 7, numpy's default), `q` in `[0, 1]`.
pub fn quantile(x: &[f64], q: f64) -> Result<f64> {
    check_sample("x", x, 1)?;
    if !(0.0..=1.0).contains(&q) {
        return Err(StatsError::InvalidParameter("quantile must lie in [0, 1]"));
    }
    Ok(quantile_sorted(&sorted(x), q))
}

/// Interquartile mean: the mean of the middle 50 % of the sorted sample, with
/// fractional weights at the edges when `n` is not a multiple of 4 (see the module docs).
///
/// Defined for any non-empty finite sample (`n = 1` returns the value).
pub fn iqm(x: &[f64]) -> Result<f64> {
    check_sample("x", x, 1)?;
    let s = sorted(x);
    let n = s.len();
    let weighted = compensated_sum(s.iter().enumerate().filter_map(|(i, &v)| {
        let (start, end) = (4 * i, 4 * (i + 1));
        let overlap = end.min(3 * n).saturating_sub(start.max(n));
        (overlap > 0).then_some(overlap as f64 * v)
    }));
    Ok(weighted / (2 * n) as f64)
}

/// Trimmed mean as `scipy.stats.trim_mean(x, proportion)`: sort, drop
/// `⌊proportion·n⌋` values from each end, average the rest.
///
/// `proportion` must lie in `[0, 0.5)`.
pub fn trim_mean(x: &[f64], proportion: f64) -> Result<f64> {
    check_sample("x", x, 1)?;
    if !(0.0..0.5).contains(&proportion) {
        return Err(StatsError::InvalidParameter("trim proportion must lie in [0, 0.5)"));
    }
    Ok(trim_mean_sorted(&sorted(x), proportion))
}

/// [`trim_mean`] of an ascending, non-empty, finite slice; `proportion` in `[0, 0.5)`.
///
/// Non-finite only if the mean overflows.
pub(crate) fn trim_mean_sorted(sorted: &[f64], proportion: f64) -> f64 {
    let n = sorted.len();
    let cut = (proportion * n as f64).floor() as usize;
    mean_unchecked(&sorted[cut..n - cut])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;
    use proptest::prelude::*;

    /// One reference sample with its pasted values:
    /// - `iqm`: exact rational arithmetic in Python (`fractions.Fraction`) on the
    ///   weights `L_i` of the module docs, `Σ L_i x_(i) / (2n)`;
    /// - `trim`: `float(scipy.stats.trim_mean(x, 0.25))`, scipy 1.17.1;
    /// - `q`: `float(np.percentile(x, q))` for q = 2.5, 25, 50, 97.5, numpy 2.4.6.
    struct Case {
        x: &'static [f64],
        iqm: f64,
        trim: f64,
        q: [f64; 4],
    }

    const CASES: &[Case] = &[
        Case {
            x: &[3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0],
            iqm: 3.5,
            trim: 3.5,
            q: [1.0, 1.75, 3.5, 8.475000000000001],
        },
        Case { x: &[10.0, 2.0, 7.0, 4.0, 100.0], iqm: 7.0, trim: 7.0, q: [2.2, 4.0, 7.0, 91.0] },
        Case {
            // exact IQM 33/28
            x: &[0.5, -1.25, 3.75, 2.0, 8.5, -4.0, 1.0],
            iqm: 1.1785714285714286,
            trim: 1.2,
            q: [-3.5875, -0.375, 1.0, 7.787499999999998],
        },
        Case {
            // exact IQM 107/10
            x: &[12.0, 7.0, 3.0, 19.0, 25.0, 1.0, 8.0, 14.0, 6.0, 30.0],
            iqm: 10.7,
            trim: 11.0,
            q: [1.45, 6.25, 10.0, 28.875],
        },
        Case { x: &[42.0], iqm: 42.0, trim: 42.0, q: [42.0, 42.0, 42.0, 42.0] },
        Case { x: &[1.0, 3.0], iqm: 2.0, trim: 2.0, q: [1.05, 1.5, 2.0, 2.95] },
    ];

    #[test]
    fn matches_references() {
        for case in CASES {
            assert_close(iqm(case.x).unwrap(), case.iqm, 1e-15);
            assert_close(trim_mean(case.x, 0.25).unwrap(), case.trim, 1e-15);
            for (q, expected) in [0.025, 0.25, 0.5, 0.975].into_iter().zip(case.q) {
                assert_close(quantile(case.x, q).unwrap(), expected, 1e-14);
            }
        }
    }

    #[test]
    fn errors() {
        assert!(matches!(iqm(&[]), Err(StatsError::TooFewSamples { .. })));
        assert_eq!(iqm(&[1.0, f64::NAN]), Err(StatsError::NonFinite { input: "x", index: 1 }));
        assert!(matches!(quantile(&[1.0], 1.5), Err(StatsError::InvalidParameter(_))));
        assert!(matches!(quantile(&[1.0], f64::NAN), Err(StatsError::InvalidParameter(_))));
        assert!(matches!(trim_mean(&[1.0], 0.5), Err(StatsError::InvalidParameter(_))));
    }

    proptest! {
        #[test]
        fn iqm_is_a_robust_centre(x in proptest::collection::vec(-1e6..1e6_f64, 1..80)) {
            let v = iqm(&x).unwrap();
            let lo = quantile(&x, 0.0).unwrap();
            let hi = quantile(&x, 1.0).unwrap();
            prop_assert!(v >= lo - 1e-9 && v <= hi + 1e-9);
            if x.len() % 4 == 0 {
                let t = trim_mean(&x, 0.25).unwrap();
                prop_assert!((v - t).abs() <= 1e-9 * (1.0 + t.abs()));
            }
        }

        #[test]
        fn quantile_is_monotone(x in proptest::collection::vec(-1e6..1e6_f64, 1..50), q1 in 0.0..=1.0_f64, q2 in 0.0..=1.0_f64) {
            let (a, b) = (q1.min(q2), q1.max(q2));
            let (qa, qb) = (quantile(&x, a).unwrap(), quantile(&x, b).unwrap());
            // One rounding step of slack where the interpolation switches sides.
            prop_assert!(qa <= qb + 1e-12 * qb.abs().max(1.0));
        }
    }
}
