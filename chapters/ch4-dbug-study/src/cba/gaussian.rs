//! A bivariate Gaussian over image coordinates, with its inverse covariance
//! and log-normaliser computed once.
//!
//! `log N(x; μ, Σ) = −log 2π − ½ log |Σ| − ½ (x − μ)ᵀ Σ⁻¹ (x − μ)`, with
//! `Σ = [[a, b], [b, c]]`, `|Σ| = ac − b²`, `Σ⁻¹ = [[c, −b], [−b, a]] / |Σ|`.
//! Two-by-two algebra written out (no matrix library): the same bits on
//! every CPU.

use serde::{Deserialize, Serialize};

/// `log 2π`.
const LOG_2PI: f64 = 1.837_877_066_409_345_3;

/// A 2-D Gaussian. Stored as its mean and covariance; the cache is
/// recomputed when it is read back.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(from = "StoredGaussian")]
pub struct Gaussian2 {
    /// Mean `(x, y)`.
    pub mean: [f64; 2],
    /// Covariance `[a, b, c]` for `[[a, b], [b, c]]`.
    pub cov: [f64; 3],
    #[serde(skip)]
    inv: [f64; 3],
    #[serde(skip)]
    log_norm: f64,
}

/// What a stored Gaussian holds.
#[derive(Deserialize)]
struct StoredGaussian {
    mean: [f64; 2],
    cov: [f64; 3],
}

impl From<StoredGaussian> for Gaussian2 {
    fn from(s: StoredGaussian) -> Gaussian2 {
        Gaussian2::new(s.mean, s.cov)
    }
}

impl Gaussian2 {
    /// A Gaussian; the covariance must be positive definite.
    pub fn new(mean: [f64; 2], cov: [f64; 3]) -> Gaussian2 {
        let [a, b, c] = cov;
        let det = a * c - b * b;
        assert!(a > 0.0 && det > 0.0, "covariance {cov:?} is not positive definite");
        Gaussian2 { mean, cov, inv: [c / det, -b / det, a / det], log_norm: -LOG_2PI - 0.5 * libm::log(det) }
    }

    /// Recomputes the cached inverse after deserialising.
    pub fn refreshed(&self) -> Gaussian2 {
        Gaussian2::new(self.mean, self.cov)
    }

    /// Squared Mahalanobis distance of `x`.
    #[inline]
    pub fn mahalanobis2(&self, x: [f64; 2]) -> f64 {
        let (dx, dy) = (x[0] - self.mean[0], x[1] - self.mean[1]);
        let [ia, ib, ic] = self.inv;
        dx * (ia * dx + ib * dy) + dy * (ib * dx + ic * dy)
    }

    /// `log N(x; μ, Σ)`.
    #[inline]
    pub fn log_pdf(&self, x: [f64; 2]) -> f64 {
        self.log_norm - 0.5 * self.mahalanobis2(x)
    }

    /// The ellipse `(x − μ)ᵀ Σ⁻¹ (x − μ) = k²`: semi-axes and the angle of
    /// the first axis (radians, image frame), from the eigen-decomposition.
    pub fn ellipse(&self, k: f64) -> ((f64, f64), f64) {
        let [a, b, c] = self.cov;
        let mid = 0.5 * (a + c);
        let rad = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        let (l1, l2) = (mid + rad, (mid - rad).max(0.0));
        let angle = 0.5 * libm::atan2(2.0 * b, a - c);
        ((k * l1.sqrt(), k * l2.sqrt()), angle)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_pdf_matches_the_formula() {
        // scipy.stats.multivariate_normal([1, 2], [[4, 1], [1, 2]]).logpdf([2, 1]) = -3.3822607123655732 (scipy 1.17.1)
        let g = Gaussian2::new([1.0, 2.0], [4.0, 1.0, 2.0]);
        assert!((g.log_pdf([2.0, 1.0]) - (-3.382_260_712_365_573_2)).abs() < 1e-13);
        let ((r1, r2), angle) = Gaussian2::new([0.0, 0.0], [9.0, 0.0, 1.0]).ellipse(2.0);
        assert!((r1 - 6.0).abs() < 1e-12 && (r2 - 2.0).abs() < 1e-12 && angle.abs() < 1e-12);
        let ((_, _), a) = Gaussian2::new([0.0, 0.0], [1.0, 0.0, 9.0]).ellipse(1.0);
        assert!((a.abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        // A stored Gaussian reads back whole, cache included.
        let json = serde_json::to_string(&g).unwrap();
        assert_eq!(json, r#"{"mean":[1.0,2.0],"cov":[4.0,1.0,2.0]}"#);
        assert_eq!(serde_json::from_str::<Gaussian2>(&json).unwrap(), g);
    }
}
