//! "How well did the robot learn the task?" (1 not at all … 4 very well),
//! judged from what the user saw.
//!
//! Section 4.5: "users evaluated performance based on the success of
//! picking up as many hexbugs as possible. Hence, *waiting* at appropriate
//! times was not considered as successful as *picking up* or *sweeping*."
//! The model: over the second half of the session (the robot as the user
//! leaves it), every action of the robot's own that the user watched counts
//! `+w` if the user judged it right and `−w` if wrong, with weight `w` 1 for
//! a pickup, 1 for a sweep and [`SatisfactionModel::wait_weight`] for a
//! wait; a pickup that lifted a bug counts [`SatisfactionModel::lift_bonus`]
//! more. The impression `q = (S + W) / 2W` (`W` the summed weights; `q = 0`
//! when the user saw the robot do nothing of its own) becomes the answer
//! `round(1 + 3q + ε)` clamped to 1…4, `ε ~ N(0, σ)` with σ
//! [`SatisfactionModel::noise`] (questionnaire noise).

use rand::Rng;
use rlfd_rl::random::standard_normal;
use serde::{Deserialize, Serialize};

use crate::dbug::Action;

/// The satisfaction model's constants (our choices, from the sentence above).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SatisfactionModel {
    /// Weight of a watched wait (pickups and sweeps weigh 1).
    pub wait_weight: f64,
    /// Extra weight of a pickup that lifted a bug.
    pub lift_bonus: f64,
    /// σ of the answer's noise, in answer points.
    pub noise: f64,
    /// The impression counts actions from this fraction of the session on.
    pub from_fraction: f64,
}

impl SatisfactionModel {
    /// Waits weigh 0.2, a lifted bug 1 more, noise 0.5 points, second half of the session.
    pub const fn thesis() -> SatisfactionModel {
        SatisfactionModel { wait_weight: 0.2, lift_bonus: 1.0, noise: 0.5, from_fraction: 0.5 }
    }
}

/// The running impression of one session.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Impression {
    score: f64,
    weight: f64,
}

impl Impression {
    /// A watched action of the robot's own, judged right or wrong.
    pub fn saw(&mut self, m: &SatisfactionModel, action: Action, judged_right: bool) {
        let w = if action == Action::Wait { m.wait_weight } else { 1.0 };
        self.weight += w;
        self.score += if judged_right { w } else { -w };
    }

    /// A pickup the user saw lift a bug.
    pub fn saw_lift(&mut self, m: &SatisfactionModel) {
        self.weight += m.lift_bonus;
        self.score += m.lift_bonus;
    }

    /// `q ∈ [0, 1]`.
    pub fn quality(&self) -> f64 {
        if self.weight > 0.0 { (self.score + self.weight) / (2.0 * self.weight) } else { 0.0 }
    }

    /// The questionnaire answer 1…4.
    pub fn answer<R: Rng + ?Sized>(&self, m: &SatisfactionModel, rng: &mut R) -> u8 {
        let v = 1.0 + 3.0 * self.quality() + m.noise * standard_normal(rng);
        v.round().clamp(1.0, 4.0) as u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn pickups_weigh_more_than_waits() {
        let m = SatisfactionModel { noise: 0.0, ..SatisfactionModel::thesis() };
        let mut rng = seeded(1);
        let mut waiter = Impression::default();
        for _ in 0..10 {
            waiter.saw(&m, Action::Wait, true);
        }
        waiter.saw(&m, Action::Pickup, false);
        // 2 right-weight against 1 wrong: q = (1 + 3) / 6.
        assert!((waiter.quality() - 4.0 / 6.0).abs() < 1e-12);
        let mut picker = Impression::default();
        picker.saw(&m, Action::Pickup, true);
        picker.saw_lift(&m);
        assert_eq!(picker.answer(&m, &mut rng), 4);
        assert_eq!(Impression::default().answer(&m, &mut rng), 1, "saw nothing: not at all");
    }
}
