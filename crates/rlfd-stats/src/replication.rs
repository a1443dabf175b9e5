//! The replication as the unit of analysis: what a set of K replication-level
//! estimates can say. The power of the one-sample t-test on them at a given
//! true effect (the noncentral t, by quadrature over the chi-square of the
//! sample variance), and the Clopper–Pearson interval of "k of K".

use statrs::distribution::{Beta, ChiSquared, Continuous, ContinuousCDF, Normal};

use crate::error::{Result, StatsError};
use crate::tdist::upper_quantile;

/// The power of the two-sided one-sample t-test at level `alpha` on `k`
/// values whose true mean is `effect` and true SD `sd`, counting only
/// rejections in the direction of `effect` (the only ones that reproduce a
/// directional claim): `P(T ≥ t_{1−α/2, k−1})` for `T` noncentral t with
/// `k − 1` degrees of freedom and noncentrality `effect·√k / sd`.
pub fn one_sample_power(effect: f64, sd: f64, k: usize, alpha: f64) -> Result<f64> {
    if k < 2 {
        return Err(StatsError::InvalidParameter("power needs at least two replications"));
    }
    if !(sd > 0.0 && sd.is_finite() && effect.is_finite()) {
        return Err(StatsError::InvalidParameter("power needs a finite effect and a positive SD"));
    }
    if !(alpha > 0.0 && alpha < 1.0) {
        return Err(StatsError::InvalidParameter("alpha must lie strictly between 0 and 1"));
    }
    let df = (k - 1) as f64;
    let critical = upper_quantile(0.5 * alpha, df)?;
    let delta = effect.abs() * (k as f64).sqrt() / sd;
    Ok(noncentral_t_sf(critical, df, delta))
}

/// `P(T > c)` for the noncentral t with `df` degrees of freedom and
/// noncentrality `delta`: `T = (Z + δ)/√(V/ν)`, so
/// `P(T > c) = E_V[Φ(δ − c√(V/ν))]`. Integrated over `u = √V` (the
/// density of V is unbounded at 0 for ν = 1 and non-zero there for ν = 2;
/// in `u` the integrand is finite and smooth) by Simpson's rule on a grid
/// wide enough that the tail beyond it weighs below 1e-12.
fn noncentral_t_sf(c: f64, df: f64, delta: f64) -> f64 {
    let chi = ChiSquared::new(df).expect("df > 0");
    let normal = Normal::standard();
    let hi = (df + 60.0 * (2.0 * df).sqrt() + 60.0).sqrt();
    let n = 20_000usize; // even
    let h = hi / n as f64;
    let f = |u: f64| {
        // The density of U = √V: f_V(u²)·2u, whose limit at 0 is √(2/π) for
        // ν = 1 and 0 above.
        let density = if u > 0.0 {
            chi.pdf(u * u) * 2.0 * u
        } else if df == 1.0 {
            (2.0 / std::f64::consts::PI).sqrt()
        } else {
            0.0
        };
        density * normal.cdf(delta - c * u / df.sqrt())
    };
    let mut sum = f(0.0) + f(hi);
    for i in 1..n {
        let w = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(i as f64 * h);
    }
    (sum * h / 3.0).clamp(0.0, 1.0)
}

/// The exact (Clopper–Pearson) two-sided `level` interval of a rate seen `k`
/// times in `n`.
pub fn clopper_pearson(k: usize, n: usize, level: f64) -> Result<(f64, f64)> {
    if n == 0 || k > n {
        return Err(StatsError::InvalidParameter("k of n needs 0 ≤ k ≤ n and n ≥ 1"));
    }
    if !(level > 0.0 && level < 1.0) {
        return Err(StatsError::InvalidParameter("confidence level must lie strictly between 0 and 1"));
    }
    let a = 0.5 * (1.0 - level);
    let (k, n) = (k as f64, n as f64);
    let lower = if k == 0.0 { 0.0 } else { Beta::new(k, n - k + 1.0).expect("k ≥ 1").inverse_cdf(a) };
    let upper = if k == n { 1.0 } else { Beta::new(k + 1.0, n - k).expect("k < n").inverse_cdf(1.0 - a) };
    Ok((lower, upper))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::assert_close;

    /// SciPy 1.10.1: `stats.nct.sf(stats.t.ppf(0.975, df), df, delta)`:
    /// (δ 2.0, df 9) 0.4312460071067432; (0.5, 4) 0.05876357503644708;
    /// (3.5, 9) 0.8747607857589689.
    #[test]
    fn power_matches_scipy_s_noncentral_t() {
        // δ = effect·√k/sd: effect 2/√10 with sd 1 and k 10 gives δ = 2.
        let p = one_sample_power(2.0 / 10f64.sqrt(), 1.0, 10, 0.05).unwrap();
        assert_close(p, 0.4312460071067432, 1e-7);
        assert_close(one_sample_power(0.5 / 5f64.sqrt(), 1.0, 5, 0.05).unwrap(), 0.05876357503644708, 1e-6);
        assert_close(one_sample_power(3.5, 10f64.sqrt(), 10, 0.05).unwrap(), 0.8747607857589689, 1e-7);
        // The direction of the effect does not matter: power counts rejections its way.
        assert_eq!(one_sample_power(-0.7, 1.0, 10, 0.05).unwrap(), one_sample_power(0.7, 1.0, 10, 0.05).unwrap());
        assert!(one_sample_power(1.0, 0.0, 10, 0.05).is_err());
        // Few replications (df 1 and 2), where the chi-square density is
        // unbounded or non-zero at 0: `stats.nct.sf(stats.t.ppf(0.975, 2), 2,
        // 3.0)` = 0.38738935018017756 and `(…, 1), 1, 3.0)` = 0.186108074242607.
        assert_close(one_sample_power(3.0 / 3f64.sqrt(), 1.0, 3, 0.05).unwrap(), 0.38738935018017756, 1e-6);
        assert_close(one_sample_power(3.0 / 2f64.sqrt(), 1.0, 2, 0.05).unwrap(), 0.186108074242607, 1e-5);
        assert!(one_sample_power(1.0, 1.0, 1, 0.05).is_err());
    }

    /// SciPy 1.10.1: `stats.binomtest(k, n).proportion_ci(0.95, "exact")`.
    #[test]
    fn clopper_pearson_matches_scipy() {
        let cases = [
            (6, 10, 0.2623780766069451, 0.8784477418801728),
            (0, 10, 0.0, 0.30849710781876294),
            (10, 10, 0.6915028921812371, 1.0),
            (3, 10, 0.06673951117773447, 0.652452850060008),
            (2, 5, 0.05274495052631566, 0.8533672003653274),
        ];
        for (k, n, lo, hi) in cases {
            let (l, h) = clopper_pearson(k, n, 0.95).unwrap();
            assert!((l - lo).abs() < 1e-9 && (h - hi).abs() < 1e-9, "{k} of {n}: {l} {h}");
        }
        assert!(clopper_pearson(3, 2, 0.95).is_err());
    }
}
