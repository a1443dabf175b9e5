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

    /// The most likely action alone: [`Self::classify`]'s action without
    /// its confidence (the final policy's accuracy needs no more), to the
    /// same bit.
    ///
    /// A mixture's `log p(x | a) = m + log Σ_j exp(t_j − m)` lies in
    /// `[m, m + log K]`, `m` its largest term `log π_j + log N_j(x)` (the
    /// largest term adds exactly 1 to the sum). Where one action's lower
    /// bound clears the others' upper bounds (with a margin far above the
    /// rounding of the sum and the logarithm), it wins without an
    /// exponential or a logarithm; elsewhere (near a decision boundary)
    /// the exact likelihoods decide, as `classify` does.
    pub fn action(&self, x: [f64; 2]) -> Action {
        let m = [0, 1, 2].map(|a| self.models[a].largest_term(x));
        let best = (1..3).fold(0, |b, a| if m[a] > m[b] { a } else { b });
        let upper = |a: usize| m[a] + self.models[a].log_components() + 1e-9 * (1.0 + m[a].abs());
        if m.iter().all(|v| v.is_finite()) && (0..3).all(|a| a == best || m[best] > upper(a)) {
            return Action::from_index(best);
        }
        let l = self.log_likelihoods(x);
        let mut best = 0;
        for a in 1..3 {
            // The first greatest in the total order, as `classify`'s sort keeps it.
            if l[a].total_cmp(&l[best]) == std::cmp::Ordering::Greater {
                best = a;
            }
        }
        Action::from_index(best)
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

    #[test]
    fn the_action_alone_is_classifys_action_everywhere() {
        use super::super::gaussian::Gaussian2;
        let g = |m: [f64; 2], c: [f64; 3]| Gaussian2::new(m, c);
        // One- and two-component mixtures whose boundaries cross the image,
        // and a classifier of three equal mixtures (every pixel a tie).
        let two = Gmm::new(
            vec![0.3, 0.7],
            vec![g([40.0, 60.0], [90.0, 10.0, 60.0]), g([200.0, 180.0], [400.0, -50.0, 300.0])],
        );
        let one = Gmm::new(vec![1.0], vec![g([160.0, 120.0], [900.0, 0.0, 900.0])]);
        let far =
            Gmm::new(vec![0.5, 0.5], vec![g([300.0, 20.0], [50.0, 0.0, 50.0]), g([10.0, 230.0], [70.0, 5.0, 40.0])]);
        let mixed = GmmClassifier { models: [two.clone(), one.clone(), far] };
        let tied = GmmClassifier { models: [one.clone(), one.clone(), one] };
        let mut seen = [0; 3];
        for y in 0..240 {
            for x in 0..320 {
                let p = [f64::from(x), f64::from(y)];
                let a = mixed.action(p);
                assert_eq!(a, mixed.classify(p).action, "{p:?}");
                seen[a.index()] += 1;
                assert_eq!(tied.action(p), Action::Pickup);
                assert_eq!(tied.classify(p).action, Action::Pickup);
            }
        }
        assert!(seen.iter().all(|&n| n > 0), "every action wins somewhere: {seen:?}");
    }

    #[test]
    fn the_action_alone_agrees_on_random_close_mixtures() {
        use super::super::gaussian::Gaussian2;
        use rlfd_rl::random::{SimRng, below, seeded, uniform01};
        // Mixtures of 1–4 components drawn close together, so that many
        // points fall near a boundary and take the exact path.
        let mut rng = seeded(11);
        let range = |rng: &mut SimRng, lo: f64, hi: f64| lo + (hi - lo) * uniform01(rng);
        let mixture = |rng: &mut SimRng| {
            let k = 1 + below(rng, 4);
            let w: Vec<f64> = (0..k).map(|_| range(rng, 0.05, 1.0)).collect();
            let total: f64 = w.iter().sum();
            let comps = (0..k)
                .map(|_| {
                    let (a, c) = (range(rng, 20.0, 400.0), range(rng, 20.0, 400.0));
                    let b = range(rng, -0.8, 0.8) * f64::sqrt(a * c);
                    Gaussian2::new([range(rng, 120.0, 200.0), range(rng, 90.0, 150.0)], [a, b, c])
                })
                .collect();
            Gmm::new(w.iter().map(|x| x / total).collect(), comps)
        };
        for _ in 0..200 {
            let c = GmmClassifier { models: [mixture(&mut rng), mixture(&mut rng), mixture(&mut rng)] };
            for _ in 0..500 {
                let p = [range(&mut rng, 100.0, 220.0), range(&mut rng, 70.0, 170.0)];
                assert_eq!(c.action(p), c.classify(p).action, "{p:?} {c:?}");
            }
        }
    }

    #[test]
    fn one_component_log_pdf_is_the_weighted_gaussian_to_the_bit() {
        use super::super::gaussian::Gaussian2;
        let g = Gaussian2::new([100.0, 50.0], [120.0, 30.0, 80.0]);
        let one = Gmm::new(vec![1.0], vec![g]);
        for p in [[0.0, 0.0], [100.0, 50.0], [319.0, 239.0], [37.5, 211.25]] {
            // The general path: m + log(Σ exp(t − m)) with a single t.
            let t = libm::log(1.0) + g.log_pdf(p);
            let general = t + libm::log(libm::exp(t - t));
            assert_eq!(one.log_pdf(p).to_bits(), general.to_bits());
        }
    }
}
