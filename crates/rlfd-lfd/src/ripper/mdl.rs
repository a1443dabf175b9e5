//! Description-length formulas of RIPPER's MDL stopping and pruning rules,
//! as Weka's `RuleStats` writes them (Quinlan, "MDL and categorical theories
//! (continued)", ICML 1995), and Weka's tolerant float comparisons.
//!
//! What it is: pure functions of counts (weights), all in bits.
//! - subset DL: S(t, k, p) = −k log₂ p − (t − k) log₂(1 − p)
//! - theory DL of a rule with k conditions out of C possible ones:
//!   ½ [log₂ k + 2 log₂(log₂ k) (k > 1 only) + S(C, k, k/C)], and 0 when k = 0
//! - data DL given the rule set's coverage and errors:
//!   log₂(cov + unc + 1) + S(cov, fp, ·) + S(unc, fn, ·), where the error
//!   rate of the larger part is expected from `exp_fp_rate` (see [`data_dl`]).
//!
//! What it is not: the bookkeeping that feeds these formulas (potential,
//! relative DL, DL reduction); that is `stats.rs`.
//!
//! Source: weka/src/main/java/weka/classifiers/rules/RuleStats.java at Weka
//! commit 19e3b5a2 (`subsetDL`, `theoryDL`, `dataDL`), and `weka.core.Utils`
//! (`log2`, `gr`, `sm`, `grOrEq`, `eq` with SMALL = 1e-6).
//!
//! One deliberate deviation: Java evaluates 0 · log₂(0) as NaN (and Weka then
//! throws "Should never happen"); here a term whose multiplier is 0 is 0, as
//! the formula means.

/// Weka's tolerance in `Utils.gr`, `Utils.sm`, `Utils.eq`, `Utils.grOrEq`.
pub(crate) const SMALL: f64 = 1e-6;

/// JRip's `MAX_DL_SURPLUS`: the rule set stops growing once its DL exceeds
/// the smallest DL seen so far by more than this many bits.
pub(crate) const MAX_DL_SURPLUS: f64 = 64.0;

/// `RuleStats.REDUNDANCY_FACTOR` times `MDL_THEORY_WEIGHT` (0.5 × 1.0).
const THEORY_FACTOR: f64 = 0.5;

/// a > b by more than [`SMALL`] (Weka `Utils.gr`).
pub(crate) fn gr(a: f64, b: f64) -> bool {
    a - b > SMALL
}

/// a < b by more than [`SMALL`] (Weka `Utils.sm`).
pub(crate) fn sm(a: f64, b: f64) -> bool {
    b - a > SMALL
}

/// a ≥ b up to [`SMALL`] (Weka `Utils.grOrEq`); false when either is NaN.
pub(crate) fn gr_or_eq(a: f64, b: f64) -> bool {
    b - a < SMALL
}

/// a = b up to [`SMALL`] (Weka `Utils.eq`).
pub(crate) fn eq(a: f64, b: f64) -> bool {
    a == b || (a - b < SMALL && b - a < SMALL)
}

/// log₂ x as Weka computes it (`Math.log(x) / Math.log(2)`), with the
/// portable `libm` logarithm: fdlibm's, i.e. Java's `StrictMath.log`. The
/// JVM's `Math.log` may round differently in the last bit, which decides
/// only between mathematically equal gains (see the module docs of
/// `ripper`).
pub fn log2(x: f64) -> f64 {
    libm::log(x) / std::f64::consts::LN_2
}

/// Subset description length S(t, k, p) = −k log₂ p − (t − k) log₂(1 − p):
/// the bits to say which k of t elements are in a subset whose expected
/// proportion is p.
///
/// As in Weka, the first term is 0 unless p > 10⁻⁶. A second term whose
/// multiplier t − k is 0 is 0 (Java would give NaN when p = 1).
pub fn subset_dl(t: f64, k: f64, p: f64) -> f64 {
    let hits = if gr(p, 0.0) { -k * log2(p) } else { 0.0 };
    let misses = t - k;
    if misses == 0.0 { hits } else { hits - misses * log2(1.0 - p) }
}

/// Theory description length of a rule with `conditions` conditions when
/// `possible` conditions could appear in a rule (RuleStats `theoryDL`):
/// ½ [log₂ k + 2 log₂(log₂ k) (only if k > 1) + S(C, k, k/C)], and 0 for the
/// empty rule.
pub fn theory_dl(conditions: usize, possible: f64) -> f64 {
    if conditions == 0 {
        return 0.0;
    }
    let k = conditions as f64;
    let mut bits = log2(k);
    if conditions > 1 {
        // log₂* k, truncated after two terms as Weka does
        bits += 2.0 * log2(bits);
    }
    bits += subset_dl(possible, k, k / possible);
    THEORY_FACTOR * bits
}

/// Data description length of a rule set's errors (RuleStats `dataDL`):
/// `cover` and `uncover` are the weights the rule set covers and leaves
/// uncovered, `fp` and `fn_` its false positives and false negatives, and
/// `exp_fp_rate` the expected share of false positives among the errors.
///
/// log₂(cover + uncover + 1) bits say how many instances there are; then the
/// errors of the larger part are coded with the expected error rate and
/// those of the smaller part with their observed rate:
/// - cover > uncover: S(cover, fp, e (fp + fn)/cover) + S(uncover, fn, fn/uncover)
/// - otherwise: S(cover, fp, fp/cover) + S(uncover, fn, (1 − e)(fp + fn)/uncover)
///
/// A part of weight 0 costs nothing.
pub fn data_dl(exp_fp_rate: f64, cover: f64, uncover: f64, fp: f64, fn_: f64) -> f64 {
    let total_bits = log2(cover + uncover + 1.0);
    let (cover_bits, uncover_bits) = if gr(cover, uncover) {
        let expected = exp_fp_rate * (fp + fn_);
        let uncover_bits = if gr(uncover, 0.0) { subset_dl(uncover, fn_, fn_ / uncover) } else { 0.0 };
        (subset_dl(cover, fp, expected / cover), uncover_bits)
    } else {
        let expected = (1.0 - exp_fp_rate) * (fp + fn_);
        let cover_bits = if gr(cover, 0.0) { subset_dl(cover, fp, fp / cover) } else { 0.0 };
        (cover_bits, subset_dl(uncover, fn_, expected / uncover))
    };
    total_bits + cover_bits + uncover_bits
}

#[cfg(test)]
mod tests {
    //! Reference values computed with python3 from the formulas in
    //! RuleStats.java (commit 19e3b5a2), log2(x) = math.log(x)/math.log(2):
    //!
    //! ```python
    //! import math
    //! def log2(x): return math.log(x) / math.log(2)
    //! def subset_dl(t, k, p):
    //!     rt = -k * log2(p) if p - 0.0 > 1e-6 else 0.0
    //!     if t - k != 0: rt -= (t - k) * log2(1 - p)
    //!     return rt
    //! def theory_dl(k, total):
    //!     if k == 0: return 0.0
    //!     tdl = log2(k)
    //!     if k > 1: tdl += 2.0 * log2(tdl)
    //!     tdl += subset_dl(total, k, k / total)
    //!     return 0.5 * tdl
    //! def data_dl(e, cover, uncover, fp, fn):
    //!     total = log2(cover + uncover + 1.0)
    //!     if cover - uncover > 1e-6:
    //!         cb = subset_dl(cover, fp, e * (fp + fn) / cover)
    //!         ub = subset_dl(uncover, fn, fn / uncover) if uncover > 1e-6 else 0.0
    //!     else:
    //!         cb = subset_dl(cover, fp, fp / cover) if cover > 1e-6 else 0.0
    //!         ub = subset_dl(uncover, fn, (1 - e) * (fp + fn) / uncover)
    //!     return total + cb + ub
    //! print(repr(subset_dl(10, 3, 0.2)))          # 9.219280948873623
    //! print(repr(subset_dl(40, 1, 1 / 40)))       # 6.74643725986681
    //! print(repr(theory_dl(1, 40)))               # 3.373218629933405
    //! print(repr(theory_dl(3, 40)))               # 9.14316084034441
    //! print(repr(theory_dl(4, 26)))               # 10.051968530823927
    //! print(repr(data_dl(0.3, 0, 100, 0, 30)))    # 98.00965540446425
    //! print(repr(data_dl(0.3, 40, 60, 5, 3)))     # 46.72246392304634
    //! print(repr(data_dl(0.25, 70, 30, 10, 4)))   # 71.3128125148392
    //! ```
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1.0)
    }

    #[test]
    fn subset_dl_matches_the_formula() {
        assert!(close(subset_dl(10.0, 3.0, 0.2), 9.219280948873623));
        assert!(close(subset_dl(40.0, 1.0, 1.0 / 40.0), 6.74643725986681));
    }

    #[test]
    fn subset_dl_treats_zero_times_log_zero_as_zero() {
        // every element in the subset, expected proportion 1: nothing to say
        assert_eq!(subset_dl(5.0, 5.0, 1.0), 0.0);
        // an empty set: nothing to say either
        assert_eq!(subset_dl(0.0, 0.0, 0.0), 0.0);
        // Weka ignores the first term when p <= 1e-6
        assert_eq!(subset_dl(4.0, 0.0, 0.0), 0.0);
    }

    #[test]
    fn theory_dl_matches_the_formula() {
        assert_eq!(theory_dl(0, 40.0), 0.0);
        assert!(close(theory_dl(1, 40.0), 3.373218629933405));
        assert!(close(theory_dl(3, 40.0), 9.14316084034441));
        assert!(close(theory_dl(4, 26.0), 10.051968530823927));
    }

    #[test]
    fn data_dl_matches_the_formula_in_both_branches() {
        // the default rule's DL: nothing covered
        assert!(close(data_dl(0.3, 0.0, 100.0, 0.0, 30.0), 98.00965540446425));
        // cover <= uncover: expected rate on the uncovered part
        assert!(close(data_dl(0.3, 40.0, 60.0, 5.0, 3.0), 46.72246392304634));
        // cover > uncover: expected rate on the covered part
        assert!(close(data_dl(0.25, 70.0, 30.0, 10.0, 4.0), 71.3128125148392));
    }

    #[test]
    fn weka_comparisons_use_the_tolerance() {
        assert!(!gr(1.0 + 1e-7, 1.0));
        assert!(gr(1.0 + 1e-5, 1.0));
        assert!(!sm(1.0 - 1e-7, 1.0));
        assert!(sm(1.0 - 1e-5, 1.0));
        assert!(gr_or_eq(0.5 - 1e-7, 0.5));
        assert!(!gr_or_eq(f64::NAN, 0.5));
        assert!(eq(2.0, 2.0 + 1e-7));
        assert!(!eq(2.0, 2.0 + 1e-5));
    }
}
