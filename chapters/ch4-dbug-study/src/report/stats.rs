//! The numbers the report is made of, computed from stored results only:
//! per-study correlations, box summaries, and their spread over studies.

use rlfd_report::figure::BoxStats;
use rlfd_stats::{Correlation, pearson, quantile};

use crate::dbug::Zone;
use crate::experiment::ParticipantRecord;
use crate::users::Algorithm;

/// The two correlations the thesis reports per algorithm.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pair {
    /// Interactions (rewards, demonstrations) against accuracy: Figures 4.4(a), 4.6(a), 4.8(a).
    Interactions,
    /// Satisfaction against accuracy: Figures 4.4(b), 4.6(b), 4.8(b).
    Satisfaction,
}

impl Pair {
    pub const ALL: [Pair; 2] = [Pair::Interactions, Pair::Satisfaction];

    /// The key in `thesis-numbers.toml`.
    pub fn key(self) -> &'static str {
        match self {
            Pair::Interactions => "r_interactions_accuracy",
            Pair::Satisfaction => "r_satisfaction_accuracy",
        }
    }

    /// Words for tables.
    pub fn label(self) -> &'static str {
        match self {
            Pair::Interactions => "interactions vs accuracy",
            Pair::Satisfaction => "satisfaction vs accuracy",
        }
    }

    /// The x value of one session.
    pub fn x(self, p: &ParticipantRecord, a: Algorithm) -> f64 {
        let s = p.session(a);
        match self {
            Pair::Interactions => f64::from(s.interactions),
            Pair::Satisfaction => f64::from(s.satisfaction),
        }
    }
}

/// Pearson's r of a pair over a study's participants (`None`: undefined, e.g. a constant column).
pub fn correlation(study: &[ParticipantRecord], a: Algorithm, pair: Pair) -> Option<Correlation> {
    let x: Vec<f64> = study.iter().map(|p| pair.x(p, a)).collect();
    let y: Vec<f64> = study.iter().map(|p| p.session(a).accuracy.overall).collect();
    pearson(&x, &y).ok()
}

/// Least-squares line `y = slope · x + intercept` (for drawing), `None` when x is constant.
pub fn fit_line(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    if n < 2.0 {
        return None;
    }
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| (sxy / sxx, my - sxy / sxx * mx))
}

/// Tukey's box: quartiles (type 7), whiskers to the most extreme data within `k` IQR, the rest outliers.
pub fn box_stats(values: &[f64], k: f64) -> Option<BoxStats> {
    let q1 = quantile(values, 0.25).ok()?;
    let median = quantile(values, 0.5).ok()?;
    let q3 = quantile(values, 0.75).ok()?;
    let iqr = q3 - q1;
    let (lo_fence, hi_fence) = (q1 - k * iqr, q3 + k * iqr);
    let inside = values.iter().copied().filter(|v| (lo_fence..=hi_fence).contains(v));
    let low = inside.clone().fold(f64::INFINITY, f64::min).min(q1);
    let high = inside.fold(f64::NEG_INFINITY, f64::max).max(q3);
    let mut outliers: Vec<f64> = values.iter().copied().filter(|v| !(lo_fence..=hi_fence).contains(v)).collect();
    outliers.sort_by(f64::total_cmp);
    Some(BoxStats { q1, median, q3, low, high, outliers })
}

/// Per-zone accuracies of an algorithm over a study.
pub fn zone_values(study: &[ParticipantRecord], a: Algorithm, z: Zone) -> Vec<f64> {
    study.iter().map(|p| p.session(a).accuracy.zone(z)).collect()
}

/// Overall accuracies of an algorithm over a study.
pub fn overall_values(study: &[ParticipantRecord], a: Algorithm) -> Vec<f64> {
    study.iter().map(|p| p.session(a).accuracy.overall).collect()
}

/// The median of a sample (NaN when empty).
pub fn median(values: &[f64]) -> f64 {
    quantile(values, 0.5).unwrap_or(f64::NAN)
}

/// The spread of a statistic over studies: median and the 5th and 95th percentiles of its defined values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    pub median: f64,
    pub p05: f64,
    pub p95: f64,
    /// Studies where it was defined.
    pub defined: usize,
}

/// The spread of values (NaN entries skipped).
pub fn spread(values: &[f64]) -> Spread {
    let v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    Spread {
        median: quantile(&v, 0.5).unwrap_or(f64::NAN),
        p05: quantile(&v, 0.05).unwrap_or(f64::NAN),
        p95: quantile(&v, 0.95).unwrap_or(f64::NAN),
        defined: v.len(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_and_lines() {
        let b = box_stats(&[1.0, 2.0, 3.0, 4.0, 100.0], 1.5).unwrap();
        assert_eq!((b.q1, b.median, b.q3), (2.0, 3.0, 4.0));
        assert_eq!((b.low, b.high), (1.0, 4.0));
        assert_eq!(b.outliers, vec![100.0]);
        assert_eq!(fit_line(&[(0.0, 1.0), (1.0, 3.0), (2.0, 5.0)]), Some((2.0, 1.0)));
        assert_eq!(fit_line(&[(1.0, 1.0), (1.0, 3.0)]), None);
        let s = spread(&[f64::NAN, 1.0, 2.0, 3.0]);
        assert_eq!((s.median, s.defined), (2.0, 3));
    }
}
