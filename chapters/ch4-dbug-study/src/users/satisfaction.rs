//! "How well did the robot learn the task?" (1 not at all … 4 very well),
//! judged from what the user saw.
//!
//! Section 4.5 (l. 681): "users evaluated performance based on the success
//! of picking up as many hexbugs as possible. Hence, *waiting* at
//! appropriate times was not considered as successful as *picking up* or
//! *sweeping*." The question is the same for the three algorithms (l. 713),
//! so is the user's way of judging. The model: over the second half of the
//! session (the robot as the user leaves it, [`SatisfactionModel::from_fraction`]),
//! the user forms an impression `q ∈ [0, 1]` from the robot's own actions
//! they watched, in the form the reading `satisfaction-form` names
//! ([`SatisfactionForm`]):
//! - `pickup-count` (default, l. 681 read literally: a count of bugs picked
//!   up): `q = min(L, 3) / 3`, `L` the bugs the user saw the robot lift; one
//!   answer point per bug, up to the three on the table ("as many hexbugs
//!   as possible": all of them is very well);
//! - `success-count`: the same count of the robot's pick-ups and sweeps the
//!   user judged right ("not considered as successful as *picking up* or
//!   *sweeping*": both arms' successes count, waits do not);
//! - `ratio` (the round-1 to round-3 form): every watched action counts
//!   `+w` if judged right and `−w` if wrong, `w` 1 for a pickup or a sweep
//!   and [`SatisfactionModel::wait_weight`] for a wait, a lifted bug
//!   [`SatisfactionModel::lift_bonus`] more; `q = (S + W) / 2W` (`W` the
//!   summed weights, `q = 0` when the user saw nothing of the robot's own).
//!
//! The answer is `round(1 + 3q + ε)` clamped to 1…4, `ε ~ N(0, σ)` with σ
//! [`SatisfactionModel::noise`] (questionnaire noise). The form is decided
//! in the session (the answer's noise is drawn there), so the reading is
//! not report-only.

use rand::Rng;
use rlfd_rl::random::standard_normal;
use serde::{Deserialize, Serialize};

use crate::dbug::Action;
use crate::dbug::table::NUM_BUGS;

/// How the user turns what they watched into an impression (the reading
/// `satisfaction-form`; levels and sources in `crate::readings`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SatisfactionForm {
    /// Bugs seen lifted, one point each up to the three on the table (the default).
    PickupCount,
    /// Pick-ups and sweeps judged right, one point each up to three.
    SuccessCount,
    /// The weighted share of watched actions judged right, `(S + W) / 2W`.
    Ratio,
}

/// The satisfaction model's constants (our choices, from the sentence above;
/// the weights serve the `ratio` form only).
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
    /// The impression's form (reading `satisfaction-form`).
    pub form: SatisfactionForm,
}

impl SatisfactionModel {
    /// Waits weigh 0.2, a lifted bug 1 more, noise 0.5 points, second half
    /// of the session; the pickup count (the reading's default).
    pub const fn thesis() -> SatisfactionModel {
        SatisfactionModel {
            wait_weight: 0.2,
            lift_bonus: 1.0,
            noise: 0.5,
            from_fraction: 0.5,
            form: SatisfactionForm::PickupCount,
        }
    }
}

/// The running impression of one session.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Impression {
    score: f64,
    weight: f64,
    /// Bugs seen lifted.
    lifts: u32,
    /// Pick-ups and sweeps seen and judged right.
    arm_successes: u32,
}

impl Impression {
    /// A watched action of the robot's own, judged right or wrong.
    pub fn saw(&mut self, m: &SatisfactionModel, action: Action, judged_right: bool) {
        let w = if action == Action::Wait { m.wait_weight } else { 1.0 };
        self.weight += w;
        self.score += if judged_right { w } else { -w };
        self.arm_successes += u32::from(judged_right && action != Action::Wait);
    }

    /// A pickup the user saw lift a bug.
    pub fn saw_lift(&mut self, m: &SatisfactionModel) {
        self.weight += m.lift_bonus;
        self.score += m.lift_bonus;
        self.lifts += 1;
    }

    /// `q ∈ [0, 1]` in the model's form.
    pub fn quality(&self, m: &SatisfactionModel) -> f64 {
        let count = |n: u32| f64::from(n.min(NUM_BUGS as u32)) / NUM_BUGS as f64;
        match m.form {
            SatisfactionForm::PickupCount => count(self.lifts),
            SatisfactionForm::SuccessCount => count(self.arm_successes),
            SatisfactionForm::Ratio => {
                if self.weight > 0.0 {
                    (self.score + self.weight) / (2.0 * self.weight)
                } else {
                    0.0
                }
            }
        }
    }

    /// The questionnaire answer 1…4.
    pub fn answer<R: Rng + ?Sized>(&self, m: &SatisfactionModel, rng: &mut R) -> u8 {
        let v = 1.0 + 3.0 * self.quality(m) + m.noise * standard_normal(rng);
        v.round().clamp(1.0, 4.0) as u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn pickups_weigh_more_than_waits() {
        let m = SatisfactionModel { noise: 0.0, form: SatisfactionForm::Ratio, ..SatisfactionModel::thesis() };
        let mut rng = seeded(1);
        let mut waiter = Impression::default();
        for _ in 0..10 {
            waiter.saw(&m, Action::Wait, true);
        }
        waiter.saw(&m, Action::Pickup, false);
        // 2 right-weight against 1 wrong: q = (1 + 3) / 6.
        assert!((waiter.quality(&m) - 4.0 / 6.0).abs() < 1e-12);
        let mut picker = Impression::default();
        picker.saw(&m, Action::Pickup, true);
        picker.saw_lift(&m);
        assert_eq!(picker.answer(&m, &mut rng), 4);
        assert_eq!(Impression::default().answer(&m, &mut rng), 1, "saw nothing: not at all");
    }

    #[test]
    fn counts_give_a_point_per_bug_up_to_three_and_waits_none() {
        let m = SatisfactionModel { noise: 0.0, ..SatisfactionModel::thesis() };
        let s = SatisfactionModel { form: SatisfactionForm::SuccessCount, ..m };
        let mut rng = seeded(1);
        let mut waiter = Impression::default();
        for _ in 0..50 {
            waiter.saw(&m, Action::Wait, true);
        }
        assert_eq!(waiter.answer(&m, &mut rng), 1, "a robot that only waits picks up nothing");
        assert_eq!(waiter.answer(&s, &mut rng), 1);
        let mut picker = Impression::default();
        picker.saw(&m, Action::Sweep, true);
        picker.saw(&m, Action::Pickup, true);
        picker.saw_lift(&m);
        assert_eq!(picker.answer(&m, &mut rng), 2, "one bug lifted");
        assert_eq!(picker.answer(&s, &mut rng), 3, "two arm actions judged right");
        for _ in 0..5 {
            picker.saw_lift(&m);
        }
        assert_eq!(picker.answer(&m, &mut rng), 4, "three or more: very well");
    }
}
