//! Multiple comparisons: Holm–Bonferroni step-down adjusted p-values for a family of tests.
//!
//! Holm (1979), "A simple sequentially rejective multiple test procedure",
//! Scand. J. Statist. 6(2). For `m` p-values sorted ascending,
//! `p₍₁₎ ≤ … ≤ p₍ₘ₎`, the adjusted values are
//! `p̃₍ᵢ₎ = min(1, max_{j ≤ i} (m − j + 1) p₍ⱼ₎)` (one-based), returned in the
//! original order. Rejecting every hypothesis with `p̃ ≤ α` controls the
//! family-wise error rate at `α` under any dependence between the tests, and
//! rejects at least what Bonferroni (`m·p`) rejects. The arithmetic is
//! statsmodels' `multipletests(p, method='holm')[1]` step for step (the
//! product `(m − j + 1)·p`, a running maximum, then the cap), so the bits agree.
//!
//! Which tests form a family is the report's decision (one claim's tests,
//! say) and must be printed beside the adjusted values.

use crate::error::{Result, StatsError, check_sample};

/// Holm–Bonferroni adjusted p-values of a family, in the order given.
///
/// Every p-value must be finite and in `[0, 1]`; the family needs at least
/// one. The result is at least the input elementwise, at most 1, and
/// monotone in the input (a smaller p never gets a larger adjusted p); tied
/// p-values get equal adjusted ones.
pub fn holm(p: &[f64]) -> Result<Vec<f64>> {
    check_sample("p", p, 1)?;
    if p.iter().any(|v| !(0.0..=1.0).contains(v)) {
        return Err(StatsError::InvalidParameter("p-values must lie in [0, 1]"));
    }
    let m = p.len();
    let mut order: Vec<usize> = (0..m).collect();
    // Stable: ties keep their input order (their adjusted values are equal anyway).
    order.sort_by(|&a, &b| p[a].total_cmp(&p[b]));
    let mut adjusted = vec![0.0; m];
    let mut running = 0.0_f64;
    for (rank, &i) in order.iter().enumerate() {
        running = running.max((m - rank) as f64 * p[i]);
        adjusted[i] = running.min(1.0);
    }
    Ok(adjusted)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    // Source: statsmodels 0.15.0 (Python 3.11.7, numpy 2.4.6):
    //   from statsmodels.stats.multitest import multipletests
    //   [float(v) for v in multipletests(p, method='holm')[1]]
    // compared exactly (bit for bit, see the module docs).
    #[test]
    fn matches_statsmodels() {
        for (p, expected) in CASES {
            assert_eq!(holm(p).unwrap(), expected.to_vec(), "p = {p:?}");
        }
    }

    // By hand: m = 4, sorted 0.01, 0.02, 0.03, 0.04 → 4·0.01 = 0.04,
    // 3·0.02 = 0.06, 2·0.03 = 0.06, 1·0.04 = 0.04 → running max 0.04, 0.06, 0.06, 0.06.
    #[test]
    fn hand_example() {
        let adjusted = holm(&[0.03, 0.01, 0.04, 0.02]).unwrap();
        let expected = [0.06, 0.04, 0.06, 0.06];
        for (a, e) in adjusted.iter().zip(expected) {
            assert!((a - e).abs() < 1e-15, "{adjusted:?}");
        }
        assert_eq!(holm(&[0.3]).unwrap(), vec![0.3]);
        assert_eq!(holm(&[0.0, 1.0]).unwrap(), vec![0.0, 1.0]);
    }

    #[test]
    fn errors() {
        assert_eq!(holm(&[]), Err(StatsError::TooFewSamples { input: "p", needed: 1, got: 0 }));
        assert_eq!(holm(&[0.1, f64::NAN]), Err(StatsError::NonFinite { input: "p", index: 1 }));
        assert!(matches!(holm(&[0.1, 1.5]), Err(StatsError::InvalidParameter(_))));
        assert!(matches!(holm(&[-0.01]), Err(StatsError::InvalidParameter(_))));
    }

    proptest! {
        #[test]
        fn adjusted_values_are_ordered_bounded_and_monotone(p in proptest::collection::vec(0.0..=1.0_f64, 1..40)) {
            let adjusted = holm(&p).unwrap();
            let m = p.len() as f64;
            for (i, (&a, &raw)) in adjusted.iter().zip(&p).enumerate() {
                prop_assert!(raw <= a && a <= 1.0);
                prop_assert!(a <= (m * raw).min(1.0), "never above Bonferroni at {}", i);
                for (&b, &other) in adjusted.iter().zip(&p) {
                    if raw <= other {
                        prop_assert!(a <= b);
                    }
                }
            }
            // Order of the family does not matter.
            let reversed: Vec<f64> = p.iter().rev().copied().collect();
            let back: Vec<f64> = holm(&reversed).unwrap().into_iter().rev().collect();
            prop_assert_eq!(back, adjusted);
        }
    }

    // Families: four tests; six around the review's C5.4 p (0.0165); ties;
    // the thesis's Table 6.2 magnitudes; one where the running maximum lifts
    // every value to the first one's 3·0.3; one test; zero and caps; 20 tests.
    const CASES: &[(&[f64], &[f64])] = &[
        (&[0.01, 0.04, 0.03, 0.005], &[0.03, 0.06, 0.06, 0.02]),
        (&[0.0165, 0.03, 0.2, 0.0009, 0.049, 0.6], &[0.0825, 0.12, 0.4, 0.0054, 0.14700000000000002, 0.6]),
        (&[0.5, 0.5, 0.01, 0.01, 0.9], &[1.0, 1.0, 0.05, 0.05, 1.0]),
        (
            &[1e-40, 3.0772e-94, 0.051603, 0.99673, 0.62928, 0.00014223, 5.5167e-09, 0.022387],
            &[6.9999999999999995e-40, 2.46176e-93, 0.154809, 1.0, 1.0, 0.00071115, 3.31002e-08, 0.089548],
        ),
        (&[0.3, 0.4, 0.35], &[0.8999999999999999, 0.8999999999999999, 0.8999999999999999]),
        (&[0.02], &[0.02]),
        (&[0.0, 0.7, 0.8], &[0.0, 1.0, 1.0]),
        (
            &[
                0.0,
                0.101,
                0.202,
                0.30300000000000005,
                0.404,
                0.505,
                0.6060000000000001,
                0.007,
                0.10800000000000001,
                0.20900000000000002,
                0.31000000000000005,
                0.41100000000000003,
                0.512,
                0.6130000000000001,
                0.014,
                0.115,
                0.21600000000000003,
                0.31700000000000006,
                0.41800000000000004,
                0.519,
            ],
            &[0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.133, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.252, 1.0, 1.0, 1.0, 1.0, 1.0],
        ),
    ];
}
