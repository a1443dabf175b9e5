//! Confidence-Based Autonomy (Chernova & Veloso, JAIR 2009) with a Gaussian
//! mixture per action (Chernova & Veloso, AAMAS 2007), as the thesis ran it
//! on DBug (sections 4.2, 4.4).
//!
//! Confident Execution, at each decision (spec `algorithms.md` §7):
//! 1. the classifier gives `(a_p, c, b)` for the state `s` (`b` the
//!    runner-up action: the decision boundary);
//! 2. `d` = distance from `s` to its nearest neighbour in the training set;
//! 3. if `c > τ_conf(a_p, b)` and `d ≤ τ_dist`, execute `a_p`;
//! 4. otherwise request a demonstration, add `(s, a_d)`, retrain.
//!
//! `τ_dist = 3 ×` the mean nearest-neighbour distance within the training
//! set; `τ_conf(a, b)` = the mean confidence of the demonstrations
//! misclassified across the boundary between `a` and `b` (0 when none is),
//! both recomputed after every retrain. Which classifier judges a
//! demonstration is the `cba-threshold` reading ([`ThresholdData`]): by
//! default one that was not fitted to it (two-fold cross-validation: each
//! action's demonstrations alternate between two folds in the order given,
//! and each fold is classified by the mixtures of the other), because a
//! mixture fitted to a point is rarely wrong about it and `τ_conf` then
//! falls to 0, leaving autonomy to `τ_dist` alone; the alternative is the
//! training points themselves (the round-1 implementation). Corrective Demonstration adds `(s,
//! a_corr)` the same way. The classifier acts only once every action has
//! "a minimum of 3 demonstrations"; until then every state requests one.
//!
//! Retraining refits the mixture of the demonstrated action ([`gmm`]); the
//! other two are unchanged. What the robot does while it waits for an
//! answer belongs to the session, not to the learner.

pub mod classifier;
pub mod gaussian;
pub mod gmm;

use serde::{Deserialize, Serialize};

use crate::dbug::{Action, Pixel};
use crate::evaluation::{Accuracy, score_pixels};
use classifier::{Classification, GmmClassifier};
use gmm::{EmSettings, Gmm, fit_bic};

/// Which classifier judges a demonstration when `τ_conf` is computed (the
/// `cba-threshold` reading, [`crate::readings::CBA_THRESHOLD`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ThresholdData {
    /// Two-fold cross-validation: a classifier not fitted to the point.
    #[default]
    HeldOut,
    /// The classifier fitted to every point, the point included.
    Training,
}

/// CBA's parameters.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CbaParams {
    /// Demonstrations of every action before the classifier acts (thesis: 3).
    pub min_demonstrations: u32,
    /// Most components per action's mixture (ours: 4; the thesis saw "multiple Gaussians for each action").
    pub max_components: usize,
    /// EM's settings (ours: covariance floor 16 px², i.e. σ ≥ 4 px; 200 iterations; tolerance 1e-6).
    pub em: EmSettings,
    /// `τ_dist` as a multiple of the mean nearest-neighbour distance (Chernova & Veloso: 3).
    pub distance_factor: f64,
    /// What `τ_conf` is computed on.
    pub threshold: ThresholdData,
}

impl CbaParams {
    /// The thesis's minimum of 3 demonstrations, Chernova & Veloso's thresholds, our EM settings.
    pub const fn thesis() -> CbaParams {
        CbaParams {
            min_demonstrations: 3,
            max_components: 4,
            em: EmSettings { reg_covar: 16.0, max_iter: 200, tol: 1e-6 },
            distance_factor: 3.0,
            threshold: ThresholdData::HeldOut,
        }
    }
}

/// What the robot does in a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Decision {
    /// Confident: execute the classifier's action.
    Act(Classification),
    /// Not confident (or not enough data): ask the user.
    Request,
}

/// The learner.
#[derive(Clone, Debug)]
pub struct Cba {
    params: CbaParams,
    points: [Vec<[f64; 2]>; 3],
    models: [Option<Gmm>; 3],
    /// Per action and fold `f`: the mixture of the demonstrations not in fold `f`.
    fold_models: [[Option<Gmm>; 2]; 3],
    classifier: Option<GmmClassifier>,
    tau_dist: f64,
    tau_conf: [[f64; 3]; 3],
}

impl Cba {
    /// An empty learner.
    pub fn new(params: CbaParams) -> Cba {
        Cba {
            params,
            points: [Vec::new(), Vec::new(), Vec::new()],
            models: [None, None, None],
            fold_models: [[None, None], [None, None], [None, None]],
            classifier: None,
            tau_dist: 0.0,
            tau_conf: [[0.0; 3]; 3],
        }
    }

    /// Demonstrations per action.
    pub fn counts(&self) -> [u32; 3] {
        [0, 1, 2].map(|a| self.points[a].len() as u32)
    }

    /// The training set per action.
    pub fn points(&self) -> &[Vec<[f64; 2]>; 3] {
        &self.points
    }

    /// Whether every action has its minimum of demonstrations.
    pub fn ready(&self) -> bool {
        self.classifier.is_some()
    }

    /// The classifier, once ready.
    pub fn classifier(&self) -> Option<&GmmClassifier> {
        self.classifier.as_ref()
    }

    /// `τ_dist` and `τ_conf`.
    pub fn thresholds(&self) -> (f64, [[f64; 3]; 3]) {
        (self.tau_dist, self.tau_conf)
    }

    /// Confident Execution's choice for state `s`.
    pub fn decide(&self, s: Pixel) -> Decision {
        let Some(c) = &self.classifier else { return Decision::Request };
        let x = s.as_f64();
        let k = c.classify(x);
        let d = self.nearest_distance(x);
        if k.confidence > self.tau_conf[k.action.index()][k.runner_up.index()] && d <= self.tau_dist {
            Decision::Act(k)
        } else {
            Decision::Request
        }
    }

    fn nearest_distance(&self, x: [f64; 2]) -> f64 {
        let mut best = f64::INFINITY;
        for ps in &self.points {
            for p in ps {
                best = best.min((p[0] - x[0]).powi(2) + (p[1] - x[1]).powi(2));
            }
        }
        best.sqrt()
    }

    /// Adds a demonstration (or correction) `(s, a)` and retrains.
    pub fn add(&mut self, s: Pixel, a: Action) {
        let i = a.index();
        self.points[i].push(s.as_f64());
        self.models[i] = Some(fit_bic(&self.points[i], self.params.max_components, &self.params.em).gmm);
        if self.params.threshold == ThresholdData::HeldOut {
            // The new point is in fold `n % 2`: only the other fold's mixture gains it.
            let fold = (self.points[i].len() - 1) % 2;
            let train: Vec<[f64; 2]> = self.points[i].iter().skip(fold).step_by(2).copied().collect();
            self.fold_models[i][1 - fold] = Some(fit_bic(&train, self.params.max_components, &self.params.em).gmm);
        }
        let min = self.params.min_demonstrations as usize;
        if self.points.iter().all(|p| p.len() >= min) {
            let models = [0, 1, 2].map(|i| self.models[i].clone().expect("fitted"));
            self.classifier = Some(GmmClassifier { models });
            self.update_thresholds();
        }
    }

    fn update_thresholds(&mut self) {
        let mut sum = [[0.0f64; 3]; 3];
        let mut n = [[0u32; 3]; 3];
        let mut tally = |c: &GmmClassifier, label: usize, p: [f64; 2]| {
            let k = c.classify(p);
            let predicted = k.action.index();
            if predicted != label {
                let (a, b) = (label.min(predicted), label.max(predicted));
                sum[a][b] += k.confidence;
                n[a][b] += 1;
            }
        };
        match self.params.threshold {
            ThresholdData::Training => {
                let c = self.classifier.as_ref().expect("ready");
                for (label, ps) in self.points.iter().enumerate() {
                    for &p in ps {
                        tally(c, label, p);
                    }
                }
            }
            ThresholdData::HeldOut => {
                for fold in 0..2 {
                    // With fewer than two demonstrations of an action a fold has no
                    // mixture for it (only when the minimum is set below 2): skip the fold.
                    let [Some(p), Some(s), Some(w)] = [0, 1, 2].map(|a| self.fold_models[a][fold].clone()) else {
                        continue;
                    };
                    let c = GmmClassifier { models: [p, s, w] };
                    for (label, ps) in self.points.iter().enumerate() {
                        for &p in ps.iter().skip(fold).step_by(2) {
                            tally(&c, label, p);
                        }
                    }
                }
            }
        }
        for a in 0..3 {
            for b in 0..3 {
                let (i, j) = (a.min(b), a.max(b));
                self.tau_conf[a][b] = if n[i][j] > 0 { sum[i][j] / f64::from(n[i][j]) } else { 0.0 };
            }
        }
        let all: Vec<[f64; 2]> = self.points.iter().flatten().copied().collect();
        let mut total = 0.0;
        for (i, p) in all.iter().enumerate() {
            let mut best = f64::INFINITY;
            for (j, q) in all.iter().enumerate() {
                if i != j {
                    best = best.min((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2));
                }
            }
            total += best.sqrt();
        }
        self.tau_dist = self.params.distance_factor * total / all.len() as f64;
    }

    /// The final policy's accuracy: the classifier's action in every state;
    /// without a classifier no state has an action (0 %).
    pub fn accuracy(&self) -> Accuracy {
        match &self.classifier {
            None => score_pixels(|_| None),
            Some(c) => score_pixels(|p| Some(c.action(p.as_f64()))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn teach(cba: &mut Cba, points: &[(u16, u16)], a: Action) {
        for &(x, y) in points {
            cba.add(Pixel::new(x, y), a);
        }
    }

    #[test]
    fn requests_until_three_demonstrations_of_each_action() {
        let mut c = Cba::new(CbaParams::thesis());
        teach(&mut c, &[(170, 200), (160, 190), (180, 210)], Action::Pickup);
        teach(&mut c, &[(60, 200), (50, 210), (70, 190)], Action::Sweep);
        teach(&mut c, &[(160, 60), (250, 100)], Action::Wait);
        assert!(!c.ready());
        assert_eq!(c.decide(Pixel::new(170, 200)), Decision::Request);
        assert_eq!(c.accuracy().overall, 0.0);
        teach(&mut c, &[(60, 80)], Action::Wait);
        assert!(c.ready());
        assert_eq!(c.counts(), [3, 3, 3]);
        // Near the pickup demonstrations it acts; far from all data it asks.
        match c.decide(Pixel::new(172, 201)) {
            Decision::Act(k) => assert_eq!(k.action, Action::Pickup),
            Decision::Request => panic!("a state among the pickup demonstrations should be confident"),
        }
        let (tau_dist, _) = c.thresholds();
        assert!(tau_dist > 100.0 && tau_dist < 140.0, "{tau_dist}");
        assert_eq!(c.decide(Pixel::new(319, 239)), Decision::Request, "142 px from the nearest demonstration");
    }

    #[test]
    fn a_clean_demonstration_set_gives_a_good_policy() {
        let mut c = Cba::new(CbaParams::thesis());
        let mut pick = Vec::new();
        let mut sweep = Vec::new();
        let mut wait = Vec::new();
        for i in 0..5u16 {
            for j in 0..4u16 {
                pick.push((125 + 20 * i, 165 + 20 * j));
                sweep.push((5 + 24 * i, 165 + 20 * j));
            }
        }
        for i in 0..8u16 {
            for j in 0..5u16 {
                wait.push((10 + 40 * i, 10 + 30 * j));
            }
        }
        for j in 0..4u16 {
            wait.push((240 + 20 * j, 200));
        }
        teach(&mut c, &pick, Action::Pickup);
        teach(&mut c, &sweep, Action::Sweep);
        teach(&mut c, &wait, Action::Wait);
        let acc = c.accuracy();
        assert!(acc.overall > 85.0, "{acc:?}");
        assert!(acc.per_zone.iter().all(|&z| z > 70.0), "{acc:?}");
    }
}
