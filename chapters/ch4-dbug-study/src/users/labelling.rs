//! How a user teaches CBA: answering the robot's requests with an action
//! and correcting its mistakes.
//!
//! Section 4.4: CBA assumes "1. The user will provide training data with
//! multiple demonstrations for each action, effectively sampling the state
//! space. 2. The user performs a correction for an incorrectly selected
//! action during the time interval between the beginning of the incorrect
//! action, and the beginning of the next action"; users gave "very
//! scattered" demonstrations, "three users violated assumption (1)", and
//! "Several users also violated assumption (2) by not providing corrections
//! within the required timeframe"; "if the teacher is distracted and reacts
//! slowly, corrections may have a negative impact"; "the environment did
//! not pause when the robot requested help".
//!
//! The model: a request is answered after the user's reaction time, plus,
//! when the user was not watching (probability `1 − attention`), a lapse of
//! mean [`LabellingModel::lapse_seconds`]; the answer is what the user then
//! judges right ([`super::perception`]) — the table has moved on meanwhile,
//! but the robot files it under the state it asked about. A watched action
//! of the robot's own judged wrong is corrected after the user recognises
//! it ([`super::reward::RewardModel::recognise_ticks`]'s timing) and
//! reacts, plus [`LabellingModel::correction_seconds`] to pick the action
//! on the screen; a correction that arrives after the next action began
//! labels that action's state instead. Scattered demonstrations are not set
//! by a rate: they follow from where the bugs are when the robot asks, and
//! from users who do not control them.
//!
//! Giving up ("three users violated assumption (1) by not providing enough
//! training data for the classifier to confidently make any predictions
//! (minimum of 3 demonstrations of each action)"; "people giving up … after
//! a few demonstrations (because robot is now behaving any
//! differently)", section 4.6, read as "not behaving"): a user stops answering when their patience
//! (the trait, scaled by [`LabellingModel::patience_scale`]) has run out
//! since the robot last did something on its own, or since the session
//! began; an unanswered request lapses after
//! [`LabellingModel::request_timeout_seconds`] and the robot asks again. The
//! scale is the one constant fitted here, on an input count: that 3 of 31
//! users leave the classifier without its minimum ([`crate::calibrations`];
//! `cargo xtask calibrate cba-users`).

use rand::Rng;
use rlfd_rl::random::{bernoulli, uniform01};
use serde::{Deserialize, Serialize};

use super::traits::UserTraits;
use crate::dbug::seconds_to_ticks;

/// The calibrated patience scale ([`crate::calibrations::fit`]).
pub const PATIENCE_SCALE: f64 = 1.3;

/// The CBA teaching model's constants (ours).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LabellingModel {
    /// Mean extra delay when the user was not watching (s, exponential).
    pub lapse_seconds: f64,
    /// Time to pick a correction on the screen (s).
    pub correction_seconds: f64,
    /// How long an unanswered request waits before the robot asks again (s).
    pub request_timeout_seconds: f64,
    /// Patience in a CBA session as a multiple of the user's patience trait
    /// (calibrated: [`crate::calibrations`]).
    pub patience_scale: f64,
}

impl LabellingModel {
    /// A lapse of 4 s on average; half a second to pick a correction; a
    /// request lapses after 5 s; the calibrated patience scale.
    pub const fn thesis() -> LabellingModel {
        LabellingModel {
            lapse_seconds: 4.0,
            correction_seconds: 0.5,
            request_timeout_seconds: 5.0,
            patience_scale: PATIENCE_SCALE,
        }
    }

    /// Ticks until the user acts on something they have to notice first.
    pub fn response_ticks<R: Rng + ?Sized>(&self, traits: &UserTraits, rng: &mut R) -> u32 {
        let mut s = traits.reaction_time;
        if !bernoulli(rng, traits.attention) {
            s += -self.lapse_seconds * libm::log(1.0 - uniform01(rng));
        }
        seconds_to_ticks(s).max(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn lapses_delay_inattentive_users() {
        let m = LabellingModel::thesis();
        let mut rng = seeded(2);
        let ideal = UserTraits::ideal();
        assert_eq!(m.response_ticks(&ideal, &mut rng), 3);
        let drifting = UserTraits { attention: 0.0, ..ideal };
        let n = 20_000;
        let mean = (0..n).map(|_| f64::from(m.response_ticks(&drifting, &mut rng))).sum::<f64>() / f64::from(n);
        assert!((mean - 43.0).abs() < 1.5, "0.3 s + 4 s on average: {mean} ticks");
    }
}
