//! Similarity-based shaping (SBS; Brys, Harutyunyan, Suay, Chernova, Taylor
//! & Nowé, IJCAI 2015): a state-action potential from demonstrated pairs.
//!
//! ```text
//! Φ(s, a) = max over demonstrated (s_d, a_d) with a_d = a of
//!           exp(−½ Σ_j (s_j − s_{d,j})² / σ_j²)
//! ```
//!
//! a non-normalised Gaussian with a diagonal covariance, in [0, 1], and 0 for
//! an action never demonstrated. Because the Gaussian decreases with the
//! scaled distance, the maximum is the value at the nearest demonstrated
//! state of that action: each action's (scaled, deduplicated) states go into
//! a k-d tree, and a query descends to the nearest leaf and backtracks only
//! into cells closer than the best distance found. The answer is exact (not
//! an approximation) and costs a few dozen comparisons and one exponential
//! instead of one exponential per demonstrated pair.
//!
//! Used as look-ahead advice (`rlfd_rl::shaping::LookAheadShaping`).

use rlfd_rl::shaping::StateActionFunction;
use thiserror::Error;

/// Why a potential cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SimilarityError {
    /// σ must have one positive, finite entry per state variable.
    #[error("sigma must hold {expected} positive finite widths, found {found:?}")]
    Sigma {
        /// The state dimension.
        expected: usize,
        /// What was given.
        found: Vec<f64>,
    },
    /// A demonstrated pair with the wrong dimension, a non-finite value or an action out of range.
    #[error("demonstrated pair {index}: {what}")]
    Pair {
        /// Position of the pair.
        index: usize,
        /// What is wrong.
        what: String,
    },
}

/// The SBS potential over demonstrated state-action pairs.
#[derive(Clone, Debug)]
pub struct SimilarityPotential {
    dim: usize,
    inv_sigma: Vec<f64>,
    /// Per action: a k-d tree over the scaled states.
    trees: Vec<KdTree>,
}

impl SimilarityPotential {
    /// Builds the potential from `(state, action)` pairs with widths `sigma` per state variable.
    pub fn new<'a>(
        pairs: impl IntoIterator<Item = (&'a [f64], usize)>,
        num_actions: usize,
        sigma: &[f64],
    ) -> Result<Self, SimilarityError> {
        let dim = sigma.len();
        if dim == 0 || sigma.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
            return Err(SimilarityError::Sigma { expected: dim.max(1), found: sigma.to_vec() });
        }
        let inv_sigma: Vec<f64> = sigma.iter().map(|s| 1.0 / s).collect();
        let mut per_action: Vec<Vec<Vec<f64>>> = vec![Vec::new(); num_actions];
        for (index, (state, action)) in pairs.into_iter().enumerate() {
            if state.len() != dim {
                return Err(SimilarityError::Pair {
                    index,
                    what: format!("{} state values, expected {dim}", state.len()),
                });
            }
            if state.iter().any(|x| !x.is_finite()) {
                return Err(SimilarityError::Pair { index, what: "a state value is not finite".into() });
            }
            if action >= num_actions {
                return Err(SimilarityError::Pair {
                    index,
                    what: format!("action {action} is out of range 0..{num_actions}"),
                });
            }
            per_action[action].push(state.iter().zip(&inv_sigma).map(|(x, i)| x * i).collect());
        }
        let trees = per_action
            .into_iter()
            .map(|mut v| {
                v.sort_by(|a, b| {
                    a.iter()
                        .zip(b)
                        .map(|(x, y)| x.total_cmp(y))
                        .find(|o| o.is_ne())
                        .unwrap_or(std::cmp::Ordering::Equal)
                });
                v.dedup();
                KdTree::new(v, dim)
            })
            .collect();
        Ok(SimilarityPotential { dim, inv_sigma, trees })
    }

    /// Number of distinct demonstrated states of `action`.
    pub fn demonstrated_states(&self, action: usize) -> usize {
        self.trees[action].len()
    }

    /// Number of actions.
    pub fn num_actions(&self) -> usize {
        self.trees.len()
    }

    /// `1 / σ` per state variable.
    pub fn inv_sigma(&self) -> &[f64] {
        &self.inv_sigma
    }

    /// The distinct demonstrated states of `action`, each variable scaled
    /// by `1 / σ` (in the index's order), for a domain that indexes them its
    /// own way.
    pub fn scaled_states(&self, action: usize) -> impl Iterator<Item = &[f64]> {
        self.trees[action].points.chunks_exact(self.dim)
    }
}

/// An exact nearest-neighbour index: a k-d tree stored as an implicit,
/// balanced binary tree over a reordered point array (the median of each
/// range on the split axis sits at the range's middle).
#[derive(Clone, Debug)]
struct KdTree {
    dim: usize,
    /// Points, flat, in tree order.
    points: Vec<f64>,
    /// Split axis of the node at each middle position.
    axis: Vec<u8>,
}

impl KdTree {
    fn new(mut pts: Vec<Vec<f64>>, dim: usize) -> Self {
        let n = pts.len();
        let mut axis = vec![0u8; n];
        Self::build(&mut pts, &mut axis, 0, n, dim);
        KdTree { dim, points: pts.into_iter().flatten().collect(), axis }
    }

    fn build(pts: &mut [Vec<f64>], axis: &mut [u8], lo: usize, hi: usize, dim: usize) {
        if hi - lo <= 1 {
            return;
        }
        // Split on the axis of largest spread (deterministic ties: lowest axis).
        let mut best_axis = 0;
        let mut best_spread = -1.0;
        for a in 0..dim {
            let (min, max) =
                pts[lo..hi].iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(mn, mx), p| (mn.min(p[a]), mx.max(p[a])));
            if max - min > best_spread {
                best_spread = max - min;
                best_axis = a;
            }
        }
        let mid = lo + (hi - lo) / 2;
        pts[lo..hi].select_nth_unstable_by(mid - lo, |p, q| {
            p[best_axis].total_cmp(&q[best_axis]).then_with(|| {
                p.iter()
                    .zip(q.iter())
                    .map(|(x, y)| x.total_cmp(y))
                    .find(|o| o.is_ne())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
        });
        axis[mid] = best_axis as u8;
        Self::build(pts, axis, lo, mid, dim);
        Self::build(pts, axis, mid + 1, hi, dim);
    }

    fn len(&self) -> usize {
        self.axis.len()
    }

    /// Smallest squared distance from `q` to a point (∞ when empty).
    fn nearest_sq(&self, q: &[f64]) -> f64 {
        let mut best = f64::INFINITY;
        self.search(q, 0, self.len(), &mut best);
        best
    }

    fn search(&self, q: &[f64], lo: usize, hi: usize, best: &mut f64) {
        if lo >= hi {
            return;
        }
        let mid = lo + (hi - lo) / 2;
        let p = &self.points[mid * self.dim..(mid + 1) * self.dim];
        let d: f64 = p.iter().zip(q).map(|(a, b)| (a - b) * (a - b)).sum();
        if d < *best {
            *best = d;
        }
        let a = self.axis[mid] as usize;
        let gap = q[a] - p[a];
        let (near, far) = if gap < 0.0 { ((lo, mid), (mid + 1, hi)) } else { ((mid + 1, hi), (lo, mid)) };
        self.search(q, near.0, near.1, best);
        if gap * gap < *best {
            self.search(q, far.0, far.1, best);
        }
    }
}

impl StateActionFunction for SimilarityPotential {
    fn values(&self, state: &[f64], out: &mut [f64]) {
        let mut q = [0.0f64; 64];
        assert!(self.dim <= q.len(), "SimilarityPotential supports up to 64 state variables");
        for (j, (x, i)) in state.iter().zip(&self.inv_sigma).enumerate() {
            q[j] = x * i;
        }
        for (a, o) in out.iter_mut().enumerate() {
            let d2 = self.trees[a].nearest_sq(&q[..self.dim]);
            *o = if d2.is_finite() { libm::exp(-0.5 * d2) } else { 0.0 };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn brute_force(pairs: &[(Vec<f64>, usize)], sigma: &[f64], state: &[f64], a: usize) -> f64 {
        pairs
            .iter()
            .filter(|(_, b)| *b == a)
            .map(|(s, _)| {
                libm::exp(-0.5 * s.iter().zip(state).zip(sigma).map(|((x, y), g)| ((x - y) / g).powi(2)).sum::<f64>())
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn matches_the_definition() {
        let pairs = vec![(vec![0.0, 0.0], 0), (vec![1.0, 0.0], 1), (vec![0.5, 0.5], 0)];
        let p = SimilarityPotential::new(pairs.iter().map(|(s, a)| (s.as_slice(), *a)), 3, &[0.5, 1.0]).unwrap();
        let mut out = [0.0; 3];
        p.values(&[0.4, 0.3], &mut out);
        for a in 0..3 {
            assert!((out[a] - brute_force(&pairs, &[0.5, 1.0], &[0.4, 0.3], a)).abs() < 1e-15);
        }
        assert_eq!(out[2], 0.0, "an action never demonstrated has potential 0");
        p.values(&[1.0, 0.0], &mut out);
        assert_eq!(out[1], 1.0);
        assert_eq!(p.demonstrated_states(0), 2);
    }

    #[test]
    fn bad_input_is_rejected() {
        let s = [0.0, 1.0];
        assert!(SimilarityPotential::new([(&s[..], 0)], 2, &[0.0, 1.0]).is_err());
        assert!(SimilarityPotential::new([(&s[..], 5)], 2, &[1.0, 1.0]).is_err());
        assert!(SimilarityPotential::new([(&s[..1], 0)], 2, &[1.0, 1.0]).is_err());
        let nan = [f64::NAN, 0.0];
        assert!(SimilarityPotential::new([(&nan[..], 0)], 2, &[1.0, 1.0]).is_err());
    }

    proptest! {
        // The sweep finds the exact maximum of the brute-force definition.
        #[test]
        fn sweep_equals_brute_force(
            pts in proptest::collection::vec((proptest::collection::vec(-2.0f64..2.0, 3), 0usize..3), 1..60),
            q in proptest::collection::vec(-3.0f64..3.0, 3),
        ) {
            let sigma = [0.3, 0.7, 1.1];
            let p = SimilarityPotential::new(pts.iter().map(|(s, a)| (s.as_slice(), *a)), 3, &sigma).unwrap();
            let mut out = [0.0; 3];
            p.values(&q, &mut out);
            for a in 0..3 {
                let b = brute_force(&pts, &sigma, &q, a);
                prop_assert!((out[a] - b).abs() <= 1e-12 * b.max(1e-300), "action {}: {} vs {}", a, out[a], b);
            }
        }
    }
}
