//! The policy of CBA's GMM variant: one Gaussian mixture per action over
//! `(x, y)`; a state's action is the one whose mixture gives it the highest
//! likelihood, and the confidence is that action's normalised likelihood
//! (Chernova & Veloso 2007; spec `algorithms.md` §7):
//!
//! `c(a | x) = p(x | a) / Σ_b p(x | b)`,
//!
//! equal priors over actions (the user's demonstrations are not a sample of
//! how often each action is right, so their counts are not priors).

use serde::{Deserialize, Serialize};

use super::gmm::Gmm;
use crate::dbug::Action;

/// One mixture per action, in [`Action::ALL`] order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GmmClassifier {
    pub models: [Gmm; 3],
}

/// A classification with its confidence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Classification {
    /// The most likely action `a_p`.
    pub action: Action,
    /// `c(a_p | x)`.
    pub confidence: f64,
    /// The second most likely action: the decision boundary the state lies against.
    pub runner_up: Action,
}

impl GmmClassifier {
    /// `log p(x | a)` per action.
    #[inline]
    pub fn log_likelihoods(&self, x: [f64; 2]) -> [f64; 3] {
        [0, 1, 2].map(|a| self.models[a].log_pdf(x))
    }

    /// The action, its confidence and the runner-up.
    pub fn classify(&self, x: [f64; 2]) -> Classification {
        classify_log_likelihoods(self.log_likelihoods(x))
    }

    /// Recomputes the components' caches after deserialising.
    pub fn refreshed(&self) -> GmmClassifier {
        GmmClassifier { models: [0, 1, 2].map(|a| self.models[a].refreshed()) }
    }
}

/// Classification from `log p(x | a)` (ties: the lower action index).
pub fn classify_log_likelihoods(l: [f64; 3]) -> Classification {
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| l[b].total_cmp(&l[a]).then(a.cmp(&b)));
    let top = l[order[0]];
    let denominator: f64 = l.iter().map(|&v| libm::exp(v - top)).sum();
    Classification {
        action: Action::from_index(order[0]),
        confidence: 1.0 / denominator,
        runner_up: Action::from_index(order[1]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn confidence_is_the_normalised_likelihood() {
        let c = classify_log_likelihoods([libm::log(0.2), libm::log(0.6), libm::log(0.2)]);
        assert_eq!(c.action, Action::Sweep);
        assert!((c.confidence - 0.6).abs() < 1e-12);
        assert_eq!(c.runner_up, Action::Pickup, "ties go to the lower index");
        let far = classify_log_likelihoods([-2000.0, -2100.0, -1990.0]);
        assert_eq!(far.action, Action::Wait);
        assert!(far.confidence > 0.9999);
    }
}
