//! A claim's family of tests, decided as the chapter decides every claim
//! that rests on more than one test.
//!
//! - **Sidedness.** A difference is tested with the thesis's two-sided
//!   pooled-variance Student t-test (MATLAB `ttest2`'s default); a
//!   directional claim ("more", "better") needs the direction and a
//!   two-sided p below its threshold.
//! - **"No difference"** is tested for, not read off a non-significant
//!   t-test: Schuirmann's two one-sided tests (TOST, pooled variance) against
//!   an equivalence margin ±δ fixed before the run ([`MAZE_MARGIN`],
//!   [`MARIO_MARGIN`]); equivalence holds when the TOST p is below 0.05,
//!   i.e. when the 90 % interval of the difference lies inside ±δ.
//! - **Multiplicity.** Every test a claim's verdict rests on forms its
//!   family; their p-values are adjusted by Holm's step-down method
//!   (`rlfd_stats::holm`), printed beside the raw ones, and the verdict uses
//!   the adjusted ones. A claim that needs every test of its family to hold
//!   would be valid at the raw level too (an intersection–union test); the
//!   adjustment is the project's uniform rule and errs on the cautious side.
//!
//! A test that cannot be computed (a sample with fewer than two values, or
//! two constant samples) counts as 1 in the adjustment and never holds.

use rlfd_report::claims::{Estimate, TestOutcome};
use rlfd_stats::format::{p_value, thousands};
use rlfd_stats::{Comparison, Margin, OneSample, Variance, hedges_g, holm, tost};

use crate::maze::demonstrator::thesis as maze_thesis;
use crate::report::metrics::{Metric, MetricTable, pair_label};
use crate::shaping::{Agent, Baseline};

/// The Maze's equivalence margin δ for last-episode rewards (C6.3): a tenth
/// of the thesis's demonstrator return, |HMN| = 327.5, so 32.75 (about 33
/// steps of the agents' −1 per step). Fixed before the run, from the
/// thesis's published input only: the chapter judges every agent against
/// the demonstrator and calls improvements of 20–50 % of its score
/// meaningful ("about a 50% increase in asymptotic performance"), so a
/// difference within a tenth of that score is small beside what the
/// chapter reports; it is independent of the `hmn-units` reading.
pub const MAZE_MARGIN: f64 = -0.1 * maze_thesis::HMN;

/// Mario's equivalence margin δ for asymptotic points (C6.10): a tenth of
/// the thesis's demonstrator mean, 1,224 points, so 122.4 (about a tenth of
/// the 1,024 a finished level pays). Fixed before the run by the Maze's rule.
pub const MARIO_MARGIN: f64 = 0.1 * crate::mario::demonstrator::thesis::MEAN_SCORE;

/// The significance level of an equivalence test (each one-sided test).
pub const EQUIVALENCE_ALPHA: f64 = 0.05;

/// What a test asks.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// `a` above `b` with a two-sided p below `alpha`.
    Above { alpha: f64 },
    /// `|μ_a − μ_b| < margin` by TOST at [`EQUIVALENCE_ALPHA`].
    Equivalent { margin: f64 },
    /// `a`'s mean above a fixed value (one-sample t-test, two-sided p below `alpha`).
    AboveValue { alpha: f64 },
}

/// What a test's sentence prints beside its p: the difference with its
/// interval, t and its degrees of freedom.
#[derive(Clone, Copy, Debug)]
struct Interval {
    difference: f64,
    lower: f64,
    upper: f64,
    t: f64,
    df: f64,
}

impl From<Comparison> for Interval {
    fn from(c: Comparison) -> Self {
        Interval { difference: c.difference, lower: c.lower, upper: c.upper, t: c.t, df: c.df }
    }
}

#[derive(Clone, Debug)]
struct Test {
    label: String,
    kind: Kind,
    means: (f64, f64),
    /// The comparison (95 % interval for a difference, 90 % for equivalence).
    comparison: Option<Interval>,
    /// Two-sided p, or the TOST p; NaN when the test is undefined.
    p: f64,
    /// The standardised effect: Hedges' g of `a` against `b`, or Cohen's d
    /// of `a` against a value (`None` when undefined).
    g: Option<f64>,
    /// The within-replication SD the effect is measured in (pooled over
    /// both samples; `a`'s alone against a value); NaN when undefined.
    sd: f64,
    /// The thesis's effect in our units, where its tables give it.
    thesis: Option<f64>,
}

/// The thesis's difference of two rows of one of its tables of means
/// (`ch6.maze.table_6_1`, column `cumulative`, rows `SIS` and `SAR`): its
/// effect in our units (both domains score as the thesis's did); NaN where
/// a cell is missing.
pub fn thesis_difference(table: &str, column: &str, a: &str, b: &str) -> f64 {
    let value = |row: &str| rlfd_report::published::published().table_value(table, column, row).unwrap_or(f64::NAN);
    value(a) - value(b)
}

/// The family "each of `agents` significantly above each of `others`" in
/// `metric` at `alpha`, each test with the thesis's effect from column
/// `column` of its table of means `thesis_table`.
pub fn above_each(
    table: &MetricTable,
    (agents, others): (&[Agent], &[Agent]),
    metric: Metric,
    (thesis_table, column): (&str, &str),
    baseline: Baseline,
    alpha: f64,
) -> Family {
    let mut family = Family::new();
    for &a in agents {
        for &b in others {
            family.above(pair_label(a, b, baseline), table.values(a, metric), table.values(b, metric), alpha);
            family.thesis_effect(thesis_difference(thesis_table, column, a.label(baseline), b.label(baseline)));
        }
    }
    family
}

/// The pooled SD of two samples (`n − 1` variances), NaN when undefined.
fn pooled_sd(a: &[f64], b: &[f64]) -> f64 {
    let var = |x: &[f64]| rlfd_stats::sample_variance(x).unwrap_or(f64::NAN);
    if b.is_empty() {
        return var(a).sqrt();
    }
    let (n, m) = (a.len() as f64, b.len() as f64);
    (((n - 1.0) * var(a) + (m - 1.0) * var(b)) / (n + m - 2.0)).sqrt()
}

/// The tests one claim rests on.
#[derive(Clone, Debug, Default)]
pub struct Family {
    tests: Vec<Test>,
}

fn mean(xs: &[f64]) -> f64 {
    if xs.is_empty() { f64::NAN } else { xs.iter().sum::<f64>() / xs.len() as f64 }
}

/// A number for the evidence: thousands separators, a true minus sign,
/// and a dash where the value is undefined.
pub fn num(x: f64, decimals: usize) -> String {
    if x.is_finite() { thousands(x, decimals).replace('-', "−") } else { "–".into() }
}

impl Family {
    /// An empty family.
    pub fn new() -> Self {
        Family::default()
    }

    /// Adds the test of `a` above `b` (two-sided pooled t-test, p below `alpha`).
    pub fn above(&mut self, label: impl Into<String>, a: &[f64], b: &[f64], alpha: f64) {
        let comparison = Comparison::of(a, b, Variance::Pooled, 0.95).ok();
        let p = comparison.map_or(f64::NAN, |c| c.p);
        self.tests.push(Test {
            label: label.into(),
            kind: Kind::Above { alpha },
            means: (mean(a), mean(b)),
            comparison: comparison.map(Interval::from),
            p,
            g: hedges_g(a, b).ok(),
            sd: pooled_sd(a, b),
            thesis: None,
        });
    }

    /// Adds the test of `a` and `b` equivalent within `±margin` (TOST, pooled variance).
    pub fn equivalent(&mut self, label: impl Into<String>, a: &[f64], b: &[f64], margin: f64) {
        let comparison = Comparison::of(a, b, Variance::Pooled, 1.0 - 2.0 * EQUIVALENCE_ALPHA).ok();
        let p =
            Margin::symmetric(margin).ok().and_then(|m| tost(a, b, m, Variance::Pooled).ok()).map_or(f64::NAN, |t| t.p);
        self.tests.push(Test {
            label: label.into(),
            kind: Kind::Equivalent { margin },
            means: (mean(a), mean(b)),
            comparison: comparison.map(Interval::from),
            p,
            g: hedges_g(a, b).ok(),
            sd: pooled_sd(a, b),
            thesis: None,
        });
    }

    /// Adds the test of `a`'s mean above `value` (one-sample t-test, two-sided p below `alpha`).
    pub fn above_value(&mut self, label: impl Into<String>, a: &[f64], value: f64, alpha: f64) {
        let test = OneSample::of(a, value, 0.95).ok();
        self.tests.push(Test {
            label: label.into(),
            kind: Kind::AboveValue { alpha },
            means: (mean(a), value),
            comparison: test.map(|c| Interval {
                difference: c.difference,
                lower: c.lower,
                upper: c.upper,
                t: c.t,
                df: c.df,
            }),
            p: test.map_or(f64::NAN, |c| c.p),
            g: test.map(|c| c.difference / c.sd),
            sd: pooled_sd(a, &[]),
            thesis: None,
        });
    }

    /// Sets the thesis's effect (in our units) of the test added last, for
    /// the pooled verdict's power.
    pub fn thesis_effect(&mut self, effect: f64) {
        if let Some(t) = self.tests.last_mut() {
            t.thesis = effect.is_finite().then_some(effect);
        }
    }

    /// The family's tests as replication-level estimates for the analysis
    /// plan's pooled verdict: each difference of means oriented so the
    /// thesis's direction is positive, or the difference with its margin.
    pub fn estimates(&self) -> Vec<Estimate> {
        self.tests
            .iter()
            .map(|t| {
                let difference = t.means.0 - t.means.1;
                match t.kind {
                    Kind::Above { .. } | Kind::AboveValue { .. } => {
                        Estimate::above(t.label.clone(), difference, t.sd, t.thesis)
                    }
                    Kind::Equivalent { margin } => Estimate::equivalent(t.label.clone(), difference, t.sd, margin),
                }
            })
            .collect()
    }

    /// Holm-adjusted p-values, in the order the tests were added (an
    /// undefined test's is NaN).
    pub fn adjusted(&self) -> Vec<f64> {
        if self.tests.is_empty() {
            return Vec::new();
        }
        let raw: Vec<f64> = self.tests.iter().map(|t| if t.p.is_nan() { 1.0 } else { t.p }).collect();
        let adjusted = holm(&raw).expect("p-values in [0, 1]");
        adjusted.into_iter().zip(&self.tests).map(|(a, t)| if t.p.is_nan() { f64::NAN } else { a }).collect()
    }

    /// Whether test `k` holds on its adjusted p.
    fn holds_at(&self, k: usize, adjusted: f64) -> bool {
        let t = &self.tests[k];
        match t.kind {
            Kind::Above { alpha } | Kind::AboveValue { alpha } => t.means.0 > t.means.1 && adjusted < alpha,
            Kind::Equivalent { .. } => adjusted < EQUIVALENCE_ALPHA,
        }
    }

    /// Whether the family has no test.
    pub fn is_empty(&self) -> bool {
        self.tests.is_empty()
    }

    /// Whether every test holds on its adjusted p (false for an empty family).
    pub fn holds(&self) -> bool {
        let adjusted = self.adjusted();
        !self.tests.is_empty() && (0..self.tests.len()).all(|k| self.holds_at(k, adjusted[k]))
    }

    /// Whether tests `range` all hold on their adjusted p (the family's adjustment).
    pub fn holds_within(&self, range: std::ops::Range<usize>) -> bool {
        let adjusted = self.adjusted();
        !range.is_empty() && range.into_iter().all(|k| self.holds_at(k, adjusted[k]))
    }

    /// One sentence per test: means, difference with its interval, t and
    /// df, Hedges' g, the raw p and Holm's.
    pub fn texts(&self, decimals: usize) -> Vec<String> {
        let adjusted = self.adjusted();
        let m = self.tests.len();
        self.tests
            .iter()
            .zip(&adjusted)
            .map(|(t, &adj)| {
                let (what, level, effect) = match t.kind {
                    Kind::Above { .. } => ("p", 95, "g"),
                    Kind::AboveValue { .. } => ("p", 95, "d"),
                    Kind::Equivalent { .. } => ("TOST p", 90, "g"),
                };
                let stats = match &t.comparison {
                    Some(c) => format!(
                        "difference {} ({level} % CI {} to {}), t({}) = {}, {effect} = {}",
                        num(c.difference, decimals),
                        num(c.lower, decimals),
                        num(c.upper, decimals),
                        num(c.df, 0),
                        num(c.t, 2),
                        num(t.g.unwrap_or(f64::NAN), 2)
                    ),
                    None => "the test is undefined".into(),
                };
                let margin = match t.kind {
                    Kind::Equivalent { margin } => format!(", margin ±{}", num(margin, 2)),
                    Kind::Above { .. } | Kind::AboveValue { .. } => String::new(),
                };
                let holm = if m > 1 { format!(", Holm p = {}", p_value(adj)) } else { String::new() };
                format!(
                    "{} {} vs {}: {stats}, {what} = {}{holm}{margin}",
                    t.label,
                    num(t.means.0, decimals),
                    num(t.means.1, decimals),
                    p_value(t.p)
                )
            })
            .collect()
    }

    /// The tests as the scorecard shows them: the p that decides (Holm's
    /// in a family of several, the raw p beside it), the margin of an
    /// equivalence test.
    pub fn outcomes(&self) -> Vec<TestOutcome> {
        let adjusted = self.adjusted();
        let m = self.tests.len();
        self.tests
            .iter()
            .zip(&adjusted)
            .map(|(t, &adj)| {
                let mut test = match t.kind {
                    Kind::Above { .. } => "two-sided pooled t-test".to_string(),
                    Kind::AboveValue { .. } => "two-sided one-sample t-test".to_string(),
                    Kind::Equivalent { margin } => format!("TOST (pooled), margin ±{}", num(margin, 2)),
                };
                if m > 1 {
                    test.push_str(&format!(", Holm over {m}"));
                }
                TestOutcome {
                    label: t.label.clone(),
                    test,
                    p: Some(if m > 1 { adj } else { t.p }),
                    note: (m > 1 && t.p.is_finite()).then(|| format!("raw p = {}", p_value(t.p))),
                }
            })
            .collect()
    }

    /// The family's size and how its verdict is taken, for the evidence.
    pub fn rule(&self) -> String {
        match self.tests.len() {
            0 => "no test".into(),
            1 => "one test".into(),
            m => format!("a family of {m} tests, decided on Holm-adjusted p"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn margins_are_a_tenth_of_the_thesis_s_demonstrator() {
        assert_eq!(MAZE_MARGIN, 32.75);
        assert!((MARIO_MARGIN - 122.4).abs() < 1e-12);
    }

    #[test]
    fn a_family_decides_on_holm_adjusted_p() {
        // Two clear differences and one weak one: raw p of the weak one
        // is below 0.05, its Holm-adjusted p (×1 as the largest of three,
        // but the step-down's running maximum) is checked against SciPy-free
        // arithmetic: adjusted = max over the ordered products.
        let a = [10.0, 11.0, 12.0, 10.5, 11.5];
        let b = [1.0, 2.0, 1.5, 2.5, 1.0];
        let c = [9.0, 10.4, 11.0, 9.8, 10.6];
        let mut f = Family::new();
        f.above("A vs B", &a, &b, 0.05);
        f.above("A vs C", &a, &c, 0.05);
        let raw: Vec<f64> = f.tests.iter().map(|t| t.p).collect();
        let adj = f.adjusted();
        let (lo, hi) = if raw[0] < raw[1] { (0, 1) } else { (1, 0) };
        assert_eq!(adj[lo], (2.0 * raw[lo]).min(1.0));
        assert_eq!(adj[hi], adj[lo].max(raw[hi]));
        assert!(f.holds_within(0..1));
        assert_eq!(f.holds(), adj[1] < 0.05);
        // The wrong direction never holds, however small p.
        let mut g = Family::new();
        g.above("B vs A", &b, &a, 0.05);
        assert!(!g.holds());
        assert!(g.texts(1)[0].starts_with("B vs A 1.6 vs 11.0: difference −9.4 (95 % CI"));
        let hedges = rlfd_stats::hedges_g(&b, &a).unwrap();
        assert!(g.texts(1)[0].contains(&format!(", g = {}, p = ", num(hedges, 2))), "{}", g.texts(1)[0]);
        // The scorecard shows the p that decides: Holm's in a family, raw alone.
        let o = f.outcomes();
        assert_eq!(o.len(), 2);
        assert_eq!(o[1].p, Some(adj[1]));
        assert_eq!(o[1].test, "two-sided pooled t-test, Holm over 2");
        assert_eq!(o[1].note.as_deref(), Some(format!("raw p = {}", p_value(raw[1])).as_str()));
        let o = g.outcomes();
        assert_eq!((o[0].p, o[0].note.clone()), (Some(g.tests[0].p), None));
    }

    #[test]
    fn equivalence_needs_the_90_percent_interval_inside_the_margin() {
        let a = [100.0, 102.0, 98.0, 101.0, 99.0, 100.5, 99.5, 100.0];
        let b = [100.5, 101.0, 99.0, 100.0, 99.5, 100.0, 101.0, 99.0];
        let mut wide = Family::new();
        wide.equivalent("A vs B", &a, &b, 5.0);
        assert!(wide.holds());
        let mut narrow = Family::new();
        narrow.equivalent("A vs B", &a, &b, 0.1);
        assert!(!narrow.holds());
        assert_eq!(narrow.outcomes()[0].test, "TOST (pooled), margin ±0.10");
        // An undefined test never holds and adjusts as 1.
        let mut undefined = Family::new();
        undefined.equivalent("A vs B", &a, &[1.0], 5.0);
        undefined.equivalent("A vs B", &a, &b, 5.0);
        assert!(undefined.adjusted()[0].is_nan() && !undefined.holds() && undefined.holds_within(1..2));
        assert!(undefined.texts(1)[0].contains("the test is undefined"));
    }
}
