//! A user's traits, drawn once per user from the master seed, and the
//! distributions they are drawn from.
//!
//! Section 4.3: "Six of the participants self-identified as an expert
//! roboticist, while 14 were novice and 11 had no robotics background."
//! Beyond expertise the thesis measures nothing about its users; the chapter
//! describes how they behaved (sections 4.4 and 4.6), and those
//! descriptions name four more traits: how fast they reacted ("if the
//! teacher is distracted and reacts slowly, corrections may have a negative
//! impact"), how closely they watched (users "abandoning rewards"), how
//! consistent their teaching was ("human teachers often make noisy
//! demonstrations"), and how long they kept a strategy without seeing
//! progress ("some … stop rewarding or … vary their reward strategy";
//! "people giving up on trial and error process after a few
//! demonstrations"). Their distributions below are our choices, fixed
//! before any learner ran and never tuned to an outcome; experts are
//! slightly faster, more attentive, more consistent and more patient, the
//! direction the chapter describes, by amounts it does not give.
//!
//! Draws: reaction time log-normal (median `m`, `σ_log`), attention and
//! consistency logit-normal (`logit x ~ N(logit m, σ)`), patience
//! log-normal.

use rand::Rng;
use rlfd_rl::random::standard_normal;
use serde::{Deserialize, Serialize};

/// Self-identified robotics background.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Expertise {
    /// "expert roboticist" (6 of 31).
    Expert,
    /// "novice" (14 of 31).
    Novice,
    /// "no robotics background" (11 of 31).
    None,
}

impl Expertise {
    /// In the thesis's order.
    pub const ALL: [Expertise; 3] = [Expertise::Expert, Expertise::Novice, Expertise::None];

    /// The label in tables.
    pub fn label(self) -> &'static str {
        match self {
            Expertise::Expert => "expert",
            Expertise::Novice => "novice",
            Expertise::None => "none",
        }
    }

    fn index(self) -> usize {
        match self {
            Expertise::Expert => 0,
            Expertise::Novice => 1,
            Expertise::None => 2,
        }
    }
}

/// One user's traits.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct UserTraits {
    pub expertise: Expertise,
    /// Seconds from seeing something to acting on it (a click, a hand move).
    pub reaction_time: f64,
    /// Probability of watching the robot at a given moment.
    pub attention: f64,
    /// Probability that a judgement follows the user's own rule (else it is noise).
    pub consistency: f64,
    /// Seconds without seeing progress before changing strategy or giving up.
    pub patience: f64,
}

impl UserTraits {
    /// The scripted ideal teacher (the thesis's authors): instant, watchful,
    /// consistent and never discouraged.
    pub const fn ideal() -> UserTraits {
        UserTraits { expertise: Expertise::Expert, reaction_time: 0.3, attention: 1.0, consistency: 1.0, patience: 1e9 }
    }
}

/// The distributions of the traits, per expertise (our choices, see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TraitModel {
    /// Median reaction time (s) per expertise, in [`Expertise::ALL`] order.
    pub reaction_median: [f64; 3],
    /// `σ_log` of the reaction time.
    pub reaction_sigma_log: f64,
    /// Median attention per expertise.
    pub attention_median: [f64; 3],
    /// Median consistency per expertise.
    pub consistency_median: [f64; 3],
    /// `σ` of attention and consistency on the logit scale.
    pub logit_sigma: f64,
    /// Median patience (s) per expertise.
    pub patience_median: [f64; 3],
    /// `σ_log` of patience.
    pub patience_sigma_log: f64,
}

impl TraitModel {
    /// The distributions the study draws from.
    pub const fn thesis() -> TraitModel {
        TraitModel {
            reaction_median: [0.6, 0.8, 0.9],
            reaction_sigma_log: 0.3,
            attention_median: [0.9, 0.8, 0.75],
            consistency_median: [0.95, 0.85, 0.8],
            logit_sigma: 0.6,
            patience_median: [240.0, 150.0, 120.0],
            patience_sigma_log: 0.4,
        }
    }

    /// Draws one user's traits (five normal draws, in a fixed order).
    pub fn draw<R: Rng + ?Sized>(&self, expertise: Expertise, rng: &mut R) -> UserTraits {
        let e = expertise.index();
        let log_normal = |median: f64, s: f64, z: f64| median * libm::exp(s * z);
        let logit_normal = |median: f64, z: f64| {
            let l = libm::log(median / (1.0 - median)) + self.logit_sigma * z;
            1.0 / (1.0 + libm::exp(-l))
        };
        let z: [f64; 4] = std::array::from_fn(|_| standard_normal(rng));
        UserTraits {
            expertise,
            reaction_time: log_normal(self.reaction_median[e], self.reaction_sigma_log, z[0]),
            attention: logit_normal(self.attention_median[e], z[1]),
            consistency: logit_normal(self.consistency_median[e], z[2]),
            patience: log_normal(self.patience_median[e], self.patience_sigma_log, z[3]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn draws_follow_their_medians() {
        let m = TraitModel::thesis();
        let mut rng = seeded(1);
        let n = 4000;
        let mut rt: Vec<f64> = Vec::new();
        let mut att: Vec<f64> = Vec::new();
        for _ in 0..n {
            let t = m.draw(Expertise::Novice, &mut rng);
            assert!(t.attention > 0.0 && t.attention < 1.0 && t.consistency > 0.0 && t.consistency < 1.0);
            assert!(t.reaction_time > 0.0 && t.patience > 0.0);
            rt.push(t.reaction_time);
            att.push(t.attention);
        }
        rt.sort_by(f64::total_cmp);
        att.sort_by(f64::total_cmp);
        assert!((rt[n / 2] - 0.8).abs() < 0.03, "median reaction {}", rt[n / 2]);
        assert!((att[n / 2] - 0.8).abs() < 0.02, "median attention {}", att[n / 2]);
    }
}
